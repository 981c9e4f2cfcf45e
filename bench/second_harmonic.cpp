// The free second harmonic a piston radiates (issue 42, acceptance 5): a 2D flume with a damping
// zone, run with first-order generation ("order": 1) and with the second-order stroke
// ("order": 2, Schäffer 1996). Gauges every 5 cm from 0.5 to 2.5 m; at each the complex
// amplitude at 2ω over whole periods of a window after the waves arrive; then the least-squares
// split of A₂(x) = B e^{−i 2k₁ x} + F e^{−i k₂ x} into Stokes' bound harmonic B (travelling with
// the first at 2k₁, k₁ fitted from the first harmonic) and the free wave F at 2ω, k₂ scanned
// about linear theory's over ±30 % (SPH waves run fast, short ones more) and fixed at theory's.
// Prints |F| for both orders and their ratios.
//
//   tide_second_harmonic [--spacing S] [--depth D] [--period T] [--height H] [--length L]
//                        [--from T0] [--periods N] [--threads N]
#include <complex>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <CLI/CLI.hpp>

#include <tide/world.hpp>

#include "sources/wave_theory.hpp"
#include "testing/scenarios.hpp"
#include "testing/wave_analysis.hpp"

namespace {

using C = std::complex<double>;

struct Options {
    float spacing = 0.0125f, depth = 0.25f, period = 1.2f, height = 0.03f, length = 4.5f;
    double from = 6.0;
    int periods = 3, threads = 1;
};

/// B and F of A_j = B e^{−i kb x_j} + F e^{−i kf x_j} (2 × 2 normal equations), and the residual.
struct Split {
    C bound, free;
    double residual;
};
Split split(const std::vector<double>& x, const std::vector<C>& a, double kb, double kf) {
    C a11 = 0.0, a12 = 0.0, a22 = 0.0, b1 = 0.0, b2 = 0.0;
    std::vector<C> e1(x.size()), e2(x.size());
    for (std::size_t j = 0; j < x.size(); ++j) {
        e1[j] = std::exp(C(0.0, -kb * x[j])), e2[j] = std::exp(C(0.0, -kf * x[j]));
        a11 += std::norm(e1[j]), a12 += std::conj(e1[j]) * e2[j], a22 += std::norm(e2[j]);
        b1 += std::conj(e1[j]) * a[j], b2 += std::conj(e2[j]) * a[j];
    }
    const C det = a11 * a22 - a12 * std::conj(a12);
    Split s{(a22 * b1 - a12 * b2) / det, (a11 * b2 - std::conj(a12) * b1) / det, 0.0};
    for (std::size_t j = 0; j < x.size(); ++j) s.residual += std::norm(a[j] - s.bound * e1[j] - s.free * e2[j]);
    s.residual = std::sqrt(s.residual / static_cast<double>(x.size()));
    return s;
}

/// The free harmonic's height 2|F|: with k₂ fitted (scanned), and with k₂ fixed at linear
/// theory's (where the free wave is small the scan fits noise and reads high).
struct FreeWave {
    double fitted, atTheory;
};

FreeWave run(const Options& o, int order) {
    tide::WaveMakerDef paddle;
    paddle.x = 0.1f;
    paddle.depth = o.depth;
    paddle.waveHeight = o.height;
    paddle.period = o.period;
    paddle.order = order;
    paddle.absorption = tide::WaveMakerDef::Absorption::Off;  // the generation alone
    tide::SolverDef solver;  // 2D: shifting off (docs/notes/waves.md § 2D waves), solves to convergence
    solver.shifting = 0.0f;
    solver.differenceForm = 0.0f;
    solver.maxIterations = 1000;
    const float length = o.spacing * std::round(o.length / o.spacing);
    tide::World world = tide::scenarios::planarFlume(o.spacing, length, paddle, 1.2f, o.threads, solver);
    std::vector<double> x;
    for (double g = 0.5; g <= 2.5 + 1e-9; g += 0.05) x.push_back(g);
    std::vector<tide::waves::Record> records(x.size(), tide::waves::Record{0.02, 0.02, {}});
    const double end = o.from + o.periods * o.period;
    for (int k = 0; k * 0.02 < end - 1e-9; ++k) {
        world.advance(0.02);
        for (std::size_t g = 0; g < x.size(); ++g)
            records[g].eta.push_back(world.surfaceHeight(static_cast<float>(x[g]), 0.0f) - o.depth);
    }
    const double omega = 2.0 * std::numbers::pi / o.period;
    std::vector<C> a1, a2;
    for (const auto& r : records) {
        const tide::waves::Record w = tide::waves::window(r, o.from, end);
        a1.push_back(tide::waves::amplitudeAt(w, omega));
        a2.push_back(tide::waves::amplitudeAt(w, 2.0 * omega));
    }
    const double k1Theory = tide::waves::waveNumber(omega, o.depth);
    const double k2Theory = tide::waves::waveNumber(2.0 * omega, o.depth);
    const tide::waves::FlumeFit first = tide::waves::fitIncidentReflected(x, a1, 0.8 * k1Theory, 1.2 * k1Theory, 0.0, 0.0);
    Split best{};
    double bestK2 = k2Theory;
    best.residual = 1e300;
    for (double f = 0.7; f <= 1.3 + 1e-9; f += 0.0025) {
        const Split s = split(x, a2, 2.0 * first.k, f * k2Theory);
        if (s.residual < best.residual) best = s, bestK2 = f * k2Theory;
    }
    const Split fixed = split(x, a2, 2.0 * first.k, k2Theory);
    std::printf("order %d: first harmonic 2|I| %.4f m, k1 %.3f 1/m (theory %.3f); at 2w: bound 2|B| %.5f m, free 2|F| %.5f m "
                "(k2 %.2f, theory %.2f), residual %.5f m; at k2 of theory: bound %.5f m, free %.5f m (phase %+.0f deg), "
                "residual %.5f m; %llu steps\n",
                order, 2.0 * std::abs(first.incident), first.k, k1Theory, 2.0 * std::abs(best.bound), 2.0 * std::abs(best.free),
                bestK2, k2Theory, best.residual, 2.0 * std::abs(fixed.bound), 2.0 * std::abs(fixed.free),
                std::arg(fixed.free) * 180.0 / std::numbers::pi, fixed.residual,
                static_cast<unsigned long long>(world.stats().steps));
    return {2.0 * std::abs(best.free), 2.0 * std::abs(fixed.free)};
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"The free second harmonic of first- and second-order generation (2D)"};
    Options o;
    int only = 0;
    app.add_option("--spacing", o.spacing)->capture_default_str();
    app.add_option("--depth", o.depth)->capture_default_str();
    app.add_option("--period", o.period)->capture_default_str();
    app.add_option("--height", o.height)->capture_default_str();
    app.add_option("--length", o.length)->capture_default_str();
    app.add_option("--from", o.from, "start of the analysis window, s")->capture_default_str();
    app.add_option("--periods", o.periods, "whole periods analysed")->capture_default_str();
    app.add_option("--threads", o.threads)->capture_default_str();
    app.add_option("--order", only, "run only this order (0: both)")->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    const FreeWave f1 = only == 2 ? FreeWave{} : run(o, 1);
    const FreeWave f2 = only == 1 ? FreeWave{} : run(o, 2);
    if (only == 0)
        std::printf("free second harmonic, order 2 / order 1: %.3f (k2 fitted), %.3f (k2 of theory)\n", f2.fitted / f1.fitted,
                    f2.atTheory / f1.atTheory);
}
