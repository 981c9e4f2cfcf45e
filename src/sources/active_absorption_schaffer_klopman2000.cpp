#include "sources/active_absorption_schaffer_klopman2000.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tide {

namespace {
/// Drift time in design periods: long enough to leave the design frequency's phase alone
/// (atan(1/(2π·4)) = 2.3° per stage), short enough that a slow 1 mm change of the measured
/// level moves the paddle by about G τ/e ≈ 1 cm at most.
constexpr double kDriftPeriods = 4.0;
/// The gauge's distance in front of the face, in particle spacings (DualSPHysics' default).
constexpr double kGaugeSpacings = 5.0;
}  // namespace

ActiveAbsorption::ActiveAbsorption(const WaveMakerDef& def, std::span<const waves::PaddleComponent> components,
                                   double g, float spacing)
    : rampTime_(def.rampTime), gaugeDistance_(kGaugeSpacings * spacing) {
    const double d = def.depth;
    const bool spectrum = def.spectrum.type != WaveSpectrumDef::Type::None;
    const double period = spectrum ? def.spectrum.peakPeriod : def.period;
    const double omegaP = 2.0 * std::numbers::pi / period;
    const double kdP = waves::waveNumber(omegaP, d, g) * d;
    // H/S = 2a/(2X): the wave amplitude a a paddle amplitude X makes, so the velocity that
    // radiates an amplitude a is ω a/F (the paddle components are made the same way).
    gain_ = omegaP / waves::pistonHeightToStroke(kdP);
    driftTime_ = kDriftPeriods * period;
    waveHeight_ = spectrum ? def.spectrum.significantHeight : def.waveHeight;
    for (const waves::PaddleComponent& c : components) {
        peakAcceleration_ += c.amplitude * c.omega * c.omega;
        maxOffset_ += 2.0 * c.amplitude;
    }
    for (const waves::PaddleComponent& c : components) {
        if (!(c.waveAmplitude > 0.0)) continue;  // Madsen's second-order stroke: no free wave
        components_.push_back({c.waveAmplitude, c.omega, c.phase, waves::waveNumber(c.omega, d, g)});
    }
    if (!spectrum && !components_.empty()) {
        // Stokes' second-order wave: η₂ = (H² k/16) cosh kd (2 + cosh 2kd)/sinh³ kd cos 2θ.
        const double H = def.waveHeight, k = components_.front().k, kd = k * d, s = std::sinh(kd);
        boundAmplitude_ = H * H * k / 16.0 * std::cosh(kd) * (2.0 + std::cosh(2.0 * kd)) / (s * s * s);
    }
}

double ActiveAbsorption::targetElevation(double t) const {
    // A component's stroke X = A sin(ωt + φ) moves the water under the face with it, so its
    // progressive wave is η = a cos(ωt + φ − kx) (in phase with the paddle's velocity).
    double eta = 0.0;
    for (const Component& c : components_) eta += c.amplitude * std::cos(c.omega * t + c.phase - c.k * gaugeDistance_);
    if (boundAmplitude_ != 0.0) {
        const Component& c = components_.front();
        eta += boundAmplitude_ * std::cos(2.0 * (c.omega * t + c.phase - c.k * gaugeDistance_));
    }
    return waves::ramp(t, rampTime_).value * eta;
}

double ActiveAbsorption::correctionVelocity(double t, float measuredY, double stillY, double offset,
                                            double previousVelocity) {
    if (!std::isfinite(measuredY)) return t < rampTime_ ? 0.0 : previousVelocity;  // a dry gauge: keep going
    const double dt = state_.started ? t - state_.lastTime : 0.0;
    const double error = (static_cast<double>(measuredY) - stillY) - targetElevation(t);
    // The mean starts from the first reading, of still water (the gauge's own bias, no wave
    // in it), and follows through the ramp, so the correction starts without a transient.
    if (!state_.started) {
        state_ = {error, t, true};
    } else {
        state_.mean += (error - state_.mean) * std::min(1.0, (t - state_.lastTime) / driftTime_);
        state_.lastTime = t;
    }
    if (t < rampTime_) return 0.0;
    // Limits (as DualSPHysics limits the paddle's acceleration): a reflection is no higher than
    // the wave made, so a larger error is the gauge misreading (a splash on the line); and the
    // correction's velocity changes no faster than twice the prescribed stroke's peak
    // acceleration, which keeps a misreading from jerking the paddle.
    const double reflected = std::clamp(error - state_.mean, -waveHeight_, waveHeight_);
    const double wanted = -gain_ * reflected - offset / driftTime_;
    const double change = 2.0 * peakAcceleration_ * dt;
    double velocity = std::clamp(wanted, previousVelocity - change, previousVelocity + change);
    // Absorbing even a full reflection takes a correction no larger than the stroke itself
    // (a_R/F ≤ a_I/F = A): past twice the stroke the paddle only comes back. Without this bound
    // the paddle of issue 42's 2D flume ran away from the water at 9.1 s (no force on it for
    // 0.5 s, then a surge of 8 cm at the gauges).
    if (offset >= maxOffset_) velocity = std::min(velocity, 0.0);
    if (offset <= -maxOffset_) velocity = std::max(velocity, 0.0);
    return velocity;
}

}  // namespace tide
