#!/usr/bin/env python3
"""Draw one frame written by `tide run --format csv` as a side view of its particles.

Usage: plot_frame.py FRAME.csv OUT.png [--color speed|pressure|material] [--view xy|xz]
                                     [--slab MIN MAX] [--title TEXT]

The CSV columns are those `tide run` writes (x, y, z, vx, vy, vz, density, pressure,
material; docs/scene-format.md). Particles are drawn back to front along the axis left out,
so the nearest ones are on top; --slab keeps only those within [MIN, MAX] along it (a cut).
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_frame(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {key: np.array([float(r[key]) for r in rows]) for key in rows[0]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("frame")
    parser.add_argument("out")
    parser.add_argument("--color", default="speed", choices=["speed", "pressure", "material"])
    parser.add_argument("--view", default="xy", choices=["xy", "xz"])
    parser.add_argument("--slab", nargs=2, type=float, metavar=("MIN", "MAX"),
                        help="keep the particles within [MIN, MAX] m along the axis left out")
    parser.add_argument("--title", default="")
    args = parser.parse_args()

    p = read_frame(args.frame)
    horizontal, vertical = args.view[0], args.view[1]
    depth_axis = ({"x", "y", "z"} - {horizontal, vertical}).pop()
    if args.slab:
        keep = (p[depth_axis] >= args.slab[0]) & (p[depth_axis] <= args.slab[1])
        p = {key: value[keep] for key, value in p.items()}
    order = np.argsort(-p[depth_axis])  # far particles first, near ones drawn over them

    if args.color == "speed":
        value = np.sqrt(p["vx"] ** 2 + p["vy"] ** 2 + p["vz"] ** 2)
        label, cmap = "speed (m/s)", "viridis"
    elif args.color == "pressure":
        value = p["pressure"] / 1000.0
        label, cmap = "pressure (kPa)", "magma"
    else:
        value = p["material"]
        label, cmap = "material", "tab10"

    fig, ax = plt.subplots(figsize=(6.4, 3.2), dpi=100)
    points = ax.scatter(p[horizontal][order], p[vertical][order], c=value[order], s=3,
                        cmap=cmap, linewidths=0)
    if args.color == "material":
        points.set_clim(-0.5, 9.5)
    else:
        fig.colorbar(points, ax=ax, label=label, fraction=0.04, pad=0.02)
    ax.set_aspect("equal")
    ax.set_xlabel(f"{horizontal} (m)")
    ax.set_ylabel(f"{vertical} (m)")
    if args.title:
        ax.set_title(args.title, fontsize=10)
    fig.tight_layout()
    fig.savefig(args.out)


if __name__ == "__main__":
    main()
