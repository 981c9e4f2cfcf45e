#pragma once
/// \file
/// Pressure from density for weakly compressible SPH.

#include <cmath>

#include <tide/defs.hpp>

namespace tide {

/// p(ρ) for one material. Linear: p = c²(ρ − ρ0) (Müller et al. 2003, eq. 12).
/// Tait: p = ρ0c²/7 ((ρ/ρ0)^7 − 1) (Becker & Teschner 2007, eq. 6).
inline float pressureFromDensity(EquationOfState eos, float density, float restDensity, float soundSpeed,
                                 bool clampNegative) {
    float p;
    if (eos == EquationOfState::Tait) {
        const float ratio = density / restDensity;
        const float r2 = ratio * ratio;
        const float r7 = r2 * r2 * r2 * ratio;
        p = restDensity * soundSpeed * soundSpeed / 7.0f * (r7 - 1.0f);
    } else {
        p = soundSpeed * soundSpeed * (density - restDensity);
    }
    return clampNegative && p < 0.0f ? 0.0f : p;
}

}  // namespace tide
