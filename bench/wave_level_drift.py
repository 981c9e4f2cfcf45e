#!/usr/bin/env python3
# The mean water level's drift and the long-wave oscillation of a wave tank over a long run
# (issue 42, acceptance 3), from the gauges.csv `tide run` writes: per gauge, the level over
# periods 5-15 against the last ten, the spread of the per-period means early and late (a
# growing seiche shows there), and the per-period heights.
#   bench/wave_level_drift.py GAUGES_CSV PERIOD HEIGHT DEPTH
# e.g. tide run scenes/issue42_flume_2d.json --end-time 72 --out out/flume60, then
#      bench/wave_level_drift.py out/flume60/gauges.csv 1.2 0.03 0.25
import sys

import numpy as np

if len(sys.argv) != 5:
    sys.exit("usage: wave_level_drift.py GAUGES_CSV PERIOD HEIGHT DEPTH")
d = np.genfromtxt(sys.argv[1], delimiter=',', names=True)
T, H, depth = (float(v) for v in sys.argv[2:5])
t = d['time']
n = int(round(t[-1] / T))
for name in d.dtype.names[1:]:
    e = d[name] - depth
    means = np.array([e[(t >= p * T) & (t < (p + 1) * T)].mean() for p in range(n)])
    heights = np.array([np.ptp(e[(t >= p * T) & (t < (p + 1) * T)]) for p in range(n)])
    early, late = means[5:15], means[n - 10:n]
    print(f"{name}: level periods 5-15 {early.mean()*1000:+.2f} mm, last 10 {late.mean()*1000:+.2f} mm, "
          f"drift {(late.mean()-early.mean())/H:+.3f} H; per-period mean swing (std) periods 5-25 {means[5:25].std()*1000:.2f} mm, "
          f"last 20 {means[n-20:].std()*1000:.2f} mm; height periods 5-15 {heights[5:15].mean()*1000:.1f} mm, last 10 {heights[n-10:].mean()*1000:.1f} mm")
