// What loads and a few floating bodies cost per step (issue 44: targets ≤ 5 % and ≤ 10 %). The
// same tank three ways, stepped in alternating rounds so a shared machine's load falls on all
// alike: three boxes fixed with loads off, the same with loads on (forces.csv's sums), and the
// boxes floating (density 500, six degrees of freedom). Prints the median seconds per step of
// each and the ratios, with the pressure iterations per step (the solves should match). The
// ratios are of CPU seconds (the process's, one thread: a shared machine's other work takes
// wall time from a round, not CPU time), each round's against loads off in the same round,
// then the median over rounds; wall-clock medians are printed beside them.
// --only k steps world k alone (0, 1, 2 as listed), for a profiler.
//   build/bin/tide_bodies_cost [--spacing 0.01] [--rounds 6] [--steps 10] [--only k]
#include <algorithm>
#include <chrono>
#include <ctime>
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

double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("cost per step of loads and of three floating bodies");
    float spacing = 0.01f;
    int rounds = 6, steps = 10, only = -1;
    app.add_option("--spacing", spacing, "particle spacing, m");
    app.add_option("--rounds", rounds, "alternating rounds");
    app.add_option("--steps", steps, "steps per world per round");
    app.add_option("--only", only, "step only this world (0, 1, 2), for a profiler")->check(CLI::Range(0, 2));
    CLI11_PARSE(app, argc, argv);
    const char* names[3] = {"boxes fixed, loads off", "boxes fixed, loads on", "boxes floating"};
    const bool floating[3] = {false, false, true}, loads[3] = {false, true, false};
    std::unique_ptr<World> worlds[3];
    for (int w = 0; w < 3; ++w)
        if (only < 0 || only == w) worlds[w] = tank(spacing, loads[w], floating[w]);
    std::vector<double> cpu[3], wall[3];
    int iterations[3] = {0, 0, 0};
    for (int r = 0; r < rounds; ++r)
        for (int w = 0; w < 3; ++w) {
            if (!worlds[w]) continue;
            const auto start = std::chrono::steady_clock::now();
            const double cpuStart = cpuSeconds();
            for (int s = 0; s < steps; ++s) {
                worlds[w]->step(2e-3);
                iterations[w] += worlds[w]->stats().lastPressureIterations;
            }
            cpu[w].push_back((cpuSeconds() - cpuStart) / steps);
            wall[w].push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps);
        }
    double cpuMedian[3] = {0.0, 0.0, 0.0};
    for (int w = 0; w < 3; ++w) {
        if (!worlds[w]) continue;
        cpuMedian[w] = median(cpu[w]);
        std::printf("%-24s %6zu particles  %.4f CPU s/step, %.4f s/step wall (medians of %d rounds)  %.1f pressure iterations/step\n",
                    names[w], static_cast<std::size_t>(worlds[w]->particles().size()), cpuMedian[w], median(wall[w]), rounds,
                    double(iterations[w]) / (rounds * steps));
    }
    if (only >= 0) return 0;
    // Each round's CPU time against loads off in the same round, then the median.
    double ratio[3] = {1.0, 1.0, 1.0};
    for (int w = 1; w < 3; ++w) {
        std::vector<double> perRound(cpu[w].size());
        for (std::size_t r = 0; r < perRound.size(); ++r) perRound[r] = cpu[w][r] / cpu[0][r];
        ratio[w] = median(perRound);
    }
    std::printf("loads: %+.1f %% per step; three floating bodies: %+.1f %% per step (CPU time against loads off in the same "
                "round, median of the rounds)\n",
                100.0 * (ratio[1] - 1.0), 100.0 * (ratio[2] - 1.0));
}
