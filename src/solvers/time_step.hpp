#pragma once
/// \file
/// Stable explicit time step for weakly compressible SPH (Monaghan 1992; Becker &
/// Teschner 2007, §4): acoustic CFL, force and viscous-diffusion limits.

#include <algorithm>
#include <cmath>

#include <tide/defs.hpp>

namespace tide {

/// The step to take when `remaining` seconds are left before a frame time: never a sliver.
/// A last step much shorter than the stable one is harmful, not just wasteful: an
/// incompressible solver removes the density error it finds within the step, so a tiny step
/// means huge velocities. Two steps of half the remaining time land instead.
inline double landOn(double stable, double remaining) {
    // Round-off slack: a float max_dt of 5e-3 is 0.00499999989, and a 0.025 s frame must
    // still be five steps, not four and two halves; 0.5 s of them leaves 2.2e-6 of a step
    // over, so the slack is 1e-4 of a step (harmless for stability).
    if (remaining <= stable * (1.0 + 1e-4)) return remaining;
    if (remaining < 2.0 * stable) return 0.5 * remaining;
    return stable;
}

/// dt = min(cfl·d/(c + v), λ_f·√(d/a), 0.125·d²/ν) for particle spacing d (the smoothing
/// length of those papers, half our support radius), clamped to [minDt, maxDt], landing on `limit` (landOn).
inline double stableTimeStep(const SolverDef& s, float spacing, float soundSpeed, float maxSpeed, float maxAccel,
                             float maxKinematicViscosity, double limit) {
    const double d = spacing;
    double dt = s.cflNumber * d / (soundSpeed + maxSpeed);
    if (maxAccel > 0.0f) dt = std::min(dt, s.forceNumber * std::sqrt(d / maxAccel));
    if (maxKinematicViscosity > 0.0f) dt = std::min(dt, 0.125 * d * d / maxKinematicViscosity);
    dt = std::clamp(dt, static_cast<double>(s.minDt), static_cast<double>(s.maxDt));
    return landOn(dt, limit);
}

/// Incompressible solvers: dt = cfl · d / |v|max (Bender & Koschier 2017, §4), clamped to
/// [minDt, maxDt] and to `limit`; the particle spacing d stands for the particle diameter.
inline double cflTimeStep(const SolverDef& s, float spacing, float maxSpeed, double limit) {
    double dt = maxSpeed > 0.0f ? s.cflNumber * spacing / maxSpeed : s.maxDt;
    dt = std::clamp(dt, static_cast<double>(s.minDt), static_cast<double>(s.maxDt));
    return landOn(dt, limit);
}

}  // namespace tide
