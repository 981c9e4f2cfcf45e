#include "sources/wave_theory.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "sources/second_order_wavemaker_schaffer1996.hpp"

namespace tide::waves {

double waveNumber(double omega, double depth, double g) {
    if (!(omega > 0.0) || !(depth > 0.0) || !(g > 0.0))
        throw std::invalid_argument("waveNumber: ω, depth and g must be > 0");
    // Deep water k = ω²/g, shallow water k = ω/√(gd); start from the larger (Newton on
    // f(k) = g k tanh(kd) − ω², convex and increasing, then converges monotonically from above).
    double k = std::max(omega * omega / g, omega / std::sqrt(g * depth));
    for (int iteration = 0; iteration < 100; ++iteration) {
        const double t = std::tanh(k * depth);
        const double f = g * k * t - omega * omega;
        const double df = g * t + g * k * depth * (1.0 - t * t);
        const double step = f / df;
        k -= step;
        if (std::abs(step) <= 1e-12 * k) break;
    }
    return k;
}

double pistonHeightToStroke(double kd) {
    return 2.0 * (std::cosh(2.0 * kd) - 1.0) / (std::sinh(2.0 * kd) + 2.0 * kd);
}

double flapHeightToStroke(double kd) {
    return 4.0 * (std::sinh(kd) / kd) * (kd * std::sinh(kd) - std::cosh(kd) + 1.0) / (std::sinh(2.0 * kd) + 2.0 * kd);
}

double pistonSecondOrderAmplitude(double waveHeight, double kd, double depth) {
    const double s = std::sinh(kd);
    return waveHeight * waveHeight / (32.0 * depth) * (3.0 * std::cosh(kd) / (s * s * s) - 2.0 / pistonHeightToStroke(kd));
}

namespace {
double transfer(WaveMakerDef::Type type, double kd) {
    return type == WaveMakerDef::Type::Flap ? flapHeightToStroke(kd) : pistonHeightToStroke(kd);
}
}  // namespace

JonswapSpectrum::JonswapSpectrum(double significantHeight, double peakPeriod, double gamma)
    : fp_(1.0 / peakPeriod), gamma_(gamma) {
    // ∫ shape df by the midpoint rule in u = fp/f (df = −fp/u² du), u ∈ (0, 1/0.05]: the shape
    // falls off as f⁻⁵ = (u/fp)⁵ for large f and as exp(−5/4 u⁴) for small f.
    constexpr int kSteps = 200000;
    const double uMax = 20.0;
    const double du = uMax / kSteps;
    double integral = 0.0;
    for (int s = 0; s < kSteps; ++s) {
        const double u = (s + 0.5) * du;
        integral += shape(fp_ / u) * fp_ / (u * u) * du;
    }
    scale_ = significantHeight * significantHeight / 16.0 / integral;
}

double JonswapSpectrum::shape(double f) const {
    if (!(f > 0.0)) return 0.0;
    const double sigma = f <= fp_ ? 0.07 : 0.09;
    const double r = std::exp(-(f - fp_) * (f - fp_) / (2.0 * sigma * sigma * fp_ * fp_));
    const double x = fp_ / f;
    return std::pow(f, -5.0) * std::exp(-1.25 * x * x * x * x) * std::pow(gamma_, r);
}

double JonswapSpectrum::operator()(double f) const { return scale_ * shape(f); }

namespace {
/// `first` with, for a piston of order 2, Schäffer 1996's second-order components: every pair's
/// super- and subharmonic, merged by frequency (3N − 2 of them; for regular waves the one
/// harmonic at 2ω, Re C sin 2ωt + Im C cos 2ωt).
std::vector<PaddleComponent> withSecondOrder(const WaveMakerDef& def, std::vector<PaddleComponent> first, double g) {
    if (def.order != 2 || def.type != WaveMakerDef::Type::Piston) return first;
    const std::vector<PaddleComponent> second = pistonSecondOrderComponents(first, def.depth, g);
    first.insert(first.end(), second.begin(), second.end());
    return first;
}
}  // namespace

std::vector<PaddleComponent> paddleComponents(const WaveMakerDef& def, double g) {
    const double d = def.depth;
    std::vector<PaddleComponent> out;
    if (def.type == WaveMakerDef::Type::Solitary) return out;  // SolitaryStroke moves it
    if (def.spectrum.type == WaveSpectrumDef::Type::None) {
        PaddleComponent c;
        c.omega = 2.0 * std::numbers::pi / def.period;
        c.waveAmplitude = 0.5 * def.waveHeight;
        const double kd = waveNumber(c.omega, d, g) * d;
        c.amplitude = c.waveAmplitude / transfer(def.type, kd);
        out.push_back(c);
        return withSecondOrder(def, std::move(out), g);
    }
    const WaveSpectrumDef& s = def.spectrum;
    const double gamma = s.type == WaveSpectrumDef::Type::PiersonMoskowitz ? 1.0 : s.gamma;
    const JonswapSpectrum spectrum(s.significantHeight, s.peakPeriod, gamma);
    const double fp = 1.0 / s.peakPeriod;
    const double fLo = s.minFrequency * fp, fHi = s.maxFrequency * fp;
    const double df = (fHi - fLo) / s.components;
    // Phases from the raw 32-bit outputs of mt19937 (specified exactly by the standard), not
    // std::uniform_real_distribution (whose algorithm differs between libraries).
    std::mt19937 random(s.seed);
    for (int n = 0; n < s.components; ++n) {
        const double f = fLo + (n + 0.5) * df;
        PaddleComponent c;
        c.omega = 2.0 * std::numbers::pi * f;
        c.waveAmplitude = std::sqrt(2.0 * spectrum(f) * df);
        c.amplitude = c.waveAmplitude / transfer(def.type, waveNumber(c.omega, d, g) * d);
        c.phase = 2.0 * std::numbers::pi * (static_cast<double>(random()) / 4294967296.0);
        out.push_back(c);
    }
    return withSecondOrder(def, std::move(out), g);
}

SolitaryStroke::SolitaryStroke(double waveHeight, double depth, double g)
    : h_(waveHeight), d_(depth), kappa_(std::sqrt(3.0 * waveHeight / (4.0 * depth * depth * depth))),
      c_(std::sqrt(g * (depth + waveHeight))), amplitude_(waveHeight / (kappa_ * depth)),
      t0_((3.8 + waveHeight / depth) / (kappa_ * c_)) {
    origin_ = xi(0.0);
}

double SolitaryStroke::xi(double t) const {
    // ξ = A tanh(κ(cτ − ξ)) by Newton's method: f(ξ) = ξ − A tanh(κ(cτ − ξ)) has
    // f' = 1 + Aκ sech² > 0, so it converges from ξ = 0 (a few steps to round-off).
    const double tau = std::clamp(t, 0.0, 2.0 * t0_) - t0_;
    double x = 0.0;
    for (int iteration = 0; iteration < 50; ++iteration) {
        const double th = std::tanh(kappa_ * (c_ * tau - x));
        const double f = x - amplitude_ * th, df = 1.0 + amplitude_ * kappa_ * (1.0 - th * th);
        const double step = f / df;
        x -= step;
        if (std::abs(step) <= 1e-15 * amplitude_) break;
    }
    return x;
}

SolitaryStroke::State SolitaryStroke::at(double t) const {
    const double x = xi(t);
    if (t <= 0.0 || t >= 2.0 * t0_) return {x - origin_, 0.0, 0.0};
    const double th = std::tanh(kappa_ * (c_ * (t - t0_) - x));
    const double eta = h_ * (1.0 - th * th);
    const double v = c_ * eta / (d_ + eta);
    // dη/dt = −2η tanh(θ) κ (c − v); d/dt [cη/(d + η)] = c d η'/(d + η)².
    const double deta = -2.0 * eta * th * kappa_ * (c_ - v);
    return {x - origin_, v, c_ * d_ * deta / ((d_ + eta) * (d_ + eta))};
}

Ramp ramp(double t, double rampTime) {
    if (!(rampTime > 0.0) || t >= rampTime) return {t >= 0.0 ? 1.0 : 0.0, 0.0, 0.0};
    if (t <= 0.0) return {0.0, 0.0, 0.0};
    const double a = std::numbers::pi / rampTime;
    return {0.5 * (1.0 - std::cos(a * t)), 0.5 * a * std::sin(a * t), 0.5 * a * a * std::cos(a * t)};
}

}  // namespace tide::waves
