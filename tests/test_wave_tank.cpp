// Acceptance of the numerical wave tank (issue 6): regular waves from a piston paddle in a
// flume with a damping zone, against linear wave theory, and waves breaking on a beach.
//
// Both run in the suite: the flume (2 cm, 11,700 particles, 9 s) takes ~45 s of one core,
// the beach (1.5 cm, 8 s) ~70 s (they were opt-in when they took 10-20 min, and while they
// were, both drifted into failing unseen: docs/waves.md § The acceptance in the suite). The
// short checks of the same machinery (paddle, gauges, probes, damping, mass) are in
// test_wave_gauges.cpp. The TIDE_WAVE_* and TIDE_BEACH_* variables change a run's settings
// for measurements (docs/waves.md gives the commands).
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <tide/world.hpp>

#include "sources/wave_theory.hpp"
#include "testing/scenarios.hpp"
#include "testing/wave_analysis.hpp"

namespace {

using namespace tide;

double envOr(const char* name, double fallback) {
    const char* v = std::getenv(name);
    return v ? std::atof(v) : fallback;
}

struct FlumeRun {
    std::vector<float> gaugeX;
    std::vector<waves::Record> records;
    std::uint32_t particlesBefore = 0, particlesAfter = 0;
    double massBefore = 0.0, massAfter = 0.0;
    std::uint32_t escaped = 0;
};

/// Runs the flume of the acceptance tests for `duration` s, sampling gauges every `sample` s.
FlumeRun runFlume(float spacing, float length, float dampingLength, const std::vector<float>& gauges, double duration,
                  double sample) {
    WaveMakerDef paddle;
    paddle.type = WaveMakerDef::Type::Piston;
    paddle.x = 0.1f;
    paddle.depth = 0.3f;
    paddle.waveHeight = 0.04f;
    paddle.period = 1.0f;
    paddle.rampTime = 2.0f;
    paddle.rampTime = static_cast<float>(envOr("TIDE_WAVE_RAMP", 2.0));
    SolverDef solver;
    solver.maxDensityError = static_cast<float>(envOr("TIDE_WAVE_ERROR", 0.003));
    solver.maxDt = static_cast<float>(envOr("TIDE_WAVE_MAXDT", solver.maxDt));
    // No XSPH smoothing: as an artificial viscosity acting every step it halves the wave height
    // the flume keeps (docs/waves.md: −22.7 % with dfsph's default ε = 0.01, −14.1 % without).
    solver.xsph = static_cast<float>(envOr("TIDE_WAVE_XSPH", 0.0));
    // No momentum in the density solve: it halves the iterations but the waves lose more
    // height (docs/waves.md: −18.9 % instead of −14.1 %).
    solver.momentum = static_cast<float>(envOr("TIDE_WAVE_MOMENTUM", 0.0));
    // Particle shifting with the difference form of the pressure's own term, as the wave
    // benchmark: without them these waves lose 13-16 % of their height by the gauges and
    // the figure is a draw either side of the 15 % asked; with them 3-6 % (docs/waves.md).
    solver.shifting = static_cast<float>(envOr("TIDE_WAVE_SHIFTING", 0.2));
    solver.differenceForm = static_cast<float>(envOr("TIDE_WAVE_DIFFERENCE", 0.5));
    if (const char* model = std::getenv("TIDE_WAVE_VISCOSITY")) solver.viscosity = model;
    if (const char* method = std::getenv("TIDE_WAVE_SOLVER")) solver.method = method;
    if (const char* kernel = std::getenv("TIDE_WAVE_KERNEL"); kernel && std::string(kernel) == "wendland_c2")
        solver.kernel = KernelShape::WendlandC2;
    solver.soundSpeed = static_cast<float>(envOr("TIDE_WAVE_SOUND_SPEED", solver.soundSpeed));
    const float supportRatio =
        scenarios::resolvedSupportRatio(solver, static_cast<float>(envOr("TIDE_WAVE_SUPPORT_RATIO", WorldDef{}.supportRatio)));
    const int width = scenarios::periodicWidthInSpacings(supportRatio);
    World world = scenarios::waveFlume(spacing, length, paddle.depth, paddle, dampingLength,
                                       static_cast<int>(envOr("TIDE_WAVE_THREADS", 0)), width, solver, supportRatio);
    // A pre-roll of the still water before the paddle starts (World::settle), with the solver's
    // default XSPH while settling (the flume runs without; without it the settling motion
    // would not die down): the state is carried over into the flume as a checkpoint is.
    if (const double settle = envOr("TIDE_WAVE_SETTLE", 0.0); settle > 0.0) {
        SolverDef settling = solver;
        settling.xsph = -1.0f;
        World settled = scenarios::waveFlume(spacing, length, paddle.depth, paddle, dampingLength,
                                             static_cast<int>(envOr("TIDE_WAVE_THREADS", 0)), width, settling, supportRatio);
        const SettleReport report = settled.settle(settle, 0.01f);
        std::printf("flume settled %.2f s in %llu steps (fastest %.4f m/s)\n", report.seconds,
                    static_cast<unsigned long long>(report.steps), report.maxSpeed);
        world.restoreState(settled.saveState());
    }
    FlumeRun run;
    run.gaugeX = gauges;
    run.records.assign(gauges.size(), waves::Record{sample, sample, {}});
    run.particlesBefore = world.particles().size();
    run.massBefore = world.totalMass();
    const float z = 0.5f * world.def().domainMax.z;
    const auto start = std::chrono::steady_clock::now();
    const int samples = static_cast<int>(std::lround(duration / sample));
    for (int k = 0; k < samples; ++k) {
        world.advance(sample);
        for (std::size_t g = 0; g < gauges.size(); ++g) run.records[g].eta.push_back(world.surfaceHeight(gauges[g], z) - paddle.depth);
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.particlesAfter = world.particles().size();
    run.massAfter = world.totalMass();
    run.escaped = world.countEscapedParticles();
    const WorldStats& s = world.stats();
    std::printf("flume: %u particles, %.1f s simulated in %llu steps (%.2f ms mean), %.1f pressure iterations/step, "
                "%.1f s wall (%.0f particle-steps/s)\n",
                run.particlesAfter, duration, static_cast<unsigned long long>(s.steps), 1e3 * s.dtSum / s.steps,
                static_cast<double>(s.pressureIterationsSum) / s.steps, wall, run.particlesAfter * s.steps / wall);
    return run;
}

TEST(WaveTank, RegularPistonWavesMatchLinearTheory) {
    const double T = 1.0, d = 0.3, H = 0.04, g = 9.81;
    const double omega = 2.0 * std::numbers::pi / T;
    const double k = waves::waveNumber(omega, d, g), lambda = 2.0 * std::numbers::pi / k;
    const float spacing = static_cast<float>(envOr("TIDE_WAVE_SPACING", 0.02));
    const double duration = envOr("TIDE_WAVE_DURATION", 9.0);
    // Paddle at 0.1 m; gauges every 0.05 m from 0.9 to 1.9 m from it (past the evanescent
    // modes, ~3d); the damping zone over the last 1.5 m (≈ 1.1 λ) of a 4 m flume (≈ 2.9 λ).
    // Each gauge's phase carries particle noise (~0.03 rad): the fit over 11 gauges 0.1 m
    // apart read λ 0.6 % longer than over these 21 on the same run (docs/waves.md).
    std::vector<float> gauges;
    for (int j = 0; j <= 20; ++j) gauges.push_back(1.0f + 0.05f * static_cast<float>(j));
    // The gauges the figures before the least-squares fit came from (heights, two-gauge
    // phase lag and reflection): 1.0, 1.5, 1.8 and 2.0 m.
    const std::size_t g10 = 0, g15 = 10, g18 = 16, g20 = 20;
    const std::vector<std::size_t> heightGauges{g10, g15, g18, g20};
    const float length = static_cast<float>(envOr("TIDE_WAVE_LENGTH", 4.0));
    const FlumeRun run = runFlume(spacing, length, 1.5f, gauges, duration, 0.02);

    // After the ramp (2 s) and the travel of the wave front to the gauges (group velocity
    // ≈ 0.95 m/s): whole periods from 5 s on.
    const double from = envOr("TIDE_WAVE_FROM", 5.0), to = from + std::floor(duration - from + 1e-9);
    std::vector<waves::Record> w;
    for (const auto& r : run.records) w.push_back(waves::window(r, from, to));
    double heightSum = 0.0;
    std::vector<double> xs;
    std::vector<std::complex<double>> amplitudes;
    for (std::size_t i = 0; i < gauges.size(); ++i) {
        const auto c = waves::upCrossings(w[i]);
        amplitudes.push_back(waves::amplitudeAt(w[i], omega));
        xs.push_back(gauges[i]);
        std::printf("gauge x = %.2f m: %zu up-crossings, period %.4f s (T %.3f), height %.4f m (H %.3f), "
                    "first harmonic 2|A| = %.4f m\n",
                    gauges[i], c.times.size(), c.meanPeriod(), T, c.meanHeight(), H, 2.0 * std::abs(amplitudes.back()));
        EXPECT_NEAR(c.meanPeriod(), T, 0.02 * T) << "gauge " << gauges[i];
    }
    for (const std::size_t i : heightGauges) heightSum += waves::upCrossings(w[i]).meanHeight();
    const double height = heightSum / static_cast<double>(heightGauges.size());
    // Wave length: the least-squares fit of an incident and a reflected wave, with k (and the
    // spatial decay α) unknown, over all the gauges (Mansard & Funke 1980). The phase lag
    // of two gauges alone is biased by the reflected wave (up to ~Kr rad at each gauge, a few
    // per cent of the 4.6 rad between 1.0 and 2.0 m); it is printed for comparison.
    const waves::FlumeFit fit = waves::fitIncidentReflected(xs, amplitudes, 0.5 * k, 1.5 * k, -1.0, 1.0);
    const double lambdaMeasured = 2.0 * std::numbers::pi / fit.k;
    const double lag = std::arg(amplitudes[g10] / amplitudes[g20]);
    const double kTwoGauge = (lag < 0.0 ? lag + 2.0 * std::numbers::pi : lag) / (gauges[g20] - gauges[g10]);
    const double lambdaTwoGauge = 2.0 * std::numbers::pi / kTwoGauge;
    // Reflection: the two-gauge method on the gauges 0.3 m apart (≈ 0.22 λ), and the fit's.
    const auto split = waves::incidentReflected(amplitudes[g15], amplitudes[g18], k, gauges[g18] - gauges[g15]);
    std::printf("mean wave height %.4f m (target %.3f, %+.1f %%); wave length %.4f m (linear theory %.4f, %+.1f %%; "
                "two gauges at 1.0/2.0 m: %.4f m, %+.1f %%), decay %.3f 1/m; "
                "incident %.4f m, reflected %.4f m: Kr = %.3f (fit: %.3f)\n",
                height, H, 100.0 * (height / H - 1.0), lambdaMeasured, lambda, 100.0 * (lambdaMeasured / lambda - 1.0),
                lambdaTwoGauge, 100.0 * (lambdaTwoGauge / lambda - 1.0), fit.alpha, split.incident, split.reflected,
                split.coefficient(), fit.coefficient());
    EXPECT_NEAR(lambdaMeasured, lambda, 0.05 * lambda);
    EXPECT_NEAR(height, H, 0.15 * H);
    EXPECT_LT(split.coefficient(), 0.15);
    EXPECT_LT(fit.coefficient(), 0.15);
    // Mass: nothing is created or lost, to the particle.
    EXPECT_EQ(run.particlesAfter, run.particlesBefore);
    EXPECT_EQ(run.massAfter, run.massBefore);
    EXPECT_EQ(run.escaped, 0u);
}

/// Waves (H = 0.08 m, T = 1.2 s in 0.3 m of water) running up a 1:10 plane beach whose toe is
/// at x = 1.5 m (still-water line at 4.5 m): the highest crest at each gauge over the last
/// periods rises while the waves shoal, then falls after they break.
TEST(WaveTank, WavesShoalAndBreakOnABeach) {
    // 1.5 cm: at 2 cm the crest's rise over the slope is within the run's scatter (+3-5 % in
    // today's draws against the 10 % asked, +13-44 % in earlier ones: docs/waves.md § Beach).
    const float spacing = static_cast<float>(envOr("TIDE_BEACH_SPACING", 0.015)), depth = 0.3f, length = 5.0f;
    WorldDef def;
    def.domainMax = {length, 2.0f * depth, 4.0f * spacing};
    def.periodic = {false, false, true};
    def.particleSpacing = spacing;
    def.solver.maxDensityError = 0.003f;
    def.solver.xsph = 0.0f;  // as in the flume: XSPH smoothing damps the waves before they reach the beach
    def.solver.momentum = 0.0f;  // as in the flume
    // No shifting, as scenes/beach.json (with shifting 0.2 and the difference form 0.5 the
    // crest rose 23 % but fell only to 0.82 of it past the break, against 0.8 asked).
    def.solver.shifting = static_cast<float>(envOr("TIDE_WAVE_SHIFTING", 0.0));
    def.solver.differenceForm = static_cast<float>(envOr("TIDE_WAVE_DIFFERENCE", 0.0));
    def.threads = static_cast<int>(envOr("TIDE_WAVE_THREADS", 0));
    World world(def);
    world.addMaterial(MaterialDef{});
    WaveMakerDef paddle;
    paddle.x = 0.1f;
    paddle.depth = depth;
    paddle.waveHeight = 0.08f;
    paddle.period = 1.2f;
    paddle.rampTime = 1.5f;
    // The paddle's stroke alone, as these figures were measured (docs/waves.md § Beach). With
    // the automatic absorption a beach switches on, the crests up to the break are the same
    // (0.0458, 0.0398, 0.0432, 0.0509, 0.0563 m at 1.0–3.7 m), the swash reads higher (0.0537,
    // 0.0475 m at 4.0 and 4.3 m) and the last gauge 0.84 of the highest.
    paddle.absorption = WaveMakerDef::Absorption::Off;
    world.addWaveMaker(paddle);
    ObstacleDef beach;
    beach.shape = ObstacleDef::Shape::Plane;
    beach.point = {1.5f, 0.0f, 0.0f};
    beach.normal = {-0.1f, 1.0f, 0.0f};
    world.addObstacle(beach);
    world.addBlock({{paddle.x, 0.0f, 0.0f}, {length, depth, def.domainMax.z}, {}, 0});
    const auto n = world.particles().size();
    const double mass = world.totalMass();
    const std::vector<float> gauges{1.0f, 2.5f, 3.0f, 3.4f, 3.7f, 4.0f, 4.3f};
    std::vector<float> crest(gauges.size(), -1.0f);
    const double duration = envOr("TIDE_BEACH_DURATION", 8.0), from = duration - 3.0 * paddle.period;
    std::uint32_t escaped = 0;
    for (double t = 0.02; t <= duration + 1e-9; t += 0.02) {
        world.advance(0.02);
        escaped = std::max(escaped, world.countEscapedParticles());
        if (t < from) continue;
        for (std::size_t g = 0; g < gauges.size(); ++g) {
            const float eta = world.surfaceHeight(gauges[g], 0.5f * def.domainMax.z);
            if (std::isfinite(eta)) crest[g] = std::max(crest[g], eta - depth);
        }
    }
    std::size_t peak = 0;
    for (std::size_t g = 0; g < gauges.size(); ++g) {
        std::printf("beach gauge x = %.2f m (still depth %.3f m): highest crest %.4f m above still water\n", gauges[g],
                    depth - std::max(0.0f, gauges[g] - 1.5f) / 10.0f, crest[g]);
        if (crest[g] > crest[peak]) peak = g;
    }
    // Shoaling: the crest grows from the flat part to the break point ...
    EXPECT_GT(crest[peak], crest[0] * 1.1f);
    EXPECT_GT(peak, 0u);
    // ... and falls after it (the break point lies inside the gauge line).
    EXPECT_LT(peak, gauges.size() - 1);
    EXPECT_LT(crest.back(), 0.8f * crest[peak]);
    EXPECT_EQ(world.particles().size(), n);
    EXPECT_EQ(world.totalMass(), mass);
    EXPECT_EQ(escaped, 0u);
}

}  // namespace
