// World creation, validation messages and block filling.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <tide/world.hpp>

namespace {

using namespace tide;

/// Expects `make` to throw std::invalid_argument whose message names `field`.
template <class F>
void expectRejected(F&& make, const std::string& field) {
    try {
        make();
        FAIL() << "accepted a bad " << field;
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
}

TEST(World, RejectsBadDefinitionsNamingTheField) {
    auto with = [](auto change) {
        return [change] {
            WorldDef def;
            change(def);
            World world(def);
        };
    };
    expectRejected(with([](WorldDef& d) { d.particleSpacing = -0.01f; }), "particleSpacing");
    expectRejected(with([](WorldDef& d) { d.domainMax.x = d.domainMin.x; }), "domain");
    expectRejected(with([](WorldDef& d) { d.gravity.y = std::nanf(""); }), "gravity");
    expectRejected(with([](WorldDef& d) { d.capacity = 0; }), "capacity");
    expectRejected(with([](WorldDef& d) { d.solver.method = "sph-of-my-dreams"; }), "solver.method");
    expectRejected(with([](WorldDef& d) { d.solver.cflNumber = 3.0f; }), "solver.cflNumber");
    expectRejected(with([](WorldDef& d) { d.solver.momentum = 1.5f; }), "solver.momentum");
    expectRejected(with([](WorldDef& d) { d.solver.shifting = -0.1f; }), "solver.shifting");
    expectRejected(with([](WorldDef& d) {
                       d.solver.method = "wcsph";
                       d.solver.shifting = 0.2f;
                   }),
                   "solver.shifting");
    expectRejected(with([](WorldDef& d) { d.solver.differenceForm = 1.5f; }), "solver.differenceForm");
    expectRejected(with([](WorldDef& d) {
                       d.solver.method = "pcisph";
                       d.solver.differenceForm = 0.5f;
                   }),
                   "solver.differenceForm");
    expectRejected(with([](WorldDef& d) { d.solver.minDivergenceIterations = -2; }), "solver.minDivergenceIterations");
    expectRejected(with([](WorldDef& d) { d.solver.maxDivergenceError = 0.0f; }), "solver.maxDivergenceError");
    expectRejected(with([](WorldDef& d) { d.solver.minDt = 1.0f; }), "solver.minDt");
    World world{WorldDef{}};
    expectRejected([&] { world.addMaterial(MaterialDef{"oil", -3.0f, 0.1f, {}}); }, "restDensity");
    expectRejected([&] { world.step(0.0); }, "maxDt");
    expectRejected([&] { world.advance(-1.0); }, "duration");
    expectRejected([&] { world.addBlock({{0, 0, 0}, {0.1f, 0.1f, 0.1f}, {0, 0, 0}, 7}); }, "material");
}

TEST(World, BlockFillsALatticeCentredInTheBox) {
    WorldDef def;
    def.particleSpacing = 0.1f;
    World world(def);
    world.addMaterial({});
    ASSERT_EQ(world.addBlock({{0, 0, 0}, {0.5f, 0.3f, 0.2f}, {1, 0, 0}, 0}), AddStatus::Added);
    const ParticleStore& p = world.particles();
    ASSERT_EQ(p.size(), 5u * 3u * 2u);
    EXPECT_FLOAT_EQ(p.position[0].x, 0.05f);
    EXPECT_FLOAT_EQ(p.velocity[0].x, 1.0f);
    // A lattice particle's mass makes a filled block exactly rest density.
    EXPECT_NEAR(world.particleMass(0), 1000.0f * 0.1f * 0.1f * 0.1f, 0.03f * 1.0f);
}

TEST(World, OutsideAndOverCapacityAddNothing) {
    WorldDef def;
    def.particleSpacing = 0.1f;
    def.capacity = 100;
    World world(def);
    world.addMaterial({});
    EXPECT_EQ(world.addBlock({{0.5f, 0.5f, 0.5f}, {1.5f, 0.9f, 0.9f}, {}, 0}), AddStatus::OutsideDomain);
    EXPECT_EQ(world.addBlock({{0, 0, 0}, {1, 1, 1}, {}, 0}), AddStatus::OverCapacity);
    EXPECT_EQ(world.particles().size(), 0u);
    EXPECT_EQ(world.addBlock({{0, 0, 0}, {0.4f, 0.4f, 0.4f}, {}, 0}), AddStatus::Added);
    EXPECT_EQ(world.particles().size(), 64u);
}

TEST(World, AdvanceLandsExactlyOnTheRequestedTime) {
    WorldDef def;
    def.particleSpacing = 0.05f;
    World world(def);
    world.addMaterial({});
    world.addBlock({{0, 0, 0}, {0.5f, 0.3f, 0.5f}, {}, 0});
    for (int frame = 1; frame <= 3; ++frame) {
        world.advance(1.0 / 30.0);
        EXPECT_NEAR(world.time(), frame / 30.0, 1e-12);
    }
    EXPECT_GT(world.stats().steps, 3u);
}

TEST(World, ManyParticlesFitIn32BitCounts) {
    WorldDef def;
    def.particleSpacing = 0.01f;
    def.domainMax = {1.0f, 0.5f, 0.2f};
    def.capacity = 200000;
    World world(def);
    world.addMaterial({});
    ASSERT_EQ(world.addBlock({{0, 0, 0}, {1.0f, 0.5f, 0.2f}, {}, 0}), AddStatus::Added);
    EXPECT_EQ(world.particles().size(), 100000u);  // beyond the seed's 16-bit cap
}

}  // namespace
