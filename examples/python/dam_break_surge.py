#!/usr/bin/env python3
"""A dam break's surge front against Koshizuka & Oka's experiment, from Python.

A water column L = 0.146 m wide and 2L high collapses along a dry floor (Koshizuka & Oka 1996,
the Martin & Moyce aspect ratio n² = 2). The front's position z on the floor, as Z = z/L
against T = t·√(2g/L), is compared with the experiment's points (data/, digitised by the
PySPH developers; see the file's header) and plotted to surge_front.png.

The flow is 2D: the tank is a slice a few particles thick, periodic across z.

    python3 examples/python/dam_break_surge.py                 # L/40 (≈ 13 000 particles, minutes)
    python3 examples/python/dam_break_surge.py --resolution 10 --out /tmp   # quick
"""
import argparse
import math
import os
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import tide  # noqa: E402

L = 0.146   # m, the column's width (Koshizuka & Oka 1996)
G = 9.81
DATA = pathlib.Path(__file__).resolve().parent / "data" / "dam_break_koshizuka_oka_1996_surge_front_exp.csv"


def scene(resolution, t_end):
    s = L / resolution
    width = 4 * s  # the thinnest periodic slice: two kernel supports
    return {
        "name": "Koshizuka & Oka dam break (2D slice)",
        "domain": {"min": [0, 0, 0], "max": [4 * L, 3 * L, width], "periodic": [False, False, True]},
        "gravity": [0, -G, 0],
        "particle_spacing": s,
        "end_time": t_end,
        "solver": {"method": "dfsph"},
        "materials": [{"name": "water", "density": 1000, "viscosity": 0.001}],
        "blocks": [{"min": [0, 0, 0], "max": [L, 2 * L, width], "material": "water"}],
        "output": {"fps": 200},
    }


def front(world):
    """The leading edge on the floor, m: the farthest particle of the lowest three layers, plus
    the half spacing its volume reaches beyond it (so the column starts at Z = 1)."""
    x = world.positions
    s = world.particle_spacing
    low = x[:, 1] < 3 * s
    return float(x[low, 0].max()) + 0.5 * s if low.any() else 0.0


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--resolution", type=int, default=40, help="particles across the column's width L (default 40)")
    p.add_argument("--out", default=".", help="folder for surge_front.png")
    p.add_argument("--threads", type=int, default=0)
    p.add_argument("--no-progress", action="store_true")
    a = p.parse_args()
    if a.resolution < 4:
        p.error("--resolution: must be >= 4")

    rows = [line for line in DATA.read_text().splitlines() if line and not line.startswith("#")]
    experiment = np.array([[float(v) for v in line.split(",")] for line in rows[1:]])  # after the T,Z header
    T_end = experiment[:, 0].max() + 0.1
    t_scale = math.sqrt(2 * G / L)  # T = t · t_scale
    world = tide.World(scene(a.resolution, T_end / t_scale), threads=a.threads)
    T, Z = [], []

    def sample(w):
        T.append(w.time * t_scale)
        Z.append(front(w) / L)

    world.run(callback=sample, progress=not a.no_progress)
    T, Z = np.array(T), np.array(Z)

    sph_at = np.interp(experiment[:, 0], T, Z)
    print(f"{world.particle_count} particles (L/{a.resolution}), {world.steps} steps")
    print("   T    Z exp    Z tide   difference")
    for (t, z), zs in zip(experiment, sph_at):
        print(f"{t:5.2f}  {z:6.3f}   {zs:6.3f}   {100 * (zs / z - 1):+5.1f} %")

    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.plot(T, Z, "-", color="tab:blue", label=f"tide (dfsph, L/{a.resolution}, {world.particle_count} particles)")
    ax.plot(experiment[:, 0], experiment[:, 1], "o", color="black", mfc="none", label="Koshizuka & Oka 1996 (experiment)")
    ax.set_xlabel(r"$T = t\,\sqrt{2g/L}$")
    ax.set_ylabel(r"$Z = z/L$ (surge front)")
    ax.set_title("Dam break: surge front")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    os.makedirs(a.out, exist_ok=True)
    png = os.path.join(a.out, "surge_front.png")
    fig.savefig(png, dpi=120)
    print("wrote", png)


if __name__ == "__main__":
    main()
