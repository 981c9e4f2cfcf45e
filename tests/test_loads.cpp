// Loads on solids: every solid's load is the reaction of what the solver applied to the fluid
// (the momentum balance closes for every solver), hydrostatic loads match ρgh²/2 and
// buoyancy, names and reference points, and the same bits on any thread count.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <tide/world.hpp>

namespace {

using namespace tide;

constexpr double kG = 9.81;

/// Σ m v over the fluid, kg·m/s.
glm::dvec3 momentum(const World& world) {
    const ParticleStore& p = world.particles();
    glm::dvec3 sum(0.0);
    for (std::uint32_t i = 0; i < p.size(); ++i) sum += static_cast<double>(p.mass[i]) * glm::dvec3(p.velocity[i]);
    return sum;
}

glm::dvec3 totalForce(const std::vector<SolidLoad>& loads) {
    glm::dvec3 sum(0.0);
    for (const SolidLoad& l : loads) sum += l.force();
    return sum;
}

/// A dam break in a closed box with a fixed obstacle in its path (x right, y up, z across).
World damBreak(const std::string& solver, int threads) {
    WorldDef def;
    def.domainMax = {0.6f, 0.4f, 0.1f};
    def.particleSpacing = 0.02f;
    def.threads = threads;
    def.solver.method = solver;
    World world(def);
    world.addMaterial(MaterialDef{});
    ObstacleDef box;
    box.min = {0.4f, 0.0f, 0.0f};
    box.max = {0.46f, 0.1f, 0.1f};
    box.name = "block";
    world.addObstacle(box);
    BlockDef water;
    water.max = {0.2f, 0.3f, 0.1f};
    EXPECT_EQ(world.addBlock(water), AddStatus::Added);
    return world;
}

// The fluid's momentum changes by gravity's impulse plus the solids' forces on it; the loads
// are minus those forces, so Σ loads · T = M g T − ΔP. Walls project strays out after each step
// (an impulse no solver applies); at these speeds it is far below the tolerance.
TEST(Loads, SolidsTakeExactlyTheMomentumTheFluidExchangesWithThem) {
    for (const std::string solver : {"dfsph", "pcisph", "wcsph", "classic"}) {
        World world = damBreak(solver, 2);
        const double mass = world.totalMass();
        const glm::dvec3 before = momentum(world);
        (void)world.takeMeanSolidLoads();
        const double seconds = 0.25;
        world.advance(seconds);
        const glm::dvec3 exchanged = seconds * totalForce(world.takeMeanSolidLoads());
        const glm::dvec3 expected = mass * glm::dvec3(0.0, -kG, 0.0) * seconds - (momentum(world) - before);
        const double weightImpulse = mass * kG * seconds;
        std::printf("%s: load impulse (%.5f, %.5f, %.5f) N s, M g T - dP (%.5f, %.5f, %.5f) N s\n", solver.c_str(),
                    exchanged.x, exchanged.y, exchanged.z, expected.x, expected.y, expected.z);
        for (int axis = 0; axis < 3; ++axis)
            EXPECT_NEAR(exchanged[axis], expected[axis], 1e-4 * weightImpulse) << solver << " axis " << axis;
        // The surge reached the block: it is pushed downstream (+x).
        const std::uint32_t block = *world.findSolid("block");
        EXPECT_GT(world.solidLoads()[block].force().x, 0.0) << solver;
    }
}

// Still water of depth h against a wall: ∫ρ g (h − y) dy = ρ g h²/2 per metre of wall. The tank
// is settled first (World::settle), then the load averaged over half a second.
TEST(Loads, HydrostaticForceOnAWallIsHalfRhoGHSquaredPerMetre) {
    WorldDef def;
    def.domainMax = {0.3f, 0.3f, 0.1f};
    def.particleSpacing = 0.01f;
    def.threads = 2;
    World world(def);
    world.addMaterial(MaterialDef{});
    BlockDef water;
    const float depth = 0.2f;
    water.max = {0.3f, depth, 0.1f};
    ASSERT_EQ(world.addBlock(water), AddStatus::Added);
    world.settle(1.0, 0.0f);
    (void)world.takeMeanSolidLoads();
    world.advance(0.5);
    const std::vector<SolidLoad> mean = world.takeMeanSolidLoads();
    const double width = 0.1;
    const double expected = 0.5 * 1000.0 * kG * depth * depth;
    const double right = mean[*world.findSolid("wall_xmax")].force().x / width;
    const double left = -mean[*world.findSolid("wall_xmin")].force().x / width;
    const double floor = -mean[*world.findSolid("wall_ymin")].force().y;
    for (std::size_t k = 0; k < mean.size(); ++k)
        std::printf("%s: (%.3f, %.3f, %.3f) N\n", world.solids()[k].name.c_str(), mean[k].force().x, mean[k].force().y, mean[k].force().z);
    std::printf("per metre: right wall %.2f N, left wall %.2f N, rho g h^2/2 = %.2f N; floor %.2f N, weight %.2f N\n", right,
                left, expected, floor, world.totalMass() * kG);
    EXPECT_NEAR(right, expected, 0.02 * expected);
    EXPECT_NEAR(left, expected, 0.02 * expected);
    // The moment about the wall's centre (y = 0.15 m): the resultant acts at h/3 from the floor.
    const double momentZ = mean[*world.findSolid("wall_xmax")].moment.z / width;
    EXPECT_NEAR(momentZ, expected * (0.15 - depth / 3.0), 0.05 * expected * 0.15);
}

// A fixed box under water feels ρ g V upwards (Archimedes), and no net side force.
TEST(Loads, ASubmergedFixedBoxFeelsItsBuoyancy) {
    WorldDef def;
    def.domainMax = {0.3f, 0.3f, 0.1f};
    def.particleSpacing = 0.01f;
    def.threads = 2;
    World world(def);
    world.addMaterial(MaterialDef{});
    ObstacleDef box;
    box.min = {0.1f, 0.06f, 0.0f};
    box.max = {0.2f, 0.12f, 0.1f};  // through the tank in z, as a 2D section
    world.addObstacle(box);
    BlockDef water;
    water.max = {0.3f, 0.22f, 0.1f};
    ASSERT_EQ(world.addBlock(water), AddStatus::Added);
    world.settle(1.0, 0.0f);
    (void)world.takeMeanSolidLoads();
    world.advance(0.5);
    const std::vector<SolidLoad> mean = world.takeMeanSolidLoads();
    const glm::dvec3 force = mean[*world.findSolid("obstacle0")].force();
    const double buoyancy = 1000.0 * kG * 0.1 * 0.06 * 0.1;
    std::printf("box: (%.3f, %.3f, %.3f) N, rho g V = %.3f N\n", force.x, force.y, force.z, buoyancy);
    EXPECT_NEAR(force.y, buoyancy, 0.02 * buoyancy);
    EXPECT_NEAR(force.x, 0.0, 0.02 * buoyancy);
}

TEST(Loads, TheSameBitsOnOneAndTwoThreads) {
    World one = damBreak("dfsph", 1), two = damBreak("dfsph", 2);
    one.advance(0.1);
    two.advance(0.1);
    const auto a = one.solidLoads(), b = two.solidLoads();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t s = 0; s < a.size(); ++s) {
        EXPECT_EQ(a[s].pressureForce, b[s].pressureForce) << s;
        EXPECT_EQ(a[s].viscousForce, b[s].viscousForce) << s;
        EXPECT_EQ(a[s].moment, b[s].moment) << s;
    }
}

TEST(Loads, SolidsAreNamedAndNamesAreUnique) {
    WorldDef def;
    def.domainMax = {0.4f, 0.4f, 0.4f};
    World world(def);
    world.addMaterial(MaterialDef{});
    ObstacleDef sphere;
    sphere.shape = ObstacleDef::Shape::Sphere;
    sphere.center = {0.2f, 0.2f, 0.2f};
    sphere.radius = 0.05f;
    world.addObstacle(sphere);
    ObstacleDef pile = sphere;
    pile.center.x = 0.3f;
    pile.name = "pile";
    world.addObstacle(pile);
    const std::vector<std::string> expected{"wall_xmin", "wall_xmax", "wall_ymin", "wall_ymax", "wall_zmin",
                                            "wall_zmax", "obstacle0", "pile"};
    ASSERT_EQ(world.solids().size(), expected.size());
    for (std::size_t s = 0; s < expected.size(); ++s) EXPECT_EQ(world.solids()[s].name, expected[s]);
    EXPECT_EQ(world.solids()[7].kind, SolidInfo::Kind::Obstacle);
    EXPECT_EQ(world.solids()[7].index, 1u);
    ObstacleDef again = sphere;
    again.name = "pile";
    try {
        world.addObstacle(again);
        FAIL() << "a second solid called pile was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("obstacle.name: \"pile\""), std::string::npos) << e.what();
    }
}

}  // namespace
