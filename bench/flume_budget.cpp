// The water budget of a flume over time (issue 42's blow-up): a piston flume with a damping
// zone at the far end, printing every --every s the particle count, the total volume Σ m/ρ,
// the volume by reach (paddle to the zone, inside the zone), the mean level over the last
// period at the gauges and in the zone, the mean density of the top layer and the fastest
// particle. Defaults: the issue's flume (d 0.25 m, T 1.2 s, H 0.03 m, 12.5 mm, 1.2 m zone).
//
//   tide_flume_budget [--spacing S] [--depth D] [--period T] [--height H] [--length L]
//                     [--damping L] [--seconds T] [--threads N] [--shifting A] [--difference-form C]
//                     [--xsph E] [--momentum M] [--plain]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <tide/world.hpp>

#include "testing/scenarios.hpp"

int main(int argc, char** argv) {
    CLI::App app{"Water budget of a piston flume over time"};
    float spacing = 0.0125f, depth = 0.25f, period = 1.2f, height = 0.03f, length = 4.5f, damping = 1.2f;
    double seconds = 12.0, every = 0.2;
    int threads = 0;
    bool plain = false;
    tide::SolverDef solver;
    solver.maxDensityError = 0.003f;
    solver.shifting = 0.2f;
    solver.differenceForm = 0.5f;
    solver.xsph = 0.0f;
    solver.momentum = 0.0f;
    app.add_option("--spacing", spacing)->capture_default_str();
    app.add_option("--depth", depth)->capture_default_str();
    app.add_option("--period", period)->capture_default_str();
    app.add_option("--height", height)->capture_default_str();
    app.add_option("--length", length)->capture_default_str();
    app.add_option("--damping", damping)->capture_default_str();
    app.add_option("--seconds", seconds)->capture_default_str();
    app.add_option("--every", every)->capture_default_str();
    app.add_option("--threads", threads)->capture_default_str();
    app.add_option("--shifting", solver.shifting)->capture_default_str();
    app.add_option("--difference-form", solver.differenceForm)->capture_default_str();
    app.add_option("--xsph", solver.xsph)->capture_default_str();
    app.add_option("--momentum", solver.momentum)->capture_default_str();
    app.add_option("--max-density-error", solver.maxDensityError)->capture_default_str();
    app.add_flag("--plain", plain, "the solver's own defaults (no solver option applies)");
    CLI11_PARSE(app, argc, argv);
    if (plain) solver = tide::SolverDef{};
    tide::WaveMakerDef paddle;
    paddle.x = 0.1f;
    paddle.depth = depth;
    paddle.waveHeight = height;
    paddle.period = period;
    paddle.rampTime = 2.0f;
    length = spacing * std::round(length / spacing);
    tide::World world = tide::scenarios::waveFlume(spacing, length, depth, paddle, damping, threads, 4, solver);
    const float zoneStart = length - damping, z = 0.5f * world.def().domainMax.z;
    const std::vector<float> at{1.0f, 1.5f, 2.0f, 3.0f, zoneStart + 0.3f, length - 0.2f};
    std::deque<std::vector<double>> window;
    const int perPeriod = std::max(1, static_cast<int>(std::lround(period / 0.02)));
    std::printf("flume %.3f m, %u particles, zone from %.2f m\n", length, world.particles().size(), zoneStart);
    std::printf("    t       n   volume  V(paddle-zone) V(zone)  meanlevel@");
    for (float x : at) std::printf(" %5.2f", x);
    std::printf("  rho_top/rho0  vmax  unconv\n");
    const double v0 = [&] {
        double v = 0;
        for (std::uint32_t i = 0; i < world.particles().size(); ++i) v += world.particles().mass[i] / world.particles().density[i];
        return v;
    }();
    int samples = 0;
    const int printEvery = static_cast<int>(std::lround(every / 0.02));
    try {
        for (double t = 0.0; t < seconds - 1e-9; t += 0.02) {
            world.advance(0.02);
            std::vector<double> eta;
            for (float x : at) eta.push_back(world.surfaceHeight(x, z) - depth);
            window.push_back(eta);
            if (static_cast<int>(window.size()) > perPeriod) window.pop_front();
            if (++samples % printEvery) continue;
            const tide::ParticleStore& p = world.particles();
            double vol = 0, volIn = 0, volZone = 0, topRho = 0;
            int top = 0;
            float vmax = 0;
            for (std::uint32_t i = 0; i < p.size(); ++i) {
                const double v = p.mass[i] / p.density[i];
                vol += v;
                (p.position[i].x < zoneStart ? volIn : volZone) += v;
                vmax = std::max(vmax, std::sqrt(p.velocity[i].x * p.velocity[i].x + p.velocity[i].y * p.velocity[i].y +
                                                p.velocity[i].z * p.velocity[i].z));
                if (p.position[i].x > 0.5f && p.position[i].x < zoneStart &&
                    p.position[i].y > world.surfaceHeight(p.position[i].x, z) - spacing)
                    topRho += p.density[i], ++top;
            }
            std::printf("%6.2f %7u %8.5f %8.5f %8.5f   ", world.time(), p.size(), vol / v0, volIn, volZone);
            for (std::size_t g = 0; g < at.size(); ++g) {
                double m = 0;
                for (const auto& e : window) m += e[g];
                std::printf(" %+6.4f", m / window.size());
            }
            std::printf("  %.4f  %.3f  %llu\n", top ? topRho / top / 1000.0 : 0.0, vmax,
                        static_cast<unsigned long long>(world.stats().unconvergedSolves));
            std::fflush(stdout);
        }
    } catch (const std::exception& e) {
        std::printf("stopped: %s\n", e.what());
        return 1;
    }
    return 0;
}
