#!/usr/bin/env python3
# The heights linear theory gives in tide_wave_bench's windows: a piston ramped up over
# RAMP s (raised cosine, as waves::ramp), each frequency of its motion carried at its own
# wave number (omega^2 = g k tanh kd) with Biesel's piston transfer function
# H/S = 2 (cosh 2kd - 1) / (sinh 2kd + 2kd) (Biesel & Suquet 1951; Dean & Dalrymple 1991, ch. 6); evanescent
# modes left out. Prints the mean zero-up-crossing height at 1, 3, 5, ... wave lengths in the
# bench's window (from the group's arrival plus one period to the run's end), relative to 1 λ:
# how much of a measured loss the wave train's front accounts for.
#   bench/linear_wave_train.py [PERIOD DEPTH REACH RAMP]   (defaults: the bench's 1 0.3 5 2)
import math
import sys

import numpy as np

T, depth, reach, ramp = (float(v) for v in (sys.argv[1:5] if len(sys.argv) == 5 else (1.0, 0.3, 5, 2.0)))
g = 9.81


def wave_number(omega):
    k = omega * omega / g + np.sqrt(omega * omega / (g * depth))  # above the root: Newton from the right
    for _ in range(60):
        f = g * k * np.tanh(k * depth) - omega * omega
        k = k - f / (g * np.tanh(k * depth) + g * k * depth / np.cosh(k * depth) ** 2)
    return k


omega0 = 2 * math.pi / T
k0 = float(wave_number(np.array([omega0]))[0])
wave_length = 2 * math.pi / k0
cg = 0.5 * omega0 / k0 * (1 + 2 * k0 * depth / math.sinh(2 * k0 * depth))
seconds = ramp + reach * wave_length / cg + 8 * T  # as tide_wave_bench
dt, total = 0.005, 400.0  # a long record: no wrap-around reaches the windows
t = np.arange(int(total / dt)) * dt
stop = seconds + 2.0  # the paddle stops smoothly after the run (linear waves travel at most at sqrt(g d))
envelope = np.where(t < ramp, 0.5 * (1 - np.cos(np.pi * t / ramp)), 1.0)
envelope *= np.where(t < stop, 1.0, np.where(t < stop + 2.0, 0.5 * (1 + np.cos(np.pi * (t - stop) / 2.0)), 0.0))
motion = np.fft.rfft(envelope * np.sin(omega0 * t))
omega = 2 * np.pi * np.fft.rfftfreq(t.size, dt)
motion[omega > 60.0] = 0.0  # nothing of the motion's there; keeps cosh finite
k = wave_number(np.clip(omega, 1e-6, 60.0))
kd = np.minimum(k * depth, 20.0)
transfer = 2 * (np.cosh(2 * kd) - 1) / (np.sinh(2 * kd) + 2 * kd)
reference = None
for gauge in range(1, int(reach) + 1, 2):
    x = gauge * wave_length
    eta = np.fft.irfft(motion * transfer * np.exp(-1j * k * x), t.size)
    start = ramp + x / cg + T
    end = start + math.floor(seconds - start)
    samples = np.arange(0.0, seconds, 0.02)  # the bench's sampling
    e = np.interp(samples, t, eta)[(samples >= start) & (samples <= end)]
    up = np.where((e[:-1] < 0) & (e[1:] >= 0))[0]
    heights = [np.ptp(e[a:b + 1]) for a, b in zip(up[:-1], up[1:])]
    mean = float(np.mean(heights))
    reference = reference or mean
    print(f"{gauge} wave lengths: {len(heights)} waves over {start:.2f}-{end:.2f} s, mean height "
          f"{(mean / reference - 1) * 100:+.2f} % against 1 wave length (single waves "
          f"{(min(heights) / mean - 1) * 100:+.1f} to {(max(heights) / mean - 1) * 100:+.1f} %)")
