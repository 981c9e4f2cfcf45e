// Sloshing: the first standing-wave mode of a closed tank against linear wave theory.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include <tide/world.hpp>

namespace {

using namespace tide;

/// Water `depth` deep in a tank `length` long (a slab a few particles wide) starts with its
/// surface tilted along the first mode, η(x) = a cos(πx/L), and sloshes. Returns the period
/// of the surface height at the x = 0 wall, from the times it crosses its mean.
double sloshingPeriod(const std::string& solver, float length, float depth, float amplitude, float spacing,
                      double duration, KernelShape kernel = KernelShape::CubicSpline, float supportRatio = 2.0f) {
    WorldDef def;
    def.domainMax = {length, 2.0f * depth, 3.0f * spacing};
    def.particleSpacing = spacing;
    def.supportRatio = supportRatio;
    def.solver.method = solver;
    def.solver.kernel = kernel;
    World world(def);
    world.addMaterial(MaterialDef{});
    // One column of whole lattice rows per x, so every column starts on the floor's lattice.
    const int columns = static_cast<int>(std::lround(length / spacing));
    for (int c = 0; c < columns; ++c) {
        const float x0 = static_cast<float>(c) * spacing;
        const float surface = depth + amplitude * std::cos(std::numbers::pi_v<float> * (x0 + 0.5f * spacing) / length);
        const float rows = std::round(surface / spacing);
        EXPECT_EQ(world.addBlock({{x0, 0.0f, 0.0f}, {x0 + spacing, rows * spacing, def.domainMax.z}, {}, 0}),
                  AddStatus::Added);
    }
    // Surface height at the wall: the top particle of the first two columns, plus half a spacing.
    auto wallHeight = [&] {
        float top = 0.0f;
        const ParticleStore& p = world.particles();
        for (std::uint32_t i = 0; i < p.size(); ++i)
            if (p.position[i].x < 2.0f * spacing) top = std::max(top, p.position[i].y);
        return top + 0.5f * spacing;
    };
    const double sample = 0.01;
    std::vector<double> height;
    for (double t = 0.0; t < duration; t += sample) {
        world.advance(sample);
        height.push_back(wallHeight());
    }
    EXPECT_EQ(world.countEscapedParticles(), 0u);
    // Crossings of the mean level, both ways (half a period apart), linearly interpolated.
    // The first is skipped (the start-up transient); the mean is then taken again over whole
    // half periods, so an unfinished swing at the end does not bias it.
    auto crossingsOf = [&](double mean) {
        std::vector<double> times;
        for (std::size_t k = 1; k < height.size(); ++k)
            if ((height[k - 1] < mean) != (height[k] < mean))
                times.push_back(sample * (static_cast<double>(k) - (height[k] - mean) / (height[k] - height[k - 1])));
        if (!times.empty()) times.erase(times.begin());
        return times;
    };
    double mean = 0.0;
    for (const double h : height) mean += h;
    mean /= static_cast<double>(height.size());
    std::vector<double> crossings = crossingsOf(mean);
    if (crossings.size() >= 2) {
        double sum = 0.0, count = 0.0;
        for (std::size_t k = 0; k < height.size(); ++k) {
            const double t = sample * static_cast<double>(k);
            if (t >= crossings.front() && t <= crossings.back()) sum += height[k], count += 1.0;
        }
        crossings = crossingsOf(sum / count);
    }
    if (crossings.size() < 4) {
        ADD_FAILURE() << solver << ": fewer than four crossings of the mean surface height";
        return 0.0;
    }
    const double period = 2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    std::printf("%s sloshing: %zu crossings of the mean, period %.4f s\n", solver.c_str(), crossings.size(), period);
    return period;
}

// Linear theory: ω² = g k tanh(k d), k = π/L. L = 1 m, d = 0.3 m: T = 1.315 s.
TEST(StandingWave, SloshesAtTheFirstNaturalFrequency) {
    const double length = 1.0, depth = 0.3, g = 9.81;
    const double k = std::numbers::pi / length;
    const double expected = 2.0 * std::numbers::pi / std::sqrt(g * k * std::tanh(k * depth));
    const double measured = sloshingPeriod("dfsph", 1.0f, 0.3f, 0.04f, 0.02f, 3.0 * expected);
    std::printf("expected period %.4f s, measured %.4f s (%.1f %%)\n", expected, measured,
                100.0 * (measured / expected - 1.0));
    EXPECT_NEAR(measured, expected, 0.05 * expected);
}

// SPH gravity waves run fast with the cubic spline at 2 spacings (+3 % in ω: docs/waves.md).
// Wendland C2 at 3 spacings keeps the particles ordered (no pairing) and the frequency
// within 1 % of linear theory.
TEST(StandingWave, WendlandAtThreeSpacingsSloshesAtTheTheorysFrequency) {
    const double length = 1.0, depth = 0.3, g = 9.81;
    const double k = std::numbers::pi / length;
    const double expected = 2.0 * std::numbers::pi / std::sqrt(g * k * std::tanh(k * depth));
    const double measured =
        sloshingPeriod("dfsph", 1.0f, 0.3f, 0.04f, 0.02f, 3.0 * expected, KernelShape::WendlandC2, 3.0f);
    std::printf("Wendland C2 at 3 spacings: expected period %.4f s, measured %.4f s (%.2f %%)\n", expected, measured,
                100.0 * (measured / expected - 1.0));
    EXPECT_NEAR(measured, expected, 0.01 * expected);
}

}  // namespace
