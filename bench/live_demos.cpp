// The seed's demos live (issue 45): light water (16,000 particles) and four materials
// (20,000) through the Fluid API with its defaults (pbf, 2 substeps a 1/60 s frame), timed
// frame by frame. Prints, per demo: simulated seconds per wall second, the frames' cost
// (median, max, max/median of wall time, and max/median of this process's CPU time: a frame whose
// wall time spikes at the median CPU time waited for a core), CPU seconds per simulated second (user + system of this
// process: on a loaded machine, wall time / CPU time is the share of the cores it got), and
// whether the layers ended in the order of their densities.
//
// With --trace FILE, one CSV row a frame (demo, frame, wall ms, CPU ms of this process, particles,
// mean compression and max speed after it, and the wall ms of each phase of World's phase clock in that frame): what a frame's cost is
// made of, and what spikes (a frame whose wall time spikes at the same CPU time waited for a core).
//
//   tide_live_bench [--seconds S] [--threads T] [--only light_water|many_materials] [--solver NAME] [--trace FILE]
//                   [--substeps N] [--iterations N]   (FluidSettings::substeps, the solver's constraint iterations)
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include <tide/fluid.hpp>

namespace {

double cpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

struct Demo {
    const char* name;
    std::function<void(tide::Fluid&)> setup;
};

/// The p-quantile of material m's heights, world units.
float heightQuantile(const tide::Fluid& fluid, tide::MaterialIndex m, double q) {
    std::vector<float> y;
    const tide::Point* points = fluid.getPointBuf();
    for (unsigned i = 0; i < fluid.getPointCounts(); ++i)
        if (points[i].material == m) y.push_back(points[i].pos.y);
    if (y.empty()) return 0.0f;
    std::sort(y.begin(), y.end());
    return y[std::min(y.size() - 1, static_cast<std::size_t>(q * static_cast<double>(y.size())))];
}

/// FNV-1a of the particles' positions' bytes: whether a change to the code changed the result.
std::uint64_t stateHash(const tide::Fluid& fluid) {
    std::uint64_t hash = 1469598103934665603ull;
    const tide::Point* points = fluid.getPointBuf();
    for (unsigned i = 0; i < fluid.getPointCounts(); ++i) {
        unsigned char bytes[sizeof(points[i].pos)];
        std::memcpy(bytes, &points[i].pos, sizeof bytes);
        for (const unsigned char b : bytes) hash = (hash ^ b) * 1099511628211ull;
    }
    return hash;
}

}  // namespace

int main(int argc, char** argv) {
    double seconds = 8.0;
    int threads = 2;
    int substeps = 0, iterations = 0;  // 0: FluidSettings' defaults
    std::string only, solver = "pbf", tracePath;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (i + 1 >= argc) {
            std::fprintf(stderr, "%s: %s needs a value\n", argv[0], flag.c_str());
            return 2;
        }
        if (flag == "--seconds") seconds = std::atof(argv[++i]);
        else if (flag == "--threads") threads = std::atoi(argv[++i]);
        else if (flag == "--only") only = argv[++i];
        else if (flag == "--solver") solver = argv[++i];
        else if (flag == "--trace") tracePath = argv[++i];
        else if (flag == "--substeps") substeps = std::atoi(argv[++i]);
        else if (flag == "--iterations") iterations = std::atoi(argv[++i]);
        else {
            std::fprintf(stderr, "usage: %s [--seconds S] [--threads T] [--only NAME] [--solver NAME] [--trace FILE] [--substeps N] [--iterations N]\n", argv[0]);
            return 2;
        }
    }
    tide::FluidSettings settings;
    settings.threads = threads;
    settings.solver = tide::FluidSettings::solverNamed(solver);
    if (substeps > 0) settings.substeps = substeps;
    if (iterations > 0) settings.solver.constraintIterations = iterations;
    const auto tank = [&](tide::Fluid& fluid) {
        fluid.init(65535, glm::vec3(-20), glm::vec3(20), glm::vec3(0), glm::vec3(0), glm::vec3(0, -9.81f, 0), settings);
    };
    // examples/light_water.cpp and examples/many_materials.cpp, call for call.
    const Demo demos[] = {
        {"light_water",
         [&](tide::Fluid& fluid) {
             tank(fluid);
             const auto light = fluid.addMaterial(tide::Material(1.0f, 200.0f, glm::vec3(1, 0.5f, 0.5f)));
             fluid.addPoint(glm::vec3(-20, -20, -10), glm::vec3(0, 0, 0), glm::vec3(0), light);
             fluid.addPoint(glm::vec3(-20, -20, -20), glm::vec3(0, 0, -10), glm::vec3(0));
             fluid.addPoint(glm::vec3(-20, -20, 0), glm::vec3(0, 0, 20), glm::vec3(0));
         }},
        {"many_materials",
         [&](tide::Fluid& fluid) {
             tank(fluid);
             const auto heavyOil = fluid.addMaterial(tide::Material(30.0f, 5000.0f, glm::vec3(0.5f, 0.5f, 1)));
             const auto lightOil = fluid.addMaterial(tide::Material(30.0f, 200.0f, glm::vec3(0.5f, 1, 0.5f)));
             const auto lightWater = fluid.addMaterial(tide::Material(1.0f, 200.0f, glm::vec3(1, 0.5f, 0.5f)));
             fluid.addPoint(glm::vec3(-20, -20, 0), glm::vec3(0, 0, 10), glm::vec3(0), lightOil);
             fluid.addPoint(glm::vec3(-20, -20, -20), glm::vec3(0, 0, -10), glm::vec3(0), lightWater);
             fluid.addPoint(glm::vec3(0, 0, 0), glm::vec3(20, 20, 20), glm::vec3(0), heavyOil);
             fluid.addPoint(glm::vec3(0, -20, -20), glm::vec3(20, -10, 0), glm::vec3(0));
         }},
    };
    FILE* trace = nullptr;
    if (!tracePath.empty()) {
        trace = std::fopen(tracePath.c_str(), "w");
        if (trace == nullptr) {
            std::fprintf(stderr, "%s: --trace %s: cannot write\n", argv[0], tracePath.c_str());
            return 2;
        }
        std::fprintf(trace, "demo,frame,ms,cpu_ms,particles,compression,max_speed,neighbor_ms,density_ms,pressure_ms,nonpressure_ms,integration_ms\n");
    }
    std::printf("%-15s %9s %6s %6s %9s %9s %9s %7s %7s %9s %s\n", "demo", "particles", "sim_s", "wall_s", "sim/wall",
                "median_ms", "max_ms", "max/med", "cpu_m/m", "cpu_s/sim", "layers (world units: water median, others' 10th/90th pct)");
    for (const Demo& demo : demos) {
        if (!only.empty() && only != demo.name) continue;
        tide::Fluid fluid;
        demo.setup(fluid);
        const float frame = 1.0f / 60.0f;
        const int frames = static_cast<int>(seconds * 60.0 + 0.5);
        std::vector<double> costs, cpuCosts;
        costs.reserve(static_cast<std::size_t>(frames));
        cpuCosts.reserve(static_cast<std::size_t>(frames));
        const double cpu0 = cpuSeconds();
        const auto start = std::chrono::steady_clock::now();
        for (int f = 0; f < frames; ++f) {
            const tide::PhaseSeconds before = fluid.world().stats().phaseSeconds;
            const double frameCpu0 = cpuSeconds();
            const auto t0 = std::chrono::steady_clock::now();
            fluid.step(frame);
            (void)fluid.getPosData();  // what a renderer reads every frame
            costs.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
            cpuCosts.push_back(cpuSeconds() - frameCpu0);
            if (trace != nullptr) {
                const tide::PhaseSeconds& after = fluid.world().stats().phaseSeconds;
                std::fprintf(trace, "%s,%d,%.3f,%.3f,%u,%.5f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f\n", demo.name, f, 1e3 * costs.back(),
                             1e3 * cpuCosts.back(), fluid.getPointCounts(), fluid.world().stats().meanCompression,
                             fluid.world().stats().maxSpeed, 1e3 * (after.neighborSearch - before.neighborSearch),
                             1e3 * (after.density - before.density), 1e3 * (after.pressureSolve - before.pressureSolve),
                             1e3 * (after.nonPressureForces - before.nonPressureForces),
                             1e3 * (after.integration - before.integration));
            }
        }
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double cpu = cpuSeconds() - cpu0;
        std::vector<double> sorted = costs;
        std::sort(sorted.begin(), sorted.end());
        const double median = sorted[sorted.size() / 2], worst = sorted.back();
        std::sort(cpuCosts.begin(), cpuCosts.end());
        const double cpuSpread = cpuCosts.back() / std::max(cpuCosts[cpuCosts.size() / 2], 1e-9);
        const float water = heightQuantile(fluid, 0, 0.5);
        std::printf("%-15s %9u %6.2f %6.1f %9.3f %9.2f %9.2f %7.2f %7.2f %9.2f water %.2f", demo.name, fluid.getPointCounts(),
                    fluid.time(), wall, fluid.time() / wall, 1e3 * median, 1e3 * worst, worst / median, cpuSpread, cpu / fluid.time(),
                    water);
        for (std::size_t m = 1; m < fluid.world().materials().size(); ++m) {
            const float rho = fluid.world().materials()[m].restDensity;
            const bool light = rho < 1000.0f;
            const float q = heightQuantile(fluid, static_cast<tide::MaterialIndex>(m), light ? 0.1 : 0.9);
            std::printf(" | %g kg/m3 %s %.2f (%s)", rho, light ? "p10" : "p90", q,
                        (light ? q > water : q < water) ? "ok" : "NOT LAYERED");
        }
        std::printf(" | escaped %u | state %016llx\n", fluid.world().countEscapedParticles(),
                    static_cast<unsigned long long>(stateHash(fluid)));
        std::fflush(stdout);
    }
    if (trace != nullptr) std::fclose(trace);
    return 0;
}
