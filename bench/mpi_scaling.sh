#!/usr/bin/env bash
# Threads against processes on this machine (issue 47, acceptance 5): the 200k benchmark dam
# break (scenes/bench_dam_break.json at 0.0168 m, 205k particles) for END seconds, as
#   1 process  x 2 threads (plain `tide run`),
#   1 rank     x 2 threads under mpiexec (the split path: global cell order, no ghosts),
#   2 ranks    x 1 thread,
# RUNS times each, interleaved; prints the median of the stepping wall time (stats.json
# `wall_time`) of each and, for 2-4 ranks, ghosts per owned particle and bytes sent a step.
#   bench/mpi_scaling.sh BUILD_DIR [END=0.1] [RUNS=3]
set -euo pipefail
build=$1 end=${2:-0.1} runs=${3:-3}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_WAIT_POLICY=PASSIVE
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$here/scenes/bench_dam_break.json" "$work/scene.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["particle_spacing"] = 0.0168
scene["output"] = {"fps": 10, "formats": []}
json.dump(scene, open(sys.argv[2], "w"))
PY
tide="$build/bin/tide"
for run in $(seq "$runs"); do
    "$tide" run "$work/scene.json" --out "$work/plain$run" --end-time "$end" --threads 2 --quiet
    mpiexec --oversubscribe -np 1 "$tide" run "$work/scene.json" --out "$work/r1t2_$run" --end-time "$end" --threads 2 --quiet
    mpiexec --oversubscribe -np 2 "$tide" run "$work/scene.json" --out "$work/r2t1_$run" --end-time "$end" --threads 1 --quiet
done
for ranks in 3 4; do
    mpiexec --oversubscribe -np "$ranks" "$tide" run "$work/scene.json" --out "$work/r${ranks}t1_1" --end-time "$end" --threads 1 --quiet
done
python3 - "$work" "$runs" <<'PY'
import json, statistics, sys
work, runs = sys.argv[1], int(sys.argv[2])
def stats(name):
    return json.load(open(f"{work}/{name}/stats.json"))
rows = [("1 process x 2 threads", "plain"), ("1 rank x 2 threads (mpiexec)", "r1t2_"), ("2 ranks x 1 thread", "r2t1_")]
first = stats("plain1")
print(f"{first['particles']} particles, {first['steps']} steps, {first['sim_time']:.3f} s simulated")
base = None
for label, prefix in rows:
    walls = [stats(f"{prefix}{r}")["wall_time"] for r in range(1, runs + 1)]
    median = statistics.median(walls)
    base = base or median
    print(f"{label:32s} median {median:7.2f} s  ({', '.join(f'{w:.2f}' for w in walls)})  {base / median:.3f}x")
for ranks in (2, 3, 4):
    s = stats(f"r{ranks}t1_1")
    ghosts = sum(s["rank_ghosts"]) / sum(s["rank_particles"])
    print(f"{ranks} ranks: owned {s['rank_particles']}, ghosts/owned {ghosts:.3f}, "
          f"bytes a step per rank {[round(b / 1e6, 2) for b in s['rank_bytes_per_step']]} MB, "
          f"imbalance {s['load_imbalance']:.3f}, re-cuts {s['rebalances']}")
PY
