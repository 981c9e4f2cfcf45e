#pragma once
/// \file
/// The first standing-wave mode of a tank of length L and depth d (z one periodic cell, so
/// 2D), started flat with the velocity of the linear mode, η = a cos(kx) sin(ωt), k = π/L:
/// its amplitude (the surface heights at gauges every 2 cm projected on cos kx), fitted with a
/// damped oscillation, against ω² = g k tanh kd. With x periodic the tank is one wave length
/// (2L) long and has no end walls: the decay is then the waves' own, as in a flume. Shared by
/// tide_standing_wave and the tests.

#include <cmath>
#include <functional>
#include <numbers>

#include <tide/world.hpp>

#include "testing/scenarios.hpp"
#include "testing/wave_analysis.hpp"

namespace tide::scenarios {

struct StandingMode {
    double omegaTheory = 0.0;  ///< rad/s, linear theory
    waves::DampedFit fit;      ///< the mode's fitted frequency, decay rate and amplitude
    [[nodiscard]] double frequencyError() const { return fit.omega / omegaTheory - 1.0; }
};

/// World for the mode: `def`'s solver and resolution, x periodic if `periodic`.
inline World standingModeTank(WorldDef def, float length, float depth, int widthInSpacings, bool periodic) {
    def.periodic.x = periodic;
    return stillTank(def, periodic ? 2.0f * length : length, depth, widthInSpacings);
}

/// Starts the mode of amplitude a in `world` (a standingModeTank, possibly settled), runs it
/// for `seconds` and fits it; `afterSample(world, mode)` is called after each 0.01 s sample.
inline StandingMode runStandingMode(World& world, float length, float depth, float amplitude, double seconds,
                                    const std::function<void(const World&, double)>& afterSample = {}) {
    const bool periodic = world.def().periodic.x;
    // |g| to 0.1 mm/s², so that 9.81f reads 9.81: the start's velocities then are the ones
    // tide_standing_wave has always set (the run is chaotic: a change in the 8th digit moves
    // the fitted decay by ~0.02 1/s).
    const double g = std::round(1e4 * std::abs(static_cast<double>(world.def().gravity.y))) * 1e-4;
    const double k = std::numbers::pi / length;
    StandingMode result;
    result.omegaTheory = std::sqrt(g * k * std::tanh(k * depth));
    // Velocity potential φ = (aω / (k sinh kd)) cosh(ky) cos(kx) at t = 0 (y from the floor).
    const auto& p = world.particles();
    auto v = world.velocities();
    const double scale = amplitude * result.omegaTheory / std::sinh(k * depth);
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        const double x = p.position[i].x, y = p.position[i].y;
        v[i] = glm::vec3(static_cast<float>(-scale * std::cosh(k * y) * std::sin(k * x)),
                         static_cast<float>(scale * std::sinh(k * y) * std::cos(k * x)), 0.0f);
    }
    waves::Record mode{0.01, 0.01, {}};
    const float z = 0.5f * world.def().domainMax.z;
    const float extent = periodic ? 2.0f * length : length;
    // Gauges every 2 cm: clear of the end walls, or over the whole period.
    const float firstGauge = periodic ? 0.0f : 0.04f, lastGauge = periodic ? extent - 0.02f : length - 0.04f;
    const int samples = static_cast<int>(std::lround(seconds / mode.dt));
    for (int n = 0; n < samples; ++n) {
        world.advance(mode.dt);
        double sum = 0.0;
        int count = 0;
        for (float x = firstGauge; x < lastGauge + 1e-4f; x += 0.02f) {
            const float height = world.surfaceHeight(x, z);
            if (!std::isfinite(height)) continue;
            sum += (height - depth) * std::cos(k * x);
            ++count;
        }
        mode.eta.push_back(count > 0 ? 2.0 * sum / count : 0.0);
        if (afterSample) afterSample(world, mode.eta.back());
    }
    result.fit = waves::fitDampedOscillation(mode, 0.7 * result.omegaTheory, 1.3 * result.omegaTheory, 2.0);
    return result;
}

}  // namespace tide::scenarios
