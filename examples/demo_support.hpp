#pragma once
// Shared by the seed's demos: command-line options and the one-line summary printed once
// per second of simulated time. Uses only the public API.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include <tide/fluid.hpp>
#include <tide/view/viewer.hpp>

namespace demo {

struct Options {
    double seconds = 10.0;  ///< simulated time
    float fps = 60.0f;      ///< frames per second (the seed's render loop)
    int threads = 0;        ///< 0 = all cores
    float speed = 2.0f;     ///< jet speed, m/s (jets demo)
    bool four = false;      ///< four jets of four materials (jets demo)
    double every = 1.0;     ///< simulated seconds between summary lines
    bool view = false;      ///< open the viewer instead of running headless
    std::string solver = "pbf";  ///< the Fluid's solver (FluidSettings::solverNamed): pbf runs live
};

inline void usage(const char* program) {
    std::fprintf(stderr,
                 "usage: %s [--seconds S] [--every S] [--fps F] [--threads N] [--speed V] [--four] [--view] [--solver NAME]\n"
                 "  runs one of the seed's demos headless, printing a summary per simulated second;\n"
                 "  --view opens the viewer on it instead (tide-view's window and controls);\n"
                 "  --solver picks the Fluid's solver: pbf (live, default), classic, wcsph, pcisph, dfsph\n",
                 program);
}

/// Parses the options; prints a message naming the bad flag and exits 2 on bad input.
inline Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        auto number = [&](double lo, double hi) {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "%s: %s needs a value\n", argv[0], flag.c_str());
                std::exit(2);
            }
            char* end = nullptr;
            const double v = std::strtod(argv[++i], &end);
            if (end == argv[i] || *end != '\0' || !(v >= lo && v <= hi)) {
                std::fprintf(stderr, "%s: %s must be a number in [%g, %g], got \"%s\"\n", argv[0], flag.c_str(), lo,
                             hi, argv[i]);
                std::exit(2);
            }
            return v;
        };
        if (flag == "--seconds") o.seconds = number(0.0, 1e6);
        else if (flag == "--every") o.every = number(1e-3, 1e6);
        else if (flag == "--fps") o.fps = static_cast<float>(number(1.0, 10000.0));
        else if (flag == "--threads") o.threads = static_cast<int>(number(0.0, 1024.0));
        else if (flag == "--speed") o.speed = static_cast<float>(number(0.0, 100.0));
        else if (flag == "--four") o.four = true;
        else if (flag == "--view") o.view = true;
        else if (flag == "--solver") {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "%s: --solver needs a name\n", argv[0]);
                std::exit(2);
            }
            o.solver = argv[++i];
        } else if (flag == "--help" || flag == "-h") {
            usage(argv[0]);
            std::exit(0);
        } else {
            std::fprintf(stderr, "%s: unknown flag \"%s\"\n", argv[0], flag.c_str());
            usage(argv[0]);
            std::exit(2);
        }
    }
    return o;
}

inline tide::FluidSettings settings(const Options& o) {
    tide::FluidSettings s;
    s.threads = o.threads;
    s.solver = tide::FluidSettings::solverNamed(o.solver);
    return s;
}

/// particles, mean density error, max speed and each material's centroid height (world units).
inline void printSummary(const tide::Fluid& fluid) {
    const unsigned n = fluid.getPointCounts();
    const auto& materials = fluid.world().materials();
    std::vector<double> heightSum(materials.size(), 0.0);
    std::vector<unsigned> count(materials.size(), 0);
    const tide::Point* points = fluid.getPointBuf();
    for (unsigned i = 0; i < n; ++i) {
        heightSum[points[i].material] += points[i].pos.y;
        ++count[points[i].material];
    }
    const tide::WorldStats& stats = fluid.world().stats();
    std::printf("t=%6.2f s  particles=%7u  density error=%5.2f %%  max speed=%5.2f m/s  centroid y:", fluid.time(), n,
                100.0 * stats.meanDensityError, stats.maxSpeed);
    for (std::size_t m = 0; m < materials.size(); ++m)
        if (count[m] > 0) std::printf("  %s=%.2f", materials[m].name.c_str(), heightSum[m] / count[m]);
    std::printf("\n");
    std::fflush(stdout);
}

/// The seed's render loop: `setup` fills a fresh Fluid (again on the viewer's reset),
/// `perFrame` runs before each step (emitters call addPointTick there). Headless, it prints a
/// summary each simulated second and a total; with --view it opens the viewer instead.
inline int run(const Options& o, const std::function<void(tide::Fluid&)>& setup,
               const std::function<void(tide::Fluid&)>& perFrame = {}) {
    if (o.view) {
        tide::view::ViewerOptions viewer;
        viewer.title = "tide demo";
        return tide::view::runViewer(tide::view::fluidSource(setup, perFrame, 1.0f / o.fps), viewer);
    }
    tide::Fluid fluid;
    setup(fluid);
    const auto start = std::chrono::steady_clock::now();
    const int frames = static_cast<int>(o.seconds * o.fps + 0.5);
    const int framesPerSummary = std::max(1, static_cast<int>(o.every * o.fps + 0.5));
    std::uint64_t particleSteps = 0;
    printSummary(fluid);
    for (int frame = 1; frame <= frames; ++frame) {
        if (perFrame) perFrame(fluid);
        const auto stepsBefore = fluid.world().stats().steps;
        fluid.step(1.0f / o.fps);
        particleSteps += (fluid.world().stats().steps - stepsBefore) * fluid.getPointCounts();
        if (frame % framesPerSummary == 0 || frame == frames) printSummary(fluid);
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("done: %.2f s simulated in %.1f s wall, %llu steps, %.2f M particle-steps/s on %d threads\n",
                fluid.time(), wall, static_cast<unsigned long long>(fluid.world().stats().steps),
                particleSteps / std::max(wall, 1e-9) / 1e6, fluid.world().threads());
    return 0;
}

/// The seed's container: a box 40 units wide, centred on 0 (1 m at the default scale).
/// Several fluids of different density need a solver with a density contrast (pbf, dfsph,
/// pcisph, wcsph; the seed's classic smears density across their interfaces).
inline void initSeedTank(tide::Fluid& fluid, const Options& o) {
    fluid.init(65535, glm::vec3(-20, -20, -20), glm::vec3(20, 20, 20), glm::vec3(0), glm::vec3(0),
               glm::vec3(0, -9.81f, 0), settings(o));
}

}  // namespace demo
