#pragma once
/// \file
/// tide::bodies — rigid bodies for the fluid to move: exact mass properties of the obstacle
/// shapes, six degrees of freedom with quaternions, constraints, moorings and contact.
/// No fluid here: the World hands each body the force and moment the fluid exerts on it per
/// fluid step, and places the body's boundary particles from its pose.
///
/// Frames: a body is defined in its *rest pose* (the pose an ObstacleDef describes, world
/// coordinates). Its pose at time t maps a rest-pose point x0 to
///   x = c(t) + R(q(t)) (x0 − c0),
/// c0 the centre of mass at rest, c(t) where it is now, q the rotation from the rest pose.
/// Velocities of material points are v = V + ω × (x − c). All state is double.
///
/// Per fluid step of length dt (one body, no contact):
///   body.step(dt, fluidForce, fluidMomentAboutCentreOfMass);
/// or, for contact with walls, fixed obstacles and between bodies, through a BodySystem:
///   system.step(dt, forces, moments);
/// Gravity, moorings and contact are added inside; the fluid load is held constant over dt.

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <tide/defs.hpp>

namespace tide::bodies {

// ---------------------------------------------------------------------------------------
// Mass properties

/// Mass, centre of mass and inertia of a rigid body in its rest pose.
struct MassProperties {
    double mass = 0.0;               ///< kg
    double volume = 0.0;             ///< m³ of the geometry
    glm::dvec3 centerOfMass{0.0};    ///< m, rest pose (world axes)
    glm::dmat3 inertia{0.0};         ///< kg m², about the centre of mass, rest-pose axes
    glm::dvec3 principalMoments{0.0};  ///< eigenvalues of `inertia`, ascending, kg m²
    glm::dmat3 principalAxes{1.0};   ///< columns: the unit principal axes (right-handed), rest-pose axes
};

/// Eigen-decomposition of a symmetric inertia tensor (cyclic Jacobi, in double): moments
/// ascending, axes as the columns of a proper rotation.
void computePrincipalAxes(MassProperties& props);

/// Exact mass properties of a solid of uniform `density` (kg/m³, > 0).
MassProperties boxMassProperties(const glm::dvec3& min, const glm::dvec3& max, double density);
MassProperties sphereMassProperties(const glm::dvec3& center, double radius, double density);
/// A flat-capped cylinder: `length` cap to cap along the unit `axis`.
MassProperties cylinderMassProperties(const glm::dvec3& center, const glm::dvec3& axis, double radius,
                                      double length, double density);
/// A closed triangle mesh by the divergence theorem (Eberly 2002, "Polyhedral mass
/// properties (revisited)", after Mirtich 1996): exact for the polyhedron.
MassProperties meshMassProperties(const TriangleMesh& mesh, double density);
/// The shape of an obstacle (box, sphere, cylinder, mesh; not a plane, not moving), as above.
/// Throws std::invalid_argument naming `path` for a plane or degenerate dimensions.
MassProperties obstacleMassProperties(const ObstacleDef& shape, double density,
                                      const std::string& path = "obstacle");

// ---------------------------------------------------------------------------------------
// Constraints

/// What a body may do. Fixed axes are world axes; a hinge or a fixed point is a point of
/// the body pinned in space (its rest-pose position).
struct ConstraintDef {
    enum class Type {
        Free,       ///< six degrees of freedom
        FixedAxes,  ///< the flagged translations / rotations (world x, y, z) are locked
        Hinge,      ///< rotation about `axis` through `point` only
        Point,      ///< a ball joint at `point`: rotation only
    };
    Type type = Type::Free;
    std::array<bool, 3> fixedTranslation{false, false, false};  ///< x, y, z (FixedAxes)
    std::array<bool, 3> fixedRotation{false, false, false};     ///< about x, y, z (FixedAxes)
    glm::dvec3 point{0.0};           ///< pinned point, m (Hinge, Point)
    glm::dvec3 axis{0.0, 0.0, 1.0};  ///< hinge axis (normalised when the body is made)
};

/// Constraint locking the named axes: "x", "y", "z" (translations), "rx", "ry", "rz"
/// (rotations about them). Throws std::invalid_argument naming `path` and an unknown axis.
ConstraintDef fixedAxes(const std::vector<std::string>& axes, const std::string& path = "constraint.fixed");
/// Constraint leaving only the named axes free, e.g. {"y"} (heave only) or {"x", "y", "rz"}
/// (2D motion in x–y). Same names and errors as fixedAxes().
ConstraintDef freeAxes(const std::vector<std::string>& axes, const std::string& path = "constraint.free");

// ---------------------------------------------------------------------------------------
// Moorings

/// An elastic line from a point of the body to a fixed anchor.
struct MooringDef {
    enum class Type {
        Spring,    ///< straight linear spring with slack: tension k (ℓ − L) when ℓ > L, else 0
        Catenary,  ///< quasi-static elastic catenary, seabed contact at the anchor (Jonkman 2007)
    };
    Type type = Type::Spring;
    std::string name;                ///< for errors and output (default mooring<k>)
    glm::dvec3 fairlead{0.0};        ///< the body's point, m, rest pose
    glm::dvec3 anchor{0.0};          ///< fixed anchor, m (Catenary: on the seabed)
    double length = 0.0;             ///< unstretched length L, m (> 0)
    double stiffness = 0.0;          ///< Spring: k, N/m (> 0)
    double damping = 0.0;            ///< Spring: c, N s/m along the line while taut (≥ 0)
    double axialStiffness = 0.0;     ///< Catenary: EA, N (> 0)
    double weightPerLength = 0.0;    ///< Catenary: submerged weight w, N/m (> 0)
};

/// A line's state after the last step.
struct MooringReading {
    double tension = 0.0;          ///< at the fairlead, N
    glm::dvec3 force{0.0};         ///< on the body at the fairlead, N
    double horizontalTension = 0.0;  ///< Catenary: H, N (Spring: the horizontal part)
    double verticalTension = 0.0;    ///< Catenary: V at the fairlead, N (Spring: the vertical part)
};

/// The fairlead tension of an elastic catenary (Jonkman 2007, NREL/TP-500-41958, eqs. 2-1, 2-2
/// hanging freely and 2-3, 2-4 resting on the seabed, without seabed friction): horizontal
/// span `span` (≥ 0) and rise `rise` (> 0) of the fairlead over the anchor. Returns {H, V}.
/// Throws std::runtime_error when Newton's method does not converge.
std::array<double, 2> solveCatenary(double span, double rise, double length, double axialStiffness,
                                    double weightPerLength);

// ---------------------------------------------------------------------------------------
// Contact (BodySystem)

/// Penalty contact of a body (spring–dashpot normal force per contact point, Coulomb
/// friction through a tangential spring). Zero means "choose from the body's mass and size".
struct ContactDef {
    bool enabled = true;
    double stiffness = 0.0;      ///< N/m per contact point; 0: m g / (4 · 1e-3 · size)
    double dampingRatio = 1.0;   ///< of the normal spring, per point
    double friction = 0.5;       ///< Coulomb coefficient μ
    /// The gap, m, at which surfaces touch. A body in a fluid sets it to the particle spacing:
    /// a film thinner than one particle cannot be resolved, and the particles squeezed into it
    /// kicked a landing box back up (World sets it; 0 for bodies alone).
    double distance = 0.0;
};

// ---------------------------------------------------------------------------------------
// Bodies

/// A rigid body: its shape in the rest pose, and how it is made to move.
struct BodyDef {
    std::string name = "body";                ///< used in errors
    ObstacleDef shape;                        ///< box, sphere, cylinder or mesh; its rest pose
    std::optional<double> density;            ///< kg/m³ (exactly one of density, mass)
    std::optional<double> mass;               ///< kg
    std::optional<glm::dvec3> centerOfMass;   ///< m, rest pose; default the geometry's
    std::optional<glm::dmat3> inertia;        ///< kg m² about the centre of mass, rest-pose axes
    glm::dvec3 velocity{0.0};                 ///< initial V of the centre of mass, m/s
    glm::dvec3 angularVelocity{0.0};          ///< initial ω, rad/s
    ConstraintDef constraint;
    std::vector<MooringDef> moorings;
    ContactDef contact;
};

/// One rigid body and its integrator. Translation: velocity Verlet; rotation: the angular
/// momentum L (world) is the state, kicked by the torque, and the torque-free rotation is
/// the symplectic splitting of the free rotor into exact rotations about the principal axes,
/// R1(τ/2) R2(τ/2) R3(τ) R2(τ/2) R1(τ/2) (Dullweber, Leimkuhler & McLachlan 1997, J. Chem.
/// Phys. 107, 5840, "NO_SQUISH"): |L| is kept to round-off and the energy without drift.
class RigidBody {
public:
    /// Validates `def` (std::invalid_argument naming `def.name` and the field at fault).
    RigidBody(const BodyDef& def, const glm::dvec3& gravity);

    /// Advance by dt (s) under the fluid's `force` (N) and `moment` (N m, about the centre of
    /// mass, world axes), held constant over dt; gravity and moorings are added inside,
    /// sub-stepping when a mooring line is stiff. No contact (see BodySystem). Throws
    /// std::runtime_error naming the body when its pose or velocity is no longer finite.
    void step(double dt, const glm::dvec3& force, const glm::dvec3& moment);

    // Pose and rates (after the last step)
    [[nodiscard]] const glm::dvec3& position() const { return x_; }        ///< centre of mass c, m
    [[nodiscard]] const glm::dquat& orientation() const { return q_; }     ///< q, rest pose → now
    [[nodiscard]] const glm::dvec3& velocity() const { return v_; }        ///< V, m/s
    [[nodiscard]] glm::dvec3 angularVelocity() const;                     ///< ω, rad/s, world
    [[nodiscard]] const glm::dvec3& angularMomentum() const { return l_; }  ///< about c (or the pin), world
    [[nodiscard]] const glm::dvec3& acceleration() const { return a_; }    ///< mean over the last step, m/s²
    [[nodiscard]] const glm::dvec3& angularAcceleration() const { return alpha_; }  ///< rad/s²
    [[nodiscard]] glm::dmat3 rotation() const;                             ///< R(q)
    [[nodiscard]] double kineticEnergy() const;                            ///< J
    [[nodiscard]] bool isFinite() const;                                   ///< pose and rates all finite

    /// Where the rest-pose point x0 is now.
    [[nodiscard]] glm::dvec3 toWorld(const glm::dvec3& restPoint) const;
    /// Velocity of the body's material point now at x: V + ω × (x − c).
    [[nodiscard]] glm::dvec3 velocityAt(const glm::dvec3& worldPoint) const;
    /// Acceleration of the material point now at x: A + α × r + ω × (ω × r).
    [[nodiscard]] glm::dvec3 accelerationAt(const glm::dvec3& worldPoint) const;
    /// Places rest-pose points (e.g. boundary particles) at the current pose, with their
    /// velocities and accelerations; each span has rest.size() entries or is empty (skipped).
    /// (Inside tide, bodies/body_pose.hpp gives the same pose as a RigidPose.)
    void placePoints(std::span<const glm::vec3> rest, std::span<glm::vec3> positions,
                     std::span<glm::vec3> velocities = {}, std::span<glm::vec3> accelerations = {}) const;

    [[nodiscard]] const MassProperties& massProperties() const { return props_; }
    [[nodiscard]] const BodyDef& def() const { return def_; }
    [[nodiscard]] const std::vector<MooringReading>& moorings() const { return moorings_; }
    /// Total contact force over the last step (time mean), N (BodySystem only).
    [[nodiscard]] const glm::dvec3& contactForce() const { return contactForce_; }

    /// Everything that evolves, as doubles; restoreState() into a body made from the same
    /// BodyDef continues bit for bit. Throws std::invalid_argument on a wrong length.
    [[nodiscard]] std::vector<double> saveState() const;
    void restoreState(std::span<const double> state);
    static constexpr std::size_t kStateSize = 3 + 4 + 3 + 3 + 3 + 3 + 3;

private:
    friend class BodySystem;
    enum class RotationMode { Free, Locked, Subspace };
    struct Loads {
        glm::dvec3 force{0.0};
        glm::dvec3 moment{0.0};  // about the centre of mass
    };

    void kick(double tau, const Loads& loads);
    void drift(double tau);
    void updateVelocities();
    [[nodiscard]] Loads internalLoads(bool record);
    [[nodiscard]] double stableSubstep() const;
    void requireFinite() const;

    BodyDef def_;
    MassProperties props_;
    glm::dvec3 gravity_{0.0};
    glm::dvec3 restCenter_{0.0};       // c0
    bool pinned_ = false;              // Hinge or Point: rotates about pin_
    glm::dvec3 pin_{0.0};
    glm::dmat3 inertiaRest_{0.0};      // about the rotation centre (c or pin), rest axes
    glm::dvec3 moments_{0.0};          // its principal moments
    glm::dmat3 axes_{1.0};             // its principal axes (rest)
    RotationMode rotation_ = RotationMode::Free;
    std::vector<glm::dvec3> freeRotationAxes_;  // world, orthonormal (Subspace)
    std::array<bool, 3> translationFixed_{false, false, false};
    double characteristicSize_ = 0.0;

    // State
    glm::dvec3 x_{0.0};
    glm::dquat q_{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 v_{0.0};
    glm::dvec3 l_{0.0};
    glm::dvec3 omega_{0.0};
    glm::dvec3 a_{0.0};
    glm::dvec3 alpha_{0.0};
    glm::dvec3 contactForce_{0.0};
    std::vector<MooringReading> moorings_;
};

/// Bodies with contact among themselves, with the walls of the domain box and with fixed
/// obstacles (half-spaces and any shape). Penalty contact, sub-stepped to be stable.
class BodySystem {
public:
    explicit BodySystem(const glm::dvec3& gravity);
    ~BodySystem();
    BodySystem(BodySystem&&) noexcept;
    BodySystem& operator=(BodySystem&&) noexcept;

    /// Bodies stay inside the box [min, max] (its six faces are walls).
    void setWalls(const glm::dvec3& min, const glm::dvec3& max);
    /// A fixed collider: a half-space (Plane) or a box, sphere, cylinder or mesh at rest;
    /// `name` is used in errors (default obstacle<k>, k counting fixed obstacles).
    void addFixedObstacle(const ObstacleDef& obstacle, const std::string& name = "");
    /// Adds a body; returns its index.
    std::size_t addBody(const BodyDef& def);

    /// Throws std::invalid_argument naming the body and what it meets when a body pokes
    /// deeper than `tolerance` (m) through a wall or a fixed obstacle or into another body, or
    /// a mooring anchor lies outside the walls. Call once after adding everything.
    void validatePlacement(double tolerance = 0.0) const;

    [[nodiscard]] std::size_t size() const;
    [[nodiscard]] RigidBody& body(std::size_t i);
    [[nodiscard]] const RigidBody& body(std::size_t i) const;

    /// Advance every body by dt under its fluid force and moment (about its centre of mass,
    /// world axes; one each per body, or empty spans for none). Throws std::runtime_error
    /// naming a body whose motion diverged.
    void step(double dt, std::span<const glm::dvec3> forces, std::span<const glm::dvec3> moments);

    /// All bodies' states (see RigidBody::saveState) and the contacts' friction springs;
    /// restoreState() into a system built the same way continues bit for bit. Its length
    /// varies with the contacts.
    [[nodiscard]] std::vector<double> saveState() const;
    void restoreState(std::span<const double> state);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace tide::bodies
