#!/usr/bin/env python3
"""The Python module's overhead: one scene stepped by `tide run` and by tide.World.run.

Both simulate the same scene for the same simulated time, writing the same VTU frames (the
CLI's own, and tide.io.write_frame from a per-frame callback in Python), alternately
(which goes first alternates too) `--repeats` times; each reports the wall time of its run (the CLI: stats.json's wall_time,
which leaves out loading and setting up, as the Python timing does). Prints each pair and
the median ratio Python / CLI, of wall time and of CPU time (all threads; the CLI's whole
process, Python's World creation and run: steadier than wall time on a loaded machine). The steps must agree: the same arithmetic runs underneath.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py            # ~54k particles
"""
import argparse
import json
import os
import pathlib
import resource
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
    p.add_argument("--repeats", type=int, default=5)
    p.add_argument("--tide", default=str(ROOT / "build" / "bin" / "tide"))
    a = p.parse_args()

    ratios, cpu_ratios, rests = [], [], []
    with tempfile.TemporaryDirectory() as tmp:
        for r in range(a.repeats):
            def cli():
                out = os.path.join(tmp, "cli")
                before = resource.getrusage(resource.RUSAGE_CHILDREN)
                subprocess.run([a.tide, "run", a.scene, "--out", out, "--force", "--quiet", "--end-time",
                                str(a.end_time), "--format", "vtu"], check=True)
                after = resource.getrusage(resource.RUSAGE_CHILDREN)
                stats = json.load(open(os.path.join(out, "stats.json")))
                stats["cpu"] = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
                return stats

            def python():
                cpu = time.process_time()
                world = tide.World(a.scene)
                frames = []

                def write(w):
                    t0 = time.perf_counter()
                    tide.io.write_frame(w, os.path.join(tmp, f"py_{len(frames)}.vtu"))
                    frames.append(time.perf_counter() - t0)

                start = time.perf_counter()
                world.run(a.end_time, progress=False, callback=write)
                wall = time.perf_counter() - start
                # What is neither stepping (the World's own phase clocks) nor writing: Python's share.
                stepping = sum(world.stats["phase_seconds"].values())
                python.rest = wall - stepping - sum(frames)
                python.cpu = time.process_time() - cpu
                return world, frames, wall

            # Alternate which goes first: the machine's load drifts.
            if r % 2 == 0:
                stats = cli()
                world, frames, wall = python()
            else:
                world, frames, wall = python()
                stats = cli()
            if world.steps != stats["steps"]:
                raise SystemExit(f"steps differ: Python {world.steps}, CLI {stats['steps']}")
            ratios.append(wall / stats["wall_time"])
            cpu_ratios.append(python.cpu / stats["cpu"])
            print(f"run {r + 1}: {world.particle_count} particles, {world.steps} steps, {len(frames)} frames: "
                  f"wall CLI {stats['wall_time']:.2f} s, Python {wall:.2f} s, ratio {ratios[-1]:.3f}; "
                  f"CPU (with loading and building the world) CLI {stats['cpu']:.2f} s, Python {python.cpu:.2f} s, "
                  f"ratio {cpu_ratios[-1]:.3f}; Python's run outside the steps and writers {1e3 * python.rest:.1f} ms "
                  f"({100 * python.rest / wall:.2f} %)", flush=True)
            rests.append(python.rest / wall)
    print(f"median ratio Python / CLI: wall {statistics.median(ratios):.3f}, CPU {statistics.median(cpu_ratios):.3f} "
          f"({a.repeats} pairs); Python outside steps and writers: median {100 * statistics.median(rests):.2f} % of its run")


if __name__ == "__main__":
    main()
