// The cubic-spline solvers (wcsph, pcisph, dfsph) against hydrostatics and each other.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
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
    float maxSpeed = 0.0f;      ///< after the last step (2 s)
    float maxSpeedLate = 0.0f;  ///< largest after any step of the last 0.5 s
    double meanDt = 0.0;
};

/// A tank 0.3 m deep and `width` square (0.24 m, spacing 0.02 m unless given), after a pre-roll
/// of `settle` seconds (World::settle; none unless given), runs for 1.5 s; pressure is then
/// averaged over 0.5 s in depth bins one spacing thick, in the middle half of the width (away
/// from the side walls).
Hydrostatics hydrostaticTank(const std::string& solver, float s = 0.02f, float width = 0.24f, float maxDt = 0.0f,
                             double settle = 0.0, KernelShape kernel = KernelShape::CubicSpline, float supportRatio = 2.0f,
                             float shifting = 0.0f, float differenceForm = 0.0f) {
    const float depth = 0.3f;
    WorldDef def;
    def.domainMax = {width, 0.5f, width};
    def.particleSpacing = s;
    def.supportRatio = supportRatio;
    def.solver.method = solver;
    def.solver.kernel = kernel;
    def.solver.shifting = shifting;
    def.solver.differenceForm = differenceForm;
    if (maxDt > 0.0f) def.solver.maxDt = maxDt;
    World world(def);
    world.addMaterial(MaterialDef{});
    world.addBlock({{0, 0, 0}, {width, depth, width}, {0, 0, 0}, 0});
    if (settle > 0.0) {
        const SettleReport settled = world.settle(settle);
        std::printf("%s: settled %.1f s in %llu steps, max speed %.4f m/s before zeroing\n", solver.c_str(), settled.seconds,
                    static_cast<unsigned long long>(settled.steps), settled.maxSpeed);
        EXPECT_EQ(world.time(), 0.0);
    }
    Hydrostatics out;
    world.advance(0.1);
    world.advance(1.4, [&] { out.maxCompression = std::max<double>(out.maxCompression, world.stats().meanCompression); });
    // The interior: at least 0.04 m (two kernel supports at 1 cm), and at least one support,
    // below the surface and above the floor: bin centres at depth 0.05 … 0.25 m at 2 cm.
    const float margin = std::max(0.04f, s * supportRatio);
    const int bins = static_cast<int>(std::lround((depth - 2.0f * margin) / s));
    std::vector<double> sum(bins, 0.0), count(bins, 0.0);
    for (int sample = 0; sample < 20; ++sample) {
        world.advance(0.025, [&] {
            out.maxCompression = std::max<double>(out.maxCompression, world.stats().meanCompression);
            out.maxSpeedLate = std::max(out.maxSpeedLate, world.stats().maxSpeed);
        });
        const ParticleStore& p = world.particles();
        for (std::uint32_t i = 0; i < p.size(); ++i) {
            const glm::vec3 x = p.position[i];
            const float lo = 0.25f * width, hi = 0.75f * width;
            if (x.x < lo || x.x > hi || x.z < lo || x.z > hi) continue;
            const int bin = static_cast<int>(std::floor((depth - x.y - margin) / s));
            if (bin < 0 || bin >= bins) continue;
            sum[bin] += p.pressure[i] / (1000.0 * 9.81 * (depth - x.y));
            count[bin] += 1.0;
        }
    }
    double rms = 0.0;
    std::printf("%s: time-averaged p / (rho g d) by depth:", solver.c_str());
    for (int b = 0; b < bins; ++b) {
        std::printf(" %.3f", sum[b] / count[b]);
        rms += std::pow(sum[b] / count[b] - 1.0, 2.0);
    }
    std::printf("\n");
    out.pressureRms = std::sqrt(rms / bins);
    EXPECT_EQ(world.countEscapedParticles(), 0u) << solver;
    out.meanDensityError = world.stats().meanDensityError;
    out.maxSpeed = world.stats().maxSpeed;
    out.meanDt = world.stats().dtSum / static_cast<double>(world.stats().steps);
    std::printf("%s: pressure RMS %.3f, mean density error %.5f, max compression %.5f, max speed %.4f (over the last "
                "0.5 s %.4f), mean dt %.2e\n",
                solver.c_str(), out.pressureRms, out.meanDensityError, out.maxCompression, out.maxSpeed, out.maxSpeedLate,
                out.meanDt);
    return out;
}

// Water started on the cubic lattice of addBlock is not at rest: the lattice buckles under the
// hydrostatic pressure from the floor up (from ~0.25 s at 2 cm), the particles rearrange into a
// denser packing (the surface sinks ~5 mm), and gravity's energy released keeps them moving at
// max speeds of 0.05–0.09 m/s at 2 s (RMS 0.026), damped by XSPH with a time constant of ~2 s
// and fed by further compaction (docs/robustness.md § Still water). What the lattice start
// must still give: the pressure, the density, and speeds bounded by the rearrangement's peak
// (0.15 m/s at 0.5 s).
TEST(DfsphSolver, HydrostaticTankFromTheLatticeMatchesRhoGD) {
    const Hydrostatics h = hydrostaticTank("dfsph");
    EXPECT_LT(h.pressureRms, 0.05);
    EXPECT_LT(h.meanDensityError, 0.002);
    EXPECT_LT(h.maxSpeedLate, 0.15f);
    EXPECT_GT(h.meanDt, 2e-3);  // the CFL step of a fluid at rest: max_dt
}

// Issue 4's tank at rest: after a pre-roll (World::settle, 10 s at 2 cm: 2000 steps, in which
// the particles find an arrangement in which they rest) the bulk moves at 1–3 mm/s; the max
// speed is a few particles' at the surface or a wall: 0.0157 m/s here over the last 0.5 s.
// That is one draw of a chaotic process: six tanks 0.20–0.30 m long read 0.004–0.056 after an
// 8 s pre-roll, and some never quieten (docs/robustness.md § Still water, "A pre-roll").
// Wendland C2 at 3 spacings from the same lattice: the pressure (RMS 3.5 %, the interior
// now a support, 6 cm, from the surface) and the density as the cubic spline's, and the
// rearrangement gentler: 0.055 m/s at most over the last 0.5 s against 0.093.
TEST(DfsphSolver, WendlandHydrostaticTankFromTheLatticeMatchesRhoGD) {
    const Hydrostatics h = hydrostaticTank("dfsph", 0.02f, 0.24f, 0.0f, 0.0, KernelShape::WendlandC2, 3.0f);
    EXPECT_LT(h.pressureRms, 0.05);
    EXPECT_LT(h.meanDensityError, 0.002);
    EXPECT_LT(h.maxSpeedLate, 0.1f);
    EXPECT_GT(h.meanDt, 2e-3);
}

// Particle shifting (solver.shifting 0.2, as scenes/wave_tank.json) in the same tank from the
// lattice. Measured at 2 s (tide_rest_layers --closed --length 0.24 --seconds 2 --shifting
// 0.2): RMS speeds below 2.5 cm halved (10–14 mm/s against 23–27), the top two layers
// busier (28–37 mm/s), pressure RMS 1.1 %. Near the surface shifting spaces the particles
// out where the solve had packed them to make their truncated kernel sums read ρ0: the top
// layer reads 4.3 % under ρ0 (0.02 % without), which is what the mean |ρ − ρ0| of 0.45 %
// is; the compression, the solver's measure, stays within its tolerance.
TEST(DfsphSolver, ShiftingTankFromTheLatticeMatchesRhoGD) {
    const Hydrostatics h = hydrostaticTank("dfsph", 0.02f, 0.24f, 0.0f, 0.0, KernelShape::CubicSpline, 2.0f, 0.2f);
    EXPECT_LT(h.pressureRms, 0.05);
    EXPECT_LT(h.maxCompression, 0.0015);
    EXPECT_LT(h.meanDensityError, 0.006);
    EXPECT_LT(h.maxSpeedLate, 0.15f);
}

// With the difference form of the smoothed pressure's self-term too (solver.difference_form
// 0.5 with shifting 0.2): the surface layers lose part of the push that held them, the solve
// makes up for it with 2–9 % more pressure (1.087 ρgd in the top bin, 1.027 at the floor;
// RMS 4.7 % against 1.1 % with shifting alone; 4.0 % with the scalar sums of an earlier build:
// a rounding draw), and the tank from the lattice is busier, most near the surface (max
// 0.202 m/s over the last 0.5 s against 0.125; tide_rest_layers
// --closed --length 0.24 --seconds 2 --shifting 0.2 --difference-form 0.5: RMS 14–20 mm/s
// in the bulk at 2 s, 50 in the top two layers). That is the key's documented price; the
// pressure is held to the 5 %, the speeds to 0.3 m/s.
TEST(DfsphSolver, DifferenceFormTankFromTheLatticeMatchesRhoGD) {
    const Hydrostatics h = hydrostaticTank("dfsph", 0.02f, 0.24f, 0.0f, 0.0, KernelShape::CubicSpline, 2.0f, 0.2f, 0.5f);
    EXPECT_LT(h.pressureRms, 0.05);
    EXPECT_LT(h.maxCompression, 0.0015);
    EXPECT_LT(h.meanDensityError, 0.006);
    EXPECT_LT(h.maxSpeedLate, 0.3f);
}

TEST(DfsphSolver, SettledHydrostaticTankIsAtRest) {
    const Hydrostatics h = hydrostaticTank("dfsph", 0.02f, 0.24f, 0.0f, 10.0);
    EXPECT_LT(h.pressureRms, 0.05);
    EXPECT_LT(h.meanDensityError, 0.002);
    EXPECT_LT(h.maxSpeedLate, 0.02f);
    EXPECT_GT(h.meanDt, 2e-3);
}

// The tank at 1 cm, 30 layers deep (0.12 m square to keep it quick). At the fixed 5 ms
// max_dt dfsph's solves ran to the iteration limit and it blew up within 0.03 s (speeds of
// 10–40,000 m/s); with the free-fall step limit alone (3.6 ms) it lasted to 1.96 s. The
// pressure-speed limit (sph::pressureSpeedStep, 2.6 ms here) holds it: measured pressure
// RMS 1.3 %, 16 iterations a step; from the lattice, max speed 0.053 m/s at 2 s; after an
// 8 s pre-roll 0.0034 over the last 0.5 s (tide_rest_layers: 0.005–0.007 after 6 s,
// 0.0015–0.0022 after 10 s). The 0.24 m tank at 1 cm runs with TIDE_LONG_TESTS=1.
TEST(DfsphSolver, SettledTankAtOneCentimetreIsAtRest) {
    const Hydrostatics h = hydrostaticTank("dfsph", 0.01f, 0.12f, 0.0f, 8.0);
    EXPECT_LT(h.pressureRms, 0.05);
    EXPECT_LT(h.meanDensityError, 0.002);
    EXPECT_LT(h.maxSpeedLate, 0.02f);
}

TEST(DfsphSolver, WideSettledTankAtOneCentimetreIsAtRest) {
    if (std::getenv("TIDE_LONG_TESTS") == nullptr) GTEST_SKIP() << "17,280 particles for 10 s: set TIDE_LONG_TESTS=1";
    const Hydrostatics h = hydrostaticTank("dfsph", 0.01f, 0.24f, 0.0f, 8.0);
    EXPECT_LT(h.pressureRms, 0.05);
    EXPECT_LT(h.meanDensityError, 0.002);
    EXPECT_LT(h.maxSpeedLate, 0.02f);
}

// A max_dt below the step the water needs must not stir it: dfsph removes the compression
// earlier solves left over the step it would have taken (5 ms here), not within 1 ms, which
// took velocities ∝ 1/Δt: this tank read 0.62 m/s and a mean density error of 1.6 % before
// (then 0.054 m/s from the lattice, 0.088 %, pressure RMS 3.1 %). Settled (4 s: 4000 steps of
// 1 ms), it rests as at 5 ms: 0.014 m/s over the last 0.5 s, pressure RMS 2.1 %.
TEST(DfsphSolver, ShortMaxDtKeepsTheSettledTankAtRest) {
    const Hydrostatics h = hydrostaticTank("dfsph", 0.02f, 0.24f, 1e-3f, 4.0);
    EXPECT_LT(h.pressureRms, 0.05);
    EXPECT_LT(h.meanDensityError, 0.002);
    EXPECT_LT(h.maxSpeedLate, 0.02f);
    EXPECT_LT(h.meanDt, 1.001e-3);
}

TEST(WcsphSolver, HydrostaticTankMatchesRhoGD) {
    const Hydrostatics h = hydrostaticTank("wcsph");
    EXPECT_LT(h.pressureRms, 0.10);
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

// Issue 4: the incompressible solvers take steps at least 5× longer than wcsph on the same
// dam break, and their density error (measured after every step, not the solver's own
// prediction) stays under the tolerance.
TEST(IncompressibleSolvers, DamBreakStepsFiveTimesLongerThanWcsphWithinTolerance) {
    const DamBreak wcsph = damBreak("wcsph");
    for (const char* solver : {"dfsph", "pcisph"}) {
        const DamBreak incompressible = damBreak(solver);
        EXPECT_GT(incompressible.meanDt, 5.0 * wcsph.meanDt) << solver;
        EXPECT_LE(incompressible.maxCompression, SolverDef{}.maxDensityError) << solver;
        EXPECT_GE(incompressible.iterationsPerStep, SolverDef{}.minIterations) << solver;
    }
}

TEST(PcisphSolver, HydrostaticTankMatchesRhoGD) {
    const Hydrostatics h = hydrostaticTank("pcisph");
    EXPECT_LT(h.pressureRms, 0.05);
    EXPECT_LT(h.meanDensityError, 0.002);
    EXPECT_LT(h.maxSpeed, 0.1f);
    EXPECT_GT(h.meanDt, 2e-3);  // the CFL step of a fluid at rest: max_dt
}

// bench_core's dam break, 27 layers tall: the first steps' compression sits in the bottom
// layer, which the mean hides, so the column falls nearly freely onto the floor. At 5 ms
// steps the squeezed bottom layer made the solve diverge within 8 steps (speeds of 200 m/s)
// until failed solves were retaken at half the length.
TEST(PcisphSolver, ColumnFallingOntoTheFloorStaysBounded) {
    World world = scenarios::damBreak(0.4f / std::cbrt(20000.0f), 0, 1.6f, 0.4f, 0.4f, WorldDef{}.reorderInterval, "pcisph");
    float maxSpeed = 0.0f;
    world.advance(0.1, [&] { maxSpeed = std::max(maxSpeed, world.stats().maxSpeed); });
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

/// Density iterations per step of dfsph in a 0.2 m tank at rest for 0.3 s.
double dfsphIterationsAtRest(float momentum) {
    WorldDef def;
    def.domainMax = {0.2f, 0.3f, 0.2f};
    def.particleSpacing = 0.02f;
    def.solver.method = "dfsph";
    def.solver.momentum = momentum;
    def.threads = 1;
    World world(def);
    world.addMaterial(MaterialDef{});
    BlockDef block;
    block.max = {0.2f, 0.2f, 0.2f};
    EXPECT_EQ(world.addBlock(block), AddStatus::Added);
    world.advance(0.3);
    return static_cast<double>(world.stats().pressureIterationsSum) / static_cast<double>(world.stats().steps);
}

// solver.momentum reaches the density solve: the default (0.7) takes far fewer iterations
// than none (14 against 35 a step measured in the 0.3 m tank).
TEST(DfsphSolver, MomentumCutsTheDensityIterations) {
    const double without = dfsphIterationsAtRest(0.0f), standard = dfsphIterationsAtRest(-1.0f);
    std::printf("dfsph at rest: %.1f iterations a step without momentum, %.1f with the default\n", without, standard);
    EXPECT_LT(standard, 0.7 * without);
}

// Still water 0.6 m deep (30 layers at 2 cm) at the wave scenes' loose tolerance (0.3 %),
// without the heavy ball: the density solve at the predicted positions diverged inside its
// iterations here, and the tank blew up (340 m/s at 0.25 s). A solve whose error doubles now
// takes the linearised prediction (Bender & Koschier eq. 9). What is left: the block's first
// sag (1.74 m/s at 0.16 s), then a rearrangement of ~0.8 m/s that slowly dies (0.63 at 1 s).
TEST(DfsphSolver, DeepTankAtALooseToleranceHolds) {
    WorldDef def;
    def.particleSpacing = 0.02f;
    def.threads = 2;
    def.solver.maxDensityError = 0.003f;
    def.solver.xsph = 0.0f;
    def.solver.momentum = 0.0f;
    World world = scenarios::stillTank(def, 0.24f, 0.6f, 4);
    const float fallSpeed = std::sqrt(2.0f * 9.81f * 0.6f);  // what a collapse would reach
    float sag = 0.0f, late = 0.0f;
    EXPECT_NO_THROW(world.advance(0.3, [&] { sag = std::max(sag, world.stats().maxSpeed); }));
    EXPECT_NO_THROW(world.advance(0.2, [&] { late = std::max(late, world.stats().maxSpeed); }));
    std::printf("0.6 m tank at 0.3 %%: max speed %.2f m/s in 0.3 s, %.2f m/s over the next 0.2 s (free fall over the "
                "depth %.2f), %llu of %llu solves short\n",
                sag, late, fallSpeed, static_cast<unsigned long long>(world.stats().unconvergedSolves),
                static_cast<unsigned long long>(world.stats().steps));
    EXPECT_LT(sag, fallSpeed);
    EXPECT_LT(late, 0.35f * fallSpeed);
    EXPECT_EQ(world.countEscapedParticles(), 0u);
}

// Supports beyond 2 spacings: the Jacobi weights tuned at 2 overshot past ~2.7 (jacobi_weight.hpp),
// and a tank at rest blew up within two steps at 3 spacings (4.9e9 m/s). With the weights
// scaled the tank holds as at the default support: the cubic lattice buckles, nothing
// collapses. Max speeds over the first 0.3 s (0.24 m long, 0.2 m deep, periodic z), dfsph /
// pcisph: 0.107 / 0.081 m/s at 2 spacings, 0.145 / 0.139 at 3, 0.269 / 0.188 at 4; every solve
// converged, the worst mean compression 0.09 % against the 0.1 % tolerance.
TEST(IncompressibleSolvers, WideSupportsHoldATankAtRest) {
    for (const char* solver : {"dfsph", "pcisph"}) {
        for (const float support : {3.0f, 4.0f}) {
            WorldDef def;
            def.particleSpacing = 0.02f;
            def.supportRatio = support;
            def.threads = 2;
            def.solver.method = solver;
            World world = scenarios::stillTank(def, 0.24f, 0.2f, scenarios::periodicWidthInSpacings(support));
            float fastest = 0.0f;
            double compression = 0.0;
            EXPECT_NO_THROW(world.advance(0.3, [&] {
                fastest = std::max(fastest, world.stats().maxSpeed);
                compression = std::max<double>(compression, world.stats().meanCompression);
            })) << solver << " at " << support;
            std::printf("%s, support %.1f: max speed %.3f m/s, worst mean compression %.5f, %llu steps, %llu solves short\n",
                        solver, support, fastest, compression, static_cast<unsigned long long>(world.stats().steps),
                        static_cast<unsigned long long>(world.stats().unconvergedSolves));
            const float fallSpeed = std::sqrt(2.0f * 9.81f * 0.2f);  // what a collapse would reach
            EXPECT_LT(fastest, 0.2f * fallSpeed) << solver << " at " << support;
            EXPECT_LT(compression, def.solver.maxDensityError) << solver << " at " << support;
            EXPECT_EQ(world.stats().unconvergedSolves, 0u) << solver << " at " << support;
            EXPECT_EQ(world.countEscapedParticles(), 0u);
        }
    }
}

}  // namespace

// Water filling a closed box without gravity has nothing to move it: the solvers must keep it
// still (round-off stirs it to ~4e-5 m/s, which stays there over 3 s; pcisph 4e-6). dfsph's
// momentum, taken in the extra iterations of solves already within their target, grew that
// round-off step after step to 0.1 m/s within 1 s.
TEST(IncompressibleSolvers, FullBoxWithoutGravityStaysStill) {
    for (const char* solver : {"dfsph", "pcisph"}) {
        WorldDef def;
        def.domainMax = {0.24f, 0.3f, 0.24f};
        def.gravity = glm::vec3(0.0f);
        def.particleSpacing = 0.02f;
        def.solver.method = solver;
        def.threads = 1;
        World world(def);
        world.addMaterial(MaterialDef{});
        ASSERT_EQ(world.addBlock({{0, 0, 0}, {0.24f, 0.3f, 0.24f}, {0, 0, 0}, 0}), AddStatus::Added);
        float fastest = 0.0f;
        world.advance(1.0, [&] { fastest = std::max(fastest, world.stats().maxSpeed); });
        std::printf("%s, full box without gravity: max speed over 1 s %.2e m/s\n", solver, fastest);
        EXPECT_LT(fastest, 1e-3f) << solver;
    }
}

// solver.min_divergence_iterations: dfsph's divergence-free solve takes at least that many
// iterations, whatever min_iterations (the density solve's) says; −1 follows min_iterations.
TEST(DfsphSolver, DivergenceSolveTakesItsOwnMinimum) {
    auto iterationsPerStep = [](int minIterations, int minDivergence) {
        WorldDef def;
        def.domainMax = {0.2f, 0.2f, 0.2f};
        def.particleSpacing = 0.02f;
        def.solver.method = "dfsph";
        def.solver.minIterations = minIterations;
        def.solver.minDivergenceIterations = minDivergence;
        def.threads = 1;
        World world(def);
        world.addMaterial(MaterialDef{});
        world.addBlock({{0, 0, 0}, {0.2f, 0.1f, 0.2f}, {0, 0, 0}, 0});
        world.advance(0.05);
        return static_cast<double>(world.stats().pressureIterationsSum) / static_cast<double>(world.stats().steps);
    };
    const double none = iterationsPerStep(0, 0), five = iterationsPerStep(0, 5), followed = iterationsPerStep(5, -1);
    std::printf("dfsph, still water: %.2f pressure iterations a step with no minimum, %.2f with 5 for the divergence "
                "solve, %.2f with 5 for both\n", none, five, followed);
    EXPECT_LT(none, five);
    EXPECT_GE(five, 5.0);
    EXPECT_GE(followed, 10.0);
}

/// What a small dfsph dam break's divergence-free solve did over 0.3 s, with the solver set up
/// by `configure` (a 0.05 % density tolerance and no minimum of iterations before it).
struct DivergenceRun {
    double divergencePerStep = 0.0, worstCompression = 0.0;
    std::uint64_t lost = 0;
};
DivergenceRun divergenceDamBreak(const std::function<void(SolverDef&)>& configure) {
    WorldDef def;
    def.domainMax = {0.6f, 0.4f, 0.1f};
    def.particleSpacing = 0.02f;
    def.solver.method = "dfsph";
    def.solver.maxDensityError = 5e-4f;
    def.solver.minIterations = 0;
    configure(def.solver);
    def.threads = 1;
    World world(def);
    world.addMaterial(MaterialDef{});
    world.addBlock({{0, 0, 0}, {0.2f, 0.3f, 0.1f}, {0, 0, 0}, 0});
    world.advance(0.3);
    const WorldStats& s = world.stats();
    return {static_cast<double>(s.divergenceIterationsSum) / static_cast<double>(s.steps), s.maxMeanCompression,
            world.countEscapedParticles()};
}

// solver.divergence_warm_start: the divergence-free solve starts from that fraction of the last
// step's κᵛ. In a dam break without a minimum the warm start saves iterations; without it
// (0, which also skips the pass that would apply it) the solve still ends within its
// tolerance and the density solve within its own in every step.
TEST(DfsphSolver, DivergenceSolveWarmStartSavesIterations) {
    auto withWarmStart = [](float share) { return divergenceDamBreak([&](SolverDef& s) { s.divergenceWarmStart = share; }); };
    const DivergenceRun cold = withWarmStart(0.0f), half = withWarmStart(0.5f);
    std::printf("dfsph dam break, divergence iterations a step: %.2f without a warm start, %.2f from half the last "
                "step's; worst mean compression %.4f / %.4f %%\n",
                cold.divergencePerStep, half.divergencePerStep, 100 * cold.worstCompression, 100 * half.worstCompression);
    EXPECT_LT(half.divergencePerStep, cold.divergencePerStep);
    for (const DivergenceRun& r : {cold, half}) {
        EXPECT_LE(r.worstCompression, 5e-4);
        EXPECT_EQ(r.lost, 0u);
    }
}

// solver.max_divergence_error: the divergence-free solve's own tolerance (SPlisHSPlasH's
// maxErrorV). A dam break's divergence solve iterates less at a looser one and more at a
// tighter one, while the density solve still holds its own tolerance in every step.
TEST(DfsphSolver, DivergenceSolveTakesItsOwnTolerance) {
    auto at = [](float tolerance) { return divergenceDamBreak([&](SolverDef& s) { s.maxDivergenceError = tolerance; }); };
    const DivergenceRun loose = at(5e-3f), same = at(-1.0f), tight = at(5e-5f);
    std::printf("dfsph dam break, divergence iterations a step: %.2f at 0.5 %%, %.2f at the density's 0.05 %%, %.2f at "
                "0.005 %%; worst mean compression %.4f / %.4f / %.4f %%\n",
                loose.divergencePerStep, same.divergencePerStep, tight.divergencePerStep, 100 * loose.worstCompression,
                100 * same.worstCompression, 100 * tight.worstCompression);
    EXPECT_LT(loose.divergencePerStep, same.divergencePerStep);
    EXPECT_LT(same.divergencePerStep, tight.divergencePerStep);
    for (const DivergenceRun& r : {loose, same, tight}) EXPECT_LE(r.worstCompression, 5e-4);
}
