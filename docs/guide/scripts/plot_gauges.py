#!/usr/bin/env python3
"""Plot the wave gauges a `tide run` wrote (gauges.csv) against the paddle's target height.

Usage: plot_gauges.py SCENE.json GAUGES.csv OUT.png [--from SECONDS]

gauges.csv has a `time` column and one column per gauge: the free-surface height y in m
(docs/scene-format.md). The elevation is y minus the still-water depth (the scene's
`wavemaker.depth`); the dashed lines are ±H/2 of the wave height the scene asks for. Also
prints each gauge's mean zero up-crossing wave height from --from seconds on.
"""
import argparse
import csv
import json

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def up_crossing_heights(t, eta):
    """Crest-to-trough height of each wave between two zero up-crossings."""
    mean = eta - eta.mean()
    ups = np.where((mean[:-1] < 0) & (mean[1:] >= 0))[0]
    return [mean[a:b + 1].max() - mean[a:b + 1].min() for a, b in zip(ups[:-1], ups[1:])]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene")
    parser.add_argument("gauges")
    parser.add_argument("out")
    parser.add_argument("--from", dest="start", type=float, default=4.0,
                        help="start of the window for the wave heights (s)")
    args = parser.parse_args()

    with open(args.scene) as f:
        maker = json.load(f)["wavemaker"]
    depth, height = maker["depth"], maker["wave_height"]
    with open(args.gauges, newline="") as f:
        rows = list(csv.DictReader(f))
    names = [key for key in rows[0] if key != "time"]
    t = np.array([float(r["time"]) for r in rows])

    fig, ax = plt.subplots(figsize=(6.4, 3.4), dpi=100)
    window = t >= args.start
    for name in names:
        eta = np.array([float(r[name]) for r in rows]) - depth
        ax.plot(t, eta * 1000.0, lw=1.0, label=name)
        heights = up_crossing_heights(t[window], eta[window])
        if heights:
            print(f"{name}: mean up-crossing height {np.mean(heights):.4f} m over {len(heights)} waves"
                  f" (target {height} m)")
    for sign in (-1, 1):
        ax.axhline(sign * height / 2 * 1000.0, color="k", ls="--", lw=0.8)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("surface elevation (mm)")
    ax.set_title(f"gauges of {args.scene.split('/')[-1]}; dashed: ±H/2 = ±{height / 2 * 1000:g} mm",
                 fontsize=10)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.0, 1.0), title="gauge", title_fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out)


if __name__ == "__main__":
    main()
