// How fast a progressive wave loses its height, on its own: one wave length of a tank
// periodic along x (no paddle, no absorber, no end walls), the wave made of two standing modes
// in quadrature. The tank starts flat with the velocity of η = a cos(kx) sin(ωt); a quarter
// period later, where that mode stands at its crest and its velocity has gone, the velocity
// of −a sin(kx) cos(ωt) is added: from then on η = a sin(ωt − kx), a linear (Airy) wave
// running towards +x. Its complex amplitude (the surface heights every 2 cm projected on
// cos kx and sin kx) gives the height's decay (a log-linear fit) and the phase speed.
// The same k and depth as tide_standing_wave --periodic, so the two read side by side:
// what the standing wave lacks (a wave's mass transport, its steady crests) shows as the
// difference (docs/notes/waves.md § Where 2D progressive waves lose their height).
//
//   tide_progressive_wave [--length 2.3118] [--depth 0.7] [--amplitude 0.04] [--dimensions 2] ...
// --length is half the wave length, as tide_standing_wave's --length. The solver starts from the
// wave settings a world with a wave maker gets in 2D (shifting 0.2, no XSPH).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <tide/world.hpp>

#include "tank_options.hpp"
#include "testing/standing_mode.hpp"

namespace {

/// Adds the velocity of the linear standing mode whose vertical surface velocity is
/// scale·sinh(kd)·cos(kx + shift) (potential flow, y from the floor).
void addModeVelocity(tide::World& world, double k, double scale, double shift) {
    const auto& p = world.particles();
    auto v = world.velocities();
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        const double x = p.position[i].x, y = p.position[i].y;
        v[i] += glm::vec3(static_cast<float>(-scale * std::cosh(k * y) * std::sin(k * x + shift)),
                          static_cast<float>(scale * std::sinh(k * y) * std::cos(k * x + shift)), 0.0f);
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Decay and phase speed of a progressive wave in a tank periodic over one wave length"};
    tide::bench::TankOptions tank;
    tank.length = 2.3118f;  // half of issue 43's wave length (T 2 s, d 0.7 m)
    tank.depth = 0.7f;
    tank.dimensions = 2;
    tank.shifting = 0.2f;  // the wave settings (sources/wave_numerics.hpp): shifting, no XSPH
    tank.xsph = 0.0f;
    float amplitude = 0.04f;
    double seconds = 12.0, series = 0.0, settle = 0.0;
    tank.addTo(app);
    app.add_option("--settle", settle, "World::settle for this long first (pre-roll with the default XSPH, velocities zeroed), s")
        ->capture_default_str()->check(CLI::NonNegativeNumber);
    app.add_option("--series", series, "print the amplitude and the mean level every this many s (0: not)")->check(CLI::NonNegativeNumber);
    app.add_option("--amplitude", amplitude, "wave amplitude a (H/2), m")->capture_default_str()->check(CLI::PositiveNumber);
    app.add_option("--seconds", seconds, "simulated time after the wave is made, s")->capture_default_str()->check(CLI::PositiveNumber);
    CLI11_PARSE(app, argc, argv);

    const float length = tank.length, depth = tank.depth;
    try {
        const tide::WorldDef def = tank.worldDef();
        tide::World world = tide::scenarios::standingModeTank(def, length, depth, tank.widthInSpacings(), true);
        if (settle > 0.0) {  // as tide_standing_wave --settle
            tide::WorldDef settling = def;
            settling.solver.xsph = -1.0f;
            tide::World settled = tide::scenarios::standingModeTank(settling, length, depth, tank.widthInSpacings(), true);
            settled.settle(settle);
            world.restoreState(settled.saveState());
        }
        const double g = std::round(1e4 * std::abs(static_cast<double>(world.def().gravity.y))) * 1e-4;
        const double k = std::numbers::pi / length, omega = std::sqrt(g * k * std::tanh(k * depth));
        const double scale = amplitude * omega / std::sinh(k * depth);
        addModeVelocity(world, k, scale, 0.0);                      // a cos(kx) sin(ωt)
        world.advance(0.5 * std::numbers::pi / omega);              // to its crest
        addModeVelocity(world, k, scale, -0.5 * std::numbers::pi);  // −a sin(kx) cos(ωt'): w = aω sin kx
        const float extent = 2.0f * length, z = 0.5f * world.def().domainMax.z;
        const double dt = 0.01;
        const int samples = static_cast<int>(std::lround(seconds / dt));
        std::vector<double> times, logAmplitude, phase, levels;
        for (int n = 0; n <= samples; ++n) {
            if (n > 0) world.advance(dt);
            double c = 0.0, s = 0.0, level = 0.0;
            int count = 0;
            for (float x = 0.0f; x < extent - 0.01f; x += 0.02f) {
                const float height = world.surfaceHeight(x, z);
                if (!std::isfinite(height)) continue;
                c += (height - depth) * std::cos(k * x);
                s += (height - depth) * std::sin(k * x);
                level += height - depth;
                ++count;
            }
            if (count == 0) throw std::runtime_error("no gauge found the surface at t = " + std::to_string(world.time()) + " s");
            levels.push_back(level / count);
            c *= 2.0 / count;
            s *= 2.0 / count;
            const int every = static_cast<int>(std::lround(series / dt));
            if (every > 0 && n % every == 0)
                std::printf("t %.2f s: amplitude %.2f mm, mean level %+.2f mm\n", n * dt, 1e3 * std::hypot(c, s), 1e3 * levels.back());
            // η = A cos(kx − θ): θ = ωt − π/2 + kx_0 grows at ω for a wave running towards +x.
            const double theta = std::atan2(s, c);
            if (!phase.empty()) {
                double step = theta - std::fmod(phase.back(), 2.0 * std::numbers::pi);
                while (step < -std::numbers::pi) step += 2.0 * std::numbers::pi;
                while (step > std::numbers::pi) step -= 2.0 * std::numbers::pi;
                phase.push_back(phase.back() + step);
            } else {
                phase.push_back(theta);
            }
            times.push_back(n * dt);
            logAmplitude.push_back(std::log(std::hypot(c, s)));
        }
        // Least-squares lines through ln|A| and θ.
        const auto slope = [&](const std::vector<double>& y, double& intercept) {
            double st = 0.0, sy = 0.0, stt = 0.0, sty = 0.0;
            const double m = static_cast<double>(y.size());
            for (std::size_t i = 0; i < y.size(); ++i) {
                st += times[i];
                sy += y[i];
                stt += times[i] * times[i];
                sty += times[i] * y[i];
            }
            const double b = (m * sty - st * sy) / (m * stt - st * st);
            intercept = (sy - b * st) / m;
            return b;
        };
        double a0 = 0.0, p0 = 0.0;
        const double decay = -slope(logAmplitude, a0), omegaFit = slope(phase, p0);
        double mass = 0.0, momentum = 0.0;
        const auto& p = world.particles();
        for (std::uint32_t i = 0; i < p.size(); ++i) {
            mass += p.mass[i];
            momentum += p.mass[i] * p.velocity[i].x;
        }
        const double period = 2.0 * std::numbers::pi / omega;
        const auto meanOfLast = [](const std::vector<double>& y, std::size_t m) {
            m = std::min(m, y.size());
            double sum = 0.0;
            for (std::size_t i = y.size() - m; i < y.size(); ++i) sum += y[i];
            return sum / static_cast<double>(m);
        };
        std::printf("%s, spacing %.4f m, a = %.4f m, wave length %.4f m, d = %.3f m: omega %.4f rad/s against %.4f (%+.2f %%), "
                    "amplitude %.4f m at the start, decay %.4f 1/s (%.2f %% a wave length), mean current at the end %.2f mm/s, "
                    "mean level %+.2f mm at the start, %+.2f mm over the last period; %llu steps, %.1f pressure iterations a step\n",
                    tank.solver.c_str(), tank.spacing, amplitude, extent, depth, omegaFit, omega, 100.0 * (omegaFit / omega - 1.0),
                    std::exp(a0), decay, 100.0 * (1.0 - std::exp(-decay * period)), 1e3 * momentum / mass, 1e3 * levels.front(),
                    1e3 * meanOfLast(levels, static_cast<std::size_t>(std::lround(period / dt))),
                    static_cast<unsigned long long>(world.stats().steps),
                    static_cast<double>(world.stats().pressureIterationsSum) / static_cast<double>(world.stats().steps));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tide_progressive_wave: %s\n", e.what());
        return 1;
    }
    return 0;
}
