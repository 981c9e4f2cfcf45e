#include "boundary/rigid_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/validate.hpp"
#include "sources/wave_theory.hpp"

namespace tide {

glm::vec3 RigidPose::toRest(const glm::vec3& x) const { return center + glm::transpose(rotation) * (x - pivot); }

glm::vec3 RigidPose::velocityAt(const glm::vec3& x) const { return velocity + glm::cross(omega, x - pivot); }

glm::vec3 RigidPose::accelerationAt(const glm::vec3& x) const {
    const glm::vec3 r = x - pivot;
    return acceleration + glm::cross(alpha, r) + glm::cross(omega, glm::cross(omega, r));
}

namespace {

/// A scalar drive and its first two time derivatives.
struct Drive {
    double value = 0.0, rate = 0.0, curvature = 0.0;
};

/// The steady part: ∫₀^τ r(u) du for the ramp r = ½(1 − cos(π u/T)) (1 after T), so the rate
/// grows smoothly from 0 to 1.
Drive steady(double tau, double rampTime) {
    if (!(tau > 0.0)) return {};
    const waves::Ramp r = waves::ramp(tau, rampTime);
    double integral = tau;
    if (rampTime > 0.0) {
        integral = tau >= rampTime ? tau - 0.5 * rampTime
                                   : 0.5 * tau - rampTime / (2.0 * std::numbers::pi) * std::sin(std::numbers::pi * tau / rampTime);
    }
    return {integral, r.value, r.rate};
}

/// The oscillating part: r(τ) sin(2π τ/T_period), as the wave paddles ramp their stroke.
Drive oscillation(double tau, double rampTime, double period) {
    if (!(tau > 0.0) || !(period > 0.0)) return {};
    const waves::Ramp r = waves::ramp(tau, rampTime);
    const double w = 2.0 * std::numbers::pi / period;
    const double s = std::sin(w * tau), c = std::cos(w * tau);
    return {r.value * s, r.rate * s + r.value * w * c, r.curvature * s + 2.0 * r.rate * w * c - r.value * w * w * s};
}

glm::dvec4 row(const MotionKey& k) { return {k.offset.x, k.offset.y, k.offset.z, k.angle}; }

/// R(θ) about the unit axis a (Rodrigues): I cos θ + sin θ [a]× + (1 − cos θ) a aᵀ.
glm::mat3 rotationAbout(const glm::dvec3& a, double theta) {
    const double c = std::cos(theta), s = std::sin(theta), k = 1.0 - c;
    glm::dmat3 m;  // column-major: m[column][row]
    m[0] = {c + k * a.x * a.x, k * a.x * a.y + s * a.z, k * a.x * a.z - s * a.y};
    m[1] = {k * a.y * a.x - s * a.z, c + k * a.y * a.y, k * a.y * a.z + s * a.x};
    m[2] = {k * a.z * a.x + s * a.y, k * a.z * a.y - s * a.x, c + k * a.z * a.z};
    return glm::mat3(m);
}

}  // namespace

RigidMotion::RigidMotion(MotionDef def) : def_(std::move(def)) {}

RigidState RigidMotion::tableState(double tau) const {
    const std::vector<MotionKey>& keys = def_.keys;
    RigidState s;
    const auto set = [&s](const glm::dvec4& p, const glm::dvec4& v, const glm::dvec4& a) {
        s.offset = glm::dvec3(p);
        s.velocity = glm::dvec3(v);
        s.acceleration = glm::dvec3(a);
        s.angle = p.w;
        s.rate = v.w;
        s.angularAcceleration = a.w;
    };
    if (keys.empty()) return s;
    if (tau <= keys.front().time) {
        set(row(keys.front()), {}, {});
        return s;
    }
    if (tau >= keys.back().time) {
        set(row(keys.back()), {}, {});
        return s;
    }
    // keys[k].time < tau < keys[k + 1].time
    const auto next = std::upper_bound(keys.begin(), keys.end(), tau,
                                       [](double t, const MotionKey& key) { return t < key.time; });
    const std::size_t k = static_cast<std::size_t>(next - keys.begin()) - 1;
    // Catmull–Rom tangents (centred differences over the neighbouring rows), zero at the ends:
    // velocity is continuous, and the motion starts from and ends at rest.
    const auto tangent = [&](std::size_t i) -> glm::dvec4 {
        if (i == 0 || i + 1 == keys.size()) return glm::dvec4(0.0);
        return (row(keys[i + 1]) - row(keys[i - 1])) / (keys[i + 1].time - keys[i - 1].time);
    };
    const double h = keys[k + 1].time - keys[k].time;
    const double u = (tau - keys[k].time) / h;
    const glm::dvec4 p0 = row(keys[k]), p1 = row(keys[k + 1]);
    const glm::dvec4 m0 = h * tangent(k), m1 = h * tangent(k + 1);
    // Cubic Hermite basis h00, h10, h01, h11 and their derivatives in u.
    const double u2 = u * u, u3 = u2 * u;
    const glm::dvec4 p = (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * m1;
    const glm::dvec4 dp = (6 * u2 - 6 * u) * p0 + (3 * u2 - 4 * u + 1) * m0 + (-6 * u2 + 6 * u) * p1 + (3 * u2 - 2 * u) * m1;
    const glm::dvec4 ddp = (12 * u - 6) * p0 + (6 * u - 4) * m0 + (-12 * u + 6) * p1 + (6 * u - 2) * m1;
    set(p, dp / h, ddp / (h * h));
    return s;
}

RigidState RigidMotion::state(double t) const {
    const double tau = t - def_.startTime;
    RigidState s;
    switch (def_.type) {
        case MotionDef::Type::None: break;
        case MotionDef::Type::Translation: {
            const Drive a = steady(tau, def_.rampTime), b = oscillation(tau, def_.rampTime, def_.period);
            const glm::dvec3 v(def_.velocity), amp(def_.amplitude);
            s.offset = a.value * v + b.value * amp;
            s.velocity = a.rate * v + b.rate * amp;
            s.acceleration = a.curvature * v + b.curvature * amp;
            break;
        }
        case MotionDef::Type::Rotation: {
            const Drive a = steady(tau, def_.rampTime), b = oscillation(tau, def_.rampTime, def_.period);
            const double w = def_.angularVelocity, amp = def_.angularAmplitude;
            s.angle = a.value * w + b.value * amp;
            s.rate = a.rate * w + b.rate * amp;
            s.angularAcceleration = a.curvature * w + b.curvature * amp;
            break;
        }
        case MotionDef::Type::Table: s = tableState(tau); break;
    }
    return s;
}

RigidPose RigidMotion::pose(double t) const {
    const RigidState s = state(t);
    const glm::dvec3 axis(def_.axis);
    RigidPose p;
    p.rotation = rotationAbout(axis, s.angle);
    p.center = def_.center;
    p.pivot = glm::vec3(glm::dvec3(def_.center) + s.offset);
    p.velocity = glm::vec3(s.velocity);
    p.acceleration = glm::vec3(s.acceleration);
    p.omega = glm::vec3(s.rate * axis);
    p.alpha = glm::vec3(s.angularAcceleration * axis);
    return p;
}

MotionDef validatedMotion(const MotionDef& def, const std::string& path) {
    MotionDef m = def;
    const auto finite = [&](const char* field, const glm::vec3& v) {
        for (int axis = 0; axis < 3; ++axis) requireFinite(path + "." + field, v[axis]);
    };
    const auto needsPeriod = [&](bool oscillates) {
        if (oscillates) requirePositive(path + ".period", m.period);
    };
    if (!std::isfinite(m.startTime))
        throw std::invalid_argument(path + ".start_time: must be finite, got " + std::to_string(m.startTime));
    if (!(m.rampTime >= 0.0f) || !std::isfinite(m.rampTime))
        throw std::invalid_argument(path + ".ramp_time: must be >= 0, got " + show(m.rampTime));
    switch (m.type) {
        case MotionDef::Type::None: return m;
        case MotionDef::Type::Translation:
            finite("velocity", m.velocity);
            finite("amplitude", m.amplitude);
            needsPeriod(m.amplitude != glm::vec3(0.0f));
            return m;
        case MotionDef::Type::Rotation:
        case MotionDef::Type::Table: break;
        default: throw std::invalid_argument(path + ".type: unknown motion type");
    }
    finite("axis", m.axis);
    finite("center", m.center);
    if (!(glm::length(m.axis) > 0.0f)) throw std::invalid_argument(path + ".axis: must be non-zero, got " + show(m.axis));
    m.axis = glm::normalize(m.axis);
    if (m.type == MotionDef::Type::Rotation) {
        requireFinite(path + ".angular_velocity", m.angularVelocity);
        requireFinite(path + ".amplitude", m.angularAmplitude);
        needsPeriod(m.angularAmplitude != 0.0f);
        return m;
    }
    if (m.keys.empty()) throw std::invalid_argument(path + ".keys: a motion table needs at least one row, got none");
    for (std::size_t k = 0; k < m.keys.size(); ++k) {
        const MotionKey& key = m.keys[k];
        const std::string where = path + ".keys[" + std::to_string(k) + "]";
        if (!std::isfinite(key.time) || (k > 0 && !(key.time > m.keys[k - 1].time)))
            throw std::invalid_argument(where + ".time: must be finite and after the previous row's, got " +
                                        std::to_string(key.time));
        for (int axis = 0; axis < 3; ++axis) requireFinite(where + ".offset", key.offset[axis]);
        requireFinite(where + ".angle", key.angle);
    }
    return m;
}

}  // namespace tide
