#pragma once
/// \file
/// Prescribed rigid motion of an obstacle (MotionDef): where each of its material points is
/// at time t, and how fast it moves and accelerates there. A point x0 of the obstacle at rest
/// is at x = c + d(t) + R(θ(t)) (x0 − c), R the rotation by θ about the unit axis a through the
/// pivot c. Its velocity and acceleration are those of a rigid body (r = x − c − d):
///   v = ḋ + ω × r,   a = d̈ + α × r + ω × (ω × r),   ω = θ̇ a, α = θ̈ a.
/// The World places the obstacle's boundary particles with them every step; the solvers take
/// v_b into the no-slip viscosity (2 v_b − v_i) and the density rate (Akinci et al. 2012,
/// "Versatile rigid-fluid coupling for incompressible SPH"), and a_b into the wall pressure
/// (Adami, Hu & Adams 2012, eq. 27: g − a_b).
///
/// A motion depends on time alone, so a checkpoint needs no state for it.

#include <string>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <tide/defs.hpp>

namespace tide {

/// The pose of a moving obstacle at one instant, with its rates.
struct RigidPose {
    glm::mat3 rotation{1.0f};      ///< R(θ)
    glm::vec3 center{0.0f};        ///< c, the pivot at rest, m
    glm::vec3 pivot{0.0f};         ///< c + d, where the pivot is now, m
    glm::vec3 velocity{0.0f};      ///< ḋ, m/s
    glm::vec3 acceleration{0.0f};  ///< d̈, m/s²
    glm::vec3 omega{0.0f};         ///< angular velocity θ̇ a, rad/s
    glm::vec3 alpha{0.0f};         ///< angular acceleration θ̈ a, rad/s²

    /// Where the rest-pose point x0 is now.
    [[nodiscard]] glm::vec3 place(const glm::vec3& x0) const { return pivot + rotation * (x0 - center); }
    /// The rest-pose point that is now at x.
    [[nodiscard]] glm::vec3 toRest(const glm::vec3& x) const;
    /// A direction of the rest pose, as it points now.
    [[nodiscard]] glm::vec3 rotate(const glm::vec3& direction) const { return rotation * direction; }
    /// Velocity of the obstacle's material point now at x, m/s.
    [[nodiscard]] glm::vec3 velocityAt(const glm::vec3& x) const;
    /// Acceleration of the obstacle's material point now at x, m/s².
    [[nodiscard]] glm::vec3 accelerationAt(const glm::vec3& x) const;
};

/// Displacement d and angle θ of a MotionDef and their first two time derivatives.
struct RigidState {
    glm::dvec3 offset{0.0}, velocity{0.0}, acceleration{0.0};  ///< d, ḋ, d̈
    double angle = 0.0, rate = 0.0, angularAcceleration = 0.0;  ///< θ, θ̇, θ̈
};

class RigidMotion {
public:
    /// `def` must be valid (World::addObstacle checks it): a unit axis, keys in increasing time.
    explicit RigidMotion(MotionDef def);

    [[nodiscard]] RigidState state(double t) const;
    [[nodiscard]] RigidPose pose(double t) const;
    [[nodiscard]] const MotionDef& def() const { return def_; }

private:
    [[nodiscard]] RigidState tableState(double tau) const;
    MotionDef def_;
};

/// Throws std::invalid_argument naming the field (prefixed by `path`, e.g. "obstacle.motion")
/// and value when `def` is not a usable motion; returns it with its axis normalised.
MotionDef validatedMotion(const MotionDef& def, const std::string& path);

}  // namespace tide
