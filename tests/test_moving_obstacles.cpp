// Moving obstacles: the prescribed motions against their own derivatives, fluid pushed by a
// plate (momentum as linear shallow-water theory has it, nobody inside), fluid dragged by a
// spinning cylinder (no slip: the contact layer turns with it), and the scene keys.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <tide/io/motion_table.hpp>
#include <tide/io/scene.hpp>
#include <tide/world.hpp>

#include "boundary/rigid_motion.hpp"
#include "cli_support.hpp"
#include "testing/scenarios.hpp"

namespace {

using namespace tide;
namespace fs = std::filesystem;

/// This process's scratch folder, and a file written into it.
const fs::path& scratchDir() {
    static const fs::path dir = [] {
        const fs::path d = tide::testing::scratch("moving_obstacles");
        fs::create_directories(d);
        return d;
    }();
    return dir;
}
void writeFile(const std::string& name, const std::string& text) { std::ofstream(scratchDir() / name) << text; }

/// Checks, at times spread over the motion, that the velocity and acceleration of material
/// points are the centred differences of their positions and velocities (step 1e-4 s).
void expectConsistentKinematics(const RigidMotion& motion, double from, double to, float tolerance) {
    const glm::vec3 points[] = {{0.0f, 0.0f, 0.0f}, {0.3f, -0.1f, 0.2f}, {-0.2f, 0.4f, 0.1f}};
    const double e = 1e-4;
    for (double t = from; t <= to; t += (to - from) / 37.0) {
        const RigidPose before = motion.pose(t - e), now = motion.pose(t), after = motion.pose(t + e);
        for (const glm::vec3& x0 : points) {
            const glm::vec3 x = now.place(x0);
            const glm::vec3 fdVelocity = (after.place(x0) - before.place(x0)) / static_cast<float>(2.0 * e);
            const glm::vec3 fdAcceleration =
                (after.velocityAt(after.place(x0)) - before.velocityAt(before.place(x0))) / static_cast<float>(2.0 * e);
            SCOPED_TRACE("t = " + std::to_string(t));
            EXPECT_LT(glm::distance(now.velocityAt(x), fdVelocity), tolerance * (1.0f + glm::length(fdVelocity)));
            EXPECT_LT(glm::distance(now.accelerationAt(x), fdAcceleration), tolerance * (1.0f + glm::length(fdAcceleration)));
            EXPECT_LT(glm::distance(now.toRest(x), x0), 1e-5f);
        }
    }
}

TEST(RigidMotion, TranslationVelocityIsTheDerivativeOfPosition) {
    MotionDef def;
    def.type = MotionDef::Type::Translation;
    def.velocity = {0.2f, 0.0f, -0.1f};
    def.amplitude = {0.0f, 0.05f, 0.02f};
    def.period = 0.8f;
    def.startTime = 0.5;
    def.rampTime = 0.4f;
    const RigidMotion motion(def);
    expectConsistentKinematics(motion, 0.3, 3.0, 2e-3f);
    // At rest before the start; after the ramp the steady part moves at `velocity`, having
    // lost half the ramp: d = v (τ − T/2).
    EXPECT_EQ(glm::length(motion.state(0.4).offset), 0.0);
    const RigidState s = motion.state(0.5 + 2.0);  // 2.5 periods after the start: sin = 0
    EXPECT_NEAR(s.offset.x, 0.2 * (2.0 - 0.2), 1e-7);
    EXPECT_NEAR(s.offset.y, 0.0, 1e-7);
    EXPECT_NEAR(s.velocity.x, 0.2, 1e-7);  // the velocity is a float
    EXPECT_NEAR(s.velocity.y, 0.05 * 2.0 * M_PI / 0.8 * std::cos(2.0 * M_PI * 2.0 / 0.8), 1e-7);
}

TEST(RigidMotion, RotationKeepsDistancesToTheAxis) {
    MotionDef def;
    def.type = MotionDef::Type::Rotation;
    def.axis = glm::normalize(glm::vec3(1.0f, 2.0f, -0.5f));
    def.center = {0.3f, 0.1f, -0.2f};
    def.angularVelocity = 3.0f;
    def.angularAmplitude = 0.4f;
    def.period = 1.3f;
    def.rampTime = 0.5f;
    const RigidMotion motion(def);
    expectConsistentKinematics(motion, 0.01, 4.0, 2e-3f);  // the ramp starts with a jump in acceleration at 0
    const glm::vec3 x0(0.7f, -0.4f, 0.9f);
    const auto axisDistance = [&](const glm::vec3& x) {
        const glm::vec3 r = x - def.center;
        return glm::length(r - glm::dot(r, def.axis) * def.axis);
    };
    for (double t = 0.0; t < 4.0; t += 0.173) {
        const RigidPose pose = motion.pose(t);
        const glm::vec3 x = pose.place(x0);
        EXPECT_NEAR(axisDistance(x), axisDistance(x0), 1e-5f);
        EXPECT_NEAR(glm::dot(x - def.center, def.axis), glm::dot(x0 - def.center, def.axis), 1e-5f);
        // The velocity of a point turning about the axis is ω r⊥, perpendicular to the axis.
        EXPECT_NEAR(glm::dot(pose.velocityAt(x), def.axis), 0.0f, 1e-5f);
    }
    // After the ramp, a steady rotation has turned ω (τ − T/2) plus the oscillation.
    const double t = 1.3 * 3;  // the oscillation's sine is 0
    EXPECT_NEAR(motion.state(t).angle, 3.0 * (t - 0.25), 1e-6);
}

TEST(RigidMotion, TableIsInterpolatedSmoothlyAndHeld) {
    MotionDef def;
    def.type = MotionDef::Type::Table;
    def.axis = {0.0f, 0.0f, 1.0f};
    def.center = {0.1f, 0.0f, 0.0f};
    def.startTime = 1.0;
    // A sampled circle of radius 0.1 m at uneven times, turning as it goes.
    for (int k = 0; k <= 12; ++k) {
        const double t = 0.25 * k + 0.03 * (k % 3);
        const float phase = static_cast<float>(k) * 0.5f;
        def.keys.push_back({t, {0.1f * std::cos(phase), 0.1f * std::sin(phase), 0.0f}, 0.2f * phase});
    }
    const RigidMotion motion(def);
    expectConsistentKinematics(motion, 0.9, 4.3, 2e-3f);
    for (const MotionKey& k : def.keys) {  // through every row
        const RigidState s = motion.state(1.0 + k.time);
        EXPECT_NEAR(glm::distance(glm::vec3(s.offset), k.offset), 0.0f, 1e-6f);
        EXPECT_NEAR(s.angle, k.angle, 1e-6);
    }
    // Velocity is continuous across a row, and zero at the ends (held before and after).
    const double row = 1.0 + def.keys[5].time;
    EXPECT_LT(glm::length(motion.state(row - 1e-9).velocity - motion.state(row + 1e-9).velocity), 1e-5);
    EXPECT_EQ(glm::length(motion.state(1.0 + def.keys.back().time + 5.0).velocity), 0.0);
    EXPECT_EQ(glm::vec3(motion.state(9.0).offset), def.keys.back().offset);
    EXPECT_EQ(glm::vec3(motion.state(0.0).offset), def.keys.front().offset);
    EXPECT_LT(glm::length(motion.state(1.0 + 1e-6).velocity), 1e-3);
}

TEST(RigidMotion, CsvTablesAndTheirProblems) {
    const io::MotionTable table =
        io::parseMotionTable("# a paddle\ntime, x, y, z, angle_deg\n0,0,0,0,0\n\n0.5, 1, 2, 3, 90\n", "t.csv", 0.01f);
    ASSERT_EQ(table.keys.size(), 2u);
    EXPECT_TRUE(table.hasAngle);
    EXPECT_NEAR(table.keys[1].offset.y, 0.02f, 1e-7f);
    EXPECT_NEAR(table.keys[1].angle, M_PI / 2, 1e-6);
    const auto problem = [](const std::string& text) {
        try {
            io::parseMotionTable(text, "m.csv");
        } catch (const io::MotionTableError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(problem("t,x,y,z\n0,0,0,0\n"),
              "m.csv: line 1: the header must be time,x,y,z or time,x,y,z,angle or time,x,y,z,angle_deg, got \"t,x,y,z\"");
    EXPECT_EQ(problem("time,x,y,z\n0,0,0,0\n0.1,0,0\n"), "m.csv: line 3: expected 4 numbers, got 3");
    EXPECT_EQ(problem("time,x,y,z\n0,0,0,0\n0.1,0,zero,0\n"), "m.csv: line 3: \"zero\" is not a finite number");
    EXPECT_EQ(problem("time,x,y,z\n0,0,0,0\n0.2,0,0,0\n0.2,1,0,0\n"), "m.csv: line 4: time 0.2 is not after the previous row's 0.2");
    EXPECT_EQ(problem("# nothing\n"), "m.csv: no header line (time,x,y,z or time,x,y,z,angle)");
    EXPECT_EQ(problem("time,x,y,z\n"), "m.csv: no rows after the header");
}

// Water filled around a stirring paddle (a box turning about y, as scenes/stirred_tank.json)
// starts still while the paddle ramps up. The fill kept half a spacing off every moving solid,
// which left empty the lattice row under the paddle's bottom face (0.17 spacing below it) and
// beside one side face: the water jumped into them at 1.1-1.3 m/s within 0.1 s. A box's
// particles fill the lattice up to its faces, so the water now fills up to them as it does
// for a fixed box (curved solids keep the half spacing: SpinningCylinder below).
TEST(MovingObstacles, WaterAroundAStirringPaddleStartsStill) {
    WorldDef def;
    def.domainMax = {0.4f, 0.4f, 0.4f};
    def.particleSpacing = 0.015f;
    def.solver.method = "dfsph";
    World world(def);
    world.addMaterial({});
    ObstacleDef paddle;
    paddle.min = {0.1f, 0.04f, 0.185f};
    paddle.max = {0.3f, 0.34f, 0.215f};
    paddle.motion.type = MotionDef::Type::Rotation;
    paddle.motion.axis = {0.0f, 1.0f, 0.0f};
    paddle.motion.center = {0.2f, 0.0f, 0.2f};
    paddle.motion.angularVelocity = 4.0f;
    paddle.motion.rampTime = 0.5f;
    world.addObstacle(paddle);
    ASSERT_EQ(world.addBlock({{0, 0, 0}, {0.4f, 0.2f, 0.4f}, {}, 0}), AddStatus::Added);
    float fastest = 0.0f;
    for (int k = 0; k < 4; ++k) {
        world.advance(0.025);
        for (const glm::vec3& v : world.particles().velocity) fastest = std::max(fastest, glm::length(v));
        ASSERT_EQ(world.countEscapedParticles(), 0u);
    }
    std::printf("%u particles around the paddle; largest speed over 0.1 s %.3f m/s (the paddle's tip: %.3f)\n",
                world.particles().size(), fastest, 0.1 * 4.0 * 0.5 * (1.0 - std::cos(M_PI * 0.1 / 0.5)));
    EXPECT_LT(fastest, 0.15f);
}

/// Σ m v_x of the fluid, kg m/s.
double momentumX(const World& world) {
    const ParticleStore& p = world.particles();
    double sum = 0.0;
    for (std::uint32_t i = 0; i < p.size(); ++i) sum += static_cast<double>(p.mass[i]) * p.velocity[i].x;
    return sum;
}

// A plate across a 2D flume pushed at U: linear shallow-water theory sends a wave of
// elevation ahead and one of depression behind, both at c = √(g d) and both carrying the
// fluid at U, so the fluid's momentum is 2 ρ W d c X(t), X the plate's travel (while neither
// wave has reached an end wall: c t = 0.3 m of the 0.38 m on each side).
TEST(MovingObstacles, PushedPlateCarriesTheWaterAndNothingGetsInside) {
    const float spacing = 0.01f, length = 0.8f, depth = 0.1f, speed = 0.1f;
    World world = scenarios::pushedPlate(spacing, length, depth, speed, 1, "dfsph");
    const double width = world.def().domainMax.z;
    const double c = std::sqrt(9.81 * depth);
    for (int frame = 1; frame <= 6; ++frame) {
        world.advance(0.05);
        ASSERT_EQ(world.countEscapedParticles(), 0u) << "at t = " << world.time();
    }
    const double travel = speed * (world.time() - 0.05);  // the 0.1 s ramp loses half its length
    EXPECT_NEAR(world.obstaclePose(0, world.time()).translation.x, travel, 1e-6);
    const double expected = 2.0 * 1000.0 * width * depth * c * travel;
    const double measured = momentumX(world);
    // The fluid 3 cm ahead of the plate's face, at mid-depth.
    const glm::vec3 front(static_cast<float>(travel) + 0.5f * length + 2.0f * spacing + 0.03f, 0.5f * depth,
                          0.5f * static_cast<float>(width));
    const float ahead = world.probe(front).velocity.x;
    std::printf("plate moved %.4f m: fluid momentum %.4f kg m/s, linear theory %.4f; u ahead of the plate %.4f m/s (plate %.2f)\n",
                travel, measured, expected, ahead, speed);
    EXPECT_NEAR(measured / expected, 1.0, 0.15);
    EXPECT_NEAR(ahead / speed, 1.0, 0.25);
}

/// Mean azimuthal velocity v_θ/(ω R) of the fluid in rings one spacing wide around the
/// spinning cylinder (ring k: R + k s ≤ r < R + (k + 1) s), and the same of the Couette flow
/// between the cylinder and a fixed circle of radius `outer`, at the same particles.
struct Rings {
    std::vector<double> measured, couette;
};
Rings azimuthalProfile(const World& world, float spacing, float width, float radius, float omega, float outer, int rings) {
    Rings out{std::vector<double>(rings, 0.0), std::vector<double>(rings, 0.0)};
    std::vector<int> count(rings, 0);
    const ParticleStore& p = world.particles();
    const glm::vec3 axis(0.5f * width, 0.0f, 0.5f * width);
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        glm::vec3 r = p.position[i] - axis;
        r.y = 0.0f;
        const double distance = glm::length(r);
        const int k = static_cast<int>(std::floor((distance - radius) / spacing));
        if (k < 0 || k >= rings) continue;
        // Counter-clockwise about +y, the cylinder's sense.
        const glm::vec3 tangent = glm::cross(glm::vec3(0, 1, 0), r / static_cast<float>(distance));
        out.measured[k] += glm::dot(p.velocity[i], tangent) / (omega * radius);
        // v(r) = ω R² (R2²/r − r)/(R2² − R²) (Landau & Lifshitz §18).
        out.couette[k] += radius * (outer * outer / distance - distance) / (outer * outer - radius * radius);
        ++count[k];
    }
    for (int k = 0; k < rings; ++k) {
        out.measured[k] /= std::max(count[k], 1);
        out.couette[k] /= std::max(count[k], 1);
    }
    return out;
}

// No slip on a moving wall: a viscous fluid (ν = 0.005 m²/s) around a cylinder spinning in a
// square box turns with it. After 0.5 s (the gap's diffusion time is 0.7 s) the profile is
// close to circular Couette flow out to the box's inscribed circle; the layer in contact
// lags it a little (its particles sit further than s/2 from the surface).
TEST(MovingObstacles, SpinningCylinderDragsTheFluidAroundLikeCouetteFlow) {
    const float spacing = 0.01f, width = 0.2f, radius = 0.04f, omega = 2.0f, mu = 5.0f;
    World world = scenarios::spinningCylinder(spacing, width, radius, omega, mu, 1, "dfsph");
    for (int frame = 0; frame < 5; ++frame) {
        world.advance(0.1);
        ASSERT_EQ(world.countEscapedParticles(), 0u) << "at t = " << world.time();
    }
    const Rings rings = azimuthalProfile(world, spacing, width, radius, omega, 0.5f * width, 6);
    for (std::size_t k = 0; k < rings.measured.size(); ++k)
        std::printf("ring %zu: v_theta / (omega R) = %.3f, Couette %.3f\n", k, rings.measured[k], rings.couette[k]);
    EXPECT_GT(rings.measured[0], 0.65);
    EXPECT_LT(rings.measured[0], 1.0);
    for (std::size_t k = 1; k < rings.measured.size(); ++k) EXPECT_NEAR(rings.measured[k], rings.couette[k], 0.06) << k;
}

// Every solver takes the wall's velocity into its viscosity: 0.1 s after the start, the
// contact layer already turns (it would stay at rest with walls taken as fixed: pressure
// cannot turn fluid around an axisymmetric body).
class SpinUp : public ::testing::TestWithParam<const char*> {};

TEST_P(SpinUp, ContactLayerTurnsWithTheCylinder) {
    const float spacing = 0.01f, width = 0.2f, radius = 0.04f, omega = 2.0f, mu = 5.0f;
    World world = scenarios::spinningCylinder(spacing, width, radius, omega, mu, 1, GetParam());
    world.advance(0.1);
    EXPECT_EQ(world.countEscapedParticles(), 0u);
    const Rings rings = azimuthalProfile(world, spacing, width, radius, omega, 0.5f * width, 3);
    std::printf("%s at 0.1 s: v_theta / (omega R) = %.3f, %.3f, %.3f in the first three rings\n", GetParam(),
                rings.measured[0], rings.measured[1], rings.measured[2]);
    // dfsph, pcisph and wcsph (Morris viscosity) reach 0.56–0.58; classic (Müller's
    // viscosity kernel, XSPH 0.25) 0.34.
    EXPECT_GT(rings.measured[0], 0.3);
    EXPECT_GT(rings.measured[0], rings.measured[1]);
    EXPECT_GT(rings.measured[1], rings.measured[2]);
    EXPECT_GT(rings.measured[2], 0.0);
}

INSTANTIATE_TEST_SUITE_P(Solvers, SpinUp, ::testing::Values("dfsph", "pcisph", "wcsph", "classic"));

/// A scene of one obstacle (a box unless `obstacle` says otherwise) with `motion`.
std::string sceneWith(const std::string& motion, const std::string& obstacle = R"("type": "box", "min": [0.4, 0, 0], "max": [0.5, 0.3, 0.3])") {
    return R"({"domain": {"min": [0, 0, 0], "max": [1, 0.5, 0.3]}, "particle_spacing": 0.05, "end_time": 0.1,
  "materials": [{"name": "water", "density": 1000}],
  "blocks": [{"min": [0, 0, 0], "max": [0.3, 0.2, 0.3]}],
  "obstacles": [{"type": "sphere", "center": [0.8, 0.1, 0.1], "radius": 0.05}, {)" + obstacle + R"(, "motion": )" + motion + "}]}";
}

TEST(MovingObstacleScenes, MotionKeysParseInMetres) {
    writeFile("paddle.csv", "# time s, displacement cm, angle degrees\ntime,x,y,z,angle_deg\n0,0,0,0,0\n1,10,0,0,45\n2,20,0,0,90\n");
    const std::string text = R"({"unit_scale": 0.01, "domain": {"min": [0, 0, 0], "max": [100, 50, 30]},
  "particle_spacing": 5, "end_time": 0.1, "materials": [{"name": "water", "density": 1000}],
  "obstacles": [
    {"type": "box", "min": [40, 0, 0], "max": [45, 30, 30],
     "motion": {"type": "translation", "velocity": [10, 0, 0], "amplitude": [0, 0, 2], "period": 1.5, "start_time": 0.5, "ramp_time": 0.2}},
    {"type": "cylinder", "center": [70, 20, 15], "axis": "z", "radius": 5, "length": 30,
     "motion": {"type": "rotation", "axis": "z", "center": [70, 20, 15], "angular_velocity": -3, "amplitude": 0.5, "period": 2}},
    {"type": "sphere", "center": [20, 30, 15], "radius": 5,
     "motion": {"type": "csv", "file": "paddle.csv", "axis": [0, 0, 2], "center": [20, 30, 15]}}]})";
    const io::Scene scene = io::parseScene(text, "moving.json", scratchDir());
    ASSERT_EQ(scene.obstacles.size(), 3u);
    const MotionDef& t = scene.obstacles[0].motion;
    EXPECT_EQ(t.type, MotionDef::Type::Translation);
    EXPECT_NEAR(t.velocity.x, 0.1f, 1e-7f);
    EXPECT_NEAR(t.amplitude.z, 0.02f, 1e-7f);
    EXPECT_EQ(t.period, 1.5f);
    EXPECT_EQ(t.startTime, 0.5);
    EXPECT_EQ(t.rampTime, 0.2f);
    const MotionDef& r = scene.obstacles[1].motion;
    EXPECT_EQ(r.type, MotionDef::Type::Rotation);
    EXPECT_EQ(r.axis, glm::vec3(0, 0, 1));
    EXPECT_NEAR(glm::distance(r.center, glm::vec3(0.7f, 0.2f, 0.15f)), 0.0f, 1e-6f);
    EXPECT_EQ(r.angularVelocity, -3.0f);
    EXPECT_EQ(r.angularAmplitude, 0.5f);
    const MotionDef& c = scene.obstacles[2].motion;
    EXPECT_EQ(c.type, MotionDef::Type::Table);
    ASSERT_EQ(c.keys.size(), 3u);
    EXPECT_NEAR(c.keys[2].offset.x, 0.2f, 1e-7f);
    EXPECT_NEAR(c.keys[2].angle, M_PI / 2, 1e-6);
    EXPECT_EQ(c.axis, glm::vec3(0, 0, 1));

    // The world moves them: at t = 2 s the sphere has done its table's last row.
    World world = io::buildWorld(scene);
    const ObstaclePose pose = world.obstaclePose(2, 2.0);
    EXPECT_NEAR(glm::distance(pose.rotation * glm::vec3(0.2f, 0.3f, 0.15f) + pose.translation, glm::vec3(0.4f, 0.3f, 0.15f)),
                0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(pose.rotation * glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
    EXPECT_EQ(world.obstaclePose(0, 0.4).translation, glm::vec3(0.0f));  // before its start time
}

TEST(MovingObstacleScenes, ProblemsNameTheFieldAndValue) {
    writeFile("good.csv", "time,x,y,z\n0,0,0,0\n1,0.1,0,0\n");
    writeFile("turns.csv", "time,x,y,z,angle\n0,0,0,0,0\n1,0.1,0,0,1\n");
    writeFile("late.csv", "time,x,y,z\n0,0,0,0\n1,0.1,0,0\n0.5,0.2,0,0\n");
    const struct {
        std::string motion, obstacle;
        std::vector<std::string> expected;
    } cases[] = {
        {R"({"type": "spin"})", "", {"obstacles[1].motion.type: \"spin\" is not one of translation, rotation, csv"}},
        {R"({"type": "rotaton", "axis": "y", "center": [0, 0, 0], "angular_velocity": 1})", "", {"did you mean \"rotation\""}},
        {R"("fast")", "", {"obstacles[1].motion: must be an object, got \"fast\""}},
        {R"({"velocity": [1, 0, 0]})", "", {"obstacles[1].motion.type: missing"}},
        {R"({"type": "translation"})", "", {"obstacles[1].motion: needs \"velocity\" or \"amplitude\""}},
        {R"({"type": "translation", "velocity": [1, 0]})", "", {"obstacles[1].motion.velocity: must be an array of 3 numbers"}},
        {R"({"type": "translation", "amplitude": [0.1, 0, 0]})", "", {"obstacles[1].motion.period: missing"}},
        {R"({"type": "translation", "amplitude": [0.1, 0, 0], "period": 0})", "", {"obstacles[1].motion.period: must be > 0", "got 0"}},
        {R"({"type": "translation", "velocity": [1, 0, 0], "ramp_time": -1})", "", {"obstacles[1].motion.ramp_time: must be >= 0", "got -1"}},
        {R"({"type": "translation", "velocity": [1, 0, 0], "speed": 2})", "", {"obstacles[1].motion.speed: unknown key"}},
        {R"({"type": "rotation", "center": [0, 0, 0], "angular_velocity": 1})", "", {"obstacles[1].motion.axis: missing"}},
        {R"({"type": "rotation", "axis": "w", "center": [0, 0, 0], "angular_velocity": 1})", "", {"obstacles[1].motion.axis: must be \"x\""}},
        {R"({"type": "rotation", "axis": "y", "angular_velocity": 1})", "", {"obstacles[1].motion.center: missing"}},
        {R"({"type": "rotation", "axis": "y", "center": [0, 0, 0], "angular_speed": 1})", "",
         {"obstacles[1].motion.angular_speed: unknown key", "obstacles[1].motion: needs \"angular_velocity\" or \"amplitude\""}},
        {R"({"type": "csv"})", "", {"obstacles[1].motion.file: missing"}},
        {R"({"type": "csv", "file": "none.csv"})", "", {"obstacles[1].motion.file: none.csv (", "none.csv): cannot open"}},
        {R"({"type": "csv", "file": "late.csv"})", "", {"obstacles[1].motion.file: late.csv (", "late.csv): line 4: time 0.5 is not after the previous row's 1"}},
        {R"({"type": "csv", "file": "turns.csv"})", "", {"obstacles[1].motion.axis: missing", "obstacles[1].motion.center: missing"}},
        {R"({"type": "csv", "file": "good.csv", "axis": "y"})", "", {"obstacles[1].motion: good.csv has no angle column"}},
        {R"({"type": "csv", "file": "good.csv", "ramp_time": 1})", "", {"obstacles[1].motion.ramp_time: unknown key"}},
        {R"({"type": "translation", "velocity": [1, 0, 0]})", R"("type": "plane", "point": [0, 0.1, 0], "normal": "y")",
         {"obstacles[1].motion: a plane cannot move"}},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.motion + " " + c.obstacle);
        const std::string text = c.obstacle.empty() ? sceneWith(c.motion) : sceneWith(c.motion, c.obstacle);
        try {
            io::parseScene(text, "bad.json", scratchDir());
            ADD_FAILURE() << "accepted";
        } catch (const io::SceneError& e) {
            std::string all;
            for (const std::string& p : e.problems) all += p + "\n";
            for (const std::string& want : c.expected) EXPECT_NE(all.find(want), std::string::npos) << want << " in\n" << all;
        }
    }
}

// The World checks what C++ callers hand it, naming the field.
TEST(MovingObstacleScenes, WorldRefusesBadMotions) {
    WorldDef def;
    def.particleSpacing = 0.05f;
    World world(def);
    world.addMaterial(MaterialDef{});
    ObstacleDef box;
    box.min = {0.4f, 0.0f, 0.0f};
    box.max = {0.5f, 0.5f, 1.0f};
    const auto problem = [&](const ObstacleDef& o) {
        try {
            world.addObstacle(o);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    ObstacleDef o = box;
    o.motion.type = MotionDef::Type::Rotation;
    o.motion.axis = glm::vec3(0.0f);
    EXPECT_EQ(problem(o), "obstacle.motion.axis: must be non-zero, got [0, 0, 0]");
    o = box;
    o.motion.type = MotionDef::Type::Table;
    EXPECT_EQ(problem(o), "obstacle.motion.keys: a motion table needs at least one row, got none");
    o.motion.keys = {{0.0, {}, 0.0f}, {0.0, {}, 0.0f}};
    EXPECT_NE(problem(o).find("obstacle.motion.keys[1].time: must be finite and after the previous row's"), std::string::npos);
    o = box;
    o.motion.type = MotionDef::Type::Translation;
    o.motion.amplitude = {0.1f, 0.0f, 0.0f};
    EXPECT_EQ(problem(o), "obstacle.motion.period: must be > 0, got 0");
    o = box;
    o.shape = ObstacleDef::Shape::Plane;
    o.motion.type = MotionDef::Type::Translation;
    EXPECT_NE(problem(o).find("obstacle.motion: a plane cannot move"), std::string::npos);
    EXPECT_TRUE(world.obstacles().empty());
}

}  // namespace
