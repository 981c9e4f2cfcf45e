#!/usr/bin/env bash
# Soak benchmark (not CI): runs scenes/beach.json for SOAK_SECONDS of wall time (default 600)
# with checkpoints, sampling the process's resident memory every 10 s, then reports memory
# growth and the fluid's kinetic energy per frame (from the CSV frames: ½ Σ m v², m from the
# scene's rest density × spacing³ as a constant per particle) so a blow-up would show.
# Usage: bench/soak.sh [BUILD_DIR] (default build); output in out/soak/.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
seconds=${SOAK_SECONDS:-600}
threads=${SOAK_THREADS:-0}
out=out/soak
mkdir -p "$out"
"$build/bin/tide" run scenes/beach.json --out "$out" --force --quiet --format csv --end-time 10000 \
  --checkpoint-every 30 --threads "$threads" &
pid=$!
echo "wall_s,rss_kib" > "$out/rss.csv"
start=$(date +%s)
while kill -0 "$pid" 2>/dev/null && [ $(( $(date +%s) - start )) -lt "$seconds" ]; do
  rss=$(awk '/VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null || echo 0)
  echo "$(( $(date +%s) - start )),$rss" >> "$out/rss.csv"
  sleep 10
done
kill "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
python3 - "$out" <<'PY'
import csv, glob, os, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(out, "rss.csv"))))
rss = [int(r["rss_kib"]) for r in rows if int(r["rss_kib"]) > 0]
frames = sorted(glob.glob(os.path.join(out, "frame_*.csv")))
energy = []
for f in frames:
    e, n = 0.0, 0
    with open(f) as fh:
        next(fh)
        for line in fh:
            v = line.split(",")
            e += float(v[3])**2 + float(v[4])**2 + float(v[5])**2
            n += 1
    energy.append((os.path.basename(f), n, 0.5 * e / max(n, 1)))
print(f"frames written: {len(frames)}, particles at the end: {energy[-1][1] if energy else 0}")
if rss:
    q = max(1, len(rss) // 4)
    print(f"RSS: first {rss[0]/1024:.1f} MiB, max {max(rss)/1024:.1f} MiB, last {rss[-1]/1024:.1f} MiB; "
          f"mean of the first quarter {sum(rss[:q])/q/1024:.1f} MiB, of the last quarter {sum(rss[-q:])/q/1024:.1f} MiB")
if energy:
    ke = [e for _, _, e in energy]
    third = max(1, len(ke) // 3)
    print(f"kinetic energy per particle, ½|v|² (J/kg): max {max(ke):.4f}, mean of the first third {sum(ke[:third])/third:.4f}, "
          f"of the last third {sum(ke[-third:])/third:.4f}, last {ke[-1]:.4f}")
    with open(os.path.join(out, "energy.csv"), "w") as fh:
        fh.write("frame,particles,kinetic_energy_per_kg\n")
        for name, n, e in energy:
            fh.write(f"{name},{n},{e:.6f}\n")
PY
