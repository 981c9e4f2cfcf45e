// How fast the simulated gravity waves run: the first standing mode of a closed tank
// (length L, depth d; z one periodic cell, so 2D), started flat with the velocity of the
// linear mode, η = a cos(kx) sin(ωt), k = π/L. The mode's amplitude (the surface heights at
// gauges every 2 cm projected on cos kx) is fitted with a damped oscillation and its
// frequency compared with ω² = g k tanh kd. At L = 0.68 m, d = 0.3 m it has the wave number
// of the acceptance flume's waves (T = 1 s), so its error predicts the flume's wave-length
// error (Δλ/λ ≈ 1.47 Δω/ω there) in ~20 s instead of 12 min (docs/waves.md).
// --periodic: the same mode in a tank periodic along x, one wave length (2L) long, without the
// end walls the water slides along: the decay of the waves themselves, as in a flume.
//
//   tide_standing_wave [--solver dfsph] [--spacing 0.02] [--support-ratio 2] [--amplitude 0.01] [--periodic] [--dimensions 2] ...
// --dimensions 2: the same tank as a true 2D world (the plane z = 0) instead of the periodic z slab.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <CLI/CLI.hpp>

#include <tide/world.hpp>

#include "mode_energy.hpp"
#include "tank_options.hpp"
#include "testing/standing_mode.hpp"

int main(int argc, char** argv) {
    CLI::App app{"Frequency of the first standing-wave mode of a closed tank against linear theory"};
    tide::bench::TankOptions tank;
    // The flume test's solver settings (tests/test_wave_tank.cpp).
    tank.maxDensityError = 0.003f;
    tank.xsph = 0.0f;
    tank.momentum = 0.0f;
    float amplitude = 0.01f;
    double seconds = 4.0;
    bool periodic = false;
    double settle = 0.0, energy = 0.0;
    tank.addTo(app);
    app.add_option("--energy", energy,
                   "print the mode and the energy (total, kinetic, and the kinetic off the mode) every this many s (0: not)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--settle", settle, "World::settle for this long first (pre-roll with the default XSPH, velocities zeroed), s")
        ->capture_default_str()->check(CLI::NonNegativeNumber);
    app.add_flag("--periodic", periodic, "x periodic over one wave length (2 × length), no end walls");
    app.add_option("--amplitude", amplitude, "mode amplitude a, m")->capture_default_str()->check(CLI::PositiveNumber);
    app.add_option("--seconds", seconds, "simulated time, s")->capture_default_str()->check(CLI::PositiveNumber);
    CLI11_PARSE(app, argc, argv);

    const float length = tank.length, depth = tank.depth;
    const double g = 9.81, k = std::numbers::pi / length;
    try {
        const float extent = periodic ? 2.0f * length : length;
        const tide::WorldDef def = tank.worldDef();
        tide::World world = tide::scenarios::standingModeTank(def, length, depth, tank.widthInSpacings(), periodic);
        if (settle > 0.0) {
            // Settled with the solver's default XSPH, as the flume test does: without it the
            // settling motion does not die down (25–33 mm/s RMS left after 8 s in the periodic tank).
            tide::WorldDef settling = def;
            settling.solver.xsph = -1.0f;
            tide::World settled = tide::scenarios::standingModeTank(settling, length, depth, tank.widthInSpacings(), periodic);
            settled.settle(settle);
            world.restoreState(settled.saveState());
        }
        const int energyEvery = static_cast<int>(std::lround(energy / 0.01));
        int sampleCount = 0;
        const auto report = [&](const tide::World& w, double eta) {
            if (energyEvery <= 0 || ++sampleCount % energyEvery != 0) return;
            const tide::bench::ModeEnergy e = tide::bench::modeEnergy(w.particles(), k, g, extent, 2.0f * depth);
            std::printf("t %.2f s: mode %+.4f m; kinetic %.4f J, kinetic + potential %.4f J; off the mode: smooth %.4f J, "
                        "particle-scale %.4f J, RMS by 3 cm layer from the floor (mm/s):",
                        w.time(), eta, e.kinetic, e.total, e.smoothResidual, e.particleScale);
            for (const double rms : e.particleScaleRms) std::printf(" %.0f", 1e3 * rms);
            std::printf("\n");
        };
        const tide::scenarios::StandingMode mode = tide::scenarios::runStandingMode(world, length, depth, amplitude, seconds, report);
        const tide::waves::DampedFit& fit = mode.fit;
        const tide::WorldStats& s = world.stats();
        std::printf("%s, spacing %.4f m, support %.2f spacings, a = %.4f m, L = %.3f m, d = %.3f m: omega %.4f rad/s "
                    "against %.4f (%+.2f %%), amplitude %.4f m, decay %.3f 1/s, fit residual %.1e m; %llu steps, %.1f "
                    "pressure iterations a step%s\n",
                    tank.solver.c_str(), tank.spacing, world.supportRadius() / tank.spacing, amplitude, length, depth, fit.omega, mode.omegaTheory,
                    100.0 * mode.frequencyError(), fit.amplitude, fit.beta, fit.rmsResidual,
                    static_cast<unsigned long long>(s.steps), static_cast<double>(s.pressureIterationsSum) / s.steps,
                    periodic ? " (periodic in x)" : "");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tide_standing_wave: %s\n", e.what());
        return 1;
    }
    return 0;
}
