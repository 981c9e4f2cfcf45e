// Emitters: layers exactly one spacing apart, whatever the step or frame length.
#include <cmath>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <tide/fluid.hpp>

#include "sources/emitter.hpp"

namespace {

using namespace tide;

/// Runs an emitter over [0, T] in steps of varying length and returns where each emitted
/// layer is at time T if it moved ballistically.
std::vector<float> layerPositionsAtEnd(double frameTime, double total) {
    EmitterState e{EmitterDef{{0, 0, 0}, {0, 0.05f, 0.05f}, {2.0f, 0, 0}, 0, 0.0, 1e9}};
    const float spacing = 0.01f;
    std::vector<std::pair<float, double>> layers;  // x at emission, emission time
    double t = 0.0;
    int k = 0;
    while (t < total - 1e-12) {
        const double frameEnd = std::min(total, t + frameTime);
        while (t < frameEnd - 1e-12) {
            const double dt = std::min(frameEnd - t, 1e-3 * (1.0 + 0.7 * std::sin(0.37 * k++)));
            e.advance(t, dt, spacing, [&](const Lattice& layer) {
                layers.emplace_back(layer.first.x, t + dt);
                return true;
            });
            t += dt;
        }
    }
    std::vector<float> out;
    for (auto [x, when] : layers) out.push_back(x + 2.0f * static_cast<float>(total - when));
    return out;
}

TEST(Emitter, LayersAreOneSpacingApartAtAnyFrameRate) {
    for (double fps : {30.0, 60.0, 144.0}) {
        const auto x = layerPositionsAtEnd(1.0 / fps, 1.0);
        const double expected = std::round(2.0 * 1.0 / 0.01);
        EXPECT_NEAR(static_cast<double>(x.size()), expected, 1.0) << fps << " fps";
        for (std::size_t k = 1; k < x.size(); ++k)
            ASSERT_NEAR(x[k - 1] - x[k], 0.01f, 1e-4f) << "layer " << k << " at " << fps << " fps";
    }
}

TEST(Emitter, FluidJetHasNoGapsOrDoubleLayers) {
    for (float fps : {30.0f, 60.0f}) {
        Fluid fluid;
        FluidSettings settings;
        settings.metresPerUnit = 0.01f;  // 1 unit = 1 cm, spacing 1 cm
        fluid.init(100000, {-50, -50, -50}, {50, 50, 50}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, settings);
        const float speed = 0.5f;  // m/s
        const float duration = 1.0f;
        const int frames = static_cast<int>(std::lround(duration * fps));
        for (int f = 0; f < frames; ++f) {
            ASSERT_TRUE(fluid.addPointTick({-40, -2, -2}, {-40, 2, 2}, {speed, 0, 0}));
            fluid.step(1.0f / fps);
        }
        const unsigned perLayer = 4 * 4;
        ASSERT_EQ(fluid.getPointCounts() % perLayer, 0u);
        const double layers = fluid.getPointCounts() / perLayer;
        EXPECT_NEAR(layers, std::round(speed * duration / 0.01), 1.0) << fps << " fps";
        // Without gravity the stream coasts: its layers stay one spacing apart.
        std::map<long, int> perX;
        const Point* points = fluid.getPointBuf();
        for (unsigned i = 0; i < fluid.getPointCounts(); ++i) ++perX[std::lround(points[i].pos.x * 100.0)];
        std::vector<double> xs;
        for (auto [x, count] : perX) {
            EXPECT_EQ(count, static_cast<int>(perLayer)) << "a double or broken layer at x = " << x / 100.0;
            xs.push_back(x / 100.0);
        }
        for (std::size_t k = 1; k < xs.size(); ++k) EXPECT_NEAR(xs[k] - xs[k - 1], 1.0, 0.02) << fps << " fps";
    }
}

}  // namespace

namespace {

// A full world drops the layers still due at once: a jet of 1e6 m/s owes ~5e7 layers per
// step, which tried one by one would hang the step (as a fuzzed scene showed through the
// size estimate). They are counted in emitterCapacityHits.
TEST(Emitter, AFullWorldDropsTheLayersDueAtOnceAndCountsThem) {
    tide::WorldDef def;
    def.particleSpacing = 0.02f;
    def.capacity = 300;
    def.threads = 1;
    tide::World world(def);
    world.addMaterial({});
    tide::EmitterDef jet;
    jet.min = {0.1f, 0.5f, 0.4f};
    jet.max = {0.1f, 0.6f, 0.5f};  // 5 × 5 = 25 particles a layer
    jet.velocity = {1e6f, 0.0f, 0.0f};
    world.addEmitter(jet);
    // The layers that do not fit are counted, not tried one by one: a loop over all of them
    // would not end within the test's timeout.
    world.step(1e-3);
    EXPECT_EQ(world.particles().size(), 300u);  // 12 layers fit
    const double due = 1e6 * world.stats().lastDt / 0.02;
    EXPECT_NEAR(static_cast<double>(world.stats().emitterCapacityHits), due - 12.0, 2.0);
}

}  // namespace
