#!/usr/bin/env python3
"""Linear stability of particle lattices under SPH pressure (docs/robustness.md).

At a uniform pressure p the symmetric SPH pressure force, a_i = -sum_j m_j (p_i/rho_i^2 +
p_j/rho_j^2) grad W_ij, derives from the pair potential U = c sum_{i<j} W(r_ij) with
c = 2 m^2 p / rho^2 > 0. A lattice is then stable when the dynamical matrix
D(k) = sum_j (1 - cos k.r_j) H_W(r_j), H_W the Hessian of W, is positive semidefinite for every
wave vector k (Born & Huang). This prints the least eigenvalue over the Brillouin zone
(relative to the lattice's kernel sum; 0 when stable, negative when a mode grows) for the
simple cubic lattice tide's blocks start on, and for body- and face-centred cubic lattices of
the same number density, for the cubic spline and the Wendland C2 kernel against the kernel
support in spacings.

The incompressible solvers add stiffness against modes that change the density, so a
weakly negative value can still hold in a simulation (measure with tide_rest_layers).

Needs Debian's python3-numpy:  python3 bench/lattice_stability.py [support ...]
"""
import itertools
import math
import sys

import numpy as np


def cubic_spline(r, h):
    """Monaghan's cubic B-spline with support h: W, dW/dr, d2W/dr2."""
    q, sigma = r / h, 8.0 / (math.pi * h**3)
    outer, inner = max(1.0 - q, 0.0), max(0.5 - q, 0.0)
    w = sigma * (2.0 * outer**3 - 8.0 * inner**3)
    dw = sigma / h * (24.0 * inner**2 - 6.0 * outer**2)
    d2w = sigma / h**2 * ((36.0 * q - 12.0) if q <= 0.5 else (12.0 * (1.0 - q) if q < 1.0 else 0.0))
    return w, dw, d2w


def wendland_c2(r, h):
    """Wendland's C2 kernel in 3D with support h (Dehnen & Aly 2012)."""
    q, sigma = r / h, 21.0 / (2.0 * math.pi * h**3)
    o = max(1.0 - q, 0.0)
    return sigma * o**4 * (1.0 + 4.0 * q), sigma / h * (-20.0 * q * o**3), sigma / h**2 * (-20.0 * o * o * (1.0 - 4.0 * q))


def lattice(kind, reach=4):
    """Neighbour vectors of one site, unit number density; and the conventional cell's edge."""
    if kind == "sc":
        edge, basis = 1.0, [(0.0, 0.0, 0.0)]
    elif kind == "bcc":
        edge, basis = 2.0 ** (1.0 / 3.0), [(0.0, 0.0, 0.0), (0.5, 0.5, 0.5)]
    else:
        edge, basis = 4.0 ** (1.0 / 3.0), [(0.0, 0.0, 0.0), (0.5, 0.5, 0.0), (0.5, 0.0, 0.5), (0.0, 0.5, 0.5)]
    points = []
    for cell in itertools.product(range(-reach, reach + 1), repeat=3):
        for b in basis:
            p = edge * (np.array(cell, dtype=float) + np.array(b))
            if np.linalg.norm(p) > 1e-9:
                points.append(p)
    return np.array(points), edge


def least_eigenvalue(kernel, support, kind, samples=8):
    points, edge = lattice(kind)
    points = points[np.linalg.norm(points, axis=1) < support]
    hessians = []
    for p in points:
        r = np.linalg.norm(p)
        _, dw, d2w = kernel(r, support)
        u = np.outer(p / r, p / r)
        hessians.append(d2w * u + dw / r * (np.eye(3) - u))
    worst = math.inf
    for k in itertools.product(np.linspace(0.0, 2.0 * math.pi / edge, samples + 1), repeat=3):
        k = np.array(k)
        d = sum((1.0 - math.cos(k @ p)) * h for p, h in zip(points, hessians))
        worst = min(worst, np.linalg.eigvalsh(d)[0])
    kernel_sum = kernel(0.0, support)[0] + sum(kernel(np.linalg.norm(p), support)[0] for p in points)
    return worst / kernel_sum


def main():
    supports = [float(a) for a in sys.argv[1:]] or [1.8, 1.9, 2.0, 2.05, 2.1, 2.2, 2.5]
    print("least eigenvalue of D(k) / sum W (0: stable, < 0: a growing mode)")
    for name, kernel in (("cubic spline", cubic_spline), ("Wendland C2", wendland_c2)):
        for support in supports:
            cells = "  ".join(f"{kind} {least_eigenvalue(kernel, support, kind):+.4f}" for kind in ("sc", "bcc", "fcc"))
            print(f"{name:12s} support {support:.2f}:  {cells}")


if __name__ == "__main__":
    main()
