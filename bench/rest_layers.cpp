// Where still water stops being still: a block of water at rest in a tank (closed in x,
// z one periodic cell unless --closed) and, every --every seconds, the RMS and the largest
// speed and the mean density error of the particles in each layer one spacing thick from the floor up. The particles of
// the cubic lattice the water starts on rearrange under the hydrostatic pressure from the
// floor up, at a rate that grows with that pressure and with the kernel support
// (docs/robustness.md § Still water at fine spacings); this shows when and where, and with
// --settle how still the water stays after a pre-roll (World::settle).
//
//   tide_rest_layers [--solver dfsph] [--spacing 0.02] [--support-ratio 2] [--depth 0.3] ...
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <CLI/CLI.hpp>

#include <tide/world.hpp>

#include "tank_options.hpp"
#include "testing/scenarios.hpp"

int main(int argc, char** argv) {
    CLI::App app{"RMS and largest speed per layer of water at rest, over time"};
    tide::bench::TankOptions tank;
    float gravity = 9.81f;
    double seconds = 0.5, every = 0.05, settle = 0.0;
    float quietSpeed = 0.0f;
    bool closed = false, traceSteps = false;
    tank.addTo(app);
    app.add_flag("--closed", closed, "walls across z too (a square tank `length` wide) instead of a periodic cell");
    app.add_option("--gravity", gravity, "|g|, m/s²")->capture_default_str()->check(CLI::NonNegativeNumber);
    app.add_option("--seconds", seconds, "simulated time, s")->capture_default_str()->check(CLI::PositiveNumber);
    app.add_option("--every", every, "report interval, s")->capture_default_str()->check(CLI::PositiveNumber);
    app.add_option("--settle", settle, "World::settle for this long first (pre-roll, velocities zeroed), s")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    app.add_option("--quiet-speed", quietSpeed, "end the settling once every particle stayed below this for 0.5 s, m/s")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    app.add_flag("--trace-steps", traceSteps,
                 "every step instead of the layers: time, mean vertical velocity of the middle third of the depth and of "
                 "the top two layers (mm/s), max speed (m/s), kinetic energy (mJ), pressure iterations");
    CLI11_PARSE(app, argc, argv);

    tide::WorldDef def = tank.worldDef();
    def.gravity = {0.0f, -gravity, 0.0f};
    try {
        tide::World world = tide::scenarios::stillTank(def, tank.length, tank.depth, tank.widthInSpacings(), closed);
        const int layers = static_cast<int>(std::lround(tank.depth / tank.spacing));
        std::printf("%s, spacing %.4f m, support %.2f spacings, %u particles, %d layers; speeds in mm/s, rho as (ρ/ρ0 − 1) in 0.01 %%, floor first\n",
                    tank.solver.c_str(), tank.spacing, world.supportRadius() / tank.spacing, world.particles().size(), layers);
        if (settle > 0.0) {
            const tide::SettleReport r = world.settle(settle, quietSpeed);
            std::printf("settled %.2f s in %llu steps%s: max speed %.4f m/s before the velocities were zeroed\n", r.seconds,
                        static_cast<unsigned long long>(r.steps), r.quiet ? " (quiet)" : "", r.maxSpeed);
        }
        if (traceSteps) {
            // A step-to-step zigzag of the whole column (the mean vertical velocity changing sign every
            // step) is the pressure solve's, not the particles' rearrangement (docs/robustness.md).
            std::printf("t_s middle_vy_mm_s top_vy_mm_s max_speed_m_s kinetic_mJ pressure_iterations\n");
            world.advance(seconds, [&] {
                const tide::ParticleStore& p = world.particles();
                double middle = 0.0, middleCount = 0.0, top = 0.0, topCount = 0.0, kinetic = 0.0;
                for (std::uint32_t i = 0; i < p.size(); ++i) {
                    const float y = p.position[i].y;
                    kinetic += 0.5 * p.mass[i] * glm::dot(p.velocity[i], p.velocity[i]);
                    if (y > tank.depth - 2.0f * tank.spacing) {
                        top += p.velocity[i].y;
                        topCount += 1.0;
                    } else if (y > tank.depth / 3.0f && y < 2.0f * tank.depth / 3.0f) {
                        middle += p.velocity[i].y;
                        middleCount += 1.0;
                    }
                }
                std::printf("%.5f %.3f %.3f %.5f %.4f %d\n", world.time(), 1e3 * middle / std::max(middleCount, 1.0),
                            1e3 * top / std::max(topCount, 1.0), world.stats().maxSpeed, 1e3 * kinetic,
                            world.stats().lastPressureIterations);
            });
            return 0;
        }
        const int reports = static_cast<int>(std::lround(seconds / every));
        for (int n = 0; n < reports; ++n) {
            world.advance(every);
            const tide::ParticleStore& p = world.particles();
            std::vector<double> sum(layers, 0.0), count(layers, 0.0), largest(layers, 0.0), density(layers, 0.0);
            for (std::uint32_t i = 0; i < p.size(); ++i) {
                const int layer = std::clamp(static_cast<int>(p.position[i].y / tank.spacing), 0, layers - 1);
                const double speed = glm::length(p.velocity[i]);
                sum[layer] += speed * speed;
                count[layer] += 1.0;
                largest[layer] = std::max(largest[layer], speed);
                density[layer] += p.density[i] / 1000.0 - 1.0;  // the tank's water: ρ0 = 1000
            }
            std::printf("t %.3f s, max %.4f m/s\n  rms:", world.time(), world.stats().maxSpeed);
            for (int l = 0; l < layers; ++l) std::printf(" %3.0f", count[l] > 0.0 ? 1e3 * std::sqrt(sum[l] / count[l]) : 0.0);
            std::printf("\n  max:");
            for (int l = 0; l < layers; ++l) std::printf(" %3.0f", 1e3 * largest[l]);
            std::printf("\n  rho:");
            for (int l = 0; l < layers; ++l) std::printf(" %3.0f", count[l] > 0.0 ? 1e4 * density[l] / count[l] : 0.0);
            std::printf("\n");
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tide_rest_layers: %s\n", e.what());
        return 1;
    }
    return 0;
}
