#!/usr/bin/env python3
"""Plot tide's benchmark rows (bench/results/<cpu>.csv, written by tide_scenarios) over time,
against SPlisHSPlasH's wall time on the same dam break.

Usage: plot_bench.py RESULTS.csv OUT.png

Each point is one run of `tide_scenarios --seconds 1 --threads 2`: the wall seconds one
simulated second took. Single runs on a shared 2-core machine: a point far above its
neighbours is a busy sitting, not a slower build.
"""
import csv
import sys
from datetime import datetime

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# SPlisHSPlasH 2.16 on the same kind of machine (2 threads), the reference of docs/performance.md.
SPLISHSPLASH = {
    ("dam_break_50k", "dfsph"): 47.9,
    ("dam_break_200k", "dfsph"): 306.7,
    ("dam_break_50k", "wcsph"): 125.4,
}
SERIES = [
    (("dam_break_50k", "dfsph"), "50k dam break, dfsph", "tab:blue"),
    (("dam_break_200k", "dfsph"), "200k dam break, dfsph", "tab:orange"),
    (("dam_break_50k", "wcsph"), "50k dam break, wcsph", "tab:green"),
]


def main():
    results, out = sys.argv[1], sys.argv[2]
    rows = {}
    with open(results, newline="") as f:
        for r in csv.DictReader(f):
            if float(r["seconds"]) != 1 or int(r["threads"]) != 2:
                continue
            key = (r["scene"], r["solver"])
            when = datetime.strptime(r["date"], "%Y-%m-%dT%H:%M:%SZ")
            rows.setdefault(key, []).append((when, 1.0 / float(r["sim_s_per_wall_s"])))

    fig, ax = plt.subplots(figsize=(6.4, 3.6), dpi=100)
    for key, label, color in SERIES:
        points = sorted(rows.get(key, []))
        if points:
            ax.plot([p[0] for p in points], [p[1] for p in points], "o", color=color, ms=4,
                    label=f"tide, {label}")
        ax.axhline(SPLISHSPLASH[key], color=color, ls="--", lw=1)
    ax.plot([], [], "k--", lw=1, label="SPlisHSPlasH, same scene (dashed)")
    ax.set_yscale("log")
    ticks = [10, 20, 50, 100, 200, 500]
    ax.set_yticks(ticks)
    ax.set_yticklabels([str(t) for t in ticks])
    ax.minorticks_off()
    ax.set_ylabel("wall seconds for 1 simulated second")
    ax.set_title("tide_scenarios --seconds 1 --threads 2 (Intel Xeon, 2 vCPUs)", fontsize=10)
    ax.legend(fontsize=7, loc="lower left")
    fig.autofmt_xdate()
    fig.tight_layout()
    fig.savefig(out)


if __name__ == "__main__":
    main()
