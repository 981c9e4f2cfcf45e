// The seed's Fluid API (SPEC.md §3), in the seed's own world units.
#include <cmath>
#include <cstring>
#include <string>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <tide/fluid.hpp>

namespace {

using namespace tide;

void initSeedBox(Fluid& fluid, std::uint32_t capacity = 65535, const FluidSettings& settings = {}) {
    fluid.init(capacity, {-20, -20, -20}, {20, 20, 20}, {0, 0, 0}, {0, 0, 0}, {0, -9.81f, 0}, settings);
}

FluidSettings seedSettings() {
    FluidSettings settings;
    settings.solver = FluidSettings::seedSolver();
    return settings;
}

// The seed's solver, asked for by name (the default is the live preset, pbf).
TEST(FluidApi, SeedFreeFallBlockRunsVerbatim) {
    Fluid fluid;
    initSeedBox(fluid, 65535, seedSettings());
    EXPECT_EQ(fluid.world().def().solver.method, "classic");
    ASSERT_TRUE(fluid.addPoint(glm::vec3(-15, -10, -15), glm::vec3(10, 20, 10), glm::vec3(0, 0, 0)));
    EXPECT_EQ(fluid.getPointCounts(), 25u * 30u * 25u);
    EXPECT_EQ(fluid.getPointStride(), sizeof(Point));
    EXPECT_EQ(sizeof(Point), 40u);
    const float* pos = fluid.getPosData();
    const Point* points = fluid.getPointBuf();
    for (unsigned i = 0; i < fluid.getPointCounts(); i += 997) {
        EXPECT_EQ(pos[3 * i + 1], points[i].pos.y);
        EXPECT_EQ(fluid.getMaterialIndex(i), 0);
    }
    const float topBefore = points[fluid.getPointCounts() - 1].pos.y;
    fluid.step(1.0f / 30.0f);
    EXPECT_NEAR(fluid.time(), 1.0 / 30.0, 1e-6);
    // A block 0.75 m tall in a 1 m tank falls like water: ½ g t² in world units at its top.
    float top = -1e9f;
    for (unsigned i = 0; i < fluid.getPointCounts(); ++i) top = std::max(top, fluid.getPosData()[3 * i + 1]);
    const float drop = topBefore - top;
    EXPECT_NEAR(drop, 0.5f * 9.81f / 900.0f / 0.025f, 0.3f);
}

// The default, live preset (pbf, 2 substeps a frame): the same block falls like water too.
TEST(FluidApi, LiveDefaultFreeFallBlock) {
    Fluid fluid;
    initSeedBox(fluid);
    EXPECT_EQ(fluid.world().def().solver.method, "pbf");
    ASSERT_TRUE(fluid.addPoint(glm::vec3(-15, -10, -15), glm::vec3(10, 20, 10), glm::vec3(0, 0, 0)));
    float topBefore = -1e9f;
    for (unsigned i = 0; i < fluid.getPointCounts(); ++i) topBefore = std::max(topBefore, fluid.getPosData()[3 * i + 1]);
    fluid.step(1.0f / 30.0f);
    EXPECT_NEAR(fluid.time(), 1.0 / 30.0, 1e-6);
    EXPECT_EQ(fluid.world().stats().steps, 2u);
    float top = -1e9f;
    for (unsigned i = 0; i < fluid.getPointCounts(); ++i) top = std::max(top, fluid.getPosData()[3 * i + 1]);
    // Implicit Euler over two substeps: g Δt² (1 + 2) for the top layer, ½ g t² × 1.5.
    const float expected = 9.81f * (1.0f / 60.0f) * (1.0f / 60.0f) * 3.0f / 0.025f;
    EXPECT_NEAR(topBefore - top, expected, 0.3f);
}

TEST(FluidApi, AddPointBeyondCapacityReturnsFalseAndChangesNothing) {
    Fluid fluid;
    initSeedBox(fluid, 1000);
    ASSERT_TRUE(fluid.addPoint({-20, -20, -20}, {-10, -10, -12}, {0, 0, 0}));  // 10×10×8 = 800
    const unsigned count = fluid.getPointCounts();
    const float* pos = fluid.getPosData();
    std::vector<float> before(pos, pos + 3 * count);
    EXPECT_FALSE(fluid.addPoint({0, 0, 0}, {5, 5, 10}, {0, 0, 0}));  // 250 more: over 1000
    EXPECT_EQ(fluid.getPointCounts(), count);
    EXPECT_EQ(std::memcmp(before.data(), fluid.getPosData(), before.size() * sizeof(float)), 0);
    EXPECT_TRUE(fluid.addPoint({0, 0, 0}, {5, 5, 8}, {0, 0, 0}));  // exactly 200 more fits
    EXPECT_EQ(fluid.getPointCounts(), 1000u);
}

TEST(FluidApi, AddPointOutsideTheWallBoxReturnsFalse) {
    Fluid fluid;
    initSeedBox(fluid);
    EXPECT_FALSE(fluid.addPoint({15, 15, 15}, {25, 25, 25}, {0, 0, 0}));
    EXPECT_FALSE(fluid.addPointTick({-30, -4, -4}, {-30, 0, 0}, {2, 0, 0}));
    EXPECT_EQ(fluid.getPointCounts(), 0u);
}

TEST(FluidApi, MaterialsByValueWithIndices) {
    Fluid fluid;
    initSeedBox(fluid);
    const MaterialIndex heavyOil = fluid.addMaterial(Material(30.0f, 5000.0f, glm::vec3(0.5f, 0.5f, 1.0f)));
    const MaterialIndex lightOil = fluid.addMaterial(Material(30.0f, 200.0f, glm::vec3(0.5f, 1.0f, 0.5f)));
    EXPECT_EQ(heavyOil, 1);
    EXPECT_EQ(lightOil, 2);
    ASSERT_TRUE(fluid.addPoint({0, 0, 0}, {4, 4, 4}, {0, 0, 0}, lightOil));
    EXPECT_EQ(fluid.getMaterialIndex(0), lightOil);
    EXPECT_EQ(fluid.world().materials()[heavyOil].restDensity, 5000.0f);
    EXPECT_THROW(fluid.addPoint({0, 0, 0}, {4, 4, 4}, {0, 0, 0}, 9), std::invalid_argument);
    EXPECT_THROW(static_cast<void>(fluid.getMaterialIndex(fluid.getPointCounts())), std::out_of_range);
    EXPECT_THROW(fluid.addMaterial(Material(-1.0f, 1000.0f, {})), std::invalid_argument);
}

TEST(FluidApi, ResetEmptiesEverything) {
    Fluid fluid;
    fluid.init(5000, {-10, -10, -10}, {10, 10, 10}, {-5, -5, -5}, {5, 5, 5}, {0, -9.81f, 0});
    EXPECT_EQ(fluid.getPointCounts(), 1000u);
    fluid.reset();
    EXPECT_EQ(fluid.getPointCounts(), 0u);
    EXPECT_FALSE(fluid.addPoint({-5, -5, -5}, {5, 5, 5}, {0, 0, 0}));
    fluid.step(0.1f);  // harmless when empty
    EXPECT_EQ(fluid.time(), 0.0);
}

TEST(FluidApi, BadSettingsAreRejectedByName) {
    Fluid fluid;
    FluidSettings settings;
    settings.metresPerUnit = 0.0f;
    try {
        fluid.init(100, {-1, -1, -1}, {1, 1, 1}, {0, 0, 0}, {0, 0, 0}, {0, -9.81f, 0}, settings);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("metresPerUnit"), std::string::npos);
    }
    EXPECT_EQ(fluid.getPointCounts(), 0u);
    EXPECT_THROW(fluid.init(100, {1, -1, -1}, {-1, 1, 1}, {0, 0, 0}, {0, 0, 0}, {0, -9.81f, 0}), std::invalid_argument);
}

// A forced time step far beyond stability: step() throws tide::DivergenceError naming the
// particle, and what the facade hands out to draw holds no NaN or infinity.
TEST(FluidApi, DivergenceThrowsAndTheDrawingBuffersStayFinite) {
    Fluid fluid;
    FluidSettings settings = seedSettings();
    settings.threads = 1;
    settings.solver.minDt = 0.05f;
    settings.solver.maxDt = 0.05f;
    fluid.init(65535, {-20, -20, -20}, {20, 20, 20}, {-20, -20, -20}, {0, 0, 20}, {0, -9.81f, 0}, settings);
    bool diverged = false;
    for (int frame = 0; frame < 40 && !diverged; ++frame) {
        try {
            fluid.step(0.05f);
        } catch (const DivergenceError& e) {
            diverged = true;
            EXPECT_NE(std::string(e.what()).find("particle "), std::string::npos) << e.what();
        }
        if (frame % 2 == 0) (void)fluid.getPosData();  // a caller that draws every other frame
    }
    ASSERT_TRUE(diverged) << "a 0.05 s step of the classic solver did not diverge in 2 s";
    EXPECT_THROW(fluid.step(0.05f), DivergenceError);
    const float* pos = fluid.getPosData();
    for (unsigned i = 0; i < 3 * fluid.getPointCounts(); ++i) ASSERT_TRUE(std::isfinite(pos[i])) << i;
    const Point* points = fluid.getPointBuf();
    for (unsigned i = 0; i < fluid.getPointCounts(); ++i) {
        ASSERT_TRUE(std::isfinite(points[i].vel.x + points[i].vel.y + points[i].vel.z)) << i;
        ASSERT_TRUE(std::isfinite(points[i].density) && std::isfinite(points[i].pressure)) << i;
    }
}

}  // namespace
