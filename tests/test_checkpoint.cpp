// Checkpoints: a restored World continues bit for bit; damaged files and misfit states are
// refused whole; the per-step divergence guard names the step, particle and quantity.
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <tide/io/checkpoint.hpp>
#include <tide/world.hpp>

#include "testing/scenarios.hpp"

namespace {

using namespace tide;

/// Every array of the store, byte for byte, and the clock.
void expectIdentical(const World& a, const World& b) {
    const ParticleStore& p = a.particles();
    const ParticleStore& q = b.particles();
    ASSERT_EQ(p.size(), q.size());
    const auto same = [](const auto& x, const auto& y) {
        return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0;
    };
    EXPECT_TRUE(same(p.position, q.position));
    EXPECT_TRUE(same(p.velocity, q.velocity));
    EXPECT_TRUE(same(p.acceleration, q.acceleration));
    EXPECT_TRUE(same(p.density, q.density));
    EXPECT_TRUE(same(p.pressure, q.pressure));
    EXPECT_TRUE(same(p.warmKappa, q.warmKappa));
    EXPECT_TRUE(same(p.warmDivergence, q.warmDivergence));
    EXPECT_TRUE(same(p.id, q.id));
    EXPECT_EQ(a.time(), b.time());
    EXPECT_EQ(a.stats().steps, b.stats().steps);
    EXPECT_EQ(a.stats().pressureIterationsSum, b.stats().pressureIterationsSum);
}

/// Runs `first` steps, checkpoints through the file format, runs `second` more; a fresh
/// World restored from the bytes must end bit-identical to the uninterrupted one.
void expectResumesIdentically(const std::function<World()>& make, int first, int second) {
    World uninterrupted = make();
    for (int s = 0; s < first; ++s) uninterrupted.step(1.0);
    const std::string bytes = io::encodeCheckpoint(uninterrupted.saveState(), "app");
    for (int s = 0; s < second; ++s) uninterrupted.step(1.0);

    World resumed = make();
    io::Checkpoint c = io::decodeCheckpoint(bytes, "memory");
    EXPECT_EQ(c.application, "app");
    resumed.restoreState(std::move(c.world));
    for (int s = 0; s < second; ++s) resumed.step(1.0);
    expectIdentical(uninterrupted, resumed);
}

TEST(Checkpoint, DfsphDamBreakResumesBitIdentically) {
    // 31 + 20 steps cross a reorder (every 25 steps) on both sides of the checkpoint.
    expectResumesIdentically([] { return scenarios::damBreak(0.02f, 2, 0.6f, 0.2f, 0.2f, 25, "dfsph"); }, 31, 20);
}

TEST(Checkpoint, PcisphAndWcsphResumeBitIdentically) {
    expectResumesIdentically([] { return scenarios::damBreak(0.02f, 2, 0.6f, 0.2f, 0.2f, 25, "pcisph"); }, 12, 12);
    expectResumesIdentically([] { return scenarios::damBreak(0.02f, 2, 0.6f, 0.2f, 0.2f, 25, "wcsph"); }, 12, 12);
}

TEST(Checkpoint, EmitterAndWaveMakerResumeBitIdentically) {
    const auto jet = [] {
        World w = scenarios::stillWater(0.06f, 0.3f, 0.02f, 2, "dfsph");
        EmitterDef e;
        e.min = {0.02f, 0.08f, 0.1f};
        e.max = {0.02f, 0.1f, 0.14f};
        e.velocity = {1.0f, 0.0f, 0.0f};
        w.addEmitter(e);
        return w;
    };
    expectResumesIdentically(jet, 15, 15);
    const auto flume = [] {
        WaveMakerDef paddle;
        paddle.x = 0.1f;
        paddle.depth = 0.12f;
        paddle.waveHeight = 0.02f;
        paddle.period = 0.8f;
        paddle.rampTime = 0.1f;
        return scenarios::waveFlume(0.02f, 1.0f, 0.12f, paddle, 0.3f, 2);
    };
    expectResumesIdentically(flume, 15, 15);
}

TEST(Checkpoint, MovingObstaclesResumeBitIdentically) {
    // Their motion is a function of time: the restored World places them where they were.
    expectResumesIdentically([] { return scenarios::pushedPlate(0.02f, 0.8f, 0.1f, 0.2f, 2); }, 15, 15);
    expectResumesIdentically([] { return scenarios::spinningCylinder(0.02f, 0.2f, 0.04f, 3.0f, 1.0f, 2, "pcisph"); }, 12, 12);
}

TEST(Checkpoint, EveryFlippedByteAndEveryTruncationIsRefused) {
    World world = scenarios::damBreak(0.04f, 1, 0.4f, 0.12f, 0.12f, 25, "dfsph");
    world.step(1.0);
    const std::string good = io::encodeCheckpoint(world.saveState(), "frame 3");
    ASSERT_NO_THROW((void)io::decodeCheckpoint(good, "good"));
    EXPECT_GT(good.size(), 60u * world.particles().size());  // ~70 bytes per particle
    for (std::size_t at = 0; at < good.size(); at += 7) {
        std::string bad = good;
        bad[at] = static_cast<char>(bad[at] ^ 0x10);
        EXPECT_THROW((void)io::decodeCheckpoint(bad, "flipped"), io::CheckpointError) << "byte " << at;
    }
    for (std::size_t length : {std::size_t{0}, std::size_t{5}, std::size_t{27}, std::size_t{28}, good.size() / 2, good.size() - 1})
        EXPECT_THROW((void)io::decodeCheckpoint(good.substr(0, length), "truncated"), io::CheckpointError) << length;
    try {
        std::string bad = good;
        bad[good.size() / 2] = static_cast<char>(bad[good.size() / 2] ^ 1);
        (void)io::decodeCheckpoint(bad, "cp.tidecp");
        FAIL();
    } catch (const io::CheckpointError& e) {
        EXPECT_NE(std::string(e.what()).find("cp.tidecp: damaged checkpoint: checksum mismatch"), std::string::npos) << e.what();
    }
}

TEST(Checkpoint, AStateThatDoesNotFitTheWorldChangesNothing) {
    World world = scenarios::damBreak(0.04f, 1, 0.4f, 0.12f, 0.12f, 25, "dfsph");
    world.step(1.0);
    const WorldState good = world.saveState();
    const double time = world.time();
    const float x0 = world.particles().position[0].x;

    WorldState badMaterial = good;
    badMaterial.particles.material[3] = 7;
    EXPECT_THROW(world.restoreState(badMaterial), std::invalid_argument);
    WorldState extraEmitter = good;
    extraEmitter.emitters.push_back({});
    EXPECT_THROW(world.restoreState(extraEmitter), std::invalid_argument);
    WorldState noSolverScalars = good;
    noSolverScalars.solverState.clear();
    EXPECT_THROW(world.restoreState(noSolverScalars), std::invalid_argument);
    WorldState farAway = good;
    farAway.particles.position[2].y = 1e30f;
    EXPECT_THROW(world.restoreState(farAway), std::invalid_argument);
    WorldState shortArray = good;
    shortArray.particles.warmKappa.pop_back();
    EXPECT_THROW(world.restoreState(shortArray), std::invalid_argument);

    EXPECT_EQ(world.time(), time);
    EXPECT_EQ(world.particles().position[0].x, x0);
    World other = scenarios::damBreak(0.04f, 1, 0.4f, 0.12f, 0.12f, 25, "classic");  // no solver scalars
    EXPECT_THROW(other.restoreState(good), std::invalid_argument);
}

TEST(DivergenceGuard, AHugeForcedTimeStepStopsAtTheStepWithTheParticleAndQuantity) {
    WorldDef def;
    def.domainMax = {0.4f, 0.4f, 0.4f};
    def.particleSpacing = 0.02f;
    def.threads = 2;
    def.solver.method = "wcsph";
    def.solver.minDt = 0.05f;  // ~100 × the CFL step of this stiff fluid
    def.solver.maxDt = 0.05f;
    World world(def);
    world.addMaterial(MaterialDef{});
    world.addBlock({{0.0f, 0.0f, 0.0f}, {0.2f, 0.2f, 0.4f}, {}, 0});
    std::optional<Divergence> caught;
    for (int s = 0; s < 50 && !caught; ++s) {
        try {
            world.step(1.0);
        } catch (const DivergenceError& e) {
            caught = e.divergence;
            EXPECT_NE(std::string(e.what()).find("step " + std::to_string(e.divergence.step)), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("particle "), std::string::npos) << e.what();
        }
    }
    ASSERT_TRUE(caught) << "a 0.05 s step of a 0.02 m wcsph fluid did not diverge in 50 steps";
    EXPECT_EQ(caught->step, world.stats().steps);
    EXPECT_DOUBLE_EQ(caught->time, world.time());
    EXPECT_EQ(caught->dt, static_cast<double>(0.05f));
    std::printf("%s\n", caught->describe().c_str());
    EXPECT_LT(caught->particle, world.particles().size());
    EXPECT_EQ(world.particles().id[caught->particle], caught->id);
    if (caught->quantity == DivergedQuantity::Speed) {
        EXPECT_GT(caught->value, caught->limit);
    }
    ASSERT_TRUE(world.divergence());
    EXPECT_THROW(world.step(1.0), DivergenceError);  // no stepping on from garbage
    EXPECT_EQ(world.stats().steps, caught->step);
    world.clear();
    EXPECT_FALSE(world.divergence());
}

TEST(DivergenceGuard, ASaneDamBreakNeverTrips) {
    World world = scenarios::damBreak(0.02f, 2, 0.6f, 0.2f, 0.2f, 25, "dfsph");
    EXPECT_NO_THROW(world.advance(0.3));
    EXPECT_FALSE(world.divergence());
    EXPECT_GT(world.stats().maxSpeed, 1.0f);  // the wave did run
}

TEST(Crc32, MatchesTheStandardCheckValue) {
    EXPECT_EQ(io::crc32("123456789"), 0xCBF43926u);  // the CRC-32/ISO-HDLC check value
    EXPECT_EQ(io::crc32(""), 0u);
    EXPECT_EQ(io::crc32("56789", io::crc32("1234")), 0xCBF43926u);
}

}  // namespace
