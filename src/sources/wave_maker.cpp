#include "sources/wave_maker.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "core/parallel.hpp"

namespace tide {

WaveMaker::WaveMaker(const WaveMakerDef& def, float floor, double g)
    : def_(def), hinge_(def.x, floor, 0.0f), components_(waves::paddleComponents(def, g)) {}

WaveMaker::Motion WaveMaker::motion(double t) const {
    double x = 0.0, v = 0.0, a = 0.0;
    for (const waves::PaddleComponent& c : components_) {
        const double phase = c.omega * t + c.phase;
        x += c.amplitude * std::sin(phase);
        v += c.amplitude * c.omega * std::cos(phase);
        a -= c.amplitude * c.omega * c.omega * std::sin(phase);
    }
    const waves::Ramp r = waves::ramp(t, def_.rampTime);
    return {r.value * x, r.rate * x + r.value * v, r.curvature * x + 2.0 * r.rate * v + r.value * a};
}

WaveMaker::Pose WaveMaker::pose(double t) const {
    Pose p{};
    p.m = motion(t);
    if (def_.type == WaveMakerDef::Type::Piston) {
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
    if (def_.type == WaveMakerDef::Type::Piston) {
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

float WaveMaker::distanceInFront(double t, const glm::vec3& x) const {
    const Pose p = pose(t);
    return (x.x - p.point.x) * p.normal.x + (x.y - p.point.y) * p.normal.y;
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
