// Bodies the fluid moves (ObstacleDef::dynamics): floating at Archimedes' draft, checkpoints and thread counts that change nothing, and bad definitions refused.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include <tide/world.hpp>

namespace {

using namespace tide;

constexpr float kSpacing = 0.01f;

/// Still water 0.2 m deep in a tank 0.3 × 0.35 × 0.1 m, and a box 0.1 m tall of `density` whose
/// bottom starts at `bottom`, heave only.
World tankWithBox(double density, float bottom, int threads = 2) {
    WorldDef def;
    def.domainMax = {0.3f, 0.35f, 0.1f};
    def.particleSpacing = kSpacing;
    def.threads = threads;
    World world(def);
    world.addMaterial(MaterialDef{});
    ObstacleDef box;
    box.min = {0.1f, bottom, 0.02f};
    box.max = {0.2f, bottom + 0.1f, 0.08f};
    box.name = "box";
    BodyDynamicsDef body;
    body.density = density;
    body.freeAxes = {"y"};
    box.dynamics = body;
    world.addObstacle(box);
    BlockDef water;
    water.max = {0.3f, 0.2f, 0.1f};
    EXPECT_EQ(world.addBlock(water), AddStatus::Added);
    return world;
}

// A box of half the water's density floats with half its height under the surface (the
// failure SPlisHSPlasH users report: bodies that need 7–10 times the density to float).
TEST(FloatingBodies, ABoxOfHalfTheDensityFloatsAtHalfItsHeight) {
    World world = tankWithBox(500.0, 0.16f);  // released 1 cm high
    world.advance(1.2);
    const BodyState box = world.bodies().at(0);
    const float surface = world.surfaceHeight(0.03f, 0.05f);
    const double draft = surface - (box.position.y - 0.05);
    std::printf("box centre %.4f m, surface %.4f m, draft %.4f m (0.05 expected), speed %.4f m/s\n", box.position.y, surface,
                draft, box.velocity.y);
    EXPECT_NEAR(draft, 0.05, std::max(0.5 * kSpacing, 0.03 * 0.1));
    EXPECT_EQ(box.position.x, 0.5 * (static_cast<double>(0.1f) + static_cast<double>(0.2f))) << "heave only";
}

// A box twice as dense as water lands on the floor and rests there. Before contact began at a
// particle spacing's gap, the water squeezed into a thinner film (closer than a spacing to both
// solids' particles) kicked the box back up at 0.8 m/s and the run diverged. On a critically
// damped contact the resting box rang, driven by the fluid load's noise, and the floor carried
// 10 % less than (rho_b - rho) g V (5.29 N) however long it rested; overdamped (World's ζ = 5)
// the floor takes what the water leaves once the tank has calmed after the landing.
// Measured: the floor carries 5.762 N, -2.1 % from (rho_b - rho) g V and +0.02 % from m g less
// what the water gives the box held still, which at 1 cm is 2.1 % above rho g V (a fixed box
// in mid-water 2.7 %, at 5 mm 0.1 %): the rest of the gap is the loads' resolution.
TEST(FloatingBodies, ADenseBoxLandsOnTheFloorAndRests) {
    World world = tankWithBox(2000.0, 0.02f);  // lands after 1 cm
    const std::uint32_t solid = *world.findSolid("box");
    double held = 0.0, heldTime = 0.0, settled = 0.0;
    world.settle(0.6, 0.0f, [&] {  // the body held where it starts, fully submerged
        settled += world.stats().lastDt;
        if (settled < 0.4) return;
        held += world.solidLoads().at(solid).force().y * world.stats().lastDt;
        heldTime += world.stats().lastDt;
    });
    world.advance(1.2);
    double impulse = 0.0, duration = 0.0, lowest = 1.0, highest = 0.0, fastest = 0.0;
    double fluid = 0.0;
    world.advance(0.3, [&]() {
        const BodyState b = world.bodies().at(0);
        const double dt = world.stats().lastDt;
        impulse += b.contactForce.y * dt;
        fluid += world.solidLoads().at(solid).force().y * dt;
        duration += dt;
        lowest = std::min(lowest, b.position.y);
        highest = std::max(highest, b.position.y);
        fastest = std::max(fastest, std::abs(b.velocity.y));
    });
    const double volume = 0.1 * 0.1 * 0.06, weight = 2000.0 * 9.81 * volume, buoyancy = 1000.0 * 9.81 * volume;
    const double contact = impulse / duration, water = held / heldTime;
    std::printf("held: the water gives %.4f N (rho g V = %.4f N, %+.2f %%); resting: contact %.4f N against m g - that = "
                "%.4f N (%+.2f %%) and (rho_b - rho) g V = %.4f N (%+.2f %%), fluid %.4f N; centre %.5f..%.5f m, speed <= %.4f m/s\n",
                water, buoyancy, 100.0 * (water / buoyancy - 1.0), contact, weight - water,
                100.0 * (contact / (weight - water) - 1.0), weight - buoyancy, 100.0 * (contact / (weight - buoyancy) - 1.0),
                fluid / duration, lowest, highest, fastest);
    // At rest a spacing above the floor (the film the fluid resolves), not bouncing.
    EXPECT_NEAR(lowest, 0.05 + kSpacing, 0.1 * kSpacing);
    EXPECT_LT(highest - lowest, 0.1 * kSpacing);
    EXPECT_NEAR(water, buoyancy, 0.03 * buoyancy) << "Archimedes at 1 cm";
    EXPECT_NEAR(contact, weight - water, 0.01 * (weight - buoyancy)) << "the floor carries what the water does not";
    EXPECT_NEAR(contact, weight - buoyancy, 0.03 * (weight - buoyancy)) << "acceptance 3";
}

TEST(FloatingBodies, CheckpointsAndThreadCountsChangeNothing) {
    World one = tankWithBox(500.0, 0.17f, 1), two = tankWithBox(500.0, 0.17f, 2);
    one.advance(0.05);
    one.advance(0.05);
    two.advance(0.05);
    const WorldState half = two.saveState();
    World resumed = tankWithBox(500.0, 0.17f, 2);
    resumed.restoreState(half);
    two.advance(0.05);
    resumed.advance(0.05);
    const BodyState a = one.bodies().at(0), b = two.bodies().at(0), c = resumed.bodies().at(0);
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.velocity, b.velocity);
    EXPECT_EQ(b.position, c.position);
    EXPECT_EQ(b.velocity, c.velocity);
    EXPECT_NE(a.position.y, 0.22) << "it moved";
}

TEST(FloatingBodies, BadBodiesAreRefusedNamingTheFieldAndLeaveTheWorldAsItWas) {
    WorldDef def;
    def.domainMax = {0.3f, 0.35f, 0.1f};
    World world(def);
    world.addMaterial(MaterialDef{});
    ObstacleDef box;
    box.min = {0.1f, 0.1f, 0.02f};
    box.max = {0.2f, 0.2f, 0.08f};
    const auto refused = [&](const BodyDynamicsDef& body, const std::string& field) {
        ObstacleDef o = box;
        o.dynamics = body;
        try {
            world.addObstacle(o);
            ADD_FAILURE() << "accepted a bad " << field;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
        }
    };
    BodyDynamicsDef negative;
    negative.density = -5.0;
    refused(negative, "density");
    BodyDynamicsDef none;
    refused(none, "density");
    BodyDynamicsDef axis;
    axis.density = 500.0;
    axis.freeAxes = {"w"};
    refused(axis, "unknown axis");
    BodyDynamicsDef outside;
    outside.density = 500.0;
    ObstacleDef far = box;
    far.min.y = -0.2f;
    far.dynamics = outside;
    EXPECT_THROW(world.addObstacle(far), std::invalid_argument);
    EXPECT_TRUE(world.obstacles().empty());
    EXPECT_TRUE(world.bodies().empty());
    BodyDynamicsDef good;
    good.density = 500.0;
    box.dynamics = good;
    world.addObstacle(box);
    EXPECT_EQ(world.bodies().size(), 1u);
    world.step(1e-3);  // one body, one load: the refused ones left nothing behind
}

}  // namespace
