#pragma once
/// \file
/// Stable explicit time step for weakly compressible SPH (Monaghan 1992; Becker &
/// Teschner 2007, §4): acoustic CFL, force and viscous-diffusion limits.

#include <algorithm>
#include <cmath>

#include <tide/defs.hpp>

namespace tide {

/// dt = min(cfl·d/(c + v), λ_f·√(d/a), 0.125·d²/ν) for particle spacing d (the smoothing
/// length of those papers, half our support radius), clamped to [minDt, maxDt] and `limit`.
inline double stableTimeStep(const SolverDef& s, float spacing, float soundSpeed, float maxSpeed, float maxAccel,
                             float maxKinematicViscosity, double limit) {
    const double d = spacing;
    double dt = s.cflNumber * d / (soundSpeed + maxSpeed);
    if (maxAccel > 0.0f) dt = std::min(dt, s.forceNumber * std::sqrt(d / maxAccel));
    if (maxKinematicViscosity > 0.0f) dt = std::min(dt, 0.125 * d * d / maxKinematicViscosity);
    dt = std::clamp(dt, static_cast<double>(s.minDt), static_cast<double>(s.maxDt));
    return std::min(dt, limit);
}

}  // namespace tide
