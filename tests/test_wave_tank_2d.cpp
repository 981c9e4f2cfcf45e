// Issue 42's flume in 2D with every solver setting at its default (a flume the suite's 3D tank
// does not cover: d = 0.25 m, T = 1.2 s, H = 0.03 m), at 12.5 mm: 2.4 particles per wave
// height, the coarse end of acceptance 1, where the tank must stay stable and its errors are
// reported (here −12.0 % height over 1.5–2.0 m, λ +1.8 %). The 8-particle run (3.75 mm, 16 min)
// is in docs/waves.md § The Wendland C2 kernel.
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include <tide/world.hpp>

#include "sources/wave_theory.hpp"
#include "testing/scenarios.hpp"
#include "testing/wave_analysis.hpp"

namespace {

using namespace tide;

// With the cubic spline at 2 spacings (9 neighbours in 2D, the 2D default before Wendland C2
// at 3) this flume kept 0.0206 / 0.0170 m at 1.5 / 2.0 m (−31 / −43 %): the height bound fails.
TEST(WaveTank2D, IssueFlumeAtDefaultSettingsKeepsItsWave) {
    const double T = 1.2, d = 0.25, H = 0.03;
    const double omega = 2.0 * std::numbers::pi / T;
    const double k = waves::waveNumber(omega, d, 9.81), lambda = 2.0 * std::numbers::pi / k;
    WaveMakerDef paddle;
    paddle.type = WaveMakerDef::Type::Piston;
    paddle.x = 0.1f;
    paddle.depth = static_cast<float>(d);
    paddle.waveHeight = static_cast<float>(H);
    paddle.period = static_cast<float>(T);
    World world = scenarios::planarFlume(0.0125f, 4.5f, paddle, 1.2f);
    EXPECT_EQ(world.def().solver.kernel, KernelShape::WendlandC2);
    std::vector<float> gauges;
    for (int j = 0; j <= 15; ++j) gauges.push_back(1.0f + 0.1f * static_cast<float>(j));  // 0.5–1.5 λ from the paddle
    const double sample = 0.02, duration = 9.0;
    std::vector<waves::Record> records(gauges.size(), waves::Record{sample, sample, {}});
    const double massBefore = world.totalMass();
    const std::uint32_t countBefore = world.particles().size();
    for (int s = 0; s < static_cast<int>(std::lround(duration / sample)); ++s) {
        world.advance(sample);
        for (std::size_t g = 0; g < gauges.size(); ++g) records[g].eta.push_back(world.surfaceHeight(gauges[g], 0.0f) - d);
    }
    // Four whole periods once the front (group velocity ≈ 1.1 m/s, after the ramp) has passed 2.5 m.
    const double from = 4.2, to = from + 4.0 * T;
    std::vector<double> xs;
    std::vector<std::complex<double>> amplitudes;
    double heightSum = 0.0, periodSum = 0.0;
    int heightCount = 0;
    for (std::size_t g = 0; g < gauges.size(); ++g) {
        const waves::Record w = waves::window(records[g], from, to);
        const auto c = waves::upCrossings(w);
        xs.push_back(gauges[g]);
        amplitudes.push_back(waves::amplitudeAt(w, omega));
        std::printf("x = %.1f m: period %.4f s, height %.4f m\n", gauges[g], c.meanPeriod(), c.meanHeight());
        // Four up-crossings a gauge scatter by ±1.6 % at this resolution: each within 2 % (as the
        // 3D tank), their mean within acceptance 1's 1 %.
        EXPECT_NEAR(c.meanPeriod(), T, 0.02 * T) << "gauge " << gauges[g];
        periodSum += c.meanPeriod();
        if (gauges[g] >= 1.45f && gauges[g] <= 2.05f) {
            heightSum += c.meanHeight();
            ++heightCount;
        }
    }
    const double height = heightSum / heightCount;
    const waves::FlumeFit fit = waves::fitIncidentReflected(xs, amplitudes, 0.5 * k, 1.5 * k, -1.0, 1.0);
    const double lambdaMeasured = 2.0 * std::numbers::pi / fit.k;
    std::printf("2D issue flume at 12.5 mm: height over 1.5-2.0 m %.4f m (%+.1f %%), wave length %.4f m (Airy %.4f, %+.2f %%), "
                "reflection %.3f; %.1f density iterations a step\n",
                height, 100.0 * (height / H - 1.0), lambdaMeasured, lambda, 100.0 * (lambdaMeasured / lambda - 1.0),
                fit.coefficient(), static_cast<double>(world.stats().pressureIterationsSum) / world.stats().steps);
    const double period = periodSum / static_cast<double>(gauges.size());
    std::printf("mean period %.4f s (%+.2f %%)\n", period, 100.0 * (period / T - 1.0));
    EXPECT_NEAR(period, T, 0.01 * T);
    EXPECT_NEAR(lambdaMeasured, lambda, 0.02 * lambda);
    EXPECT_NEAR(height, H, 0.15 * H);
    EXPECT_EQ(world.particles().size(), countBefore);
    EXPECT_EQ(world.totalMass(), massBefore);
    EXPECT_EQ(world.countEscapedParticles(), 0u);
}

}  // namespace

namespace {

// Issue 42 acceptance 6: Goring's solitary wave (H 0.05 m in d 0.25 m) at 5 particles per
// height. bench/solitary_wave.cpp gives the whole flume: −3.8 % after 10 depths, celerity
// −0.5 % (at 10 per height −4.9 % and −0.7 %; at 2.5, −17 % and −2.2 %).
TEST(WaveTank2D, SolitaryWaveKeepsItsHeightAndCelerityOverTenDepths) {
    const float d = 0.25f, H = 0.05f, spacing = 0.01f;
    WaveMakerDef paddle;
    paddle.type = WaveMakerDef::Type::Solitary;
    paddle.x = 0.1f;
    paddle.depth = d;
    paddle.waveHeight = H;
    const double g = 9.81, c = std::sqrt(g * (d + H)), kappa = std::sqrt(3.0 * H / (4.0 * d * d * d));
    const double t0 = (3.8 + H / d) / (kappa * c);
    // Gauges 2, 4, 5, …, 10 depths past the paddle's end position; the wall 3/κ past the last
    // (the wave's front is at 1 % of its crest there), so no reflection reaches them first.
    const float start = paddle.x + static_cast<float>(2.0 * H / (kappa * d));
    std::vector<float> at{start + 2.0f * d};
    for (int n = 4; n <= 10; ++n) at.push_back(start + static_cast<float>(n) * d);
    const float length = spacing * std::ceil((at.back() + 3.0f / static_cast<float>(kappa)) / spacing);
    World world = scenarios::planarFlume(spacing, length, paddle);
    std::vector<double> still;
    for (const float x : at) still.push_back(world.surfaceHeight(x, 0.0f));
    const double dt = 0.01, end = t0 + (at.back() - paddle.x) / c + 0.4;  // the crest past the last gauge
    std::vector<waves::Record> records(at.size(), waves::Record{dt, dt, {}});
    for (int s = 0; s < static_cast<int>(std::lround(end / dt)); ++s) {
        world.advance(dt);
        for (std::size_t k = 0; k < at.size(); ++k) records[k].eta.push_back(world.surfaceHeight(at[k], 0.0f) - still[k]);
    }
    std::vector<double> x, when;
    for (std::size_t k = 0; k < at.size(); ++k) {
        const waves::CrestPassage crest = waves::crestPassage(records[k], records[k].eta.size());
        std::printf("x = %.3f m: crest %.4f m (%+.1f %%) at %.3f s\n", at[k], crest.height, 100.0 * (crest.height / H - 1.0), crest.time);
        if (k > 0) x.push_back(at[k]), when.push_back(crest.time);
        if (k == 0) {
            EXPECT_NEAR(crest.height, H, 0.05 * H) << "generated";
        } else if (k + 1 == at.size()) {
            EXPECT_NEAR(crest.height, H, 0.05 * H) << "after 10 depths";
        }
    }
    const double celerity = waves::celerity(x, when);
    std::printf("celerity %.4f m/s against sqrt(g(d + H)) %.4f (%+.2f %%)\n", celerity, c, 100.0 * (celerity / c - 1.0));
    EXPECT_NEAR(celerity, c, 0.02 * c);
}

}  // namespace
