// World::settle, the pre-roll: the clock held (boundaries still, nothing emitted), velocities
// zeroed, statistics restarted, an early end once quiet, bad values refused. How still the water stays after it is
// tests/test_incompressible_solvers.cpp's.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <tide/world.hpp>

#include "testing/scenarios.hpp"

namespace {

using namespace tide;

/// Mean x of the fluid particles, m.
double meanX(const World& world) {
    const ParticleStore& p = world.particles();
    double sum = 0.0;
    for (std::uint32_t i = 0; i < p.size(); ++i) sum += p.position[i].x;
    return sum / std::max<double>(1.0, p.size());
}

TEST(Settle, HoldsTheClockZeroesVelocitiesAndRestartsTheStatistics) {
    WorldDef def;
    def.particleSpacing = 0.02f;
    def.domainMax = {0.2f, 0.3f, 0.1f};
    World world(def);
    world.addMaterial({});
    ASSERT_EQ(world.addBlock({{0, 0, 0}, {0.2f, 0.12f, 0.1f}, {0.3f, 0, 0}, 0}), AddStatus::Added);
    const SettleReport report = world.settle(0.2);
    EXPECT_NEAR(report.seconds, 0.2, 1e-9);
    EXPECT_GT(report.steps, 10u);
    EXPECT_GT(report.maxSpeed, 0.0f);  // the block started at 0.3 m/s and sloshes
    EXPECT_EQ(world.time(), 0.0);
    for (const glm::vec3& v : world.particles().velocity) ASSERT_EQ(glm::length(v), 0.0f);
    EXPECT_EQ(world.stats().steps, 0u);
    EXPECT_EQ(world.stats().dtSum, 0.0);
    EXPECT_EQ(world.countEscapedParticles(), 0u);
    // The run after it starts from t = 0.
    world.advance(0.05);
    EXPECT_NEAR(world.time(), 0.05, 1e-12);
    EXPECT_GT(world.stats().steps, 0u);
}

// The plate of the moving-obstacle tests, pushed at 0.1 m/s after a 0.1 s ramp: over a 0.5 s
// settle it must stay where it is at t = 0. Had it moved (4.5 cm), it would have pushed the
// water's centre of mass ~2 cm along x.
TEST(Settle, MovingBoundariesStandStill) {
    World world = scenarios::pushedPlate(0.02f, 0.8f, 0.1f, 0.1f);
    const double before = meanX(world);
    world.settle(0.5);
    EXPECT_NEAR(meanX(world), before, 1e-3);
    EXPECT_EQ(world.countEscapedParticles(), 0u);
    // Then it moves with the clock: travel 0.1 × (0.3 − 0.05) m by t = 0.3 s.
    world.advance(0.3);
    EXPECT_NEAR(world.obstaclePose(0, world.time()).translation.x, 0.025, 1e-6);
    EXPECT_GT(meanX(world), before + 2e-3);
}

TEST(Settle, EmitsNothing) {
    WorldDef def;
    def.particleSpacing = 0.02f;
    def.domainMax = {0.4f, 0.4f, 0.2f};
    World world(def);
    world.addMaterial({});
    EmitterDef jet;
    jet.min = {0.02f, 0.2f, 0.06f};
    jet.max = {0.02f, 0.28f, 0.14f};
    jet.velocity = {1.0f, 0.0f, 0.0f};
    world.addEmitter(jet);
    world.settle(0.1);
    EXPECT_EQ(world.particles().size(), 0u);
    world.advance(0.1);
    EXPECT_GT(world.particles().size(), 0u);
}

// With a quiet speed the pre-roll ends once every particle has stayed below it for
// kSettleQuietTime: at once for water already at rest (a full box without gravity), never for
// a block thrown at 0.3 m/s within 0.2 s.
TEST(Settle, EndsOnceQuiet) {
    WorldDef def;
    def.particleSpacing = 0.02f;
    def.domainMax = {0.2f, 0.2f, 0.2f};
    def.gravity = {0.0f, 0.0f, 0.0f};
    World still(def);
    still.addMaterial({});
    ASSERT_EQ(still.addBlock({{0, 0, 0}, {0.2f, 0.2f, 0.2f}, {}, 0}), AddStatus::Added);
    const SettleReport quiet = still.settle(10.0, 1e-3f);
    EXPECT_TRUE(quiet.quiet);
    EXPECT_GE(quiet.seconds, kSettleQuietTime);
    EXPECT_LT(quiet.seconds, kSettleQuietTime + 0.01);

    def.domainMax = {0.2f, 0.3f, 0.1f};
    def.gravity = {0.0f, -9.81f, 0.0f};
    World thrown(def);
    thrown.addMaterial({});
    ASSERT_EQ(thrown.addBlock({{0, 0, 0}, {0.2f, 0.12f, 0.1f}, {0.3f, 0, 0}, 0}), AddStatus::Added);
    const SettleReport busy = thrown.settle(0.2, 0.01f);
    EXPECT_FALSE(busy.quiet);
    EXPECT_NEAR(busy.seconds, 0.2, 1e-9);
}

TEST(Settle, RefusesABadDurationNamingTheField) {
    World world{WorldDef{}};
    world.addMaterial({});
    for (const double bad : {-1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
        try {
            world.settle(bad);
            FAIL() << "accepted settle(" << bad << ")";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("settle.time"), std::string::npos) << e.what();
        }
    }
    for (const float bad : {-1.0f, std::nanf("")}) {
        try {
            world.settle(1.0, bad);
            FAIL() << "accepted a quiet speed of " << bad;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("settle.speed"), std::string::npos) << e.what();
        }
    }
    EXPECT_EQ(world.settle(0.0).steps, 0u);
}

}  // namespace
