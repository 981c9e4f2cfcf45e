// Rigid bodies without fluid (issue 44, acceptance 1 and the kernel's parts): exact mass
// properties, free motion (thrown, torque-free rotation), constraints, moorings, contact and
// checkpoints of tide::bodies.
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <tide/bodies.hpp>
#include <tide/triangle_mesh.hpp>

#include "bodies/body_pose.hpp"

namespace {

using namespace tide;
using namespace tide::bodies;

/// The box [lo, hi] as 12 outward triangles, turned by `rot` about `pivot`.
std::shared_ptr<const TriangleMesh> boxMesh(const glm::vec3& lo, const glm::vec3& hi,
                                            const glm::mat3& rot = glm::mat3(1.0f), const glm::vec3& pivot = {}) {
    std::vector<glm::vec3> v;
    for (int k = 0; k < 8; ++k)
        v.push_back(pivot + rot * (glm::vec3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z) - pivot));
    std::vector<glm::uvec3> t{{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                              {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return std::make_shared<const TriangleMesh>(v, t);
}

/// A closed prism of `n` sides approximating a cylinder along the unit `axis`.
std::shared_ptr<const TriangleMesh> cylinderMesh(const glm::dvec3& c, const glm::dvec3& axis, double r, double len,
                                                 int n) {
    const glm::dvec3 a = glm::normalize(axis);
    const glm::dvec3 e1 = glm::normalize(glm::cross(a, glm::dvec3(1, 0, 0)));
    const glm::dvec3 e2 = glm::cross(a, e1);
    std::vector<glm::vec3> v{glm::vec3(c - 0.5 * len * a), glm::vec3(c + 0.5 * len * a)};
    for (int s = 0; s < 2; ++s)
        for (int k = 0; k < n; ++k) {
            const double phi = 2.0 * M_PI * k / n;
            v.emplace_back(c + (s ? 0.5 : -0.5) * len * a + r * (std::cos(phi) * e1 + std::sin(phi) * e2));
        }
    auto ring = [n](int s, int k) { return static_cast<unsigned>(2 + s * n + (k % n)); };
    std::vector<glm::uvec3> t;
    for (int k = 0; k < n; ++k) {
        t.emplace_back(0u, ring(0, k + 1), ring(0, k));
        t.emplace_back(1u, ring(1, k), ring(1, k + 1));
        t.emplace_back(ring(0, k), ring(0, k + 1), ring(1, k));
        t.emplace_back(ring(0, k + 1), ring(1, k + 1), ring(1, k));
    }
    return std::make_shared<const TriangleMesh>(v, t);
}

ObstacleDef box(const glm::vec3& lo, const glm::vec3& hi) {
    ObstacleDef o;
    o.shape = ObstacleDef::Shape::Box;
    o.min = lo;
    o.max = hi;
    return o;
}

double maxRelDiff(const glm::dmat3& a, const glm::dmat3& b) {
    double scale = 0.0, diff = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) {
            scale = std::max(scale, std::abs(b[c][r]));
            diff = std::max(diff, std::abs(a[c][r] - b[c][r]));
        }
    return diff / scale;
}

glm::dmat3 rotationFrom(const glm::dquat& q) { return glm::mat3_cast(q); }

// ---------------------------------------------------------------------------------------
// Mass properties

TEST(MassProperties, IdenticalCubesHaveTheAnalyticInertia) {
    // Three cubes of side 0.125 m at different places: identical inertia m a²/6, bit for bit
    // (no particles are involved; dyadic sizes make the float corners exact).
    const double rho = 700.0, a = 0.125, m = rho * a * a * a;
    const glm::vec3 corners[3] = {{0.25f, 0.5f, 0.75f}, {1.0f, 0.0f, 0.375f}, {-2.0f, 3.5f, 0.0f}};
    for (const auto& c : corners) {
        const MassProperties p = obstacleMassProperties(box(c, c + glm::vec3(0.125f)), rho);
        EXPECT_EQ(p.mass, m);
        for (int i = 0; i < 3; ++i) {
            EXPECT_EQ(p.inertia[i][i], m * a * a / 6.0);
            for (int j = 0; j < 3; ++j)
                if (i != j) {
                    EXPECT_EQ(p.inertia[i][j], 0.0);
                }
        }
    }
    // Arbitrary placement in float: the same to the float rounding of the corners.
    const MassProperties p1 = obstacleMassProperties(box({0.1f, 0.2f, 0.3f}, {0.2f, 0.3f, 0.4f}), rho);
    const MassProperties p2 = obstacleMassProperties(box({1.7f, 0.9f, 2.3f}, {1.8f, 1.0f, 2.4f}), rho);
    EXPECT_LT(maxRelDiff(p1.inertia, p2.inertia), 1e-5);  // float corners: ~1e-7 relative per side
}

TEST(MassProperties, BoxMeshEqualsTheAnalyticBox) {
    const glm::vec3 lo(0.3f, 0.1f, -0.2f), hi(0.5f, 0.4f, 0.3f);
    const double rho = 1234.0;
    const MassProperties analytic = obstacleMassProperties(box(lo, hi), rho);
    ObstacleDef mesh;
    mesh.shape = ObstacleDef::Shape::Mesh;
    mesh.mesh = boxMesh(lo, hi);
    const MassProperties p = obstacleMassProperties(mesh, rho);
    EXPECT_NEAR(p.mass / analytic.mass, 1.0, 1e-6);
    EXPECT_LT(glm::length(p.centerOfMass - analytic.centerOfMass), 1e-7);
    EXPECT_LT(maxRelDiff(p.inertia, analytic.inertia), 1e-6);
    // A cube turned by 30° about an oblique axis: a cube's inertia is isotropic, so it is
    // still m a²/6 · 1 — a check of the off-diagonal integrals.
    const glm::vec3 cLo(0.0f), cHi(0.25f);
    const glm::mat3 rot = glm::mat3_cast(glm::angleAxis(0.5236f, glm::normalize(glm::vec3(1, 2, 3))));
    mesh.mesh = boxMesh(cLo, cHi, rot, glm::vec3(0.125f));
    const MassProperties turned = obstacleMassProperties(mesh, rho);
    const MassProperties cube = obstacleMassProperties(box(cLo, cHi), rho);
    EXPECT_LT(maxRelDiff(turned.inertia, cube.inertia), 1e-6);
    EXPECT_LT(glm::length(turned.centerOfMass - glm::dvec3(0.125)), 1e-7);
}

TEST(MassProperties, PrincipalAxesOfATurnedBox) {
    // A 0.1 × 0.2 × 0.4 box turned by 40° about z: the principal axes are the turned box axes.
    const glm::vec3 lo(0.0f), hi(0.1f, 0.2f, 0.4f);
    const glm::dquat q = glm::angleAxis(0.7, glm::dvec3(0, 0, 1));
    ObstacleDef mesh;
    mesh.shape = ObstacleDef::Shape::Mesh;
    mesh.mesh = boxMesh(lo, hi, glm::mat3(rotationFrom(q)), glm::vec3(0.05f, 0.1f, 0.2f));
    const MassProperties p = obstacleMassProperties(mesh, 1000.0);
    const MassProperties ref = obstacleMassProperties(box(lo, hi), 1000.0);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.principalMoments[k] / ref.principalMoments[k], 1.0, 1e-6);
    const glm::dmat3 R = rotationFrom(q);
    // Ascending moments: the longest side (z) has the smallest moment, then y, then x.
    const glm::dvec3 expected[3] = {R * glm::dvec3(0, 0, 1), R * glm::dvec3(0, 1, 0), R * glm::dvec3(1, 0, 0)};
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(std::abs(glm::dot(p.principalAxes[k], expected[k])), 1.0, 1e-9);
    EXPECT_NEAR(glm::determinant(p.principalAxes), 1.0, 1e-12);
}

TEST(MassProperties, CylinderFormulaMatchesAFineMeshOnAnObliqueAxis) {
    const glm::dvec3 c(0.2, 0.3, 0.1), axis(1.0, 2.0, -0.5);
    const double r = 0.05, len = 0.3, rho = 900.0;
    const MassProperties exact = cylinderMassProperties(c, axis, r, len, rho);
    ObstacleDef mesh;
    mesh.shape = ObstacleDef::Shape::Mesh;
    mesh.mesh = cylinderMesh(c, axis, r, len, 512);
    const MassProperties p = obstacleMassProperties(mesh, rho);
    // A 512-gon holds 1 − sin(2π/n)/(2π/n) ≈ 2.5e-5 less area than its circle.
    EXPECT_NEAR(p.mass / exact.mass, 1.0, 1e-4);
    EXPECT_LT(maxRelDiff(p.inertia, exact.inertia), 2e-4);
    const double sphere = 0.4 * rho * 4.0 / 3.0 * M_PI * r * r * r * r * r;
    EXPECT_NEAR(sphereMassProperties(c, r, rho).inertia[1][1] / sphere, 1.0, 1e-14);
}

// ---------------------------------------------------------------------------------------
// Free motion

BodyDef cubeBody(double density, const glm::vec3& lo, float side) {
    BodyDef def;
    def.shape = box(lo, lo + glm::vec3(side));
    def.density = density;
    return def;
}

TEST(RigidBody, ThrownBodyKeepsItsPointsOnItsOwnMotion) {
    // Thrown at 1 m/s (45° up) and spinning at 3 rad/s about z under gravity, 10⁴ steps of
    // 1e-4 s: every boundary point placed from the pose lies on the analytic motion
    // c0 + V t + ½ g t² + R_z(ω t)(x0 − c0) to 1e-6 m, and moves with v = V + g t + ω × r.
    BodyDef def = cubeBody(500.0, {0.2f, 0.3f, 0.4f}, 0.1f);
    def.shape.max.z = 0.6f;  // a 0.1 × 0.1 × 0.2 box: z is a principal axis
    def.velocity = glm::dvec3(std::sqrt(0.5), std::sqrt(0.5), 0.0);
    def.angularVelocity = glm::dvec3(0.0, 0.0, 3.0);
    const glm::dvec3 g(0.0, -9.81, 0.0);
    RigidBody body(def, g);
    std::vector<glm::vec3> rest;  // boundary particles: a 0.01 m lattice on and inside the surface
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j)
            for (int k = 0; k <= 20; ++k)
                if (i % 10 == 0 || j % 10 == 0 || k % 20 == 0 || (i + j + k) % 7 == 0)
                    rest.emplace_back(0.2f + 0.01f * i, 0.3f + 0.01f * j, 0.4f + 0.01f * k);
    const glm::dvec3 c0 = body.position();
    const double dt = 1e-4;
    const int steps = 10000;
    std::vector<glm::vec3> x(rest.size()), v(rest.size());
    double worst = 0.0, worstV = 0.0;
    for (int s = 1; s <= steps; ++s) {
        body.step(dt, glm::dvec3(0.0), glm::dvec3(0.0));
        if (s % 1000 != 0) continue;
        const double t = s * dt;
        const glm::dvec3 c = c0 + def.velocity * t + 0.5 * g * t * t;
        const glm::dmat3 R = rotationFrom(glm::angleAxis(3.0 * t, glm::dvec3(0, 0, 1)));
        body.placePoints(rest, x, v);
        for (std::size_t i = 0; i < rest.size(); ++i) {
            const glm::dvec3 r = R * (glm::dvec3(rest[i]) - c0);
            worst = std::max(worst, glm::length(glm::dvec3(x[i]) - (c + r)));
            worst = std::max(worst, glm::length(body.toWorld(glm::dvec3(rest[i])) - (c + r)));
            const glm::dvec3 vExact = def.velocity + g * t + glm::cross(glm::dvec3(0, 0, 3.0), r);
            worstV = std::max(worstV, glm::length(glm::dvec3(v[i]) - vExact));
        }
    }
    EXPECT_LT(worst, 1e-6);
    EXPECT_LT(worstV, 1e-6);
    // The same pose as the moving obstacles' RigidPose, with its acceleration g (float).
    const RigidPose pose = poseOf(body);
    std::vector<glm::vec3> acc(rest.size());
    body.placePoints(rest, x, {}, acc);
    for (std::size_t i = 0; i < rest.size(); i += 97) {
        EXPECT_LT(glm::length(pose.place(rest[i]) - x[i]), 1e-6f);
        EXPECT_LT(glm::length(pose.velocityAt(x[i]) - v[i]), 1e-5f);
        EXPECT_LT(glm::length(pose.accelerationAt(x[i]) - acc[i]), 1e-4f);
        const glm::dvec3 r = glm::dvec3(x[i]) - body.position();
        const glm::dvec3 aExact = g - 9.0 * glm::dvec3(r.x, r.y, 0.0);  // centripetal ω² r about z
        EXPECT_LT(glm::length(glm::dvec3(acc[i]) - aExact), 1e-4);
    }
}

TEST(RigidBody, TorqueFreeAsymmetricBodyKeepsItsAngularMomentum) {
    // I = diag(1, 2, 3), spinning mostly about the unstable middle axis, 10⁴ steps of 1e-3 s.
    BodyDef def = cubeBody(1.0, {0, 0, 0}, 1.0f);
    def.density.reset();
    def.mass = 1.0;
    def.inertia = glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 2, 0), glm::dvec3(0, 0, 3));
    def.angularVelocity = glm::dvec3(0.05, 1.0, 0.05);
    RigidBody body(def, glm::dvec3(0.0));
    const glm::dvec3 L0 = body.angularMomentum();
    const double E0 = body.kineticEnergy();
    double worstL = 0.0, worstE = 0.0;
    // Reference: Euler's equations in the body frame by RK4 at a 20× finer step.
    glm::dvec3 w = def.angularVelocity;
    const glm::dvec3 I(1, 2, 3);
    auto euler = [&I](const glm::dvec3& o) {
        return glm::dvec3((I.y - I.z) * o.y * o.z / I.x, (I.z - I.x) * o.z * o.x / I.y, (I.x - I.y) * o.x * o.y / I.z);
    };
    const double dt = 1e-3;
    for (int s = 0; s < 10000; ++s) {
        body.step(dt, glm::dvec3(0.0), glm::dvec3(0.0));
        worstL = std::max(worstL, std::abs(glm::length(body.angularMomentum()) - glm::length(L0)) / glm::length(L0));
        worstE = std::max(worstE, std::abs(body.kineticEnergy() - E0) / E0);
        for (int k = 0; k < 20; ++k) {
            const double h = dt / 20;
            const glm::dvec3 k1 = euler(w), k2 = euler(w + 0.5 * h * k1), k3 = euler(w + 0.5 * h * k2),
                             k4 = euler(w + h * k3);
            w += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        }
    }
    EXPECT_LT(worstL, 1e-6);
    EXPECT_LT(glm::length(body.angularMomentum() - L0), 1e-12);
    EXPECT_LT(worstE, 1e-7) << "the splitting's energy error is O(dt²), bounded (measured 7e-9)";
    // ω in the body frame after 10 s (a flip of the middle axis happens within it).
    const glm::dvec3 wBody = glm::transpose(body.rotation()) * body.angularVelocity();
    EXPECT_LT(glm::length(wBody - w) / glm::length(w), 1e-3) << wBody.x << ' ' << wBody.y << ' ' << wBody.z;
}

// ---------------------------------------------------------------------------------------
// Constraints

TEST(Constraints, HeaveOnlyMovesOnlyInY) {
    BodyDef def = cubeBody(500.0, {0.3f, 0.4f, 0.5f}, 0.2f);
    def.constraint = freeAxes({"y"});
    def.velocity = glm::dvec3(1.0, 0.5, -1.0);
    def.angularVelocity = glm::dvec3(1.0, 2.0, 3.0);
    const glm::dvec3 g(0.0, -9.81, 0.0);
    RigidBody body(def, g);
    const glm::dvec3 c0 = body.position();
    const double m = body.massProperties().mass;
    const glm::dvec3 F(3.0, 20.0, -1.0), M(0.5, -0.2, 0.3);
    const double dt = 1e-3;
    for (int s = 0; s < 1000; ++s) body.step(dt, F, M);
    EXPECT_EQ(body.position().x, c0.x);
    EXPECT_EQ(body.position().z, c0.z);
    EXPECT_EQ(body.orientation(), glm::dquat(1, 0, 0, 0));
    const double t = 1.0, ay = F.y / m + g.y;
    EXPECT_NEAR(body.position().y, c0.y + 0.5 * t + 0.5 * ay * t * t, 1e-9);
}

TEST(Constraints, PlanarMotionTurnsOnlyAboutZ) {
    // 2D: x, y and rotation about z free. A box turned off the axes (a mesh) so that its
    // principal axes are oblique: a moment with x and y parts must still turn it about z only.
    ObstacleDef mesh;
    mesh.shape = ObstacleDef::Shape::Mesh;
    mesh.mesh = boxMesh({0, 0, 0}, {0.1f, 0.2f, 0.3f},
                        glm::mat3_cast(glm::angleAxis(0.4f, glm::normalize(glm::vec3(1, 1, 0)))), {0.05f, 0.1f, 0.15f});
    BodyDef def;
    def.shape = mesh;
    def.density = 800.0;
    def.constraint = freeAxes({"x", "y", "rz"});
    RigidBody body(def, glm::dvec3(0.0, -9.81, 0.0));
    const double z0 = body.position().z;
    const glm::dvec3 M(0.3, -0.4, 0.05);
    for (int s = 0; s < 2000; ++s) body.step(1e-3, glm::dvec3(0.5, 0.0, 2.0), M);
    EXPECT_EQ(body.position().z, z0);
    EXPECT_EQ(body.orientation().x, 0.0);
    EXPECT_EQ(body.orientation().y, 0.0);
    EXPECT_GT(std::abs(body.orientation().z), 0.01);  // it did turn
    // About a fixed axis ω̇ = M_z / I_zz exactly.
    const double Izz = body.massProperties().inertia[2][2];
    EXPECT_NEAR(body.angularVelocity().z, M.z / Izz * 2.0, 1e-9 * M.z / Izz * 2.0);
}

TEST(Constraints, TwoFreeRotationsNeverSpinAboutTheLockedAxis) {
    // Rotation about z locked, about x and y free: ω has no z part, whatever the moment, and
    // a torque-free body keeps the free components of its angular momentum.
    BodyDef def = cubeBody(700.0, {0.0f, 0.0f, 0.0f}, 0.1f);
    def.shape.max.y = 0.3f;
    def.constraint = fixedAxes({"rz"});
    def.angularVelocity = glm::dvec3(1.0, 0.5, 2.0);
    RigidBody body(def, glm::dvec3(0.0));
    EXPECT_EQ(body.angularVelocity().z, 0.0);
    const glm::dvec3 L0 = body.angularMomentum();
    for (int s = 0; s < 2000; ++s) {
        body.step(1e-3, glm::dvec3(0.0), glm::dvec3(0.0));
        ASSERT_EQ(body.angularVelocity().z, 0.0);
    }
    EXPECT_LT(glm::length(body.angularMomentum() - L0), 1e-15);
    for (int s = 0; s < 1000; ++s) {
        body.step(1e-3, glm::dvec3(0.0), glm::dvec3(0.01, -0.02, 0.5));
        ASSERT_EQ(body.angularVelocity().z, 0.0);
    }
    EXPECT_TRUE(body.isFinite());
}

TEST(Constraints, HingeKeepsItsPointFixedAndSwingsWithThePendulumPeriod) {
    // A 0.1 × 0.4 × 0.1 box hinged about z at its top face centre, released at 3°.
    BodyDef def;
    def.shape = box({-0.05f, -0.4f, -0.05f}, {0.05f, 0.0f, 0.05f});
    def.density = 1000.0;
    def.constraint.type = ConstraintDef::Type::Hinge;
    def.constraint.point = glm::dvec3(0.0);
    def.constraint.axis = glm::dvec3(0, 0, 2);
    const double theta0 = 3.0 * M_PI / 180.0;
    // Release at θ0: put the pin at the origin and tilt by giving gravity the angle instead.
    const glm::dvec3 g = 9.81 * glm::dvec3(std::sin(theta0), -std::cos(theta0), 0.0);
    RigidBody body(def, g);
    const double m = body.massProperties().mass, d = 0.2;
    const double Ip = body.massProperties().inertia[2][2] + m * d * d;
    const double period = 2.0 * M_PI * std::sqrt(Ip / (m * 9.81 * d));
    const double dt = 1e-4;
    double worstPin = 0.0, lastCross = -1.0, firstCross = -1.0, prev = 0.0;
    int crossings = 0;
    const double E0 = body.kineticEnergy() - m * glm::dot(g, body.position());
    double worstE = 0.0;
    for (int s = 1; s <= 30000; ++s) {
        body.step(dt, glm::dvec3(0.0), glm::dvec3(0.0));
        worstPin = std::max(worstPin, glm::length(body.toWorld(glm::dvec3(0.0))));
        worstE = std::max(worstE, std::abs(body.kineticEnergy() - m * glm::dot(g, body.position()) - E0));
        // The swing angle relative to the tilted vertical: zero crossings of ω_z's sign change.
        const double w = body.angularVelocity().z;
        if (s > 1 && (w > 0) != (prev > 0)) {
            const double t = s * dt - dt * w / (w - prev);
            if (firstCross < 0) firstCross = t;
            lastCross = t;
            ++crossings;
        }
        prev = w;
        EXPECT_EQ(body.orientation().x, 0.0);
        EXPECT_EQ(body.orientation().y, 0.0);
    }
    EXPECT_LT(worstPin, 1e-12);
    ASSERT_GE(crossings, 4);
    const double measured = 2.0 * (lastCross - firstCross) / (crossings - 1);
    // Small-angle period; at 3° the exact period is longer by θ0²/16 = 0.017 %.
    EXPECT_NEAR(measured / period, 1.0 + theta0 * theta0 / 16.0, 1e-3);
    EXPECT_LT(worstE, 1e-6 * m * 9.81 * d);
}

TEST(Constraints, BallJointKeepsItsPoint) {
    BodyDef def = cubeBody(700.0, {0.0f, -0.3f, 0.0f}, 0.1f);
    def.constraint.type = ConstraintDef::Type::Point;
    def.constraint.point = glm::dvec3(0.0, 0.0, 0.0);
    def.angularVelocity = glm::dvec3(0.5, 1.0, 2.0);
    RigidBody body(def, glm::dvec3(0.0, -9.81, 0.0));
    double worst = 0.0;
    for (int s = 0; s < 5000; ++s) {
        body.step(1e-3, glm::dvec3(0.3, 0.0, 0.0), glm::dvec3(0.0, 0.01, 0.0));
        worst = std::max(worst, glm::length(body.toWorld(glm::dvec3(0.0))));
        worst = std::max(worst, glm::length(body.velocityAt(body.toWorld(glm::dvec3(0.0)))));
    }
    EXPECT_LT(worst, 1e-12);
}

TEST(Constraints, BadInputIsRefusedNamingTheField) {
    auto message = [](auto&& make) {
        try {
            make();
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string axis = message([] { static_cast<void>(fixedAxes({"x", "w"}, "box.constraint.fixed")); });
    EXPECT_NE(axis.find("box.constraint.fixed[1]"), std::string::npos) << axis;
    EXPECT_NE(axis.find("\"w\""), std::string::npos) << axis;
    const std::string mass = message([] {
        BodyDef d = cubeBody(1.0, {0, 0, 0}, 0.1f);
        d.name = "crate";
        d.density.reset();
        d.mass = -2.0;
        RigidBody b(d, glm::dvec3(0.0));
    });
    EXPECT_NE(mass.find("crate.mass"), std::string::npos) << mass;
    EXPECT_NE(mass.find("-2"), std::string::npos) << mass;
    const std::string density = message([] {
        BodyDef d = cubeBody(0.0, {0, 0, 0}, 0.1f);
        d.name = "crate";
        RigidBody b(d, glm::dvec3(0.0));
    });
    EXPECT_NE(density.find("crate.density: must be > 0, got 0"), std::string::npos) << density;
    const std::string both = message([] {
        BodyDef d = cubeBody(500.0, {0, 0, 0}, 0.1f);
        d.mass = 1.0;
        RigidBody b(d, glm::dvec3(0.0));
    });
    EXPECT_NE(both.find("exactly one of density and mass"), std::string::npos) << both;
    const std::string spring = message([] {
        BodyDef d = cubeBody(500.0, {0, 0, 0}, 0.1f);
        MooringDef m;
        m.length = 1.0;
        m.stiffness = -5.0;
        d.moorings.push_back(m);
        RigidBody b(d, glm::dvec3(0.0));
    });
    EXPECT_NE(spring.find("body.moorings[0].stiffness"), std::string::npos) << spring;
}

// ---------------------------------------------------------------------------------------
// Moorings

TEST(Moorings, SpringStretchesByWeightOverStiffness) {
    // A 0.2 m cube (8 kg) hanging from an anchor 1 m above its top by a damped spring of
    // length 0.8 m: at rest the spring is stretched by m g / k.
    BodyDef def = cubeBody(1000.0, {-0.1f, 0.0f, -0.1f}, 0.2f);
    def.constraint = freeAxes({"y"});
    MooringDef line;
    line.fairlead = glm::dvec3(0.0, 0.2, 0.0);
    line.anchor = glm::dvec3(0.0, 1.2, 0.0);
    line.length = 0.8;
    line.stiffness = 2000.0;
    line.damping = 2.0 * 0.5 * std::sqrt(2000.0 * 8.0);  // ζ = 0.5
    def.moorings.push_back(line);
    RigidBody body(def, glm::dvec3(0.0, -9.81, 0.0));
    const double m = body.massProperties().mass;
    for (int s = 0; s < 3000; ++s) body.step(1e-3, glm::dvec3(0.0), glm::dvec3(0.0));
    const double stretch = glm::length(line.anchor - body.toWorld(line.fairlead)) - line.length;
    EXPECT_NEAR(stretch / (m * 9.81 / line.stiffness), 1.0, 1e-6);
    EXPECT_NEAR(body.moorings()[0].tension / (m * 9.81), 1.0, 1e-6);
    EXPECT_NEAR(body.moorings()[0].force.y, m * 9.81, 1e-6 * m * 9.81);
}

TEST(Moorings, SlackSpringPullsNothing) {
    BodyDef def = cubeBody(1000.0, {0.0f, 0.0f, 0.0f}, 0.1f);
    MooringDef line;
    line.fairlead = glm::dvec3(0.05, 0.1, 0.05);
    line.anchor = glm::dvec3(0.05, 0.6, 0.05);
    line.length = 1.0;
    line.stiffness = 1e4;
    def.moorings.push_back(line);
    RigidBody body(def, glm::dvec3(0.0, -9.81, 0.0));
    const double y0 = body.position().y;
    for (int s = 0; s < 100; ++s) body.step(1e-3, glm::dvec3(0.0), glm::dvec3(0.0));
    EXPECT_EQ(body.moorings()[0].tension, 0.0);
    EXPECT_NEAR(body.position().y, y0 - 0.5 * 9.81 * 0.01, 1e-12);  // free fall, exactly
}

/// Integrates the line from the fairlead down (tension (H, V − w s) after unstretched arc
/// s, stretched by T/EA), laying what remains on the seabed from its lowest point: where the
/// anchor end lands, relative to the fairlead.
glm::dvec2 shootCatenary(double H, double V, double L, double EA, double w) {
    const int n = 200000;
    const double ds = L / n;
    glm::dvec2 p(0.0, 0.0);  // (towards the anchor, up)
    for (int i = 0; i < n; ++i) {
        const double s = (i + 0.5) * ds;
        const double Tv = V - w * s;
        if (Tv <= 0.0) {  // the lowest point: the rest lies on the seabed, horizontal, tension H
            p.x += (L - i * ds) * (1.0 + H / EA);
            break;
        }
        const double T = std::sqrt(H * H + Tv * Tv);
        p += ds * (1.0 + T / EA) * glm::dvec2(H / T, -Tv / T);
    }
    return p;
}

TEST(Moorings, CatenaryTensionsPutTheLineOnItsAnchor) {
    const double L = 10.0, EA = 5e5, w = 50.0;
    struct Case {
        double span, rise;
    } cases[] = {{7.0, 4.0}, {9.0, 4.0}, {8.5, 4.0}, {3.0, 8.0}, {8.0, 6.2}};  // on the seabed; taut; hanging
    for (const auto& c : cases) {
        const auto [H, V] = solveCatenary(c.span, c.rise, L, EA, w);
        const glm::dvec2 end = shootCatenary(H, V, L, EA, w);
        EXPECT_NEAR(end.x, c.span, 2e-4) << c.span << ' ' << c.rise << " H " << H << " V " << V;
        EXPECT_NEAR(end.y, -c.rise, 2e-4) << c.span << ' ' << c.rise << " H " << H << " V " << V;
        EXPECT_GT(H, 0.0);
    }
    // More line than the span and rise need: it hangs straight down, the rest on the seabed.
    const auto [H0, V0] = solveCatenary(5.0, 4.0, L, EA, w);
    EXPECT_EQ(H0, 0.0);
    EXPECT_NEAR(V0 / (w * 4.0), 1.0, 1e-3);
    // A body with a catenary: its reading is the solved tension, pointing to the anchor.
    BodyDef def = cubeBody(500.0, {-0.5f, 4.0f, -0.5f}, 1.0f);
    MooringDef line;
    line.type = MooringDef::Type::Catenary;
    line.fairlead = glm::dvec3(0.5, 4.0, 0.0);
    line.anchor = glm::dvec3(7.5, 0.0, 0.0);
    line.length = L;
    line.axialStiffness = EA;
    line.weightPerLength = w;
    def.moorings.push_back(line);
    RigidBody body(def, glm::dvec3(0.0, -9.81, 0.0));
    const auto [H, V] = solveCatenary(7.0, 4.0, L, EA, w);
    EXPECT_DOUBLE_EQ(body.moorings()[0].horizontalTension, H);
    EXPECT_DOUBLE_EQ(body.moorings()[0].verticalTension, V);
    EXPECT_GT(body.moorings()[0].force.x, 0.0);
    EXPECT_LT(body.moorings()[0].force.y, 0.0);
}

// ---------------------------------------------------------------------------------------
// Contact

TEST(Contact, HeavyBoxComesToRestOnTheFloorCarryingItsWeight) {
    // A 0.1 m cube of density 2000 dropped from 5 cm, turned 10° about z, at fluid-like steps
    // of 1 ms for 2 s.
    BodySystem system(glm::dvec3(0.0, -9.81, 0.0));
    system.setWalls(glm::dvec3(0.0), glm::dvec3(1.0));
    BodyDef def = cubeBody(2000.0, {0.45f, 0.05f, 0.45f}, 0.1f);
    def.angularVelocity = glm::dvec3(0.0, 0.0, 2.0);
    system.addBody(def);
    for (int s = 0; s < 2000; ++s) system.step(1e-3, {}, {});
    const RigidBody& b = system.body(0);
    const double weight = b.massProperties().mass * 9.81;
    EXPECT_NEAR(b.contactForce().y / weight, 1.0, 0.03);
    EXPECT_LT(std::abs(b.contactForce().x) + std::abs(b.contactForce().z), 1e-3 * weight);
    EXPECT_LT(glm::length(b.velocity()), 1e-4);
    EXPECT_NEAR(b.position().y, 0.05, 1e-3);  // resting on a face, sunk < 1 mm
    // Flat on a face: its up axis is (anti)parallel to some body axis.
    const glm::dmat3 R = b.rotation();
    const double alignment = std::max({std::abs(R[0].y), std::abs(R[1].y), std::abs(R[2].y)});
    EXPECT_NEAR(alignment, 1.0, 1e-4);

    // Under water: the fluid's buoyancy ρ g V, handed in as the fluid load, leaves the floor
    // (ρ_b − ρ) g V to carry (issue 44, acceptance 3, without the fluid).
    BodySystem wet(glm::dvec3(0.0, -9.81, 0.0));
    wet.setWalls(glm::dvec3(0.0), glm::dvec3(1.0));
    wet.addBody(def);
    const double V = wet.body(0).massProperties().volume;
    const std::vector<glm::dvec3> buoyancy{{0.0, 1000.0 * 9.81 * V, 0.0}}, none{glm::dvec3(0.0)};
    for (int s = 0; s < 2000; ++s) wet.step(1e-3, buoyancy, none);
    EXPECT_NEAR(wet.body(0).contactForce().y / ((2000.0 - 1000.0) * 9.81 * V), 1.0, 0.03);
}

TEST(Contact, StackedBoxesSettleWithoutExploding) {
    BodySystem system(glm::dvec3(0.0, -9.81, 0.0));
    system.setWalls(glm::dvec3(0.0), glm::dvec3(1.0));
    system.addBody(cubeBody(1500.0, {0.45f, 0.0f, 0.45f}, 0.1f));
    system.addBody(cubeBody(1500.0, {0.46f, 0.12f, 0.44f}, 0.1f));  // off by 1 cm, 2 cm above
    system.addBody(cubeBody(1500.0, {0.44f, 0.24f, 0.45f}, 0.1f));
    double fastest = 0.0;
    for (int s = 0; s < 3000; ++s) {
        system.step(1e-3, {}, {});
        for (std::size_t i = 0; i < 3; ++i) fastest = std::max(fastest, glm::length(system.body(i).velocity()));
    }
    EXPECT_LT(fastest, 2.0);  // nothing faster than the ~1.6 m/s a 0.14 m fall gives
    for (std::size_t i = 0; i < 3; ++i) {
        const RigidBody& b = system.body(i);
        const double weight = b.massProperties().mass * 9.81;
        EXPECT_NEAR(b.contactForce().y / weight, 1.0, 0.03) << "box " << i;
        EXPECT_NEAR(b.position().y, 0.05 + 0.1 * i, 2e-3) << "box " << i;
        EXPECT_LT(glm::length(b.velocity()), 1e-3) << "box " << i;
    }
}

TEST(Contact, DebrisHittingAPileBouncesWithoutGainingEnergy) {
    BodySystem system(glm::dvec3(0.0, 0.0, 0.0));
    system.setWalls(glm::dvec3(-1.0), glm::dvec3(1.0));
    ObstacleDef pile;
    pile.shape = ObstacleDef::Shape::Cylinder;
    pile.center = glm::vec3(0.0f);
    pile.axis = glm::vec3(0, 1, 0);
    pile.radius = 0.05f;
    pile.length = 1.0f;
    system.addFixedObstacle(pile);
    BodyDef debris = cubeBody(600.0, {-0.5f, -0.03f, -0.02f}, 0.06f);  // centred 1 cm off the pile's axis
    debris.velocity = glm::dvec3(2.0, 0.0, 0.0);
    system.addBody(debris);
    const double E0 = system.body(0).kineticEnergy();
    double worstE = 0.0, closest = 1.0;
    for (int s = 0; s < 500; ++s) {
        system.step(1e-3, {}, {});
        worstE = std::max(worstE, system.body(0).kineticEnergy());
        // The debris' nearest corner to the pile's axis: never deep inside the pile.
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 corner(k & 1 ? -0.44 : -0.5, k & 2 ? 0.03 : -0.03, k & 4 ? 0.04 : -0.02);
            const glm::dvec3 p = system.body(0).toWorld(corner);
            closest = std::min(closest, std::hypot(p.x, p.z));
        }
    }
    EXPECT_LE(worstE, E0 * (1.0 + 1e-9));
    EXPECT_GT(closest, 0.05 - 0.005);       // penetrates the pile by less than 5 mm
    EXPECT_LT(system.body(0).position().x, 0.0);  // it did not pass through
    EXPECT_LT(system.body(0).velocity().x, 1.0);  // it was stopped or turned back
}

TEST(Contact, FrictionHoldsOnAGentleSlopeAndSlidesOnASteepOne) {
    // A cube on a plane tilted by θ (gravity tilted instead), μ = 0.5: it sticks at 20°
    // (tan θ = 0.36 < μ) and slides at 35° with a = g (sin θ − μ cos θ) (Coulomb).
    for (const double degrees : {20.0, 35.0}) {
        const double theta = degrees * M_PI / 180.0;
        BodySystem system(9.81 * glm::dvec3(std::sin(theta), -std::cos(theta), 0.0));
        system.setWalls(glm::dvec3(-10.0, 0.0, -10.0), glm::dvec3(10.0));
        BodyDef def = cubeBody(1500.0, {0.0f, 0.0f, 0.0f}, 0.1f);
        def.contact.friction = 0.5;
        system.addBody(def);
        for (int s = 0; s < 1000; ++s) system.step(1e-3, {}, {});
        const double x1 = system.body(0).position().x, v1 = system.body(0).velocity().x;
        for (int s = 0; s < 1000; ++s) system.step(1e-3, {}, {});
        const double moved = system.body(0).position().x - x1;
        if (degrees < 30.0) {
            EXPECT_LT(std::abs(moved), 1e-5) << "creeps at " << degrees << " degrees";
        } else {
            const double a = 9.81 * (std::sin(theta) - 0.5 * std::cos(theta));
            EXPECT_NEAR(moved / (v1 + 0.5 * a), 1.0, 0.01);
            EXPECT_NEAR((system.body(0).velocity().x - v1) / a, 1.0, 0.01);
        }
    }
}

TEST(Contact, PlacementIsCheckedNamingTheBody) {
    BodySystem system(glm::dvec3(0.0, -9.81, 0.0));
    system.setWalls(glm::dvec3(0.0), glm::dvec3(1.0));
    ObstacleDef pile;
    pile.shape = ObstacleDef::Shape::Sphere;
    pile.center = glm::vec3(0.8f, 0.5f, 0.5f);
    pile.radius = 0.1f;
    system.addFixedObstacle(pile, "rock");
    BodyDef a = cubeBody(500.0, {0.1f, 0.1f, 0.1f}, 0.2f);
    a.name = "crate";
    system.addBody(a);
    EXPECT_NO_THROW(system.validatePlacement());
    auto message = [&system] {
        try {
            system.validatePlacement(1e-6);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    BodyDef b = cubeBody(500.0, {0.25f, 0.25f, 0.25f}, 0.1f);  // pokes 5 cm into the crate
    b.name = "barrel";
    system.addBody(b);
    EXPECT_NE(message().find("crate: overlaps barrel"), std::string::npos) << message();

    BodySystem walls(glm::dvec3(0.0, -9.81, 0.0));
    walls.setWalls(glm::dvec3(0.0), glm::dvec3(1.0));
    walls.addFixedObstacle(pile, "rock");
    BodyDef c = cubeBody(500.0, {0.65f, 0.45f, 0.45f}, 0.1f);  // inside the rock
    c.name = "crate";
    walls.addBody(c);
    try {
        walls.validatePlacement();
        ADD_FAILURE() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("crate: overlaps rock"), std::string::npos) << e.what();
    }
    BodySystem anchors(glm::dvec3(0.0, -9.81, 0.0));
    anchors.setWalls(glm::dvec3(0.0), glm::dvec3(1.0));
    BodyDef d = cubeBody(500.0, {0.4f, 0.4f, 0.4f}, 0.1f);
    d.name = "buoy";
    MooringDef line;
    line.fairlead = glm::dvec3(0.45, 0.4, 0.45);
    line.anchor = glm::dvec3(0.45, -0.2, 0.45);
    line.length = 0.3;
    line.stiffness = 100.0;
    d.moorings.push_back(line);
    anchors.addBody(d);
    try {
        anchors.validatePlacement();
        ADD_FAILURE() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("buoy.moorings[0].anchor: outside the domain"), std::string::npos)
            << e.what();
    }
}

TEST(RigidBody, DivergedMotionStopsNamingTheBody) {
    BodyDef def = cubeBody(500.0, {0.0f, 0.0f, 0.0f}, 0.1f);
    def.name = "buoy";
    RigidBody body(def, glm::dvec3(0.0, -9.81, 0.0));
    try {
        body.step(1e-3, glm::dvec3(std::numeric_limits<double>::infinity(), 0.0, 0.0), glm::dvec3(0.0));
        ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("buoy: the body's motion diverged"), std::string::npos) << e.what();
    }
}

// ---------------------------------------------------------------------------------------
// Checkpoints

TEST(Checkpoint, RestoredBodiesContinueBitForBit) {
    auto make = [] {
        BodySystem system(glm::dvec3(0.0, -9.81, 0.0));
        system.setWalls(glm::dvec3(0.0), glm::dvec3(1.0));
        BodyDef a = cubeBody(800.0, {0.2f, 0.3f, 0.2f}, 0.1f);
        a.angularVelocity = glm::dvec3(1.0, 2.0, 0.5);
        a.velocity = glm::dvec3(0.3, 0.0, 0.1);
        MooringDef line;
        line.fairlead = glm::dvec3(0.25, 0.4, 0.25);
        line.anchor = glm::dvec3(0.25, 0.9, 0.25);
        line.length = 0.3;
        line.stiffness = 500.0;
        line.damping = 1.0;
        a.moorings.push_back(line);
        system.addBody(a);
        BodyDef b = cubeBody(1500.0, {0.6f, 0.02f, 0.6f}, 0.08f);  // lands and slides: friction springs
        b.constraint = freeAxes({"x", "y", "rz"});
        system.addBody(b);
        return system;
    };
    const std::vector<glm::dvec3> forces{{0.1, 0.2, 0.0}, {0.0, 1.0, 0.0}}, moments{{0.0, 0.0, 0.01}, {0.0, 0.0, 0.0}};
    BodySystem first = make();
    for (int s = 0; s < 200; ++s) first.step(7e-4, forces, moments);
    const std::vector<double> saved = first.saveState();
    ASSERT_GT(saved.size(), 1 + 2 * RigidBody::kStateSize + 1) << "no contact to carry over";
    for (int s = 0; s < 300; ++s) first.step(7e-4, forces, moments);
    BodySystem second = make();
    second.restoreState(saved);
    EXPECT_EQ(second.saveState(), saved);
    for (int s = 0; s < 300; ++s) second.step(7e-4, forces, moments);
    const std::vector<double> a = first.saveState(), b = second.saveState();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
    EXPECT_EQ(first.body(0).moorings()[0].tension, second.body(0).moorings()[0].tension);
    EXPECT_THROW(second.restoreState(std::span<const double>(saved).first(5)), std::invalid_argument);
}

}  // namespace
