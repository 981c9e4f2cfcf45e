"""What every validation case shares: running `tide run` on a scene, reading what it writes,
the data files, and one row of the report's table."""
import csv
import glob
import json
import os
import subprocess
import time
from dataclasses import dataclass, field

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data")
SCENES = os.path.join(os.path.dirname(HERE), "scenes")   # the shipped scenes the cases start from


@dataclass
class Row:
    """One line of the table: a measure of a case against its reference."""
    measure: str
    tide: float
    reference: float
    tolerance: str          # as stated in the table, e.g. "±5 %"
    passed: bool
    fmt: str = "{:.3g}"


@dataclass
class Result:
    case: str
    figure: str             # file name under docs/images/
    resolution: str
    wall_time: float
    rows: list = field(default_factory=list)
    note: str = ""


def within(value, reference, relative):
    return bool(np.isfinite(value)) and abs(value - reference) <= relative * abs(reference)


def rel_row(measure, value, reference, relative, fmt="{:.3g}"):
    return Row(measure, value, reference, f"±{100 * relative:g} %", within(value, reference, relative), fmt)


def abs_row(measure, value, reference, bound, fmt="{:.3g}", unit=""):
    ok = bool(np.isfinite(value)) and abs(value - reference) <= bound
    return Row(measure, value, reference, f"±{bound:g}{unit}", ok, fmt)


def read_data(name):
    """A data file of validation/data/ as a dict of numpy columns (string columns kept as str)."""
    with open(os.path.join(DATA, name)) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#") and line.strip())]
    header, body = rows[0], rows[1:]
    out = {}
    for i, h in enumerate(header):
        col = [r[i] for r in body]
        try:
            out[h] = np.array([float(v) for v in col])
        except ValueError:
            out[h] = np.array(col)
    return out


def load_scene(name):
    with open(os.path.join(SCENES, name)) as f:
        return json.load(f)


class Tide:
    """Runs the `tide` command line on scene dicts in a work folder."""

    def __init__(self, binary, work, threads):
        self.binary, self.work, self.threads = binary, work, threads
        os.makedirs(work, exist_ok=True)

    def run(self, name, scene):
        """Writes the scene, runs it, returns (output folder, wall seconds)."""
        path = os.path.join(self.work, name + ".json")
        with open(path, "w") as f:
            json.dump(scene, f, indent=1)
        out = os.path.join(self.work, name)
        cmd = [self.binary, "run", path, "--out", out, "--force", "--quiet", "--threads", str(self.threads)]
        start = time.monotonic()
        # Sleeping, not spinning, OpenMP workers: the machine may be shared (as tests/CMakeLists.txt).
        env = dict(os.environ, OMP_WAIT_POLICY=os.environ.get("OMP_WAIT_POLICY", "PASSIVE"))
        proc = subprocess.run(cmd, capture_output=True, text=True, env=env)
        wall = time.monotonic() - start
        if proc.returncode != 0:
            raise RuntimeError(f"{' '.join(cmd)} failed ({proc.returncode}):\n{proc.stderr[-2000:]}")
        return out, wall


def frames(out):
    """The PLY frames of a run, in order: frame k is at time k / fps."""
    return sorted(glob.glob(os.path.join(out, "frame_*.ply")))


_PLY_TYPES = {"float": "<f4", "double": "<f8", "uchar": "u1", "ushort": "<u2", "uint": "<u4", "int": "<i4"}


def read_frame(path):
    """A binary PLY frame of `tide run` as a dict of numpy columns named as its properties
    (x, y, z, vx, vy, vz, density, pressure, material, ...)."""
    with open(path, "rb") as f:
        n, props = 0, []
        while True:
            line = f.readline().decode().strip()
            if line.startswith("element vertex"):
                n = int(line.split()[2])
            elif line.startswith("property"):
                _, kind, name = line.split()
                props.append((name, _PLY_TYPES[kind]))
            elif line == "end_header":
                break
        a = np.frombuffer(f.read(), dtype=np.dtype(props), count=n)
    return {name: a[name].astype(float) for name, _ in props}


def read_table(path):
    """gauges.csv / probes.csv as a dict of numpy columns."""
    with open(path) as f:
        header = f.readline().strip().split(",")
    a = np.genfromtxt(path, delimiter=",", skip_header=1, ndmin=2)
    return {h: a[:, i] for i, h in enumerate(header)}


def column_blocks(nx, ny, spacing, x0, y0, z_extent, value):
    """One block per lattice cell of an nx × ny patch (each spanning z): `value(x, y)` gives the
    cell's (velocity, material) at its centre. How a scene sets a velocity field per particle
    column, as tests/test_multifluid.cpp builds a disc from one-row blocks."""
    blocks = []
    for i in range(nx):
        for j in range(ny):
            xa, ya = x0 + i * spacing, y0 + j * spacing
            vel, material = value(xa + 0.5 * spacing, ya + 0.5 * spacing)
            blocks.append({"min": [xa, ya, 0.0], "max": [xa + spacing, ya + spacing, z_extent],
                           "velocity": [float(vel[0]), float(vel[1]), 0.0], "material": material})
    return blocks


def fit_damped_cosine(t, y):
    """Least-squares fit y ≈ A e^{-βt} cos(ωt + φ) + c; returns (ω, β, A). Starts from the
    spectrum's peak (uniform samples, zero-padded) and refines on a grid around it."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    ok = np.isfinite(y)
    t, y = t[ok], y[ok]
    dt = np.median(np.diff(t))
    n = 16 * len(y)
    power = np.abs(np.fft.rfft(y - y.mean(), n))
    freqs = 2 * np.pi * np.fft.rfftfreq(n, dt)
    omega = freqs[1 + np.argmax(power[1:])]
    # Linear in (a, b, c) for fixed (ω, β): grid-refine ω and β.
    best = None
    for w in np.linspace(0.8 * omega, 1.2 * omega, 161):
        for beta in np.linspace(-0.2 * w, 0.5 * w, 71):
            e = np.exp(-beta * (t - t[0]))
            m = np.column_stack([e * np.cos(w * t), e * np.sin(w * t), np.ones_like(t)])
            coef, res, *_ = np.linalg.lstsq(m, y, rcond=None)
            r = np.sum((m @ coef - y) ** 2)
            if best is None or r < best[0]:
                best = (r, w, beta, np.hypot(coef[0], coef[1]))
    return best[1], best[2], best[3]
