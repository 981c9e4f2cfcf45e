#include "ocean/sea.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <stdexcept>
#include <utility>

#include "core/parallel.hpp"
#include "ocean/spectrum.hpp"
#include "ocean/stokes_wave_fenton1985.hpp"
#include "ocean/uniform_random.hpp"

namespace tide::ocean {

namespace {

constexpr double kPi = std::numbers::pi;

// The frequency comb of a discretised spectrum (see discretise).
struct Comb {
    int bands, directions;
    double step;    // δω
    double offset;  // n0
};

Comb combOf(const OceanWavesDef& w, SpectrumRange range) {
    Comb comb{};
    comb.bands = w.components;
    comb.directions = w.spreading ? (w.directions > 0 ? w.directions : 16) : 1;
    const double wp = 2.0 * kPi / w.tp;
    comb.step = (range.high - range.low) * wp / (comb.bands * comb.directions);
    comb.offset = std::round(range.low * wp / comb.step);
    return comb;
}

}  // namespace

std::vector<WaveComponent> discretise(const OceanDef& def, double g, SpectrumRange range) {
    validateOcean(def);
    const OceanWavesDef& w = def.waves;
    const double mean = w.direction * kPi / 180.0;
    if (w.type == OceanWavesDef::Type::Regular) {
        const double omega = 2.0 * kPi / w.period;
        const auto stokes = oceanStokesWave(def, g);
        if (!stokes) {
            const double k = waveNumber(omega, def.depth, g);
            return {WaveComponent{0.5 * w.height, omega, k * std::cos(mean), k * std::sin(mean), 0.0}};
        }
        std::vector<WaveComponent> harmonics;
        for (int j = 1; j <= stokes->order; ++j) {
            const double k = j * stokes->k;
            harmonics.push_back(WaveComponent{stokes->elevation[j - 1], j * omega, k * std::cos(mean), k * std::sin(mean), 0.0,
                                              true, stokes->velocity[j - 1]});
        }
        return harmonics;
    }
    if (!(range.low > 0.0 && range.high > range.low))
        throw std::invalid_argument("ocean::discretise: the spectrum range must have 0 < low < high");
    const Comb comb = combOf(w, range);
    const double gamma = oceanGamma(w);
    std::vector<double> directions{0.0};
    if (w.spreading) directions = Cos2sSpreading(*w.spreading).equalEnergyDirections(comb.directions);

    std::mt19937_64 random(w.seed);
    std::vector<WaveComponent> components;
    components.reserve(static_cast<std::size_t>(comb.bands) * comb.directions);
    std::vector<int> order(static_cast<std::size_t>(comb.directions));
    for (int band = 0; band < comb.bands; ++band) {
        // Fisher–Yates from raw bits (std::shuffle's draws are the library's choice).
        for (int j = 0; j < comb.directions; ++j) order[j] = j;
        for (int j = comb.directions - 1; j > 0; --j) std::swap(order[j], order[uniformIndex(random, j + 1)]);
        for (int j = 0; j < comb.directions; ++j) {
            const int n = band * comb.directions + j;
            const double omega = (comb.offset + n + 0.5) * comb.step;
            const double variance = jonswap(omega, w.hs, w.tp, gamma) * comb.step;
            const double k = waveNumber(omega, def.depth, g);
            const double beta = mean + directions[order[j]];
            components.push_back(WaveComponent{std::sqrt(2.0 * variance), omega, k * std::cos(beta),
                                               k * std::sin(beta), 2.0 * kPi * uniform01(random)});
        }
    }
    return components;
}

glm::dvec2 meanCurrent(const OceanDef& def, double g) {
    const double beta = def.waves.direction * kPi / 180.0;
    return oceanMeanCurrent(def, g) * glm::dvec2(std::cos(beta), std::sin(beta));
}

double repeatPeriod(const OceanDef& def, SpectrumRange range) {
    validateOcean(def);
    if (def.waves.type == OceanWavesDef::Type::Regular) return def.waves.period;
    // The frequencies are odd multiples of δω/2.
    return 4.0 * kPi / combOf(def.waves, range).step;
}

Sea::Sea(std::vector<WaveComponent> components, double depth, double g, double density, glm::dvec2 current)
    : components_(std::move(components)), depth_(depth), g_(g), density_(density), current_(current) {
    if (!(depth > 0.0 && std::isfinite(depth)) || !(g > 0.0 && std::isfinite(g)) ||
        !(density > 0.0 && std::isfinite(density)) || !std::isfinite(current.x + current.y)) {
        std::ostringstream message;
        message << "ocean::Sea: depth, g and density must be > 0 and the current finite, got " << depth << ", " << g
                << ", " << density << ", (" << current.x << ", " << current.y << ")";
        throw std::invalid_argument(message.str());
    }
    profiles_.reserve(components_.size());
    for (std::size_t i = 0; i < components_.size(); ++i) {
        const WaveComponent& c = components_[i];
        const double k = std::hypot(c.kx, c.kz);
        const bool dispersive = k > 0.0 && std::abs(c.omega * c.omega - g * k * std::tanh(k * depth)) <=
                                               1e-9 * c.omega * c.omega;
        const bool boundOk = c.bound && k > 0.0 && std::isfinite(k) && c.omega > 0.0 && std::isfinite(c.omega) &&
                             std::isfinite(c.velocity);
        if (!(c.bound ? boundOk : dispersive) || !(c.amplitude >= 0.0) || !std::isfinite(c.phase)) {
            std::ostringstream message;
            message << "ocean::Sea: component " << i << " (a " << c.amplitude << ", omega " << c.omega << ", k ("
                    << c.kx << ", " << c.kz << ")) needs a >= 0 and "
                    << (c.bound ? "finite k > 0, omega > 0 and velocity" : "omega^2 = g k tanh(k d)");
            throw std::invalid_argument(message.str());
        }
        if (c.bound) kinematics_ = Stretching::Truncated;
        const double decay = std::exp(-2.0 * k * depth);
        const double overSinh = 1.0 / -std::expm1(-2.0 * k * depth);
        const double velocity = c.bound ? c.velocity : c.amplitude * c.omega;
        profiles_.push_back(Profile{k, c.kx / k, c.kz / k, decay, (1.0 + decay) * overSinh, overSinh, velocity,
                                    velocity * c.omega / (g * k)});
    }
    if (kinematics_ == Stretching::Truncated)
        for (const WaveComponent& c : components_) kinematicTop_ += c.amplitude;
}

Sea Sea::fromDef(const OceanDef& def, double g, double density) {
    return Sea(discretise(def, g), def.depth, g, density, meanCurrent(def, g));
}

double Sea::phaseAt(const WaveComponent& c, double x, double z, double t) const {
    return c.kx * x + c.kz * z - c.omega * t + c.phase;
}

double Sea::elevation(double x, double z, double t) const {
    double eta = 0.0;
    for (const WaveComponent& c : components_) eta += c.amplitude * std::cos(phaseAt(c, x, z, t));
    return eta;
}

double Sea::elevationRate(double x, double z, double t) const {
    double rate = 0.0;
    for (const WaveComponent& c : components_) rate += c.amplitude * c.omega * std::sin(phaseAt(c, x, z, t));
    return rate;
}

double Sea::meanElevation(glm::dvec2 lo, glm::dvec2 hi, double t) const {
    const glm::dvec2 centre = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    // sin(u)/u, 1 − u²/6 near 0 (its error there, u⁴/120, below double's).
    const auto sinc = [](double u) { return std::abs(u) < 1e-4 ? 1.0 - u * u / 6.0 : std::sin(u) / u; };
    double mean = 0.0;
    for (const WaveComponent& c : components_)
        mean += c.amplitude * std::cos(phaseAt(c, centre.x, centre.y, t)) * sinc(c.kx * half.x) * sinc(c.kz * half.y);
    return mean;
}

glm::dvec2 Sea::horizontalDisplacement(double x, double z, double t) const {
    glm::dvec2 d(0.0);
    for (std::size_t i = 0; i < components_.size(); ++i) {
        const WaveComponent& c = components_[i];
        const Profile& p = profiles_[i];
        const double s = -p.velocity / c.omega * p.coth * std::sin(phaseAt(c, x, z, t));
        d += glm::dvec2(s * p.ux, s * p.uz);
    }
    return d;
}

WaterSample Sea::sample(const glm::dvec3& point, double t, std::optional<Stretching> how) const {
    const Stretching stretching = how.value_or(kinematics_);
    // Each phase's cosine and sine once: η needs them all before the stretched height is known.
    thread_local std::vector<double> trig;
    trig.resize(2 * components_.size());
    WaterSample out;
    for (std::size_t i = 0; i < components_.size(); ++i) {
        const double theta = phaseAt(components_[i], point.x, point.z, t);
        trig[2 * i] = std::cos(theta);
        trig[2 * i + 1] = std::sin(theta);
        out.elevation += components_[i].amplitude * trig[2 * i];
    }
    double y = point.y;  // where the profiles are evaluated
    if (stretching == Stretching::Wheeler) {
        const double column = depth_ + out.elevation;
        out.wet = point.y <= out.elevation && column > 0.0;
        y = out.wet ? depth_ * (point.y + depth_) / column - depth_ : 0.0;
    } else {
        out.wet = point.y <= out.elevation;
        if (stretching == Stretching::Truncated) y = std::min(point.y, out.elevation);
    }
    double dynamic = 0.0;  // −∂φ/∂t / g: Σ (V ω/(g k)) cosh(k(y'+d))/sinh(kd) cos θ (a cosh/cosh for a free wave)
    for (std::size_t i = 0; i < components_.size(); ++i) {
        const Profile& p = profiles_[i];
        // cosh(k(y+d)) and sinh(k(y+d)) over e^{kd}: e^{ky} ± e^{−k(y+2d)}, the second as
        // e^{−2kd}/e^{ky} (0 where e^{ky} underflows: then both terms are negligible).
        const double up = std::exp(p.k * y);
        const double down = up > 0.0 ? p.decay / up : 0.0;
        const double horizontal = p.velocity * (up + down) * p.overSinh * trig[2 * i];
        out.velocity.x += horizontal * p.ux;
        out.velocity.z += horizontal * p.uz;
        out.velocity.y += p.velocity * (up - down) * p.overSinh * trig[2 * i + 1];
        dynamic += p.head * (up + down) * p.overSinh * trig[2 * i];
    }
    out.velocity.x += current_.x;
    out.velocity.z += current_.y;
    // Wheeler and Truncated: the air above the surface is at atmospheric pressure. The linear
    // field keeps its formula everywhere (its surface condition holds at y = 0, not at η).
    out.pressure = out.wet || stretching == Stretching::None ? density_ * g_ * (dynamic - point.y) : 0.0;
    return out;
}

void Sea::sample(std::span<const glm::dvec3> points, double t, std::span<WaterSample> out, int threads,
                 std::optional<Stretching> stretching) const {
    if (out.size() != points.size())
        throw std::invalid_argument("ocean::Sea::sample: " + std::to_string(points.size()) + " points but " +
                                    std::to_string(out.size()) + " results");
    parallelFor(static_cast<std::uint32_t>(points.size()), threads,
                [&](std::uint32_t i) { out[i] = sample(points[i], t, stretching); });
}

double Sea::variance() const {
    double sum = 0.0;
    for (const WaveComponent& c : components_) sum += 0.5 * c.amplitude * c.amplitude;
    return sum;
}

}  // namespace tide::ocean
