// The viewer's parts that need no window: the camera's projections and default view, and the
// worker that steps a World between the window's commands (play, pause, step, reset, push,
// emitters) and publishes snapshots.
#include <chrono>
#include <cmath>
#include <functional>
#include <thread>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <tide/render/camera.hpp>
#include <tide/view/viewer.hpp>

#include "view/simulation_runner.hpp"

namespace {

using namespace tide;
using render::Camera;

TEST(Camera, PixelRayAndProjectionAgree) {
    const Camera camera{{1.0f, 0.8f, 2.0f}, {0.2f, 0.1f, -0.3f}, 40.0f};
    const glm::vec3 centre = render::projectToPixel(camera, 320, 200, camera.target);
    EXPECT_NEAR(centre.x, 160.0f, 1e-3f);
    EXPECT_NEAR(centre.y, 100.0f, 1e-3f);
    for (const glm::vec3& p : {glm::vec3(0.5f, 0.4f, 0.1f), glm::vec3(-0.3f, 0.0f, -0.5f)}) {
        const glm::vec3 pixel = render::projectToPixel(camera, 320, 200, p);
        ASSERT_GT(pixel.z, 0.0f);
        const glm::vec3 ray = render::pixelRay(camera, 320, 200, {pixel.x, pixel.y});
        EXPECT_GT(glm::dot(ray, glm::normalize(p - camera.eye)), 0.99999f);
    }
}

TEST(Camera, DefaultViewFramesTheWholeContainerFromAbove) {
    for (const auto& [lo, hi] : {std::pair{glm::vec3(0.0f), glm::vec3(1.6f, 0.6f, 0.6f)},
                                 std::pair{glm::vec3(-20.0f), glm::vec3(20.0f)},
                                 std::pair{glm::vec3(0.0f), glm::vec3(0.1f, 2.0f, 0.1f)}}) {
        const Camera camera = render::defaultCamera(lo, hi);
        EXPECT_GT(camera.eye.y, 0.5f * (lo.y + hi.y) + 0.1f * glm::length(hi - lo)) << "looks down on the container";
        for (const auto& [w, h] : {std::pair{960, 540}, std::pair{640, 480}})
            for (int corner = 0; corner < 8; ++corner) {
                const glm::vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
                const glm::vec3 pixel = render::projectToPixel(camera, w, h, p);
                EXPECT_GT(pixel.z, camera.nearPlane);
                EXPECT_LT(pixel.z, camera.farPlane);
                EXPECT_GE(pixel.x, 0.0f) << "corner " << corner << " of a " << w << "x" << h << " view";
                EXPECT_LE(pixel.x, static_cast<float>(w));
                EXPECT_GE(pixel.y, 0.0f);
                EXPECT_LE(pixel.y, static_cast<float>(h));
            }
    }
}

/// A still block of water in a small tank, and optionally an emitter.
World smallTank(bool emitter) {
    WorldDef def;
    def.domainMax = glm::vec3(0.2f);
    def.particleSpacing = 0.02f;
    def.threads = 1;
    def.capacity = 4000;
    World world(def);
    world.addMaterial(MaterialDef{});
    BlockDef block;
    block.max = glm::vec3(0.2f, 0.08f, 0.2f);
    world.addBlock(block);
    if (emitter) {
        EmitterDef e;
        e.min = glm::vec3(0.0f, 0.12f, 0.08f);
        e.max = glm::vec3(0.0f, 0.16f, 0.12f);
        e.velocity = glm::vec3(1.0f, 0.0f, 0.0f);
        world.addEmitter(e);
    }
    return world;
}

/// Fetches snapshots until `done` holds of one (true) or 120 s pass (false: a hang, not a
/// slow machine).
bool waitFor(view::SimulationRunner& runner, render::Snapshot& s, view::RunnerStatus& status,
             const std::function<bool()>& done) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (std::chrono::steady_clock::now() < deadline) {
        runner.fetch(s, status);
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
}

TEST(SimulationRunner, PlaysPausesStepsAndResets) {
    view::SimulationRunner runner(view::worldSource([] { return smallTank(false); }), false, 1.0);
    render::Snapshot s;
    view::RunnerStatus status;
    ASSERT_TRUE(runner.fetch(s, status)) << "a first snapshot before any step";
    EXPECT_EQ(s.time, 0.0);
    EXPECT_GT(s.size(), 100u);
    EXPECT_FALSE(status.playing);

    runner.send({view::Command::Kind::Step});
    ASSERT_TRUE(waitFor(runner, s, status, [&] { return s.time > 0.0; }));
    const double afterStep = s.time;
    EXPECT_EQ(s.stats.steps, 1u) << "one step, then paused";
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    runner.fetch(s, status);
    EXPECT_EQ(s.time, afterStep);

    runner.send({view::Command::Kind::Play});
    ASSERT_TRUE(waitFor(runner, s, status, [&] { return s.time > afterStep + 0.02 && status.playing; }));
    runner.send({view::Command::Kind::Pause});
    ASSERT_TRUE(waitFor(runner, s, status, [&] { return !status.playing; }));
    runner.fetch(s, status);
    const double paused = s.time;
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    runner.fetch(s, status);
    EXPECT_EQ(s.time, paused) << "no steps while paused";

    runner.send({view::Command::Kind::Reset});
    ASSERT_TRUE(waitFor(runner, s, status, [&] { return s.time == 0.0; }));
    EXPECT_EQ(s.stats.steps, 0u);
}

// A diverging world stops the worker with the guard's message; the window keeps the last
// good snapshot (no step count past the divergence, nothing non-finite), and Reset recovers.
TEST(SimulationRunner, DivergenceStopsWithTheMessageAndKeepsTheLastGoodSnapshot) {
    const auto unstable = [] {
        World world = smallTank(false);
        WorldDef def = world.def();
        def.solver.method = "wcsph";
        def.solver.minDt = 0.05f;  // far beyond stability
        def.solver.maxDt = 0.05f;
        World w(def);
        w.addMaterial(MaterialDef{});
        BlockDef block;
        block.max = glm::vec3(0.2f, 0.08f, 0.2f);
        w.addBlock(block);
        return w;
    };
    view::SimulationRunner runner(view::worldSource(unstable), true, 100.0);
    render::Snapshot s;
    view::RunnerStatus status;
    ASSERT_TRUE(waitFor(runner, s, status, [&] { return !status.error.empty(); }));
    EXPECT_NE(status.error.find("particle "), std::string::npos) << status.error;
    EXPECT_FALSE(status.playing);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    runner.fetch(s, status);
    for (std::uint32_t i = 0; i < s.size(); ++i) {
        ASSERT_TRUE(std::isfinite(s.position[i].x + s.position[i].y + s.position[i].z)) << i;
        ASSERT_TRUE(std::isfinite(s.velocity[i].x + s.velocity[i].y + s.velocity[i].z)) << i;
    }
    runner.send({view::Command::Kind::Reset});
    ASSERT_TRUE(waitFor(runner, s, status, [&] { return s.time == 0.0 && status.error.empty(); }));
}

TEST(SimulationRunner, RealTimeAtMostAtTheRequestedSpeed) {
    view::SimulationRunner runner(view::worldSource([] { return smallTank(false); }), true, 0.25);
    render::Snapshot s;
    view::RunnerStatus status;
    const auto start = std::chrono::steady_clock::now();
    std::this_thread::sleep_for(std::chrono::milliseconds(800));
    ASSERT_TRUE(waitFor(runner, s, status, [&] { return s.time > 0.0; }));
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // A quarter of real time, give or take one step (the budget may run one step ahead).
    EXPECT_LE(s.time, 0.25 * wall + 0.006);
}

TEST(SimulationRunner, PushGivesTheFluidNearTheRayTheDragsVelocity) {
    view::SimulationRunner runner(view::worldSource([] { return smallTank(false); }), false, 1.0);
    render::Snapshot s;
    view::RunnerStatus status;
    runner.fetch(s, status);
    view::Command push{view::Command::Kind::Push};
    push.origin = glm::vec3(0.1f, 0.5f, 0.1f);   // straight down through the tank's middle
    push.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    push.radius = 0.03f;
    push.deltaV = glm::vec3(0.5f, 0.0f, 0.0f);
    runner.send(push);
    ASSERT_TRUE(waitFor(runner, s, status, [&] {
        for (const glm::vec3& v : s.velocity)
            if (v.x > 0.1f) return true;
        return false;
    }));
    for (std::uint32_t i = 0; i < s.size(); ++i) {
        const glm::vec2 offset(s.position[i].x - 0.1f, s.position[i].z - 0.1f);
        if (glm::length(offset) >= 0.03f) EXPECT_EQ(s.velocity[i], glm::vec3(0.0f)) << "particle " << i;
        else EXPECT_NEAR(s.velocity[i].x, 0.5f * (1.0f - glm::length(offset) / 0.03f), 1e-5f);
    }
}

TEST(SimulationRunner, EmittersSwitchOffAndOn) {
    view::SimulationRunner runner(view::worldSource([] { return smallTank(true); }), false, 1.0);
    render::Snapshot s;
    view::RunnerStatus status;
    runner.fetch(s, status);
    EXPECT_TRUE(status.hasEmitters);
    const std::uint32_t initial = s.size();
    view::Command off{view::Command::Kind::Emitters};
    off.flag = false;
    runner.send(off);
    for (int k = 0; k < 20; ++k) runner.send({view::Command::Kind::Step});
    ASSERT_TRUE(waitFor(runner, s, status, [&] { return s.stats.steps >= 20 && !status.emitters; }));
    EXPECT_EQ(s.size(), initial) << "no particles from a switched-off emitter";
    view::Command on{view::Command::Kind::Emitters};
    on.flag = true;
    runner.send(on);
    for (int k = 0; k < 40; ++k) runner.send({view::Command::Kind::Step});
    ASSERT_TRUE(waitFor(runner, s, status, [&] { return s.stats.steps >= 60; }));
    EXPECT_GT(s.size(), initial);
}

TEST(FluidSource, RunsTheSeedApiAndResetsByBuildingAgain) {
    int builds = 0, frames = 0;
    auto source = view::fluidSource(
        [&](Fluid& fluid) {
            ++builds;
            FluidSettings settings;
            settings.threads = 1;
            fluid.init(4000, glm::vec3(-4), glm::vec3(4), glm::vec3(-4), glm::vec3(0, -2, 4), glm::vec3(0, -9.81f, 0),
                       settings);
        },
        [&](Fluid&) { ++frames; }, 1.0f / 60.0f);
    EXPECT_EQ(builds, 1);
    const std::uint32_t n = source->world().particles().size();
    EXPECT_GT(n, 0u);
    EXPECT_NEAR(source->advance(), 1.0 / 60.0, 1e-9);
    EXPECT_EQ(frames, 1);
    EXPECT_NEAR(source->world().time(), 1.0 / 60.0, 1e-6);
    source->setEmittersActive(false);
    source->advance();
    EXPECT_EQ(frames, 1) << "per-frame callbacks are the Fluid's emitters: off means not called";
    source->reset();
    EXPECT_EQ(builds, 2);
    EXPECT_EQ(source->world().time(), 0.0);
    EXPECT_EQ(source->world().particles().size(), n);
}

}  // namespace
