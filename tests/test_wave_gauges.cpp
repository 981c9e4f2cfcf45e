// Wave gauges, probes and the damping zone on simple setups.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include <tide/world.hpp>

#include "boundary/damping_zone.hpp"
#include "testing/scenarios.hpp"

namespace {

using namespace tide;

TEST(WaveGauge, ReadsTheWaterDepthOfAStillTank) {
    const float spacing = 0.02f, depth = 0.2f;
    World world = scenarios::stillWater(depth, 0.3f, spacing, 0, "dfsph");
    // The lattice's top layer is at depth − s/2: the colour field crosses ½ at its surface.
    for (const float x : {0.05f, 0.15f, 0.27f}) EXPECT_NEAR(world.surfaceHeight(x, 0.15f), depth, 0.25f * spacing) << x;
    world.advance(0.5);
    for (const float x : {0.05f, 0.15f, 0.27f}) {
        const float eta = world.surfaceHeight(x, 0.15f);
        std::printf("still tank after 0.5 s: gauge at x = %.2f reads %.4f m (depth %.2f)\n", x, eta, depth);
        EXPECT_NEAR(eta, depth, 0.25f * spacing) << x;
    }
    // Dry line: outside any fluid.
    EXPECT_TRUE(std::isnan(world.surfaceHeight(0.15f, 5.0f)));
}

TEST(Probe, ReadsHydrostaticPressureAndRest) {
    const float spacing = 0.02f, depth = 0.3f;
    World world = scenarios::stillWater(depth, 0.3f, spacing, 0, "dfsph");
    world.advance(0.5);
    // A tank of particles at rest is never still: single readings wander with the particles'
    // noise (~0.02 m/s RMS), so the probe is averaged over 0.2 s as a gauge's signal would be.
    ProbeSample s{0.0f, 0.0f, glm::vec3(0.0f)};
    const int samples = 10;
    for (int k = 0; k < samples; ++k) {
        world.advance(0.02);
        const ProbeSample one = world.probe({0.15f, 0.1f, 0.15f});
        s.density += one.density / samples;
        s.pressure += one.pressure / samples;
        s.velocity += one.velocity / static_cast<float>(samples);
    }
    const float expected = 1000.0f * 9.81f * (depth - 0.1f);
    std::printf("probe at y = 0.1, mean of 0.5-0.7 s: p = %.1f Pa (hydrostatic %.1f), |v| = %.4f m/s\n", s.pressure,
                expected, std::sqrt(s.velocity.x * s.velocity.x + s.velocity.y * s.velocity.y + s.velocity.z * s.velocity.z));
    EXPECT_NEAR(s.pressure, expected, 0.05f * expected);
    EXPECT_NEAR(s.density, 1000.0f, 10.0f);
    EXPECT_LT(std::abs(s.velocity.y), 0.02f);
    EXPECT_TRUE(std::isnan(world.probe({0.15f, 0.55f, 0.15f}).pressure));
}

TEST(DampingZone, RelaxesVelocitiesQuadraticallyAlongTheZone) {
    ParticleStore p;
    for (const float x : {0.5f, 1.0f, 1.5f, 2.0f, 2.5f}) p.append({x, 0.0f, 0.0f}, {1.0f, -1.0f, 0.5f}, 1.0f, 0, 1000.0f);
    const DampingZoneDef zone{1.0f, 2.0f, 10.0f};
    applyDampingZones(std::span(&zone, 1), p, 0.01, 1);
    EXPECT_EQ(p.velocity[0].x, 1.0f);                      // before the zone
    EXPECT_EQ(p.velocity[1].x, 1.0f);                      // its start
    EXPECT_NEAR(p.velocity[2].x, 1.0f - 0.1f * 0.25f, 1e-6f);  // halfway: s² = ¼
    EXPECT_NEAR(p.velocity[3].y, -(1.0f - 0.1f), 1e-6f);   // its end
    EXPECT_NEAR(p.velocity[4].z, 0.5f * (1.0f - 0.1f), 1e-6f);  // beyond: full strength
}

TEST(WaveMaker, PistonPushesTheWaterAndConservesMass) {
    WaveMakerDef paddle;
    paddle.x = 0.1f;
    paddle.depth = 0.2f;
    paddle.waveHeight = 0.03f;
    paddle.period = 0.8f;
    paddle.rampTime = 0.4f;
    World world = scenarios::waveFlume(0.02f, 1.5f, 0.2f, paddle, 0.4f, 0);
    const auto n = world.particles().size();
    const double mass = world.totalMass();
    float maxEta = 0.0f;
    for (int k = 0; k < 12; ++k) {
        world.advance(0.1);
        maxEta = std::max(maxEta, world.surfaceHeight(0.3f, 0.04f) - 0.2f);
    }
    std::printf("piston: highest crest at x = 0.3 m in 1.2 s: %.4f m\n", maxEta);
    EXPECT_GT(maxEta, 0.005f);  // a wave was made
    EXPECT_EQ(world.particles().size(), n);
    EXPECT_EQ(world.totalMass(), mass);
    EXPECT_EQ(world.countEscapedParticles(), 0u);
}

TEST(WaveMaker, FlapIsBitIdenticalAcrossThreadCounts) {
    WaveMakerDef paddle;
    paddle.type = WaveMakerDef::Type::Flap;
    paddle.x = 0.1f;
    paddle.depth = 0.15f;
    paddle.waveHeight = 0.02f;
    paddle.period = 0.8f;
    paddle.rampTime = 0.2f;
    const auto run = [&](int threads) {
        World world = scenarios::waveFlume(0.03f, 1.2f, 0.15f, paddle, 0.3f, threads);
        world.advance(0.1);
        std::vector<glm::vec3> byId(world.particles().size());
        for (std::uint32_t i = 0; i < world.particles().size(); ++i) byId[world.particles().id[i]] = world.particles().position[i];
        return byId;
    };
    const auto one = run(1), two = run(2), three = run(3);
    ASSERT_EQ(one.size(), two.size());
    EXPECT_TRUE(one == two);
    EXPECT_TRUE(one == three);
}

TEST(WaveNumerics, AWorldWithAWaveMakerGetsTheWaveSettingsUnlessItSetsItsOwn) {
    WaveMakerDef paddle;
    paddle.x = 0.1f;
    paddle.depth = 0.2f;
    paddle.waveHeight = 0.03f;
    paddle.period = 0.8f;
    // Without a wave maker the automatic settings act as off (the solvers' own defaults).
    WorldDef still;
    still.particleSpacing = 0.05f;
    EXPECT_LT(World(still).def().solver.shifting, 0.0f);
    EXPECT_LT(World(still).def().solver.differenceForm, 0.0f);
    EXPECT_FALSE(World(still).def().solver.smoothDensityError.value_or(false));
    World flume = scenarios::waveFlume(0.03f, 1.5f, 0.2f, paddle, 0.4f, 1);
    const SolverDef& s = flume.def().solver;
    EXPECT_EQ(s.shifting, 0.2f);
    EXPECT_EQ(s.differenceForm, 0.5f);
    EXPECT_EQ(s.xsph, 0.0f);
    EXPECT_EQ(s.smoothDensityError, std::optional<bool>(false)) << "the filtered residual is for 2D waves";
    EXPECT_LT(s.momentum, 0.0f) << "the density solve keeps its heavy ball";
    // In 2D the difference form stays off (it diverged in a deep 2D flume).
    const SolverDef planar = scenarios::planarFlume(0.03f, 1.5f, paddle, 0.4f, 1).def().solver;
    EXPECT_EQ(planar.shifting, 0.2f);
    EXPECT_EQ(planar.differenceForm, 0.0f);
    EXPECT_EQ(planar.smoothDensityError, std::optional<bool>(true));
    // A solitary wave keeps no more height with the filtered residual (wave_numerics.hpp).
    WaveMakerDef solitary = paddle;
    solitary.type = WaveMakerDef::Type::Solitary;
    EXPECT_EQ(scenarios::planarFlume(0.03f, 1.5f, solitary, 0.4f, 1).def().solver.smoothDensityError, std::optional<bool>(false));
    // What a scene sets stays.
    SolverDef own;
    own.shifting = 0.0f;
    own.xsph = 0.01f;
    World mine = scenarios::waveFlume(0.03f, 1.5f, 0.2f, paddle, 0.4f, 1, 4, own);
    EXPECT_EQ(mine.def().solver.shifting, 0.0f);
    EXPECT_EQ(mine.def().solver.xsph, 0.01f);
    EXPECT_EQ(mine.def().solver.differenceForm, 0.5f);
    SolverDef plain;
    plain.smoothDensityError = false;
    EXPECT_EQ(scenarios::planarFlume(0.03f, 1.5f, paddle, 0.4f, 1, plain).def().solver.smoothDensityError, std::optional<bool>(false));
}

}  // namespace
