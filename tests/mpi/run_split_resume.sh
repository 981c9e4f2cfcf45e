#!/usr/bin/env bash
# A split run's checkpoints resume on another number of ranks, bit for bit (issue 47,
# acceptance 2): a dam break past a fixed block with a gauge and a probe (~1,500 particles at
# 1.25 cm, 5 frames 0.025 s apart, ~10-25 steps each) run whole on 1 rank; stopped after frame 2 on
# 1 rank and resumed on 3; stopped on 4 and resumed on 2. Frames, forces.csv, gauges.csv and
# probes.csv must be byte-identical to the whole run's; the gauges and probes also to 3 ranks'.
#   run_split_resume.sh TIDE MPIEXEC SOLVER
set -euo pipefail
tide=$1 mpiexec=$2 solver=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/scene.json" <<JSON
{
  "name": "split dam break, resumed",
  "domain": {"min": [0, 0, 0], "max": [0.6, 0.4, 0.08]},
  "particle_spacing": 0.0125,
  "end_time": 0.1,
  "solver": {"method": "$solver"},
  "materials": [{"name": "water", "density": 1000, "viscosity": 0.001}],
  "blocks": [{"min": [0, 0, 0], "max": [0.2, 0.2, 0.08]}],
  "obstacles": [{"type": "box", "name": "block", "min": [0.4, 0, 0], "max": [0.45, 0.06, 0.08]}],
  "gauges": [{"name": "g_tank", "x": 0.15, "z": 0.04}, {"name": "g_front", "x": 0.3, "z": 0.04}],
  "probes": [{"name": "p_floor", "position": [0.1, 0.02, 0.04]}],
  "output": {"fps": 40, "formats": ["csv", "ply"]}
}
JSON
run() {  # ranks [flags]
    local ranks=$1
    shift
    "$mpiexec" --oversubscribe -np "$ranks" "$tide" run "$work/scene.json" --threads 1 --quiet "$@"
}
fail() { echo "FAIL: $*" >&2; exit 1; }
same() {  # reference folder, compared folder, what
    for f in "$1"/frame_*.csv "$1"/frame_*.ply "$1/forces.csv" "$1/gauges.csv" "$1/probes.csv"; do
        cmp -s "$f" "$2/$(basename "$f")" || fail "$(basename "$f") differs: $3 ($solver)"
    done
}
run 1 --out "$work/whole"
[ "$(ls "$work/whole"/frame_*.csv | wc -l)" -eq 5 ] || fail "the whole run wrote $(ls "$work/whole"/frame_*.csv | wc -l) frames, expected 5"
# The gauges read the water: the column's level falls from 0.2 m as it collapses.
python3 - "$work/whole/gauges.csv" "$work/whole/probes.csv" <<'PY' || fail "gauges or probes read nothing"
import csv, sys
g = list(csv.DictReader(open(sys.argv[1])))
assert abs(float(g[0]["g_tank"]) - 0.2) < 0.01, g[0]
assert float(g[-1]["g_tank"]) < 0.19, g[-1]
# The probe 2 cm above the floor, from 0.05 s (wcsph's start-up pressure wave has passed): of
# the order of the column's hydrostatic 1766 Pa, and the water flowing towards the block (+x).
for row in list(csv.DictReader(open(sys.argv[2])))[2:]:
    assert 0.5 < float(row["p_floor_p"]) / (1000 * 9.81 * 0.18) < 1.5, row
    assert float(row["p_floor_vx"]) > 0.05, row
PY
run 3 --out "$work/np3"
cmp -s "$work/whole/gauges.csv" "$work/np3/gauges.csv" || fail "gauges.csv differs between 1 and 3 ranks ($solver)"
cmp -s "$work/whole/probes.csv" "$work/np3/probes.csv" || fail "probes.csv differs between 1 and 3 ranks ($solver)"

run 1 --out "$work/a" --end-time 0.05 --checkpoint-every 1
[ -f "$work/a/checkpoint_00002.tidecp" ] || fail "no checkpoint after frame 2 on 1 rank"
run 3 --resume "$work/a" --end-time 0.1
same "$work/whole" "$work/a" "1 rank resumed on 3"

run 4 --out "$work/b" --end-time 0.05 --checkpoint-every 1
for r in 1 2 3; do
    [ -f "$work/b/checkpoint_00002_r$r.tidecp" ] || fail "rank $r wrote no piece of checkpoint 2"
done
run 2 --resume "$work/b" --end-time 0.1 --checkpoint-every 1
same "$work/whole" "$work/b" "4 ranks resumed on 2"
# Two checkpoints are kept, with their pieces: 3 and 4 of 2 ranks now, none of the 4 ranks'.
pieces=$(cd "$work/b" && ls checkpoint_* | tr '\n' ' ')
[ "$pieces" = "checkpoint_00003.tidecp checkpoint_00003_r1.tidecp checkpoint_00004.tidecp checkpoint_00004_r1.tidecp " ] ||
    fail "checkpoint files after pruning: $pieces"

# Without mpirun a split run's checkpoint resumes too (its own cell order: not compared).
cp -r "$work/b" "$work/c"
rm "$work/c"/checkpoint_00004*
"$tide" run "$work/scene.json" --resume "$work/c" --threads 1 --quiet || fail "a plain tide run did not resume a 2-rank checkpoint"
# A missing piece, or a checkpoint of another scene, is refused on every rank with exit 2.
rm "$work/c"/checkpoint_0000*_r1.tidecp "$work/c"/checkpoint_00004.tidecp
set +e
message=$(run 2 --resume "$work/c" 2>&1)
code=$?
set -e
[ "$code" -eq 2 ] || fail "a missing piece: exit $code, expected 2"
grep -q "checkpoint_00003_r1.tidecp: missing" <<<"$message" || fail "the refusal does not name the missing piece: $message"
sed -i 's/"end_time": 0.1/"end_time": 0.15/' "$work/scene.json"
set +e
message=$(run 3 --resume "$work/a" --end-time 0.2 2>&1)
code=$?
set -e
[ "$code" -eq 2 ] || fail "another scene's checkpoint: exit $code, expected 2"
grep -q "another version of the scene file" <<<"$message" || fail "the refusal does not say why: $message"
echo "split runs of $solver resumed on other rank counts: identical frames, loads, gauges and probes"
