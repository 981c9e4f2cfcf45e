// A solitary wave from a piston on Goring's 1978 trajectory (issue 42): its crest height at
// gauges along a flume and its celerity from the crests' arrival times, against Boussinesq's
// c = √(g(d + H)). Acceptance: height within 5 % after 10 depths of travel, celerity within 2 %.
//
//   tide_solitary_wave [--spacing S] [--depth D] [--height H] [--dimensions 2|3] [--threads N]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <CLI/CLI.hpp>

#include <tide/world.hpp>

#include "testing/scenarios.hpp"

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
    tide::World world = dimensions == 2 ? tide::scenarios::planarFlume(spacing, length, paddle, 0.0f, threads)
                                        : tide::scenarios::waveFlume(spacing, length, depth, paddle, 0.0f, threads);
    std::printf("%dD flume %.2f m, %u particles, d %.3f m, H %.3f m (%.1f spacings), stroke %.3f m, c = %.4f m/s\n", dimensions,
                length, world.particles().size(), depth, height, height / spacing, stroke, c);
    std::vector<double> crest(at.size(), -1.0), when(at.size(), 0.0), still(at.size(), 0.0);
    std::vector<std::vector<double>> records(at.size());
    const float z = 0.5f * world.def().domainMax.z;
    // Elevations from the level each gauge reads before the wave (the gauges read still water
    // ~half a spacing low: docs/waves.md).
    for (std::size_t k = 0; k < at.size(); ++k) still[k] = world.surfaceHeight(at[k], z);
    const double dt = 0.01, end = t0 + (length - paddle.x) / c;
    for (double t = dt; t <= end + 1e-9; t += dt) {
        world.advance(dt);
        for (std::size_t k = 0; k < at.size(); ++k) {
            const double eta = world.surfaceHeight(at[k], z) - still[k];
            records[k].push_back(std::isfinite(eta) ? eta : 0.0);
        }
    }
    // Each gauge's crest: its highest sample before the wave would reach the far wall (its
    // reflection comes later), timed by the centroid of η² over the samples around it above
    // half its height (less noisy than the highest sample's time).
    for (std::size_t k = 0; k < at.size(); ++k) {
        const std::vector<double>& r = records[k];
        const std::size_t last = std::min(r.size(), static_cast<std::size_t>((t0 + (length - paddle.x) / c) / dt));
        const std::size_t top = static_cast<std::size_t>(std::max_element(r.begin(), r.begin() + last) - r.begin());
        crest[k] = r[top];
        std::size_t a = top, b = top;
        while (a > 0 && r[a - 1] > 0.5 * crest[k]) --a;
        while (b + 1 < last && r[b + 1] > 0.5 * crest[k]) ++b;
        double w = 0.0, wt = 0.0;
        for (std::size_t s = a; s <= b; ++s) w += r[s] * r[s], wt += r[s] * r[s] * dt * (s + 1);
        when[k] = wt / w;
    }
    for (std::size_t k = 0; k < at.size(); ++k)
        std::printf("%2zu depths (x = %.3f m): crest %.4f m (%+.1f %%), at %.3f s\n", k + 2, at[k], crest[k],
                    100.0 * (crest[k] / height - 1.0), when[k]);
    // Celerity: least-squares slope of x against arrival time over the gauges from 4 depths on.
    double st = 0, sx = 0, stt = 0, stx = 0, n = 0;
    for (std::size_t k = 2; k < at.size(); ++k) st += when[k], sx += at[k], stt += when[k] * when[k], stx += when[k] * at[k], ++n;
    const double speed = (n * stx - st * sx) / (n * stt - st * st);
    std::printf("celerity %.4f m/s against sqrt(g(d + H)) = %.4f (%+.2f %%); height after 10 depths %+.1f %%\n", speed, c,
                100.0 * (speed / c - 1.0), 100.0 * (crest[8] / height - 1.0));
    return 0;
}
