// A solitary wave from a piston on Goring's 1978 trajectory (issue 42): its crest height at
// gauges along a flume and its celerity from the crests' arrival times, against Boussinesq's
// c = √(g(d + H)). Acceptance: height within 5 % after 10 depths of travel, celerity within 2 %.
//
//   tide_solitary_wave [--spacing S] [--depth D] [--height H] [--dimensions 2|3] [--threads N]
//                      [--shifting S] [--difference-form F] (negative: the wave defaults)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <CLI/CLI.hpp>

#include <tide/world.hpp>

#include "testing/scenarios.hpp"
#include "testing/wave_analysis.hpp"
#include "tank_options.hpp"

int main(int argc, char** argv) {
    CLI::App app{"A solitary wave (Goring 1978) along a flume: crest height and celerity"};
    float spacing = 0.02f, depth = 0.25f, height = 0.05f;
    int threads = 0, dimensions = 3;
    app.add_option("--spacing", spacing)->capture_default_str();
    app.add_option("--depth", depth)->capture_default_str();
    app.add_option("--height", height)->capture_default_str();
    app.add_option("--threads", threads)->capture_default_str();
    app.add_option("--dimensions", dimensions, "2: the planar flume; 3: the periodic slab 4 spacings wide")
        ->check(CLI::IsMember({2, 3}))
        ->capture_default_str();
    tide::SolverDef solver;
    app.add_option("--shifting", solver.shifting, "solver.shifting (negative: the wave default)")->capture_default_str();
    app.add_option("--difference-form", solver.differenceForm, "solver.difference_form (negative: the wave default)")
        ->capture_default_str();
    tide::bench::addSmoothDensityErrorFlags(app, solver);
    CLI11_PARSE(app, argc, argv);
    tide::WaveMakerDef paddle;
    paddle.type = tide::WaveMakerDef::Type::Solitary;
    paddle.x = 0.1f;
    paddle.depth = depth;
    paddle.waveHeight = height;
    const double g = 9.81, c = std::sqrt(g * (depth + height));
    const double kappa = std::sqrt(3.0 * height / (4.0 * depth * depth * depth));
    const double stroke = 2.0 * height / (kappa * depth), t0 = (3.8 + height / depth) / (kappa * c);
    // Gauges from 2 to 12 depths past the paddle's end position; the far wall 3/κ beyond (where
    // the wave's front is at 1 % of its crest), so its reflection reaches none of them first.
    const float start = paddle.x + static_cast<float>(stroke);
    std::vector<float> at;
    for (int n = 2; n <= 12; ++n) at.push_back(start + static_cast<float>(n) * depth);
    const float length = spacing * std::ceil((at.back() + 3.0f / static_cast<float>(kappa)) / spacing);
    tide::World world = dimensions == 2 ? tide::scenarios::planarFlume(spacing, length, paddle, 0.0f, threads, solver)
                                        : tide::scenarios::waveFlume(spacing, length, depth, paddle, 0.0f, threads, 4, solver);
    std::printf("%dD flume %.2f m, %u particles, d %.3f m, H %.3f m (%.1f spacings), stroke %.3f m, c = %.4f m/s\n", dimensions,
                length, world.particles().size(), depth, height, height / spacing, stroke, c);
    std::vector<double> still(at.size(), 0.0);
    const double dt = 0.01, end = t0 + (length - paddle.x) / c;
    std::vector<tide::waves::Record> records(at.size(), tide::waves::Record{dt, dt, {}});
    const float z = 0.5f * world.def().domainMax.z;
    // Elevations from the level each gauge reads before the wave (the gauges read still water
    // ~half a spacing low: docs/waves.md).
    for (std::size_t k = 0; k < at.size(); ++k) still[k] = world.surfaceHeight(at[k], z);
    for (double t = dt; t <= end + 1e-9; t += dt) {
        world.advance(dt);
        for (std::size_t k = 0; k < at.size(); ++k) {
            const double eta = world.surfaceHeight(at[k], z) - still[k];
            records[k].eta.push_back(std::isfinite(eta) ? eta : 0.0);
        }
    }
    // Each gauge's crest before the wave would reach the far wall (its reflection comes later).
    std::vector<tide::waves::CrestPassage> crest;
    for (const tide::waves::Record& r : records) crest.push_back(tide::waves::crestPassage(r, static_cast<std::size_t>(end / dt) - 1));
    for (std::size_t k = 0; k < at.size(); ++k)
        std::printf("%2zu depths (x = %.3f m): crest %.4f m (%+.1f %%), at %.3f s\n", k + 2, at[k], crest[k].height,
                    100.0 * (crest[k].height / height - 1.0), crest[k].time);
    // Celerity: over the gauges from 4 depths on.
    std::vector<double> x, when;
    for (std::size_t k = 2; k < at.size(); ++k) x.push_back(at[k]), when.push_back(crest[k].time);
    const double speed = tide::waves::celerity(x, when);
    std::printf("celerity %.4f m/s against sqrt(g(d + H)) = %.4f (%+.2f %%); height after 10 depths %+.1f %%\n", speed, c,
                100.0 * (speed / c - 1.0), 100.0 * (crest[8].height / height - 1.0));
    return 0;
}
