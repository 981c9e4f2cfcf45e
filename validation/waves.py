"""Gravity waves: the first sloshing mode's frequency (bench/standing_wave.cpp), Faltinsen's
forced sloshing, and regular waves from a piston paddle against Airy theory and Biésel's
wavemaker transfer function."""
import math
import os
import re
import subprocess
import time

import numpy as np

from common import Result, abs_row, fit_damped_cosine, load_scene, read_data, read_table, rel_row

G = 9.81


def wave_number(omega, depth):
    """k of ω² = g k tanh(k d) (Airy), by Newton from the deep-water guess."""
    k = omega ** 2 / G
    for _ in range(50):
        f = G * k * math.tanh(k * depth) - omega ** 2
        df = G * math.tanh(k * depth) + G * k * depth / math.cosh(k * depth) ** 2
        k -= f / df
    return k


def standing_wave(ctx):
    """Faltinsen's tank (L = 1.73 m, h = 0.6 m): the first mode's frequency, started from the
    linear mode's velocity by tide_standing_wave (bench/standing_wave.cpp)."""
    L, h = 1.73, 0.6
    spacing = 0.03 if ctx.quick else 0.02
    cmd = [os.path.join(ctx.bin, "tide_standing_wave"), "--length", str(L), "--depth", str(h), "--spacing", str(spacing),
           "--amplitude", str(max(0.02, 1.5 * spacing)), "--seconds", "6", "--energy", "0.01", "--threads",
           str(ctx.tide.threads)]
    start = time.monotonic()
    env = dict(os.environ, OMP_WAIT_POLICY=os.environ.get("OMP_WAIT_POLICY", "PASSIVE"))
    proc = subprocess.run(cmd, capture_output=True, text=True, env=env)
    wall = time.monotonic() - start
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed:\n{proc.stderr[-2000:]}")
    series = re.findall(r"^t ([0-9.]+) s: mode ([-+0-9.]+) m", proc.stdout, re.M)
    t = np.array([float(a) for a, _ in series])
    eta = np.array([float(b) for _, b in series])
    summary = re.search(r"omega ([0-9.]+) rad/s against ([0-9.]+)", proc.stdout)
    omega = float(summary.group(1))
    ref = read_data("sloshing_natural_frequencies.csv")
    sel = (ref["case"] == "Faltinsen2000") & (ref["mode_n"] == 1)
    omega_ref = float(ref["omega_rad_s"][sel][0])
    fig, (a,) = ctx.figure(1, width=7)
    a.plot(t, eta, "-", label=f"tide, mode amplitude ({1000 * spacing:g} mm)")
    amp = np.max(np.abs(eta[: max(1, len(eta) // 6)]))
    a.plot(t, amp * np.sin(omega_ref * t), "--", lw=0.8, label=f"linear theory ω = {omega_ref:.3f} rad/s")
    a.set_xlabel("t (s)"), a.set_ylabel("η (m)"), a.legend()
    ctx.save(fig, "validation-standing-wave.png")
    return Result("Standing wave (first sloshing mode)", "validation-standing-wave.png",
                  f"{1000 * spacing:g} mm (h/{round(h / spacing)})", wall,
                  [rel_row("frequency ω of mode 1, rad/s", omega, omega_ref, 0.02, "{:.4f}")])


def faltinsen(ctx):
    """Faltinsen et al. (2000): the tank (L = 1.73 m, h = 0.6 m) shaken at A = 0.032 m, T = 1.3 s.
    The side walls are box obstacles moving by x(t) = A (cos ωt − 1) (a CSV motion: the
    acceleration −Aω² cos ωt of the experiment's forcing, from rest); η at 0.05 m from the wall."""
    L, h, A, T = 1.73, 0.6, 0.032, 1.3
    spacing = 0.03 if ctx.quick else 0.02
    depth = 4 * spacing
    wall_t = 4 * spacing
    end = 10.0
    omega = 2 * math.pi / T
    motion = os.path.join(ctx.tide.work, "faltinsen_motion.csv")
    with open(motion, "w") as f:
        f.write("time,x,y,z\n")
        for t in np.arange(0, end + 0.5, T / 80):
            f.write(f"{t:.5f},{A * (math.cos(omega * t) - 1):.7f},0,0\n")
    x0 = -0.1 - wall_t
    scene = {
        "name": "validation Faltinsen sloshing",
        "domain": {"min": [x0, 0, 0], "max": [L + wall_t + 0.02, 1.15, depth], "periodic": [False, False, True]},
        "particle_spacing": spacing, "end_time": end,
        "solver": {"method": "dfsph", "max_density_error": 0.003, "xsph": 0, "momentum": 0},
        "materials": [{"name": "water", "density": 1000, "viscosity": 0.001}],
        "blocks": [{"min": [0, 0, 0], "max": [L, h, depth]}],
        "obstacles": [{"type": "box", "min": [-wall_t, 0, 0], "max": [0, 1.15, depth],
                       "motion": {"type": "csv", "file": os.path.basename(motion)}},
                      {"type": "box", "min": [L, 0, 0], "max": [L + wall_t, 1.15, depth],
                       "motion": {"type": "csv", "file": os.path.basename(motion)}}],
        "gauges": [{"name": "wall", "x": 0.05 - A, "z": 0.5 * depth}],
        "output": {"fps": 50, "formats": ["ply"]},
    }
    out, wall = ctx.tide.run("faltinsen", scene)
    g = read_table(out + "/gauges.csv")
    t, eta = g["time"], g["wall"] - h
    exp = read_data("sloshing_faltinsen2000_wave_elevation_h0.6_T1.3.csv")
    te, ee = exp["t_s"], exp["eta_m"]
    fig, (a,) = ctx.figure(1, width=8)
    shown = t >= 0.2
    a.plot(t[shown], eta[shown], "-", label=f"tide ({1000 * spacing:g} mm)")
    a.plot(te, ee, "o", ms=3, label="Faltinsen et al. 2000 (experiment)")
    a.set_xlabel("t (s)"), a.set_ylabel("η at 0.05 m from the wall (m)"), a.legend()
    ctx.save(fig, "validation-faltinsen.png")
    # From 0.2 s: at rest the gauge stands within a spacing of the wall's particles (it reads nonsense there).
    window = (te <= t[-1]) & (te >= 0.2)
    shown = t >= 0.2
    rms_t = float(np.sqrt(np.nanmean(np.interp(te[window], t, eta) ** 2)))
    rms_e = float(np.sqrt(np.mean(ee[window] ** 2)))
    return Result("Forced sloshing (Faltinsen et al. 2000)", "validation-faltinsen.png",
                  f"{1000 * spacing:g} mm (h/{round(h / spacing)})", wall,
                  [rel_row("RMS elevation near the wall over the record, m", rms_t, rms_e, 0.15, "{:.4f}"),
                   rel_row("largest elevation near the wall, m", float(np.nanmax(eta[shown & (t <= te[-1])])), float(ee.max()), 0.15,
                           "{:.4f}")],
                  "Side walls moving, floor fixed (the water slides on it: negligible at ν of water); the gauge is fixed at "
                  "the wall's mean distance 0.05 m, and read from 0.2 s on. A gauge reads the highest point of its "
                  "vertical line where the fluid's colour field reaches ½, so water running up the wall in a sheet counts.")


def flume(ctx):
    """scenes/wave_tank.json: a piston makes H = 0.04 m, T = 1 s waves in d = 0.3 m."""
    scene = load_scene("wave_tank.json")
    spacing = 0.02 if ctx.quick else 0.3 / 18
    depth = 4 * spacing
    scene["particle_spacing"] = spacing
    scene["domain"]["max"][2] = depth
    scene["blocks"][0]["max"][2] = depth
    for gauge in scene["gauges"]:
        gauge["z"] = 0.5 * depth
    scene["probes"] = []
    scene["end_time"] = 10.0 if ctx.quick else 12.0
    scene["output"] = {"fps": 50, "formats": ["ply"]}
    wm = scene["wavemaker"]
    H, T, d = wm["wave_height"], wm["period"], wm["depth"]
    out, wall = ctx.tide.run("flume", scene)
    g = read_table(out + "/gauges.csv")
    t = g["time"]
    omega = 2 * math.pi / T
    k = wave_number(omega, d)
    steady = t >= 5.0
    heights, periods, phases = {}, {}, {}
    for gauge in scene["gauges"]:
        eta = g[gauge["name"]][steady] - d
        ts = t[steady]
        up = [ts[i - 1] - eta[i - 1] * (ts[i] - ts[i - 1]) / (eta[i] - eta[i - 1])
              for i in range(1, len(eta)) if eta[i - 1] < 0 <= eta[i]]
        periods[gauge["name"]] = float(np.mean(np.diff(up)))
        waves = [(eta[(ts >= a) & (ts < b)]) for a, b in zip(up[:-1], up[1:])]
        heights[gauge["name"]] = float(np.mean([w.max() - w.min() for w in waves]))
        c, s = np.mean(eta * np.cos(omega * ts)), np.mean(eta * np.sin(omega * ts))
        phases[gauge["name"]] = math.atan2(s, c)
    # Wave length from the phase lag between g1 (x = 1.0) and g4 (x = 2.0).
    x = {gg["name"]: gg["x"] for gg in scene["gauges"]}
    lag = (phases["g4"] - phases["g1"]) % (2 * math.pi)
    lam = 2 * math.pi * (x["g4"] - x["g1"]) / lag
    lam_ref = 2 * math.pi / k
    table = read_data("linear_wave_theory_table.csv")
    kd = k * d
    hs = 2 * (math.cosh(2 * kd) - 1) / (math.sinh(2 * kd) + 2 * kd)   # piston, the table's formula
    stroke = H / hs
    fig, (a, b) = ctx.figure(2)
    a.plot(t, g["g2"] - d, "-", label="tide, g2 (x = 1.5 m)")
    ts = t[steady]
    a.plot(ts, 0.5 * H * np.cos(omega * ts - phases["g2"]), "--", lw=0.8, label="Airy, H = 0.04 m, phase fitted")
    a.set_xlabel("t (s)"), a.set_ylabel("η (m)"), a.legend(fontsize=7)
    b.plot(table["kd"], table["H_over_S_piston"], ".-", label="piston H/S (Biésel & Suquet 1951), data file")
    b.plot([kd], [heights["g1"] / stroke], "o", label="tide, g1 (x = 1.0 m)")
    b.set_xlabel("k d"), b.set_ylabel("H / S"), b.set_xlim(0, 3), b.legend(fontsize=7)
    ctx.save(fig, "validation-regular-waves.png")
    return Result("Regular waves from a piston", "validation-regular-waves.png",
                  f"{1000 * spacing:.3g} mm (d/{round(d / spacing)}, H/{H / spacing:.1f})", wall,
                  [rel_row("period at g2, s", periods["g2"], T, 0.02, "{:.4f}"),
                   rel_row("wave length from the g1–g4 phase lag, m", lam, lam_ref, 0.03, "{:.3f}"),
                   rel_row("H/S at g1 (transfer function), kd = {:.2f}".format(kd), heights["g1"] / stroke, hs, 0.10,
                           "{:.3f}")],
                  "Height and phase from t ≥ 5 s; gauges 1–2 m from the paddle (> 3 depths).")
