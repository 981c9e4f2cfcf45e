#!/usr/bin/env bash
# `mpirun -np N tide run` writes the same frames for every N (issue 47, acceptance 1): a dam
# break onto a fixed block (~1,500 particles at 1.25 cm, 0.1 s, 5 frames) with the given solver on
# 1-4 ranks (dfsph) or 1 and 3 (the others). CSV, PLY and forces.csv must be byte-identical, the
# VTU pieces must hold every particle once, and --gather's single VTU must be byte-identical too;
# so must a 3-rank run whose boxes are cut again every 3 steps and (dfsph) 2 ranks of 2 threads.
# A rank count that leaves a rank without water is refused.
#   run_split_identical.sh TIDE MPIEXEC SOLVER
set -euo pipefail
tide=$1 mpiexec=$2 solver=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/scene.json" <<JSON
{
  "name": "split dam break",
  "domain": {"min": [0, 0, 0], "max": [0.6, 0.4, 0.08]},
  "particle_spacing": 0.0125,
  "end_time": 0.1,
  "solver": {"method": "$solver"},
  "materials": [{"name": "water", "density": 1000, "viscosity": 0.001}],
  "blocks": [{"min": [0, 0, 0], "max": [0.2, 0.2, 0.08]}],
  "obstacles": [{"type": "box", "name": "block", "min": [0.25, 0, 0], "max": [0.3, 0.06, 0.08]}],
  "output": {"fps": 40, "formats": ["csv", "ply", "vtu"]}
}
JSON
run() {  # ranks folder [flags]
    local ranks=$1 out=$2
    shift 2
    "$mpiexec" --oversubscribe -np "$ranks" "$tide" run "$work/scene.json" --out "$out" --threads 1 --quiet "$@"
}
fail() { echo "FAIL: $*" >&2; exit 1; }
# dfsph on 1-4 ranks and with --gather; wcsph and pcisph, slower, on 1 and 3 (test_world_mpi
# has every solver on 1-4 ranks step by step).
others="2 3 4"
[ "$solver" = dfsph ] || others="3"
for ranks in 1 $others; do run "$ranks" "$work/np$ranks"; done
frames=$(ls "$work/np1"/frame_*.csv | wc -l)
[ "$frames" -eq 5 ] || fail "$frames CSV frames on 1 rank, expected 5"
particles=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['particles'])" "$work/np1/stats.json")
[ "$particles" -gt 1000 ] || fail "only $particles particles"
for ranks in $others; do
    for f in "$work/np1"/frame_*.csv "$work/np1"/frame_*.ply "$work/np1/forces.csv"; do
        cmp -s "$f" "$work/np$ranks/$(basename "$f")" || fail "$(basename "$f") differs between 1 and $ranks ranks ($solver)"
    done
    python3 - "$work/np$ranks" "$ranks" "$particles" <<'PY' || fail "VTU pieces on $ranks ranks"
import json, re, sys
folder, ranks, particles = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
stats = json.load(open(f"{folder}/stats.json"))
assert stats["particles"] == particles, stats["particles"]
assert stats["ranks"] == ranks and len(stats["rank_particles"]) == ranks, stats
assert sum(stats["rank_particles"]) == particles and min(stats["rank_particles"]) > 0, stats["rank_particles"]
assert sum(stats["rank_ghosts"]) > 0, stats["rank_ghosts"]
# Every rank sends ghosts to a neighbour every step: hundreds of bytes a step at least.
assert len(stats["rank_bytes_per_step"]) == ranks and min(stats["rank_bytes_per_step"]) > 100, stats["rank_bytes_per_step"]
assert min(stats["rank_messages_sent"]) >= stats["steps"], (stats["rank_messages_sent"], stats["steps"])
assert stats["particles_lost"] == 0
pvtu = open(f"{folder}/frame_00004.pvtu").read()
pieces = re.findall(r'Source="([^"]+)"', pvtu)
assert len(pieces) == ranks, pieces
total = 0
for piece in pieces:
    head = open(f"{folder}/{piece}", "rb").read(400).decode("latin-1")
    total += int(re.search(r'NumberOfPoints="(\d+)"', head).group(1))
assert total == particles, (total, particles)
assert "frame_00004.pvtu" in open(f"{folder}/frames.pvd").read()
PY
done
# The forces on the block are not zero: the surge reaches it.
python3 - "$work/np1/forces.csv" <<'PY' || fail "no load on the block"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert max(abs(float(r["block_fx"])) for r in rows) > 0.01, rows[-1]
PY
if [ "$solver" = dfsph ]; then
    # Threads within the ranks change nothing either: 2 ranks x 2 threads.
    "$mpiexec" --oversubscribe -np 2 "$tide" run "$work/scene.json" --out "$work/np2t2" --threads 2 --quiet
    for f in "$work/np1"/frame_*.csv "$work/np1/forces.csv"; do
        cmp -s "$f" "$work/np2t2/$(basename "$f")" || fail "$(basename "$f") differs between 1 rank x 1 thread and 2 x 2"
    done
    run 1 "$work/g1" --gather --format vtu
    run 3 "$work/g3" --gather --format vtu
    for f in "$work/g1"/frame_*.vtu; do
        cmp -s "$f" "$work/g3/$(basename "$f")" || fail "gathered $(basename "$f") differs between 1 and 3 ranks"
    done
fi
# The boxes cut again every 3 steps (acceptance 3): the same frames, and the cuts did move.
run 3 "$work/recut3" --rebalance-every 3
for f in "$work/np1"/frame_*.csv "$work/np1/forces.csv"; do
    cmp -s "$f" "$work/recut3/$(basename "$f")" || fail "$(basename "$f") differs with the boxes re-cut every 3 steps ($solver)"
done
python3 -c "import json,sys; n=json.load(open(sys.argv[1]))['rebalances']; assert n >= 1, n" "$work/recut3/stats.json" ||
    fail "--rebalance-every 3 never moved a box"
# A rank count that leaves a rank without water is refused on every rank, before any file is
# written, naming the counts.
sed 's/"max": \[0.2, 0.2, 0.08\]/"max": [0.02, 0.02, 0.02]/' "$work/scene.json" > "$work/drop.json"
set +e
message=$("$mpiexec" --oversubscribe -np 3 "$tide" run "$work/drop.json" --out "$work/refused" --threads 1 --quiet 2>&1)
code=$?
set -e
[ "$code" -eq 2 ] || fail "a drop on 3 ranks: exit $code, expected 2"
grep -q '3 ranks leave rank' <<<"$message" || fail "the refusal does not name the ranks: $message"
[ ! -e "$work/refused" ] || fail "a refused split run wrote its output folder"
echo "split runs of $solver on 1 and $others ranks: identical frames and loads ($particles particles)"
