/// \file
/// One rigid body's integrator (see RigidBody in include/tide/bodies.hpp).
///
/// State: centre of mass x, orientation q (rest pose → now), velocity V, angular momentum L
/// (world axes, about the centre of mass, or about the pin of a hinge or ball joint).
/// A sub-step of length τ is velocity Verlet (kick–drift–kick), Strang-split for rotation as
/// in Dullweber, Leimkuhler & McLachlan 1997 (J. Chem. Phys. 107, 5840, §III):
///   kick  V += τ/2 F/m,  L += τ/2 M
///   drift x += τ V,  q ← free-rotor flow over τ
///   kick  with the loads at the new pose.
/// The free rotor H = Σ L_k²/(2 I_k) is split into its three principal parts, each an exact
/// rotation of the body about its principal axis u_k by τ (L·u_k)/I_k, in the symmetric
/// order 1(τ/2) 2(τ/2) 3(τ) 2(τ/2) 1(τ/2): symplectic, time-reversible, second order;
/// L does not change in the drift, so |L| of a torque-free body is kept to round-off and
/// its energy oscillates without drift. Under a constant force the kicks and drift integrate
/// the parabola exactly, so a thrown body's points follow their motion to round-off.
///
/// Constraints (world axes): locked translations have their V components (and so their
/// position) held at zero change. Rotations restricted to a subspace S spanned by free unit
/// axes B (fixed axes with one or two rotations free, or a hinge) keep only Bᵀ L, and turn
/// with the ω ∈ S that carries it: ω = B (Bᵀ I B)⁻¹ Bᵀ L — the inertia-weighted projection,
/// i.e. the constraint torque removes exactly the components along the locked axes. One free
/// axis (the common case) has Bᵀ I B constant and its rotation exact. A hinge or ball joint
/// rotates the body about its pin p with the inertia about p (parallel-axis theorem) and the
/// moment about p, M_p = M_c + (c − p) × F; the centre of mass follows, c = p + R (c0 − p).

#include <tide/bodies.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "bodies/checks.hpp"
#include "bodies/mooring.hpp"

namespace tide::bodies {

namespace {

glm::dmat3 parallelAxis(double m, const glm::dvec3& d) {
    glm::dmat3 out(glm::dot(d, d) * m);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) out[c][r] -= m * d[r] * d[c];
    return out;
}

glm::dvec3 up(const glm::dvec3& gravity) {
    const double g = glm::length(gravity);
    return g > 0.0 ? -gravity / g : glm::dvec3(0.0, 1.0, 0.0);
}

}  // namespace

RigidBody::RigidBody(const BodyDef& def, const glm::dvec3& gravity) : def_(def), gravity_(gravity) {
    const std::string& path = def.name;
    requireFiniteD("gravity", gravity);
    if (def.density.has_value() == def.mass.has_value())
        throw std::invalid_argument(path + ": give exactly one of density and mass");
    if (def.density) requirePositiveD(path + ".density", *def.density);
    if (def.mass) requirePositiveD(path + ".mass", *def.mass);
    if (def.shape.shape == ObstacleDef::Shape::Plane)
        throw std::invalid_argument(path + ".shape: a plane cannot be a body (use a box, sphere, cylinder or mesh)");
    const MassProperties unit = obstacleMassProperties(def.shape, 1.0, path);
    const double density = def.density ? *def.density : *def.mass / unit.volume;
    props_ = obstacleMassProperties(def.shape, density, path);
    if (def.mass) props_.mass = *def.mass;  // exactly what was asked for
    if (def.centerOfMass) {
        requireFiniteD(path + ".center_of_mass", *def.centerOfMass);
        // The geometry's inertia moved to the new centre: I_c' = I_c + m (|d|² 1 − d dᵀ).
        const glm::dvec3 d = *def.centerOfMass - props_.centerOfMass;
        props_.inertia += parallelAxis(props_.mass, d);
        props_.centerOfMass = *def.centerOfMass;
    }
    if (def.inertia) {
        const glm::dmat3& I = *def.inertia;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r)
                if (!std::isfinite(I[c][r]) || std::abs(I[c][r] - I[r][c]) > 1e-12 * std::abs(I[c][c] + I[r][r]))
                    throw std::invalid_argument(path + ".inertia: must be a finite symmetric matrix");
        props_.inertia = I;
    }
    computePrincipalAxes(props_);
    const glm::dvec3& pm = props_.principalMoments;
    if (!(pm.x > 0.0) || pm.x + pm.y < pm.z * (1.0 - 1e-12))
        throw std::invalid_argument(path + ".inertia: must be positive definite with I1 + I2 >= I3, got moments " +
                                    showd(pm));

    restCenter_ = props_.centerOfMass;
    x_ = restCenter_;
    {
        const glm::dvec3 lo(def.shape.min), hi(def.shape.max);
        characteristicSize_ = def.shape.shape == ObstacleDef::Shape::Box ? std::cbrt((hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z))
                                                                          : std::cbrt(props_.volume);
    }

    // Constraints.
    const ConstraintDef& con = def.constraint;
    inertiaRest_ = props_.inertia;
    switch (con.type) {
        case ConstraintDef::Type::Free: rotation_ = RotationMode::Free; break;
        case ConstraintDef::Type::FixedAxes: {
            translationFixed_ = con.fixedTranslation;
            static const glm::dvec3 kAxes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
            for (int k = 0; k < 3; ++k)
                if (!con.fixedRotation[k]) freeRotationAxes_.push_back(kAxes[k]);
            rotation_ = freeRotationAxes_.size() == 3 ? RotationMode::Free
                        : freeRotationAxes_.empty()   ? RotationMode::Locked
                                                      : RotationMode::Subspace;
            if (rotation_ == RotationMode::Free) freeRotationAxes_.clear();
            break;
        }
        case ConstraintDef::Type::Hinge:
        case ConstraintDef::Type::Point: {
            requireFiniteD(path + ".constraint.point", con.point);
            pinned_ = true;
            pin_ = con.point;
            inertiaRest_ = props_.inertia + parallelAxis(props_.mass, restCenter_ - pin_);
            if (con.type == ConstraintDef::Type::Hinge) {
                requireFiniteD(path + ".constraint.axis", con.axis);
                if (!(glm::length(con.axis) > 0.0))
                    throw std::invalid_argument(path + ".constraint.axis: must be non-zero, got " + showd(con.axis));
                freeRotationAxes_.push_back(glm::normalize(con.axis));
                rotation_ = RotationMode::Subspace;
            } else {
                rotation_ = RotationMode::Free;
            }
            break;
        }
    }
    {
        MassProperties about;
        about.inertia = inertiaRest_;
        computePrincipalAxes(about);
        moments_ = about.principalMoments;
        axes_ = about.principalAxes;
        if (!(moments_.x > 0.0))  // a ball joint at the centre of a sphere is fine; a zero moment is not
            throw std::invalid_argument(path + ".inertia: a principal moment about the rotation centre is " +
                                        showd(moments_.x));
    }

    for (std::size_t i = 0; i < def.moorings.size(); ++i) {
        const MooringDef& m = def.moorings[i];
        validateMooring(m, path + ".moorings[" + std::to_string(i) + "]" + (m.name.empty() ? "" : " (" + m.name + ")"));
    }
    moorings_.resize(def.moorings.size());

    // Initial rates, made consistent with the constraints.
    requireFiniteD(path + ".velocity", def.velocity);
    requireFiniteD(path + ".angular_velocity", def.angularVelocity);
    v_ = def.velocity;
    for (int k = 0; k < 3; ++k)
        if (translationFixed_[k]) v_[k] = 0.0;
    glm::dvec3 w0 = def.angularVelocity;
    if (rotation_ == RotationMode::Locked) w0 = glm::dvec3(0.0);
    if (rotation_ == RotationMode::Subspace) {
        glm::dvec3 p(0.0);
        for (const auto& b : freeRotationAxes_) p += glm::dot(w0, b) * b;
        w0 = p;
    }
    l_ = inertiaRest_ * w0;  // q is the identity: world = rest axes
    if (rotation_ == RotationMode::Subspace) {
        glm::dvec3 p(0.0);
        for (const auto& b : freeRotationAxes_) p += glm::dot(l_, b) * b;
        l_ = p;
    }
    updateVelocities();
    static_cast<void>(internalLoads(true));
}

glm::dmat3 RigidBody::rotation() const { return glm::mat3_cast(q_); }

glm::dvec3 RigidBody::angularVelocity() const { return omega_; }

void RigidBody::updateVelocities() {
    const glm::dmat3 R = rotation();
    switch (rotation_) {
        case RotationMode::Locked: omega_ = glm::dvec3(0.0); break;
        case RotationMode::Free: {
            // ω = I⁻¹ L through the principal axes (no matrix inverse to lose digits in).
            glm::dvec3 w(0.0);
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3 u = R * axes_[k];
                w += (glm::dot(l_, u) / moments_[k]) * u;
            }
            omega_ = w;
            break;
        }
        case RotationMode::Subspace: {
            const glm::dmat3 I = R * inertiaRest_ * glm::transpose(R);
            const auto& B = freeRotationAxes_;
            if (B.size() == 1) {
                omega_ = (glm::dot(B[0], l_) / glm::dot(B[0], I * B[0])) * B[0];
            } else {  // two free axes: solve the 2×2 system (Bᵀ I B) s = Bᵀ L
                const double a = glm::dot(B[0], I * B[0]), b = glm::dot(B[0], I * B[1]), d = glm::dot(B[1], I * B[1]);
                const double r0 = glm::dot(B[0], l_), r1 = glm::dot(B[1], l_);
                const double det = a * d - b * b;
                omega_ = ((d * r0 - b * r1) / det) * B[0] + ((a * r1 - b * r0) / det) * B[1];
            }
            break;
        }
    }
    if (pinned_) v_ = glm::cross(omega_, x_ - pin_);
}

void RigidBody::kick(double tau, const Loads& loads) {
    if (pinned_) {
        l_ += tau * (loads.moment + glm::cross(x_ - pin_, loads.force));
    } else {
        v_ += (tau / props_.mass) * loads.force;
        for (int k = 0; k < 3; ++k)
            if (translationFixed_[k]) v_[k] = 0.0;
        l_ += tau * loads.moment;
    }
    if (rotation_ == RotationMode::Locked) l_ = glm::dvec3(0.0);
    if (rotation_ == RotationMode::Subspace) {
        glm::dvec3 p(0.0);
        for (const auto& b : freeRotationAxes_) p += glm::dot(l_, b) * b;
        l_ = p;
    }
    updateVelocities();
}

void RigidBody::drift(double tau) {
    if (!pinned_) x_ += tau * v_;
    auto turn = [this](const glm::dvec3& axis, double angle) {
        if (angle != 0.0) q_ = glm::angleAxis(angle, axis) * q_;
    };
    switch (rotation_) {
        case RotationMode::Locked: break;
        case RotationMode::Free: {
            // Dullweber et al. 1997: exact principal-axis rotations, symmetric order.
            static constexpr int kAxis[5] = {0, 1, 2, 1, 0};
            static constexpr double kFraction[5] = {0.5, 0.5, 1.0, 0.5, 0.5};
            for (int s = 0; s < 5; ++s) {
                const int k = kAxis[s];
                const glm::dvec3 u = glm::normalize(glm::dmat3(glm::mat3_cast(q_)) * axes_[k]);
                turn(u, kFraction[s] * tau * glm::dot(l_, u) / moments_[k]);
            }
            break;
        }
        case RotationMode::Subspace: {
            const double w = glm::length(omega_);
            if (w > 0.0) turn(omega_ / w, w * tau);
            break;
        }
    }
    q_ = glm::normalize(q_);
    if (pinned_) x_ = pin_ + rotation() * (restCenter_ - pin_);
    updateVelocities();
}

RigidBody::Loads RigidBody::internalLoads(bool record) {
    Loads loads;
    loads.force = props_.mass * gravity_;
    const glm::dvec3 vertical = up(gravity_);
    for (std::size_t i = 0; i < def_.moorings.size(); ++i) {
        const MooringDef& m = def_.moorings[i];
        const glm::dvec3 p = toWorld(m.fairlead);
        const MooringReading r = mooringLoad(m, p, velocityAt(p), vertical);
        loads.force += r.force;
        loads.moment += glm::cross(p - x_, r.force);
        if (record) moorings_[i] = r;
    }
    return loads;
}

double RigidBody::stableSubstep() const {
    // Velocity Verlet is stable for ωτ < 2; 0.2 keeps a line's oscillation accurate to ~0.3 %.
    double tau = std::numeric_limits<double>::infinity();
    for (const MooringDef& m : def_.moorings) {
        // The body's effective mass at the fairlead: 1/m + r²/I_min.
        const double r = glm::length(m.fairlead - (pinned_ ? pin_ : restCenter_));
        const double invMass = (pinned_ ? 0.0 : 1.0 / props_.mass) + r * r / moments_.x;
        const double k = mooringStiffness(m);
        const double c = mooringDamping(m);
        tau = std::min(tau, 0.2 / std::sqrt(k * invMass));
        if (c > 0.0) tau = std::min(tau, 0.5 / (c * invMass));
    }
    return tau;
}

void RigidBody::step(double dt, const glm::dvec3& force, const glm::dvec3& moment) {
    if (!(dt > 0.0) || !std::isfinite(dt)) throw std::invalid_argument(def_.name + ": step dt must be > 0, got " + showd(dt));
    const double tau0 = stableSubstep();
    const int n = std::isfinite(tau0) ? std::max(1, static_cast<int>(std::ceil(dt / tau0))) : 1;
    const double tau = dt / n;
    const glm::dvec3 v0 = v_, w0 = omega_;
    for (int s = 0; s < n; ++s) {
        Loads l = internalLoads(false);
        l.force += force;
        l.moment += moment;
        kick(0.5 * tau, l);
        drift(tau);
        l = internalLoads(false);
        l.force += force;
        l.moment += moment;
        kick(0.5 * tau, l);
    }
    a_ = (v_ - v0) / dt;
    alpha_ = (omega_ - w0) / dt;
    contactForce_ = glm::dvec3(0.0);
    requireFinite();
    static_cast<void>(internalLoads(true));
}

bool RigidBody::isFinite() const {
    auto ok = [](const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    return ok(x_) && ok(v_) && ok(l_) && ok(omega_) && std::isfinite(q_.w) && std::isfinite(q_.x) &&
           std::isfinite(q_.y) && std::isfinite(q_.z);
}

void RigidBody::requireFinite() const {
    if (!isFinite())
        throw std::runtime_error(def_.name + ": the body's motion diverged (position " + showd(x_) + ", velocity " +
                                 showd(v_) + ", angular momentum " + showd(l_) + ")");
}

double RigidBody::kineticEnergy() const {
    const double rot = 0.5 * glm::dot(omega_, l_);
    return pinned_ ? rot : 0.5 * props_.mass * glm::dot(v_, v_) + rot;
}

glm::dvec3 RigidBody::toWorld(const glm::dvec3& restPoint) const { return x_ + rotation() * (restPoint - restCenter_); }

glm::dvec3 RigidBody::velocityAt(const glm::dvec3& worldPoint) const { return v_ + glm::cross(omega_, worldPoint - x_); }

glm::dvec3 RigidBody::accelerationAt(const glm::dvec3& worldPoint) const {
    const glm::dvec3 r = worldPoint - x_;
    return a_ + glm::cross(alpha_, r) + glm::cross(omega_, glm::cross(omega_, r));
}

void RigidBody::placePoints(std::span<const glm::vec3> rest, std::span<glm::vec3> positions,
                            std::span<glm::vec3> velocities, std::span<glm::vec3> accelerations) const {
    auto fits = [&rest](std::size_t n) { return n == 0 || n == rest.size(); };
    if (!fits(positions.size()) || !fits(velocities.size()) || !fits(accelerations.size()))
        throw std::invalid_argument(def_.name + ": placePoints needs as many positions, velocities and "
                                                "accelerations as rest points (or none)");
    const glm::dmat3 R = rotation();
    for (std::size_t i = 0; i < rest.size(); ++i) {
        const glm::dvec3 r = R * (glm::dvec3(rest[i]) - restCenter_);
        if (!positions.empty()) positions[i] = glm::vec3(x_ + r);
        if (!velocities.empty()) velocities[i] = glm::vec3(v_ + glm::cross(omega_, r));
        if (!accelerations.empty())
            accelerations[i] = glm::vec3(a_ + glm::cross(alpha_, r) + glm::cross(omega_, glm::cross(omega_, r)));
    }
}

std::vector<double> RigidBody::saveState() const {
    std::vector<double> s;
    s.reserve(kStateSize);
    auto put = [&s](const glm::dvec3& v) { s.insert(s.end(), {v.x, v.y, v.z}); };
    put(x_);
    s.insert(s.end(), {q_.w, q_.x, q_.y, q_.z});
    put(v_);
    put(l_);
    put(a_);
    put(alpha_);
    put(contactForce_);
    return s;
}

void RigidBody::restoreState(std::span<const double> s) {
    if (s.size() != kStateSize)
        throw std::invalid_argument(def_.name + ": body state has " + std::to_string(s.size()) + " values, expected " +
                                    std::to_string(kStateSize));
    std::size_t i = 0;
    auto get = [&s, &i]() {
        const glm::dvec3 v(s[i], s[i + 1], s[i + 2]);
        i += 3;
        return v;
    };
    x_ = get();
    q_ = glm::dquat(s[i], s[i + 1], s[i + 2], s[i + 3]);
    i += 4;
    v_ = get();
    l_ = get();
    a_ = get();
    alpha_ = get();
    contactForce_ = get();
    updateVelocities();
    static_cast<void>(internalLoads(true));
}

}  // namespace tide::bodies
