// Active absorption in a flume closed by a vertical wall (issue 42, acceptance 4): a 2D piston
// flume whose far end reflects every wave, run with and without absorption at the paddle. It
// prints the wave-height envelope (each period's highest minus lowest level, averaged) at
// three gauges over periods 10-15 and 25-30 and their ratio, and the paddle's correction.
//
// The default flume is resonant: a piston that does not absorb reflects like a wall, and the
// forced standing wave between it and the far wall grows like 1/|sin kL| (kL = nπ: without
// bound in linear theory). 2.74 m from paddle to wall (n = 4: two Airy wave lengths, 2.746 m)
// is the middle of the resonance a scan of lengths found at the defaults (without absorption
// the envelope grows by 1.3-1.6 at 2.68-2.78 m; docs/notes/waves.md § The closed flume at
// resonance); the gauges stand at a quarter, half and three quarters of it, the standing
// wave's antinodes.
// The solver settings default to those a 2D wave scene gets (shifting 0.2, the heavy ball 0.7,
// no difference form; sources/wave_numerics.hpp).
//
//   tide_closed_flume [--spacing S] [--depth D] [--period T] [--height H] [--length L]
//                     [--periods N] [--threads N] [--absorption on|off|both]
//                     [--shifting A] [--difference-form C] [--momentum M] [--max-iterations N]
//                     [--trace PREFIX]
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <tide/world.hpp>

#include "testing/scenarios.hpp"
#include "testing/wave_analysis.hpp"

namespace {

struct Options {
    float spacing = 0.02f, depth = 0.3f, period = 1.0f, height = 0.04f, length = 2.74f;
    int periods = 30, threads = 1;
    // Negative: automatic, the settings a 2D wave scene gets.
    float shifting = -1.0f, differenceForm = -1.0f, momentum = -1.0f;
    std::string trace;  ///< a CSV of time, paddle displacement and the level in front of it
    int maxIterations = 1000;  // solved to convergence (at the 2D defaults the default 100 gives the same figures)
};

void run(const Options& o, bool absorb) {
    tide::WaveMakerDef paddle;
    paddle.x = 0.1f;
    paddle.depth = o.depth;
    paddle.waveHeight = o.height;
    paddle.period = o.period;
    paddle.rampTime = 2.0f * o.period;
    paddle.absorption = absorb ? tide::WaveMakerDef::Absorption::On : tide::WaveMakerDef::Absorption::Off;
    const float length = o.spacing * std::round((o.length + paddle.x) / o.spacing);
    tide::SolverDef solver;
    solver.shifting = o.shifting;
    solver.differenceForm = o.differenceForm;
    solver.momentum = o.momentum;
    solver.maxIterations = o.maxIterations;
    tide::World world = tide::scenarios::planarFlume(o.spacing, length, paddle, 0.0f, o.threads, solver);
    const float span = length - paddle.x;
    const std::vector<float> at{paddle.x + 0.25f * span, paddle.x + 0.5f * span, paddle.x + 0.75f * span};
    std::vector<tide::waves::Record> records(at.size(), tide::waves::Record{0.02, 0.02, {}});
    std::printf("absorption %s: %.3f m flume closed by a wall, %u particles, gauges at %.2f %.2f %.2f m\n",
                absorb ? "on" : "off", length, world.particles().size(), at[0], at[1], at[2]);
    double drift = 0.0;
    std::FILE* trace = o.trace.empty() ? nullptr : std::fopen((o.trace + (absorb ? "_on.csv" : "_off.csv")).c_str(), "w");
    if (trace) std::fprintf(trace, "time,displacement,level_in_front\n");
    const int samples = static_cast<int>(std::lround(o.periods * o.period / 0.02));
    try {
        for (int k = 0; k < samples; ++k) {
            world.advance(0.02);
            for (std::size_t g = 0; g < at.size(); ++g) records[g].eta.push_back(world.surfaceHeight(at[g], 0.0f) - o.depth);
            // The stroke the paddle takes (prescribed plus correction).
            const double x = world.waveMakerDisplacement(0, world.time());
            drift = std::max(drift, std::abs(x));
            if (trace)
                std::fprintf(trace, "%.3f,%.6f,%.6f\n", world.time(), x,
                             world.surfaceHeight(paddle.x + static_cast<float>(x) + 5.0f * o.spacing, 0.0f) - o.depth);
        }
    } catch (const tide::DivergenceError& e) {
        std::printf("  diverged at %.3f s: %s\n", world.time(), e.what());
    }
    std::printf("  per period, mean envelope of the three gauges (m):");
    for (int n = 0; n < o.periods; ++n) {
        double sum = 0.0;
        for (const auto& r : records) sum += tide::waves::envelope(r, o.period, n, n + 1);
        std::printf("%s%.4f", n % 10 == 0 ? "\n   " : " ", sum / records.size());
    }
    if (trace) std::fclose(trace);
    std::printf("\n  gauge   periods 10-15   periods 25-30   ratio\n");
    for (std::size_t g = 0; g < at.size(); ++g) {
        const double early = tide::waves::envelope(records[g], o.period, 10, 15);
        const double late = tide::waves::envelope(records[g], o.period, 25, 30);
        std::printf("  %5.2f   %.4f          %.4f          %.3f\n", at[g], early, late, late / early);
    }
    std::printf("  largest paddle displacement %.4f m, %llu steps, %llu unconverged solves\n", drift,
                static_cast<unsigned long long>(world.stats().steps),
                static_cast<unsigned long long>(world.stats().unconvergedSolves));
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Active absorption in a flume closed by a wall (2D)"};
    Options o;
    std::string absorption = "both";
    app.add_option("--spacing", o.spacing)->capture_default_str();
    app.add_option("--depth", o.depth)->capture_default_str();
    app.add_option("--period", o.period)->capture_default_str();
    app.add_option("--height", o.height)->capture_default_str();
    app.add_option("--length", o.length, "paddle face to the wall, m")->capture_default_str();
    app.add_option("--periods", o.periods)->capture_default_str();
    app.add_option("--threads", o.threads)->capture_default_str();
    app.add_option("--shifting", o.shifting, "negative: the 2D wave default, 0.2")->capture_default_str();
    app.add_option("--difference-form", o.differenceForm, "negative: the 2D wave default, 0")->capture_default_str();
    app.add_option("--momentum", o.momentum, "negative: dfsph's default, 0.7")->capture_default_str();
    app.add_option("--max-iterations", o.maxIterations)->capture_default_str();
    app.add_option("--trace", o.trace, "write PREFIX_on.csv / PREFIX_off.csv")->capture_default_str();
    app.add_option("--absorption", absorption)->check(CLI::IsMember({"on", "off", "both"}))->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    if (absorption != "off") run(o, true);
    if (absorption != "on") run(o, false);
}
