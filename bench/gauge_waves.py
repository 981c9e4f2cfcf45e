#!/usr/bin/env python3
# Regular waves at a row of gauges (issue 42, acceptance 1), from the gauges.csv `tide run`
# writes: per gauge, the mean zero-up-crossing height and period over a time window, and
# the wave length from the phase of the first harmonic along the row (the slope of the
# unwrapped phase against x is -k, so neighbouring gauges must stand closer than half a wave
# length), against Airy's (omega^2 = g k tanh kd). The mean level is against DEPTH.
#   bench/gauge_waves.py GAUGES_CSV SCENE_JSON PERIOD HEIGHT DEPTH T_FROM T_TO
# e.g. tide run scenes/issue42_flume_2d.json --out out/f, then
#      bench/gauge_waves.py out/f/gauges.csv scenes/issue42_flume_2d.json 1.2 0.03 0.25 4 8
import json
import math
import sys

import numpy as np

if len(sys.argv) != 8:
    sys.exit("usage: gauge_waves.py GAUGES_CSV SCENE_JSON PERIOD HEIGHT DEPTH T_FROM T_TO")
with open(sys.argv[1]) as f:
    names = f.readline().strip().split(',')
d = np.loadtxt(sys.argv[1], delimiter=',', skiprows=1)
scene = json.load(open(sys.argv[2]))
T, H, depth, t0, t1 = (float(v) for v in sys.argv[3:8])
xs = {g['name']: float(g['x']) for g in scene.get('gauges', [])}
missing = [name for name in names[1:] if name not in xs]
if missing:
    sys.exit(f"gauge_waves.py: {sys.argv[2]} has no gauge named {missing[0]!r} (the CSV's columns: {names[1:]})")
g = 9.81
omega = 2 * math.pi / T
k = omega * omega / g
for _ in range(100):  # Newton on omega^2 = g k tanh(k d)
    f = g * k * math.tanh(k * depth) - omega * omega
    df = g * math.tanh(k * depth) + g * k * depth / math.cosh(k * depth) ** 2
    k -= f / df
airy = 2 * math.pi / k

t = d[:, 0]
window = (t >= t0) & (t <= t1)
rows = []
for column, name in enumerate(names[1:], start=1):
    e = d[window, column] - depth
    tw = t[window]
    e0 = e - e.mean()
    up = np.where((e0[:-1] < 0) & (e0[1:] >= 0))[0]
    crossings = tw[up] - e0[up] * (tw[up + 1] - tw[up]) / (e0[up + 1] - e0[up])
    heights = [np.ptp(e[(tw >= a) & (tw < b)]) for a, b in zip(crossings[:-1], crossings[1:])]
    periods = np.diff(crossings)
    phase = np.angle(np.sum(e0 * np.exp(-1j * omega * tw)))
    rows.append((xs[name], name, np.mean(heights), np.mean(periods), phase, e.mean()))
rows.sort()
x = np.array([r[0] for r in rows])
phase = np.unwrap(np.array([r[4] for r in rows]))
slope = np.polyfit(x, phase, 1)[0]
measured = 2 * math.pi / abs(slope)
for x_, name, h, p, _, level in rows:
    print(f"{name} x {x_:.3f} m: height {h:.4f} m ({(h / H - 1) * 100:+.1f} %), period {p:.4f} s "
          f"({(p / T - 1) * 100:+.2f} %), mean level {level * 1000:+.2f} mm")
print(f"wave length {measured:.4f} m against Airy {airy:.4f} m ({(measured / airy - 1) * 100:+.2f} %), "
      f"over {len(rows)} gauges {x.min():.2f}-{x.max():.2f} m, {t0:g}-{t1:g} s")
mean_period = np.mean([r[3] for r in rows])
print(f"mean period {mean_period:.4f} s ({(mean_period / T - 1) * 100:+.2f} %), heights {min(r[2] for r in rows) / H * 100 - 100:+.1f} "
      f"to {max(r[2] for r in rows) / H * 100 - 100:+.1f} %")
