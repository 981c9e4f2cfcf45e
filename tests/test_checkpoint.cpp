// Checkpoints: a restored World continues bit for bit; damaged files and misfit states are
// refused whole; the per-step divergence guard names the step, particle and quantity.
#include <cstdio>
#include <cstring>
#include <functional>
#include <optional>
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
    EXPECT_EQ(a.stats().unconvergedSolves, b.stats().unconvergedSolves);
    EXPECT_EQ(a.stats().recentUnconverged, b.stats().recentUnconverged);
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

/// `current` (a version-4 file) as the older `version` wrote it. Version 3 lacks the
/// divergence solve's iteration sum, 8 bytes after the phase times; version 2 also the 12
/// bytes of the two unconverged-solve stats, which follow the pressure iteration sum. Where
/// they sit: after the header (magic, version, byte order, size, CRC), the time, sound speed
/// and reorder counter (16 bytes), then the stats up to that sum (48 bytes); the rest of the
/// stats up to the divergence sum is 80 bytes.
std::string downgrade(const std::string& latest, std::uint32_t version) {
    constexpr std::size_t header = 8 + 4 + 4 + 8 + 4, unconverged = header + 16 + 48, divergence = unconverged + 12 + 80;
    // Version 5's count of body scalars and version 6's of wave maker scalars (0 and 0: no
    // bodies, no wave maker), then version 7's two ocean counts (8 bytes each), sit before the
    // application block "app" (its 8-byte length and 3 bytes).
    std::string current = latest;
    current.erase(current.size() - 3 - 8 - 16 - 8, 8 + 16);
    std::string payload = current.substr(header, divergence - header) + current.substr(divergence + 8);
    if (version < 3) payload = payload.substr(0, unconverged - header) + payload.substr(unconverged + 12 - header);
    std::string old = current.substr(0, header);
    const std::uint32_t crc = io::crc32(payload);
    const std::uint64_t size = payload.size();
    std::memcpy(old.data() + 8, &version, 4);
    std::memcpy(old.data() + 16, &size, 8);
    std::memcpy(old.data() + 24, &crc, 4);
    return old + payload;
}

TEST(Checkpoint, Version2And3FilesStillResume) {
    const auto make = [] { return scenarios::damBreak(0.04f, 1, 0.4f, 0.12f, 0.12f, 25, "dfsph"); };
    World uninterrupted = make();
    for (int s = 0; s < 5; ++s) uninterrupted.step(1.0);
    const std::string v4 = io::encodeCheckpoint(uninterrupted.saveState(), "app");
    ASSERT_GT(uninterrupted.stats().divergenceIterationsSum, 0u);
    ASSERT_EQ(io::decodeCheckpoint(v4, "memory").world.stats.divergenceIterationsSum,
              uninterrupted.stats().divergenceIterationsSum);
    std::vector<World> resumed;
    for (const std::uint32_t version : {2u, 3u}) {
        io::Checkpoint c = io::decodeCheckpoint(downgrade(v4, version), "memory");
        EXPECT_EQ(c.world.stats.unconvergedSolves, version >= 3 ? uninterrupted.stats().unconvergedSolves : 0u);
        EXPECT_EQ(c.world.stats.pressureIterationsSum, uninterrupted.stats().pressureIterationsSum);
        EXPECT_EQ(c.world.stats.divergenceIterationsSum, 0u) << "version " << version;
        resumed.push_back(make());
        resumed.back().restoreState(std::move(c.world));
    }
    for (int s = 0; s < 5; ++s) {
        uninterrupted.step(1.0);
        for (World& w : resumed) w.step(1.0);
    }
    for (const World& w : resumed) expectIdentical(uninterrupted, w);

    std::string v9 = v4;
    const std::uint32_t future = 9;
    std::memcpy(v9.data() + 8, &future, 4);
    try {
        (void)io::decodeCheckpoint(v9, "memory");
        ADD_FAILURE() << "a version 9 checkpoint was read";
    } catch (const io::CheckpointError& e) {
        EXPECT_NE(std::string(e.what()).find("version 9, this tide reads 2 to 7"), std::string::npos) << e.what();
    }
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

/// Steps until World::step throws DivergenceError (its what() is the report's describe()), at most `steps` times.
std::optional<Divergence> stepUntilDivergence(World& world, int steps) {
    for (int s = 0; s < steps; ++s) {
        try {
            world.step(1.0);
        } catch (const DivergenceError& e) {
            EXPECT_EQ(std::string(e.what()), e.divergence.describe());
            return e.divergence;
        }
    }
    return std::nullopt;
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
    const std::optional<Divergence> caught = stepUntilDivergence(world, 50);
    ASSERT_TRUE(caught) << "a 0.05 s step of a 0.02 m wcsph fluid did not diverge in 50 steps";
    EXPECT_NE(caught->describe().find("step " + std::to_string(caught->step)), std::string::npos) << caught->describe();
    EXPECT_NE(caught->describe().find("particle "), std::string::npos) << caught->describe();
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

// The density solve of 0.3 m of water at 2 cm without the heavy ball needs ~35 Jacobi
// iterations a step (docs/waves.md); capped at 3 it stops short in every step and leaves the
// water compressed beyond its tolerance. The stats count those steps; a divergence after
// them names them, with the knobs that help.
TEST(DivergenceGuard, PressureSolvesThatStopShortAreCountedAndNamedInADivergence) {
    WorldDef def;
    def.particleSpacing = 0.02f;
    def.threads = 2;
    def.solver.momentum = 0.0f;
    WorldDef cappedDef = def;
    cappedDef.solver.maxIterations = 3;
    World capped = scenarios::stillTank(cappedDef, 0.4f, 0.3f, 4);
    World uncapped = scenarios::stillTank(def, 0.4f, 0.3f, 4);
    for (int s = 0; s < 100; ++s) {
        capped.step(1.0);
        uncapped.step(1.0);
    }
    const WorldStats& c = capped.stats();
    const WorldStats& u = uncapped.stats();
    std::printf("capped at 3: %llu of %llu steps unconverged, compression %.3f %%; uncapped: %llu, %.3f %%\n",
                static_cast<unsigned long long>(c.unconvergedSolves), static_cast<unsigned long long>(c.steps),
                100.0 * c.meanCompression, static_cast<unsigned long long>(u.unconvergedSolves), 100.0 * u.meanCompression);
    EXPECT_GE(c.unconvergedSolves, 90u);
    EXPECT_EQ(c.recentUnconverged, 0xffffffffu);
    EXPECT_GT(c.meanCompression, def.solver.maxDensityError);
    EXPECT_EQ(u.unconvergedSolves, 0u);
    EXPECT_EQ(u.recentUnconverged, 0u);
    EXPECT_LE(u.meanCompression, def.solver.maxDensityError);

    // Forced 50 ms steps (≈10× the step limits) with the cap: the solves stop short, then it blows up.
    cappedDef.solver.minDt = cappedDef.solver.maxDt = 0.05f;
    World forced = scenarios::stillTank(cappedDef, 0.4f, 0.3f, 4);
    const std::optional<Divergence> caught = stepUntilDivergence(forced, 50);
    ASSERT_TRUE(caught) << "50 ms steps of 0.3 m of water at 2 cm did not diverge in 50 steps";
    const std::string text = caught->describe();
    std::printf("%s\n", text.c_str());
    EXPECT_EQ(caught->unconvergedOfLast32, static_cast<int>(std::min<std::uint64_t>(forced.stats().steps, 32)));
    EXPECT_EQ(caught->maxIterations, 3);
    const std::string window = std::to_string(std::min<std::uint64_t>(caught->step, 32));
    EXPECT_NE(text.find(std::to_string(caught->unconvergedOfLast32) + " of the last " + window +
                        " steps (solver.max_iterations 3)"),
              std::string::npos);
    EXPECT_NE(text.find("raise solver.max_iterations"), std::string::npos);
    EXPECT_EQ(caught->solver, "dfsph");
    EXPECT_EQ(caught->densityRatio, 1.0f);
    EXPECT_EQ(text.find("pcisph"), std::string::npos) << "one rest density: no hint of another solver";
}

// A dfsph run with rest densities 5:1 or more apart that diverges is pointed at pcisph, which
// holds the thin layers and thin boxes dfsph's Jacobi solve does not (docs/robustness.md); other
// solvers and closer densities are not.
TEST(DivergenceGuard, DfsphWithDensitiesFarApartIsPointedAtPcisph) {
    Divergence d;
    d.step = 12;
    d.quantity = DivergedQuantity::Speed;
    d.unconvergedOfLast32 = 3;
    d.maxIterations = 100;
    d.solver = "dfsph";
    d.densityRatio = 25.0f;
    EXPECT_NE(d.describe().find("25:1 apart"), std::string::npos) << d.describe();
    EXPECT_NE(d.describe().find("solver.method \"pcisph\""), std::string::npos) << d.describe();
    d.densityRatio = 2.0f;
    EXPECT_EQ(d.describe().find("pcisph"), std::string::npos) << d.describe();
    d.densityRatio = 25.0f;
    d.solver = "pcisph";
    EXPECT_EQ(d.describe().find("apart"), std::string::npos) << d.describe();
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
