// The cubic-spline solvers (wcsph, pcisph, dfsph) against hydrostatics and each other.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <tide/world.hpp>

#include "testing/scenarios.hpp"

namespace {

using namespace tide;

struct Hydrostatics {
    double pressureRms = 0.0;   ///< RMS over depth bins of (p̄ − ρ g d)/(ρ g d), time-averaged
    double meanDensityError = 0.0;
    double maxCompression = 0.0;  ///< largest per-step mean compression after the first 0.1 s
    float maxSpeed = 0.0f;
    double meanDt = 0.0;
};

/// A tank 0.3 m deep (spacing 0.02 m) settles for 1.5 s; pressure is then averaged over
/// 0.5 s in depth bins one spacing thick, away from the side walls.
Hydrostatics hydrostaticTank(const std::string& solver) {
    const float depth = 0.3f, s = 0.02f;
    WorldDef def;
    def.domainMax = {0.3f, 0.5f, 0.3f};
    def.particleSpacing = s;
    def.solver.method = solver;
    World world(def);
    world.addMaterial(MaterialDef{});
    world.addBlock({{0, 0, 0}, {0.3f, depth, 0.3f}, {0, 0, 0}, 0});
    Hydrostatics out;
    world.advance(0.1);
    world.advance(1.4, [&] { out.maxCompression = std::max<double>(out.maxCompression, world.stats().meanCompression); });
    const int bins = 11;  // centres at depth 0.03 … 0.23 m below the surface
    std::vector<double> sum(bins, 0.0), count(bins, 0.0);
    for (int sample = 0; sample < 20; ++sample) {
        world.advance(0.025, [&] { out.maxCompression = std::max<double>(out.maxCompression, world.stats().meanCompression); });
        const ParticleStore& p = world.particles();
        for (std::uint32_t i = 0; i < p.size(); ++i) {
            const glm::vec3 x = p.position[i];
            if (x.x < 0.06f || x.x > 0.24f || x.z < 0.06f || x.z > 0.24f) continue;
            const int bin = static_cast<int>(std::floor((depth - x.y - 0.02) / s));
            if (bin < 0 || bin >= bins) continue;
            sum[bin] += p.pressure[i] / (1000.0 * 9.81 * (depth - x.y));
            count[bin] += 1.0;
        }
    }
    double rms = 0.0;
    for (int b = 0; b < bins; ++b) rms += std::pow(sum[b] / count[b] - 1.0, 2.0);
    out.pressureRms = std::sqrt(rms / bins);
    out.meanDensityError = world.stats().meanDensityError;
    out.maxSpeed = world.stats().maxSpeed;
    out.meanDt = world.stats().dtSum / static_cast<double>(world.stats().steps);
    std::printf("%s: pressure RMS %.3f, mean density error %.5f, max compression %.5f, max speed %.4f, mean dt %.2e\n",
                solver.c_str(), out.pressureRms, out.meanDensityError, out.maxCompression, out.maxSpeed, out.meanDt);
    return out;
}

// Not yet asserted (issue 4 asks for them, and they are not met yet): the time-averaged
// interior pressure is off ρgd by ~24 % (dfsph) and ~15 % (wcsph) RMS, dfsph's per-step
// compression peaks at ~1.5× its tolerance, and its max speed at rest is ~0.09 m/s.
TEST(DfsphSolver, HydrostaticTankKeepsRestDensity) {
    const Hydrostatics h = hydrostaticTank("dfsph");
    EXPECT_LT(h.meanDensityError, 0.002);
    EXPECT_LT(h.maxSpeed, 0.15f);
    EXPECT_GT(h.meanDt, 2e-3);  // the CFL step of a fluid at rest: max_dt
}

TEST(WcsphSolver, HydrostaticTankSettles) {
    const Hydrostatics h = hydrostaticTank("wcsph");
    EXPECT_LT(h.meanDensityError, 0.01);  // c = 10 v_max: compression ~ (v/c)² ≈ 1 %
    EXPECT_LT(h.maxSpeed, 0.1f);
}

struct DamBreak {
    double meanDt = 0.0;
    double maxCompression = 0.0;  ///< largest per-step mean compression
    double iterationsPerStep = 0.0;
};

/// A 0.2 m × 0.3 m column released in a 0.8 m tank, 0.4 s.
DamBreak damBreak(const std::string& solver) {
    WorldDef def;
    def.domainMax = {0.8f, 0.4f, 0.2f};
    def.particleSpacing = 0.02f;
    def.solver.method = solver;
    World world(def);
    world.addMaterial(MaterialDef{});
    world.addBlock({{0, 0, 0}, {0.2f, 0.3f, 0.2f}, {0, 0, 0}, 0});
    DamBreak out;
    world.advance(0.4, [&] { out.maxCompression = std::max<double>(out.maxCompression, world.stats().meanCompression); });
    EXPECT_EQ(world.countEscapedParticles(), 0u) << solver;
    const auto steps = static_cast<double>(world.stats().steps);
    out.meanDt = world.stats().dtSum / steps;
    out.iterationsPerStep = static_cast<double>(world.stats().pressureIterationsSum) / steps;
    std::printf("%s dam break: mean dt %.2e s, max mean compression %.5f, %.1f pressure iterations per step\n",
                solver.c_str(), out.meanDt, out.maxCompression, out.iterationsPerStep);
    return out;
}

TEST(DfsphSolver, TakesFiveTimesLongerStepsThanWcsphOnADamBreak) {
    const double dfsph = damBreak("dfsph").meanDt;
    const double wcsph = damBreak("wcsph").meanDt;
    EXPECT_GT(dfsph, 5.0 * wcsph);
}

// The time-averaged pressure is not asserted yet (see the note above dfsph's tank test):
// pcisph's is ~10 % RMS off ρgd, most of it in the top bins, where SPH's free surface sits
// lower than the block's top face.
TEST(PcisphSolver, HydrostaticTankKeepsRestDensity) {
    const Hydrostatics h = hydrostaticTank("pcisph");
    EXPECT_LT(h.meanDensityError, 0.002);
    EXPECT_LT(h.maxCompression, 1.5 * SolverDef{}.maxDensityError);
    EXPECT_LT(h.maxSpeed, 0.15f);
    EXPECT_GT(h.meanDt, 2e-3);  // the CFL step of a fluid at rest: max_dt
}

TEST(PcisphSolver, DamBreakStaysWithinTolerance) {
    const DamBreak pcisph = damBreak("pcisph");
    // Per-step mean compression near the asked 0.1 %: the solve stops at the tolerance and
    // XSPH and the wall projection move particles after it.
    EXPECT_LE(pcisph.maxCompression, 1.5 * SolverDef{}.maxDensityError);
    EXPECT_GE(pcisph.iterationsPerStep, SolverDef{}.minIterations);
    EXPECT_GT(pcisph.meanDt, 5.0 * damBreak("wcsph").meanDt);
}

// bench_core's dam break, 27 layers tall: the first steps' compression sits in the bottom
// layer, which the mean hides, so the column falls nearly freely onto the floor. At 5 ms
// steps the squeezed bottom layer made the solve diverge within 8 steps (speeds of 200 m/s)
// until failed solves were retaken at half the length.
TEST(PcisphSolver, ColumnFallingOntoTheFloorStaysBounded) {
    World world = scenarios::damBreak(0.4f / std::cbrt(20000.0f), 0, 1.6f, 0.4f, 0.4f, WorldDef{}.reorderInterval, "pcisph");
    float maxSpeed = 0.0f;
    world.advance(0.2, [&] { maxSpeed = std::max(maxSpeed, world.stats().maxSpeed); });
    const float fallSpeed = std::sqrt(2.0f * 9.81f * 0.4f);
    std::printf("pcisph falling column: max speed %.2f m/s (free fall over the column %.2f m/s), %llu steps, shortest %.2e s\n",
                maxSpeed, fallSpeed, static_cast<unsigned long long>(world.stats().steps), world.stats().dtMin);
    EXPECT_LT(maxSpeed, 1.5f * fallSpeed);
    EXPECT_EQ(world.countEscapedParticles(), 0u);
}

// A block released at rest sags into its compressed state, and the impact of that first
// sag rings for seconds: ~10 % of the free-fall speed after 1 s, halving each second (dfsph
// rings the same way). Asserted: the ringing dies down and nothing leaks or collapses.
TEST(PcisphSolver, StillWaterDoesNotDrift) {
    World world = scenarios::stillWater(0.2f, 0.2f, 0.02f, 0, "pcisph");
    world.advance(1.0);
    const float afterOne = world.stats().maxSpeed;
    world.advance(1.0);
    const float afterTwo = world.stats().maxSpeed;
    const float fallSpeed = std::sqrt(2.0f * 9.81f * 0.2f);  // what a leak or a collapse would reach
    std::printf("pcisph still water: max speed %.4f m/s after 1 s, %.4f m/s after 2 s (free fall over the depth %.2f m/s)\n",
                afterOne, afterTwo, fallSpeed);
    EXPECT_LT(afterOne, 0.15f * fallSpeed);
    EXPECT_LT(afterTwo, 0.75f * afterOne);
    EXPECT_EQ(world.countEscapedParticles(), 0u);
}

}  // namespace
