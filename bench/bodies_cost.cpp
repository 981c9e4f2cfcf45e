// What loads and a few floating bodies cost per step (issue 44: targets ≤ 5 % and ≤ 10 %). The
// same tank three ways, stepped in alternating rounds so a shared machine's load falls on all
// alike: three boxes fixed with loads off, the same with loads on (forces.csv's sums), and the
// boxes floating (density 500, six degrees of freedom). Prints the median seconds per step of
// each and the ratios, with the pressure iterations per step (the solves should match).
//   build/bin/tide_bodies_cost [--spacing 0.01] [--rounds 6] [--steps 10]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <vector>

#include <CLI/CLI.hpp>

#include <tide/world.hpp>

using namespace tide;

namespace {

std::unique_ptr<World> tank(float spacing, bool loads, bool floating) {
    WorldDef def;
    def.domainMax = {0.6f, 0.35f, 0.3f};
    def.particleSpacing = spacing;
    def.threads = 1;
    def.loads = loads;
    def.solver.maxDt = 2e-3f;  // the same steps in all three (the CFL limit stays above it)
    auto world = std::make_unique<World>(def);
    world->addMaterial(MaterialDef{});
    for (int k = 0; k < 3; ++k) {
        ObstacleDef box;
        box.min = {0.07f + 0.18f * k, 0.15f, 0.1f};
        box.max = {0.17f + 0.18f * k, 0.25f, 0.2f};
        if (floating) {
            BodyDynamicsDef body;
            body.density = 500.0;
            box.dynamics = body;
        }
        world->addObstacle(box);
    }
    BlockDef water;
    water.max = {0.6f, 0.2f, 0.3f};
    world->addBlock(water);
    world->settle(0.1);
    return world;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("cost per step of loads and of three floating bodies");
    float spacing = 0.01f;
    int rounds = 6, steps = 10;
    app.add_option("--spacing", spacing, "particle spacing, m");
    app.add_option("--rounds", rounds, "alternating rounds");
    app.add_option("--steps", steps, "steps per world per round");
    CLI11_PARSE(app, argc, argv);
    const char* names[3] = {"boxes fixed, loads off", "boxes fixed, loads on", "boxes floating"};
    std::unique_ptr<World> worlds[3] = {tank(spacing, false, false), tank(spacing, true, false), tank(spacing, false, true)};
    std::vector<double> perStep[3];
    int iterations[3] = {0, 0, 0};
    for (int r = 0; r < rounds; ++r)
        for (int w = 0; w < 3; ++w) {
            const auto start = std::chrono::steady_clock::now();
            for (int s = 0; s < steps; ++s) {
                worlds[w]->step(2e-3);
                iterations[w] += worlds[w]->stats().lastPressureIterations;
            }
            perStep[w].push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps);
        }
    double median[3];
    for (int w = 0; w < 3; ++w) {
        std::sort(perStep[w].begin(), perStep[w].end());
        median[w] = perStep[w][perStep[w].size() / 2];
        std::printf("%-24s %6zu particles  %.4f s/step (median of %d rounds)  %.1f pressure iterations/step\n", names[w],
                    static_cast<std::size_t>(worlds[w]->particles().size()), median[w], rounds, double(iterations[w]) / (rounds * steps));
    }
    std::printf("loads: %+.1f %% per step; three floating bodies: %+.1f %% per step (against loads off)\n",
                100.0 * (median[1] / median[0] - 1.0), 100.0 * (median[2] / median[0] - 1.0));
}
