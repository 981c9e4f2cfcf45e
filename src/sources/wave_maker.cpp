#include "sources/wave_maker.hpp"

#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "core/parallel.hpp"

namespace tide {

namespace {
std::string show(double v) {
    std::ostringstream out;
    out << std::setprecision(4) << v;
    return out.str();
}
}  // namespace

void checkWaveFitsTank(const WaveMakerDef& def, float length, float spacing, double g) {
    if (def.order != 1 && def.order != 2)
        throw std::invalid_argument("wavemaker.order: must be 1 or 2, got " + std::to_string(def.order));
    if (def.order == 2 && def.type != WaveMakerDef::Type::Piston)
        throw std::invalid_argument("wavemaker.order: 2 is for a piston's regular or irregular waves, got 2 with " +
                                    std::string(def.type == WaveMakerDef::Type::Flap ? "a flap" : "a solitary wave"));
    if (def.absorption == WaveMakerDef::Absorption::On && def.type != WaveMakerDef::Type::Piston)
        throw std::invalid_argument(std::string("wavemaker.absorption: active absorption is for a piston making regular "
                                                "or irregular waves, got true with ") +
                                    (def.type == WaveMakerDef::Type::Flap ? "a flap" : "a solitary wave"));
    const double d = def.depth;
    if (def.type == WaveMakerDef::Type::Solitary) {
        if (!(def.waveHeight > 0.0f)) return;  // the caller reports it
        if (def.waveHeight > 0.6 * d)
            throw std::invalid_argument("wavemaker.wave_height: a solitary wave must be at most 0.6 of the depth (" +
                                        show(0.6 * d) + " m), got " + show(def.waveHeight));
        if (def.waveHeight < kMinSpacingsPerHeight * spacing)
            throw std::invalid_argument("wavemaker.wave_height: must be at least " + show(kMinSpacingsPerHeight) +
                                        " particle spacings (" + show(kMinSpacingsPerHeight * spacing) + " m), got " +
                                        show(def.waveHeight));
        return;
    }
    const bool spectrum = def.spectrum.type != WaveSpectrumDef::Type::None;
    const double period = spectrum ? def.spectrum.peakPeriod : def.period;
    const double height = spectrum ? def.spectrum.significantHeight : def.waveHeight;
    if (!(period > 0.0) || !(height > 0.0) || !(d > 0.0)) return;  // the caller reports them
    const std::string periodField = spectrum ? "wavemaker.spectrum.tp" : "wavemaker.period";
    const std::string heightField = spectrum ? "wavemaker.spectrum.hs" : "wavemaker.wave_height";
    const double lambda = 2.0 * std::numbers::pi / waves::waveNumber(2.0 * std::numbers::pi / period, d, g);
    const std::string what = " m (period " + show(period) + " s in " + show(d) + " m of water)";
    if (lambda > length)
        throw std::invalid_argument(periodField + ": the wave is too long for the tank: its length " + show(lambda) + what +
                                    " exceeds the " + show(length) + " m in front of the paddle, got " + show(period));
    if (lambda < kMinSpacingsPerWave * spacing)
        throw std::invalid_argument(periodField + ": the wave is too short for the particle spacing: its length " +
                                    show(lambda) + what + " is below " + show(kMinSpacingsPerWave) + " spacings (" +
                                    show(kMinSpacingsPerWave * spacing) + " m), got " + show(period));
    if (height > lambda / 7.0)
        throw std::invalid_argument(heightField + ": the wave is too steep: above the breaking limit λ/7 = " +
                                    show(lambda / 7.0) + " m for its length " + show(lambda) + " m, got " + show(height));
    if (height < kMinSpacingsPerHeight * spacing)
        throw std::invalid_argument(heightField + ": the wave is too low for the particle spacing: below " +
                                    show(kMinSpacingsPerHeight) + " spacings (" + show(kMinSpacingsPerHeight * spacing) +
                                    " m), got " + show(height));
}

void checkRoomAboveWaves(const WaveMakerDef& def, double headroom) {
    const bool spectrum = def.type != WaveMakerDef::Type::Solitary && def.spectrum.type != WaveSpectrumDef::Type::None;
    const double crest = spectrum ? def.spectrum.significantHeight : def.waveHeight;
    if (headroom < crest - 1e-6)  // (the domain is in float)
        throw std::invalid_argument("domain.max[1]: the domain's top stands " + show(headroom) +
                                    " m above the wave maker's still water, under its crests (about " + show(crest) +
                                    " m: " + (spectrum ? "spectrum.hs" : "wave_height") + "); raise it by " +
                                    show(crest - headroom) + " m or more");
}

WaveMaker::WaveMaker(const WaveMakerDef& def, float floor, double g)
    : def_(def), hinge_(def.x, floor, 0.0f), components_(waves::paddleComponents(def, g)) {
    if (def.type == WaveMakerDef::Type::Solitary) solitary_.emplace(def.waveHeight, def.depth, g);
}

WaveMaker::Motion WaveMaker::motion(double t) const {
    if (solitary_) {
        const waves::SolitaryStroke::State s = solitary_->at(t);
        return {s.x, s.v, s.a};
    }
    double x = 0.0, v = 0.0, a = 0.0;
    for (const waves::PaddleComponent& c : components_) {
        const double phase = c.omega * t + c.phase;
        x += c.amplitude * std::sin(phase);
        v += c.amplitude * c.omega * std::cos(phase);
        a -= c.amplitude * c.omega * c.omega * std::sin(phase);
    }
    const waves::Ramp r = waves::ramp(t, def_.rampTime);
    // The correction's velocity is constant over a step: it adds no acceleration.
    return {r.value * x + correction_.at(t), r.rate * x + r.value * v + correction_.velocity,
            r.curvature * x + 2.0 * r.rate * v + r.value * a};
}

WaveMaker::Pose WaveMaker::pose(double t) const {
    Pose p{};
    p.m = motion(t);
    if (def_.type != WaveMakerDef::Type::Flap) {
        p.point = hinge_ + glm::vec3(static_cast<float>(p.m.x), 0.0f, 0.0f);
        p.normal = {1.0f, 0.0f, 0.0f};
    } else {
        const double d = def_.depth;
        p.angle = p.m.x / d;
        p.rate = p.m.v / d;
        p.angularAcceleration = p.m.a / d;
        p.point = hinge_;
        p.normal = {static_cast<float>(std::cos(p.angle)), static_cast<float>(-std::sin(p.angle)), 0.0f};
    }
    return p;
}

std::vector<glm::vec3> WaveMaker::sample(const glm::vec3& domainMin, const glm::vec3& domainMax, float spacing,
                                         int layers) const {
    const auto count = [&](int axis) {
        return std::max(1, static_cast<int>(std::lround((domainMax[axis] - domainMin[axis]) / spacing)));
    };
    const int ny = count(1), nz = count(2);
    const float stepY = (domainMax.y - domainMin.y) / static_cast<float>(ny);
    const float stepZ = (domainMax.z - domainMin.z) / static_cast<float>(nz);
    std::vector<glm::vec3> points;
    points.reserve(static_cast<std::size_t>(layers) * ny * nz);
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int layer = 0; layer < layers; ++layer)
                points.emplace_back(def_.x - (static_cast<float>(layer) + 0.5f) * spacing,
                                    domainMin.y + (static_cast<float>(j) + 0.5f) * stepY,
                                    domainMin.z + (static_cast<float>(k) + 0.5f) * stepZ);
    return points;
}

void WaveMaker::place(double t, std::span<const glm::vec3> rest, std::span<glm::vec3> position,
                      std::span<glm::vec3> velocity, std::span<glm::vec3> acceleration) const {
    const Pose p = pose(t);
    if (def_.type != WaveMakerDef::Type::Flap) {
        const glm::vec3 shift(static_cast<float>(p.m.x), 0.0f, 0.0f);
        for (std::size_t b = 0; b < rest.size(); ++b) {
            position[b] = rest[b] + shift;
            velocity[b] = {static_cast<float>(p.m.v), 0.0f, 0.0f};
            acceleration[b] = {static_cast<float>(p.m.a), 0.0f, 0.0f};
        }
        return;
    }
    // Rotation by −θ about +z through the hinge: a positive θ leans the top towards +x.
    const double c = std::cos(p.angle), s = std::sin(p.angle);
    for (std::size_t b = 0; b < rest.size(); ++b) {
        const double rx = rest[b].x - hinge_.x, ry = rest[b].y - hinge_.y;
        const double x = rx * c + ry * s, y = -rx * s + ry * c;
        position[b] = {hinge_.x + static_cast<float>(x), hinge_.y + static_cast<float>(y), rest[b].z};
        // v = ω × r with ω = −θ̇ ẑ; a = α × r + ω × (ω × r).
        velocity[b] = {static_cast<float>(p.rate * y), static_cast<float>(-p.rate * x), 0.0f};
        acceleration[b] = {static_cast<float>(p.angularAcceleration * y - p.rate * p.rate * x),
                           static_cast<float>(-p.angularAcceleration * x - p.rate * p.rate * y), 0.0f};
    }
}

WaveMaker::Face WaveMaker::face(double t) const {
    const Pose p = pose(t);
    return {p.point, p.normal};
}

void WaveMaker::project(double t, ParticleStore& particles, float margin, int threads) const {
    const Pose p = pose(t);
    parallelFor(particles.size(), threads, [&](std::uint32_t i) {
        glm::vec3& x = particles.position[i];
        const float d = (x.x - p.point.x) * p.normal.x + (x.y - p.point.y) * p.normal.y;
        if (d >= margin) return;
        x += (margin - d) * p.normal;
        glm::vec3 wall(static_cast<float>(p.m.v), 0.0f, 0.0f);
        if (def_.type == WaveMakerDef::Type::Flap) {
            const float rx = x.x - hinge_.x, ry = x.y - hinge_.y;
            wall = {static_cast<float>(p.rate) * ry, -static_cast<float>(p.rate) * rx, 0.0f};
        }
        glm::vec3& v = particles.velocity[i];
        const float into = glm::dot(v - wall, p.normal);
        if (into < 0.0f) v -= into * p.normal;
    });
}

}  // namespace tide
