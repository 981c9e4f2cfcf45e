// Where still water stops being still: a block of water at rest in a tank (closed in x,
// z one periodic cell unless --closed) and, every --every seconds, the RMS and the largest
// speed of the particles in each layer one spacing thick from the floor up. The particles of
// the cubic lattice the water starts on rearrange under the hydrostatic pressure from the
// floor up, at a rate that grows with that pressure and with the kernel support
// (docs/robustness.md § The tank at rest); this shows when and where.
//
//   tide_rest_layers [--solver dfsph] [--spacing 0.02] [--support-ratio 2] [--depth 0.3] ...
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <tide/world.hpp>

int main(int argc, char** argv) {
    CLI::App app{"RMS and largest speed per layer of water at rest, over time"};
    std::string solver = "dfsph";
    float spacing = 0.02f, supportRatio = tide::WorldDef{}.supportRatio, depth = 0.3f, length = 0.68f;
    float maxDensityError = tide::SolverDef{}.maxDensityError, xsph = -1.0f, momentum = -1.0f, gravity = 9.81f;
    double seconds = 0.5, every = 0.05;
    int threads = 1, width = 0;
    bool closed = false;
    app.add_option("--solver", solver, "solver.method")->capture_default_str();
    app.add_option("--spacing", spacing, "particle spacing, m")->capture_default_str()->check(CLI::PositiveNumber);
    app.add_option("--support-ratio", supportRatio, "kernel support / spacing")->capture_default_str()->check(CLI::Range(1.0, 4.0));
    app.add_option("--depth", depth, "water depth, m")->capture_default_str()->check(CLI::PositiveNumber);
    app.add_option("--length", length, "tank length (x), m")->capture_default_str()->check(CLI::PositiveNumber);
    app.add_option("--width", width, "z width in spacings (0: the least a periodic z allows, at least 4)");
    app.add_flag("--closed", closed, "walls across z too (a square tank `length` wide) instead of a periodic cell");
    app.add_option("--gravity", gravity, "|g|, m/s²")->capture_default_str()->check(CLI::NonNegativeNumber);
    app.add_option("--seconds", seconds, "simulated time, s")->capture_default_str()->check(CLI::PositiveNumber);
    app.add_option("--every", every, "report interval, s")->capture_default_str()->check(CLI::PositiveNumber);
    app.add_option("--max-density-error", maxDensityError, "solver.max_density_error")->capture_default_str();
    app.add_option("--xsph", xsph, "solver.xsph (negative: the solver's default)")->capture_default_str();
    app.add_option("--momentum", momentum, "solver.momentum (negative: the solver's default)")->capture_default_str();
    app.add_option("--threads", threads, "worker threads")->capture_default_str();
    CLI11_PARSE(app, argc, argv);

    if (width <= 0) width = std::max(4, static_cast<int>(std::ceil(2.0f * supportRatio - 1e-4f)));
    tide::WorldDef def;
    def.domainMax = {length, 2.0f * depth, closed ? length : static_cast<float>(width) * spacing};
    def.periodic = {false, false, !closed};
    def.gravity = {0.0f, -gravity, 0.0f};
    def.particleSpacing = spacing;
    def.supportRatio = supportRatio;
    def.threads = threads;
    def.solver.method = solver;
    def.solver.maxDensityError = maxDensityError;
    def.solver.xsph = xsph;
    def.solver.momentum = momentum;
    try {
        tide::World world(def);
        world.addMaterial(tide::MaterialDef{});
        world.addBlock({{0.0f, 0.0f, 0.0f}, {length, depth, def.domainMax.z}, {}, 0});
        const int layers = static_cast<int>(std::lround(depth / spacing));
        std::printf("%s, spacing %.4f m, support %.2f spacings, %u particles, %d layers; speeds in mm/s, floor first\n",
                    solver.c_str(), spacing, supportRatio, world.particles().size(), layers);
        const int reports = static_cast<int>(std::lround(seconds / every));
        for (int n = 0; n < reports; ++n) {
            world.advance(every);
            const tide::ParticleStore& p = world.particles();
            std::vector<double> sum(layers, 0.0), count(layers, 0.0), largest(layers, 0.0);
            for (std::uint32_t i = 0; i < p.size(); ++i) {
                const int layer = std::clamp(static_cast<int>(p.position[i].y / spacing), 0, layers - 1);
                const double speed = glm::length(p.velocity[i]);
                sum[layer] += speed * speed;
                count[layer] += 1.0;
                largest[layer] = std::max(largest[layer], speed);
            }
            std::printf("t %.3f s, max %.4f m/s\n  rms:", world.time(), world.stats().maxSpeed);
            for (int l = 0; l < layers; ++l) std::printf(" %3.0f", count[l] > 0.0 ? 1e3 * std::sqrt(sum[l] / count[l]) : 0.0);
            std::printf("\n  max:");
            for (int l = 0; l < layers; ++l) std::printf(" %3.0f", 1e3 * largest[l]);
            std::printf("\n");
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tide_rest_layers: %s\n", e.what());
        return 1;
    }
    return 0;
}
