#!/usr/bin/env python3
"""A wave tank's gauges against linear wave theory, from Python.

A piston paddle makes regular waves (H = 0.04 m, T = 1 s) in 0.3 m of water
(scenes/wave_tank.json, a slice periodic across z); a damping zone absorbs them at the far end.
Two gauges, at 1 m and 2 m from the paddle, are read every frame and plotted with the
progressive wave of linear (Airy) theory, η = H/2 · r(t − x/c_g) · cos(ωt − kx), k from
ω² = g k tanh(kd) (tide.waves.wave_number), the paddle's smooth start r travelling at the
group velocity c_g. Written to wave_gauges.png.

    python3 examples/python/wave_tank_gauge.py                         # 0.02 m spacing, 8 s (minutes)
    python3 examples/python/wave_tank_gauge.py --spacing 0.04 --duration 3 --out /tmp   # quick
"""
import argparse
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import tide  # noqa: E402

DEPTH, HEIGHT, PERIOD, RAMP, PADDLE_X = 0.3, 0.04, 1.0, 2.0, 0.1
GAUGES = (1.1, 2.1)  # m: 1 m and 2 m from the paddle, past its evanescent modes (~3 depths)


def scene(spacing, duration):
    width = 4 * spacing  # the thinnest periodic slice: two kernel supports
    return {
        "name": "wave tank (Python example)",
        "domain": {"min": [0, 0, 0], "max": [5.5, 0.6, width], "periodic": [False, False, True]},
        "gravity": [0, -9.81, 0],
        "particle_spacing": spacing,
        "end_time": duration,
        "solver": {"method": "dfsph", "max_density_error": 0.003, "shifting": 0.2, "max_dt": 0.005, "xsph": 0,
                   "momentum": 0},
        "materials": [{"name": "water", "density": 1000, "viscosity": 0.001}],
        "wavemaker": {"type": "piston", "x": PADDLE_X, "depth": DEPTH, "wave_height": HEIGHT, "period": PERIOD,
                      "ramp_time": RAMP},
        "damping": {"x_start": 4.0, "x_end": 5.5},
        "gauges": [{"name": f"x{x - PADDLE_X:.0f}m", "x": x, "z": width / 2} for x in GAUGES],
        "blocks": [{"min": [PADDLE_X, 0, 0], "max": [5.5, DEPTH, width], "material": "water"}],
        "output": {"fps": 50},
    }


def linear_theory(t, x):
    """η of the progressive wave a piston paddle at PADDLE_X makes (its displacement is
    S/2 sin ωt, so η is in phase with its velocity), switched on by the ramp at c_g."""
    g = 9.81
    omega = 2 * math.pi / PERIOD
    k = tide.waves.wave_number(omega, DEPTH, g)
    kd = k * DEPTH
    cg = omega / k * 0.5 * (1 + 2 * kd / math.sinh(2 * kd))
    r = np.array([tide.waves.ramp(max(tt - (x - PADDLE_X) / cg, 0.0), RAMP) for tt in t])
    return 0.5 * HEIGHT * r * np.cos(omega * t - k * (x - PADDLE_X))


def crest_to_trough(t, eta, since):
    """Mean crest-to-trough height over the whole periods after `since`, m."""
    heights = []
    t0 = since
    while t0 + PERIOD <= t[-1] + 1e-9:
        window = (t >= t0) & (t < t0 + PERIOD)
        heights.append(eta[window].max() - eta[window].min())
        t0 += PERIOD
    return float(np.mean(heights)) if heights else float("nan")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--spacing", type=float, default=0.02, help="particle spacing, m (default 0.02: 15 across the depth)")
    p.add_argument("--duration", type=float, default=8.0, help="simulated seconds (default 8)")
    p.add_argument("--out", default=".", help="folder for wave_gauges.png")
    p.add_argument("--threads", type=int, default=0)
    p.add_argument("--no-progress", action="store_true")
    a = p.parse_args()

    world = tide.World(scene(a.spacing, a.duration), threads=a.threads)
    times, rows = [], []

    def sample(w):
        times.append(w.time)
        rows.append(w.read_gauges())

    world.run(callback=sample, progress=not a.no_progress)
    t = np.array(times)
    eta = np.array(rows) - np.array(rows[0])  # from the still level the lattice gives (d to within a spacing)
    print(f"{world.particle_count} particles (spacing {a.spacing} m), {world.steps} steps")

    fig, axes = plt.subplots(len(GAUGES), 1, figsize=(7, 2.2 * len(GAUGES) + 0.6), sharex=True)
    for g, (ax, x) in enumerate(zip(np.atleast_1d(axes), GAUGES)):
        theory = linear_theory(t, x)
        since = max(RAMP + (x - PADDLE_X) / 0.95, t[-1] - 3 * PERIOD)  # after the ramp reached the gauge
        measured = crest_to_trough(t, eta[:, g], since)
        if math.isnan(measured):
            print(f"gauge {x - PADDLE_X:.0f} m from the paddle: the run ends before a whole period after {since:.1f} s")
        else:
            print(f"gauge {x - PADDLE_X:.0f} m from the paddle: wave height {measured:.4f} m over the periods after "
                  f"{since:.1f} s (linear theory {HEIGHT} m, {100 * (measured / HEIGHT - 1):+.1f} %)")
        ax.plot(t, 100 * theory, "--", color="black", lw=1, label="linear theory")
        ax.plot(t, 100 * eta[:, g], "-", color="tab:blue", lw=1.2, label="tide")
        ax.set_ylabel(r"$\eta$ (cm)")
        ax.set_title(f"gauge {x - PADDLE_X:.0f} m from the paddle", fontsize=9)
        ax.grid(alpha=0.3)
    np.atleast_1d(axes)[0].legend(loc="upper left", fontsize=8)
    np.atleast_1d(axes)[-1].set_xlabel("t (s)")
    fig.suptitle(f"Piston waves H = {HEIGHT} m, T = {PERIOD} s, d = {DEPTH} m (spacing {a.spacing} m)", fontsize=10)
    fig.tight_layout()
    os.makedirs(a.out, exist_ok=True)
    png = os.path.join(a.out, "wave_gauges.png")
    fig.savefig(png, dpi=120)
    print("wrote", png)


if __name__ == "__main__":
    main()
