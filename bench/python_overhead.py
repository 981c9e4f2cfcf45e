#!/usr/bin/env python3
"""The Python module's overhead: one scene stepped by `tide run` and by tide.World.run.

Both simulate the same scene for the same simulated time, writing the same VTU frames (the
CLI's own, and tide.io.write_frame from a per-frame callback in Python), alternately
`--repeats` times; each reports the wall time of its run (the CLI: stats.json's wall_time,
which leaves out loading and setting up, as the Python timing does). Prints each pair and
the median ratio Python / CLI. The steps must agree: the same arithmetic runs underneath.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py            # ~54k particles
"""
import argparse
import json
import os
import pathlib
import statistics
import subprocess
import tempfile
import time

import tide

ROOT = pathlib.Path(__file__).resolve().parents[1]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--scene", default=str(ROOT / "scenes" / "bench_dam_break.json"))
    p.add_argument("--end-time", type=float, default=0.12)
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--tide", default=str(ROOT / "build" / "bin" / "tide"))
    a = p.parse_args()

    ratios = []
    with tempfile.TemporaryDirectory() as tmp:
        for r in range(a.repeats):
            out = os.path.join(tmp, "cli")
            subprocess.run([a.tide, "run", a.scene, "--out", out, "--force", "--quiet", "--end-time", str(a.end_time),
                            "--format", "vtu"], check=True)
            stats = json.load(open(os.path.join(out, "stats.json")))

            world = tide.World(a.scene)
            frames = []
            start = time.perf_counter()
            world.run(a.end_time, progress=False,
                      callback=lambda w: frames.append(tide.io.write_frame(w, os.path.join(tmp, f"py_{len(frames)}.vtu"))))
            wall = time.perf_counter() - start
            if world.steps != stats["steps"]:
                raise SystemExit(f"steps differ: Python {world.steps}, CLI {stats['steps']}")
            ratios.append(wall / stats["wall_time"])
            print(f"run {r + 1}: {world.particle_count} particles, {world.steps} steps, {len(frames)} frames: "
                  f"CLI {stats['wall_time']:.2f} s, Python {wall:.2f} s, ratio {ratios[-1]:.3f}", flush=True)
    print(f"median ratio Python / CLI: {statistics.median(ratios):.3f} ({a.repeats} pairs)")


if __name__ == "__main__":
    main()
