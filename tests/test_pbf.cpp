// Position based fluids (Macklin & Müller 2013, solvers/pbf_macklin2013.hpp): still water at
// rest density, a dam break's surge front against Koshizuka & Oka 1996, light fluid over
// water, a frame of fixed substeps, and bad settings refused by name (1 and 2 threads give
// the same result: tests/test_determinism.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <tide/fluid.hpp>
#include <tide/world.hpp>

#include "testing/scenarios.hpp"

namespace {

using namespace tide;

/// Mean |ρ − ρ0|/ρ0 over the particles at least a kernel support below the surface `top`
/// (the free surface's deficit is geometry, not compression).
double interiorDensityError(const World& world, float top, float support) {
    const ParticleStore& p = world.particles();
    double sum = 0.0;
    int count = 0;
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        if (p.position[i].y > top - support) continue;
        const double rho0 = world.materials()[p.material[i]].restDensity;
        sum += std::abs(p.density[i] - rho0) / rho0;
        ++count;
    }
    return count > 0 ? sum / count : 1.0;
}

// A tank 0.2 m deep at 2 cm (one periodic cell across z), 5 ms steps of 4 iterations: after
// 2 s the density is within 1 % of ρ0 and the water is at rest.
TEST(PbfSolver, StillWaterKeepsRestDensityAndSettles) {
    WorldDef def;
    def.particleSpacing = 0.02f;
    def.solver.method = "pbf";
    def.threads = 2;
    const float depth = 0.2f;
    World world = scenarios::stillTank(def, 0.3f, depth, 4);
    world.advance(2.0);
    const double error = interiorDensityError(world, depth, 2.0f * def.particleSpacing);
    std::printf("pbf still water: interior density error %.4f, all particles %.4f, compression %.4f, max speed %.4f m/s\n",
                error, world.stats().meanDensityError, world.stats().meanCompression, world.stats().maxSpeed);
    EXPECT_LT(error, 0.01);
    EXPECT_LT(world.stats().meanCompression, 0.01);
    EXPECT_LT(world.stats().maxSpeed, 0.05f);
    EXPECT_EQ(world.countEscapedParticles(), 0u);
}

/// Koshizuka & Oka's 1996 surge front (T = t √(2g/L), Z = z/L), as digitised by PySPH
/// (/work/shared/validation/dam_break_koshizuka_oka_1996_surge_front_exp.csv, ±0.05): the rows
/// from T 0.7 until the front nears the far wall of the 4L tank.
constexpr std::pair<double, double> kKoshizukaOka[] = {{0.769, 1.252}, {1.153, 1.505}, {1.537, 1.892},
                                                       {1.935, 2.241}, {2.323, 2.615}, {2.719, 3.003}};

// Koshizuka & Oka's column, L = 0.146 m wide and 2L high in a tank 4L long, at L/14 spacing
// (one periodic cell across z: 2D). The surge front is the farthest particle of the lowest
// three layers (as examples/python/dam_break_surge.py measures it). Within 10 % of the
// experiment until T = 1.6 (measured +2.5, +7.4, +6.0 %); later the front runs ahead of it, as
// every inviscid solver here does (dfsph at L/40: 14–21 % at T 1.9–2.7, docs/python.md; at
// this resolution +15, +17, +20 %; pbf +9, +13, +18 %): the experiment's gate and floor
// friction slow the real surge, the walls here are free-slip. Those rows are held ahead of
// the experiment and within 25 %.
TEST(PbfSolver, DamBreakSurgeFrontFollowsKoshizukaOka) {
    const float L = 0.146f, s = L / 14.0f;
    WorldDef def;
    def.particleSpacing = s;
    def.solver.method = "pbf";
    def.threads = 2;
    def.domainMax = {4.0f * L, 2.5f * L, 4.0f * s};
    def.periodic.z = true;
    World world(def);
    world.addMaterial(MaterialDef{});
    world.addBlock({{0, 0, 0}, {L, 2.0f * L, def.domainMax.z}, {}, 0});
    const double toT = std::sqrt(2.0 * 9.81 / L);
    for (const auto& [T, Z] : kKoshizukaOka) {
        world.advance(T / toT - world.time());
        float front = 0.0f;
        for (const glm::vec3& x : world.particles().position)
            if (x.y < 3.0f * s) front = std::max(front, x.x);
        const double z = (front + 0.5 * s) / L;  // a particle's extent beyond its centre
        std::printf("pbf dam break: T %.3f  Z %.3f  (Koshizuka & Oka %.3f, %+.1f %%)\n", T, z, Z, 100.0 * (z / Z - 1.0));
        if (T < 1.6) {
            EXPECT_NEAR(z, Z, 0.1 * Z) << "T = " << T;
        } else {
            EXPECT_GT(z, Z) << "T = " << T;
            EXPECT_LT(z, 1.25 * Z) << "T = " << T;
        }
    }
}

/// The heights of material m's particles, sorted.
std::vector<float> heightsOf(const World& world, MaterialIndex m) {
    std::vector<float> y;
    const ParticleStore& p = world.particles();
    for (std::uint32_t i = 0; i < p.size(); ++i)
        if (p.material[i] == m) y.push_back(p.position[i].y);
    std::sort(y.begin(), y.end());
    return y;
}

// The seed's light water: 200 kg/m³ between two blocks of water (1000) rises and floats; 5000
// sinks below. At 2 cm in a small tank, 3 s: the light fluid's 10th percentile of heights
// above the water's median, the heavy fluid's 90th below it, nothing escapes or blows up.
TEST(PbfSolver, LightFluidFloatsAndHeavySinks) {
    WorldDef def;
    def.particleSpacing = 0.02f;
    def.solver.method = "pbf";
    def.threads = 2;
    def.domainMax = {0.32f, 0.4f, 0.08f};
    World world(def);
    world.addMaterial(MaterialDef{});
    MaterialDef light;
    light.name = "light";
    light.restDensity = 200.0f;
    const MaterialIndex l = world.addMaterial(light);
    MaterialDef heavy;
    heavy.name = "heavy";
    heavy.restDensity = 5000.0f;
    const MaterialIndex hv = world.addMaterial(heavy);
    world.addBlock({{0.0f, 0.0f, 0.0f}, {0.12f, 0.16f, 0.08f}, {}, 0});
    world.addBlock({{0.12f, 0.0f, 0.0f}, {0.2f, 0.16f, 0.08f}, {}, l});
    world.addBlock({{0.2f, 0.0f, 0.0f}, {0.32f, 0.16f, 0.08f}, {}, 0});
    world.addBlock({{0.12f, 0.16f, 0.0f}, {0.2f, 0.2f, 0.08f}, {}, hv});
    world.advance(3.0);
    const auto water = heightsOf(world, 0), lightY = heightsOf(world, l), heavyY = heightsOf(world, hv);
    const float waterMedian = water[water.size() / 2];
    const float light10 = lightY[lightY.size() / 10];
    const float heavy90 = heavyY[heavyY.size() * 9 / 10];
    std::printf("pbf layers: water median %.3f m, light 10th percentile %.3f m, heavy 90th percentile %.3f m, max speed %.3f\n",
                waterMedian, light10, heavy90, world.stats().maxSpeed);
    EXPECT_GT(light10, waterMedian);
    EXPECT_LT(heavy90, waterMedian);
    EXPECT_LT(world.stats().maxSpeed, 0.5f);
    EXPECT_EQ(world.countEscapedParticles(), 0u);
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

TEST(PbfSolver, IterationsSubstepsAndFrameStepsOutOfRangeAreRefusedByName) {
    WorldDef def;
    def.solver.method = "pbf";
    def.solver.constraintIterations = 0;
    EXPECT_NE(errorOf([&] { World w(def); }).find("solver.constraintIterations"), std::string::npos);
    def.solver.constraintIterations = 101;
    EXPECT_NE(errorOf([&] { World w(def); }).find("solver.constraintIterations"), std::string::npos);
    def.solver.constraintIterations = 4;
    def.solver.vorticity = -1.0f;
    EXPECT_NE(errorOf([&] { World w(def); }).find("solver.vorticity"), std::string::npos);

    Fluid fluid;
    FluidSettings settings;
    settings.substeps = 0;
    EXPECT_NE(errorOf([&] { fluid.init(1000, {-5, -5, -5}, {5, 5, 5}, {}, {}, {0, -9.81f, 0}, settings); })
                  .find("FluidSettings.substeps"),
              std::string::npos);
    settings.substeps = 101;
    EXPECT_NE(errorOf([&] { fluid.init(1000, {-5, -5, -5}, {5, 5, 5}, {}, {}, {0, -9.81f, 0}, settings); })
                  .find("FluidSettings.substeps"),
              std::string::npos);
    settings.substeps = 2;
    settings.solver.constraintIterations = 0;
    EXPECT_NE(errorOf([&] { fluid.init(1000, {-5, -5, -5}, {5, 5, 5}, {}, {}, {0, -9.81f, 0}, settings); })
                  .find("solver.constraintIterations"),
              std::string::npos);
    settings.solver.constraintIterations = 4;
    fluid.init(1000, {-5, -5, -5}, {5, 5, 5}, {-5, -5, -5}, {0, 0, 0}, {0, -9.81f, 0}, settings);
    // 2 substeps of at most 1/60 s: a frame of 0.1 s is refused, naming it.
    const std::string message = errorOf([&] { fluid.step(0.1f); });
    EXPECT_NE(message.find("frameTime"), std::string::npos) << message;
    EXPECT_NE(message.find("FluidSettings.substeps"), std::string::npos) << message;
    EXPECT_EQ(fluid.time(), 0.0);
}

// The live default: a frame is exactly FluidSettings::substeps pbf steps, each frameTime/substeps.
TEST(PbfSolver, FluidStepIsAFixedNumberOfEqualSubsteps) {
    Fluid fluid;
    fluid.init(20000, {-20, -20, -20}, {20, 20, 20}, {-20, -20, -20}, {0, 0, 0}, {0, -9.81f, 0});
    EXPECT_EQ(fluid.world().def().solver.method, "pbf");
    for (int frame = 1; frame <= 30; ++frame) {
        fluid.step(1.0f / 60.0f);
        EXPECT_EQ(fluid.world().stats().steps, static_cast<std::uint64_t>(2 * frame));
    }
    EXPECT_NEAR(fluid.time(), 0.5, 1e-6);
}

// World::prepare (which Fluid::addPoint calls, so that a live demo's first frame costs what the
// others do) sizes scratch ahead of the steps and changes nothing they compute: a dam break
// prepared before its steps, and prepared twice midway, ends where the unprepared one does, bit for bit.
TEST(PbfSolver, PreparingAWorldChangesNoResult) {
    const auto run = [](bool prepared) {
        WorldDef def;
        def.particleSpacing = 0.02f;
        def.domainMin = {0.0f, 0.0f, 0.0f};
        def.domainMax = {0.6f, 0.4f, 0.1f};
        def.solver.method = "pbf";
        def.threads = 2;
        World world(def);
        world.addMaterial(MaterialDef{});
        world.addBlock({{0.0f, 0.0f, 0.0f}, {0.2f, 0.3f, 0.1f}, {0.0f, 0.0f, 0.0f}, 0});
        if (prepared) world.prepare();
        for (int step = 0; step < 40; ++step) {
            if (prepared && step == 20) {
                world.prepare();
                world.prepare();
            }
            world.step(1.0 / 120.0);
        }
        return std::vector<glm::vec3>(world.particles().position.begin(), world.particles().position.end());
    };
    const std::vector<glm::vec3> plain = run(false), prepared = run(true);
    ASSERT_EQ(plain.size(), prepared.size());
    ASSERT_GT(plain.size(), 500u);
    std::size_t moved = 0, differ = 0;
    for (std::size_t i = 0; i < plain.size(); ++i) {
        differ += plain[i] != prepared[i] ? 1 : 0;
        moved += plain[i].y < 0.25f && plain[i].x > 0.21f ? 1 : 0;  // the surge left the column
    }
    EXPECT_EQ(differ, 0u);
    EXPECT_GT(moved, 10u);
}

}  // namespace
