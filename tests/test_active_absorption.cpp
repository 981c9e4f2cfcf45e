// Active absorption at the piston (issue 42; sources/active_absorption_schaffer_klopman2000.hpp):
// the absorption law against linear wavemaker theory, its drift correction, the flume closed
// by a wall (acceptance 4, at a small resolution; the long run is bench/closed_flume.cpp),
// determinism across thread counts, checkpoint resume and the scene key.
#include <cmath>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <tide/io/checkpoint.hpp>
#include <tide/io/scene.hpp>
#include <tide/world.hpp>

#include "sources/active_absorption_schaffer_klopman2000.hpp"
#include "sources/wave_theory.hpp"
#include "testing/scenarios.hpp"
#include "testing/wave_analysis.hpp"

namespace {

using namespace tide;

constexpr double kG = 9.81;

WaveMakerDef piston(float depth, float height, float period, float ramp) {
    WaveMakerDef p;
    p.x = 0.1f;
    p.depth = depth;
    p.waveHeight = height;
    p.period = period;
    p.rampTime = ramp;
    return p;
}

TEST(ActiveAbsorption, GainIsThePistonsInverseTransferFunctionAndSqrtGOverDForLongWaves) {
    // The issue's flume: kd = 0.946, F = H/S = 0.931, ω/F = 5.62 1/s (√(g/d) = 6.26 over-absorbs by 11 %).
    const WaveMakerDef flume = piston(0.25f, 0.03f, 1.2f, 2.0f);
    const ActiveAbsorption a(flume, waves::paddleComponents(flume, kG), kG, 0.0125f);
    const double omega = 2.0 * std::numbers::pi / static_cast<double>(1.2f);
    const double kd = waves::waveNumber(omega, static_cast<double>(0.25f), kG) * static_cast<double>(0.25f);
    EXPECT_NEAR(kd, 0.946, 0.001);
    EXPECT_NEAR(a.gain(), omega / waves::pistonHeightToStroke(kd), 1e-12);
    EXPECT_NEAR(a.gain(), 5.62, 0.01);
    EXPECT_NEAR(a.gaugeDistance(), 5 * 0.0125, 1e-7);
    // A long wave (kd = 0.08): the shallow-water form DualSPHysics uses.
    const WaveMakerDef longWave = piston(0.25f, 0.01f, 20.0f, 2.0f);
    const ActiveAbsorption b(longWave, waves::paddleComponents(longWave, kG), kG, 0.0125f);
    EXPECT_NEAR(b.gain() / std::sqrt(kG / 0.25), 1.0, 0.002);
}

TEST(ActiveAbsorption, AbsorbsAWaveComingBackAndIgnoresAMeasurementBias) {
    const WaveMakerDef flume = piston(0.25f, 0.03f, 1.2f, 2.0f);
    ActiveAbsorption a(flume, waves::paddleComponents(flume, kG), kG, 0.0125f);
    const double omega = 2.0 * std::numbers::pi / 1.2, still = 0.25, dt = 0.005;
    // The gauge reads the target, a wave coming back (5 mm) and a bias of 3 mm from the start; the paddle
    // integrates its correction as the World does.
    double offset = 0.0, u = 0.0, sumUR = 0.0, sumRR = 0.0, largest = 0.0, t = 0.0;
    for (; t < 2.0 + 24 * 1.2; t += dt) {
        // It arrives at 4 s (after the ramp), rising over 2 s as a reflection would.
        const double back = 0.005 * std::cos(omega * t + 0.7) * waves::ramp(t - 4.0, 2.0).value;
        const double y = still + a.targetElevation(t) + back + 0.003;
        u = a.correctionVelocity(t, static_cast<float>(y), still, offset, u);
        offset += u * dt;
        if (t > 2.0 + 12 * 1.2) {  // after three drift times
            sumUR += u * back;
            sumRR += back * back;
            largest = std::max(largest, std::abs(offset));
        }
    }
    // U = −G η_R: the regression of U on the returning wave is −G, within the drift
    // correction's few per cent (float rounding of the reading is 3e-8 m).
    EXPECT_NEAR(sumUR / sumRR / -a.gain(), 1.0, 0.05);
    // The bias moves nothing (it is in the first reading, of still water): the paddle's
    // correction is the returning wave's, G·a/ω = 5.4 mm.
    EXPECT_LT(largest, 1.2 * a.gain() * 0.005 / omega);
    // A misreading (a splash 0.3 m above the line) changes the correction's velocity by at
    // most twice the stroke's peak acceleration over the step (0.44 m/s² · 2 · 5 ms here; t is
    // the step after the loop's last).
    const double peak = waves::paddleComponents(flume, kG).front().amplitude * omega * omega;
    const double jump = a.correctionVelocity(t, static_cast<float>(still + 0.3), still, offset, u) - u;
    EXPECT_GT(std::abs(jump), 0.5 * 2.0 * peak * dt);
    EXPECT_LE(std::abs(jump), 2.0 * peak * dt * 1.001);
    // Nothing during the ramp.
    ActiveAbsorption fresh(flume, waves::paddleComponents(flume, kG), kG, 0.0125f);
    EXPECT_EQ(fresh.correctionVelocity(1.0, 0.3f, still, 0.0, 0.0), 0.0);
}

/// The wave-height envelopes (periods 10-15, 25-30) at three gauges of a 2D flume closed by
/// a wall 2.74 m from the paddle, 2 cm, H = 0.04 m, T = 1 s in 0.3 m of water, at the 2D wave
/// defaults and up to 1000 density iterations; the gauges at a quarter, half and three quarters
/// of the way (the run of `tide_closed_flume`, bench/closed_flume.cpp, at its defaults).
struct Envelopes {
    std::vector<double> early, late;
};
Envelopes closedFlume(bool absorb) {
    WaveMakerDef paddle = piston(0.3f, 0.04f, 1.0f, 2.0f);
    paddle.absorption = absorb ? WaveMakerDef::Absorption::On : WaveMakerDef::Absorption::Off;
    SolverDef solver;
    solver.maxIterations = 1000;
    const float spacing = 0.02f, length = 2.84f, span = length - paddle.x;
    World world = scenarios::planarFlume(spacing, length, paddle, 0.0f, 1, solver);
    const std::vector<float> at{paddle.x + 0.25f * span, paddle.x + 0.5f * span, paddle.x + 0.75f * span};
    std::vector<waves::Record> records(at.size(), waves::Record{0.02, 0.02, {}});
    for (int k = 0; k < 1500; ++k) {
        world.advance(0.02);
        for (std::size_t g = 0; g < at.size(); ++g) records[g].eta.push_back(world.surfaceHeight(at[g], 0.0f) - 0.3);
    }
    Envelopes e;
    for (const auto& r : records) {
        e.early.push_back(waves::envelope(r, 1.0, 10, 15));
        e.late.push_back(waves::envelope(r, 1.0, 25, 30));
    }
    return e;
}

// Issue 42's acceptance 4. A piston that does not absorb reflects like a wall, so the flume is a
// cavity whose forced standing wave grows like 1/|sin kL|, without bound in linear theory where
// kL = nπ. 2.74 m (two Airy wave lengths, 2.746 m) is the middle of the resonance a scan of
// lengths found at the defaults (docs/notes/waves.md § The closed flume at resonance) and the
// gauges stand on the standing wave's antinodes. Measured: 0.943, 0.952, 1.035 with absorption,
// 1.469, 1.500, 1.535 without (0.0533 against 0.113 m at the first gauge over periods 25-30).
// At 3.0 m (kL = 4.37π, off resonance) neither grew: 1.077, 1.004, 1.119 and 0.899, 0.877, 1.037.
TEST(ClosedFlume, AbsorptionHoldsTheEnvelopeSteadyWhereWithoutItTheResonantFlumeGrows) {
    const Envelopes on = closedFlume(true), off = closedFlume(false);
    for (std::size_t g = 0; g < on.early.size(); ++g) {
        std::printf("gauge %zu: absorbing %.4f -> %.4f m, reflecting %.4f -> %.4f m\n", g, on.early[g], on.late[g],
                    off.early[g], off.late[g]);
        EXPECT_GT(on.early[g], 0.01) << "gauge " << g;  // waves, not noise
        EXPECT_NEAR(on.late[g] / on.early[g], 1.0, 0.10) << "gauge " << g;
        EXPECT_GT(off.late[g] / off.early[g], 1.25) << "gauge " << g;  // the contrast: it keeps growing
    }
}

/// A short 2D flume with a damping zone and an absorbing paddle with a short ramp.
World absorbingFlume(int threads, WaveMakerDef::Absorption absorption = WaveMakerDef::Absorption::On,
                     float dampingLength = 0.4f) {
    WaveMakerDef paddle = piston(0.3f, 0.04f, 1.0f, 0.2f);
    paddle.absorption = absorption;
    return scenarios::planarFlume(0.02f, 1.6f, paddle, dampingLength, threads);
}

/// The absorbing flume run past the start of the absorption: every particle by id, and the
/// paddle's displacement.
std::vector<glm::vec3> absorbingRun(int threads, double seconds, double* displacement = nullptr) {
    World world = absorbingFlume(threads);
    world.advance(seconds);
    if (displacement) *displacement = world.waveMakerDisplacement(0, world.time());
    const ParticleStore& p = world.particles();
    std::vector<glm::vec3> byId(2 * p.size());
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        byId[p.id[i]] = p.position[i];
        byId[p.size() + p.id[i]] = p.velocity[i];
    }
    return byId;
}

TEST(ActiveAbsorption, CorrectsThePaddleBitIdenticallyOnOneAndTwoThreadsAndIsOnByDefaultWithADampingZone) {
    double moved = 0.0;
    const auto one = absorbingRun(1, 0.6, &moved), two = absorbingRun(2, 0.6);
    ASSERT_EQ(one.size(), two.size());
    EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(glm::vec3)), 0);
    // The prescribed stroke alone at 0.6 s, against which the correction shows.
    World plain = absorbingFlume(1, WaveMakerDef::Absorption::Off);
    const double prescribed = plain.waveMakerDisplacement(0, 0.6);
    EXPECT_GT(std::abs(moved - prescribed), 1e-5);
    // Automatic: on where the far end absorbs (here a damping zone), off where it reflects.
    World automatic = absorbingFlume(1, WaveMakerDef::Absorption::Automatic);
    automatic.advance(0.6);
    EXPECT_EQ(automatic.waveMakerDisplacement(0, 0.6), moved);
    World closed = absorbingFlume(1, WaveMakerDef::Absorption::Automatic, 0.0f);
    closed.advance(0.6);
    EXPECT_EQ(closed.waveMakerDisplacement(0, 0.6), prescribed);
}

TEST(ActiveAbsorption, ResumesBitIdenticallyFromACheckpoint) {
    const auto make = [] { return absorbingFlume(1); };
    World uninterrupted = make();
    uninterrupted.advance(0.4);  // the absorption runs from 0.2 s
    const std::string bytes = io::encodeCheckpoint(uninterrupted.saveState(), "test");
    EXPECT_EQ(uninterrupted.saveState().paddleState.size(), 6u);
    uninterrupted.advance(0.3);
    World resumed = make();
    resumed.restoreState(io::decodeCheckpoint(bytes, "memory").world);
    resumed.advance(0.3);
    const ParticleStore& a = uninterrupted.particles();
    const ParticleStore& b = resumed.particles();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.position.data(), b.position.data(), a.size() * sizeof(glm::vec3)), 0);
    EXPECT_EQ(std::memcmp(a.velocity.data(), b.velocity.data(), a.size() * sizeof(glm::vec3)), 0);
    EXPECT_EQ(uninterrupted.waveMakerDisplacement(0, uninterrupted.time()), resumed.waveMakerDisplacement(0, resumed.time()));
    // A state from another world is refused, naming what does not fit.
    WorldState wrong = uninterrupted.saveState();
    wrong.paddleState.push_back(0.0);
    World other = make();
    try {
        other.restoreState(wrong);
        ADD_FAILURE() << "a misfit state was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("7 wave maker scalars saved"), std::string::npos) << e.what();
    }
}

/// The problems parseScene reports for `text` (empty when it parses).
std::string sceneProblems(const std::string& text) {
    try {
        io::parseScene(text, "scene.json", ".");
    } catch (const io::SceneError& e) {
        std::string all;
        for (const auto& p : e.problems) all += p + "\n";
        return all;
    }
    return "";
}

std::string flumeScene(const std::string& wavemakerExtra) {
    return R"({"dimensions": 2, "domain": {"min": [0, 0], "max": [3, 0.6]}, "gravity": [0, -9.81],
      "particle_spacing": 0.02, "end_time": 0.1, "materials": [{"name": "water", "density": 1000}],
      "wavemaker": {"type": "piston", "x": 0.1, "depth": 0.3, "wave_height": 0.04, "period": 1.0)" +
           wavemakerExtra + R"(},
      "blocks": [{"min": [0.1, 0], "max": [3, 0.3], "material": "water"}]})";
}

TEST(ActiveAbsorption, SceneKeyIsABooleanAndRefusedWhereItDoesNotApply) {
    EXPECT_EQ(io::parseScene(flumeScene(""), "s.json", ".").waveMakers.at(0).absorption, WaveMakerDef::Absorption::Automatic);
    EXPECT_EQ(io::parseScene(flumeScene(R"(, "absorption": true)"), "s.json", ".").waveMakers.at(0).absorption,
              WaveMakerDef::Absorption::On);
    EXPECT_EQ(io::parseScene(flumeScene(R"(, "absorption": false)"), "s.json", ".").waveMakers.at(0).absorption,
              WaveMakerDef::Absorption::Off);
    EXPECT_NE(sceneProblems(flumeScene(R"(, "absorption": "yes")")).find("wavemaker.absorption: must be true or false, got \"yes\""),
              std::string::npos);
    WaveMakerDef flap = piston(0.3f, 0.04f, 1.0f, 2.0f);
    flap.type = WaveMakerDef::Type::Flap;
    flap.absorption = WaveMakerDef::Absorption::On;
    try {
        scenarios::planarFlume(0.02f, 3.0f, flap);
        ADD_FAILURE() << "a flap with absorption was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("wavemaker.absorption: active absorption is for a piston"), std::string::npos)
            << e.what();
    }
}

}  // namespace
