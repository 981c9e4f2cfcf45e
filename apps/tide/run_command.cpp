// `tide run`: simulate a scene, writing frame k at simulated time k/fps, then gauges.csv and
// probes.csv (when the scene has gauges or probes) and stats.json.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <tide/io/exporters.hpp>
#include <tide/io/scene.hpp>

#include "commands.hpp"
#include "measurements.hpp"
#include "output_folder.hpp"
#include "progress.hpp"

namespace tide::cli {

namespace fs = std::filesystem;

namespace {

/// The first particle with a non-finite or runaway state, described; empty when all is well.
std::string findDivergence(const World& world) {
    const ParticleStore& p = world.particles();
    // No fluid particle of a sane run comes near this speed (sound speed ≫ flow speed).
    const glm::vec3 extent = world.def().domainMax - world.def().domainMin;
    const float runaway = 1e3f * std::max(1.0f, glm::length(extent));
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        const char* quantity = nullptr;
        if (!std::isfinite(p.position[i].x + p.position[i].y + p.position[i].z)) quantity = "position";
        else if (!std::isfinite(p.velocity[i].x + p.velocity[i].y + p.velocity[i].z)) quantity = "velocity";
        else if (!std::isfinite(p.density[i]) || !std::isfinite(p.pressure[i])) quantity = "density or pressure";
        else if (glm::length(p.velocity[i]) > runaway) quantity = "speed (runaway)";
        if (quantity) {
            std::ostringstream out;
            out << "particle " << p.id[i] << " has a bad " << quantity;
            return out.str();
        }
    }
    // A liquid compressed by half on average has collapsed (e.g. a forced time step far
    // beyond stability): name its most compressed particle.
    if (world.stats().meanCompression > 0.5f) {
        std::uint32_t worst = 0;
        float worstRatio = 0.0f;
        for (std::uint32_t i = 0; i < p.size(); ++i) {
            const float ratio = p.density[i] / world.materials()[p.material[i]].restDensity;
            if (ratio > worstRatio) {
                worstRatio = ratio;
                worst = i;
            }
        }
        std::ostringstream out;
        out << "the fluid collapsed (mean compression " << 100.0f * world.stats().meanCompression
            << " %): particle " << p.id[worst] << " has density " << p.density[worst] << " kg/m3, " << worstRatio
            << " times its rest density";
        return out.str();
    }
    return {};
}

std::string frameName(int frame, io::Format format) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%05d.%s", frame, std::string(io::extension(format)).c_str());
    return name;
}

void writeStats(const fs::path& file, const World& world, double wall, std::uint64_t particleSteps,
                std::uint32_t lost) {
    const WorldStats& s = world.stats();
    nlohmann::ordered_json j;
    j["particles"] = world.particles().size();
    j["steps"] = s.steps;
    j["sim_time"] = world.time();
    j["wall_time"] = wall;
    j["particle_steps_per_second"] = particleSteps / std::max(wall, 1e-9);
    j["dt_min"] = s.dtMin;
    j["dt_mean"] = s.steps ? s.dtSum / static_cast<double>(s.steps) : 0.0;
    j["dt_max"] = s.dtMax;
    j["max_density_error"] = s.maxMeanDensityError;
    j["avg_density_error"] = s.steps ? s.sumMeanDensityError / static_cast<double>(s.steps) : 0.0;
    j["particles_lost"] = lost;
    j["threads"] = world.threads();
    j["solver"] = world.def().solver.method;
    j["pressure_iterations_mean"] =
        s.steps ? static_cast<double>(s.pressureIterationsSum) / static_cast<double>(s.steps) : 0.0;
    io::writeFileAtomically(file, [&](std::ostream& out) { out << j.dump(2) << '\n'; });
}

}  // namespace

int runCommand(const RunOptions& o) {
    io::Scene scene;
    try {
        scene = io::loadScene(o.scene);
    } catch (const io::SceneError& e) {
        reportSceneProblems(o.scene, e.problems);
        return kExitBadInput;
    }
    if (o.endTime) scene.endTime = *o.endTime;
    if (!o.solver.empty()) {
        const auto known = solverNames();
        if (std::find(known.begin(), known.end(), o.solver) == known.end()) {
            std::fprintf(stderr, "--solver: unknown solver \"%s\"\n", o.solver.c_str());
            return kExitBadInput;
        }
        scene.world.solver.method = o.solver;
    }
    if (!o.formats.empty()) {
        scene.output.formats.clear();
        for (const std::string& name : o.formats)
            if (auto f = io::parseFormat(name);
                f && std::find(scene.output.formats.begin(), scene.output.formats.end(), *f) == scene.output.formats.end())
                scene.output.formats.push_back(*f);
    }
    scene.world.threads = o.threads;
    const fs::path dir = o.out.empty() ? fs::path("out") / fs::path(o.scene).stem() : fs::path(o.out);

    // A longer end time lets emitters emit more: size the world for it.
    scene.world.capacity = static_cast<std::uint32_t>(
        std::min<std::uint64_t>(io::estimate(scene).totalParticles + 1, 0xfffffff0ull));

    std::optional<World> world;
    try {
        world.emplace(io::buildWorld(scene));
        prepareOutputFolder(dir, o.force);
    } catch (const io::SceneError& e) {
        reportSceneProblems(o.scene, e.problems);
        return kExitBadInput;
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "%s: %s\n", o.scene.c_str(), e.what());
        return kExitBadInput;
    } catch (const OutputFolderError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return kExitBadInput;
    }

    const int frames = static_cast<int>(std::floor(scene.endTime * scene.output.fps + 1e-9));
    const auto start = std::chrono::steady_clock::now();
    Progress progress(scene.endTime, frames, o.quiet);
    io::PvdWriter pvd(dir / "frames.pvd");
    const bool vtu = std::find(scene.output.formats.begin(), scene.output.formats.end(), io::Format::Vtu) !=
                     scene.output.formats.end();
    std::uint64_t particleSteps = 0;
    std::uint32_t lost = 0;
    Measurements measurements(scene);
    try {
        for (int frame = 0; frame <= frames; ++frame) {
            if (frame > 0) {
                const double target = frame / scene.output.fps;
                world->advance(target - world->time(), [&] {
                    particleSteps += world->particles().size();
                    progress.step(world->time(), frame, world->particles().size(), particleSteps);
                });
                const std::string bad = findDivergence(*world);
                if (!bad.empty()) {
                    progress.finish();
                    measurements.write(dir);  // the rows up to the last good frame
                    std::fprintf(stderr, "tide: the simulation diverged by step %llu (t = %.6f s): %s; frames up to %d are kept in %s\n",
                                 static_cast<unsigned long long>(world->stats().steps), world->time(), bad.c_str(),
                                 frame - 1, dir.string().c_str());
                    return kExitRunFailed;
                }
            }
            for (io::Format format : scene.output.formats)
                io::writeFrame(dir / frameName(frame, format), format, world->particles());
            if (vtu) {
                pvd.add(frame / scene.output.fps, frameName(frame, io::Format::Vtu));
                pvd.write();
            }
            measurements.sample(*world, world->time());
            lost = std::max(lost, world->countEscapedParticles());
            progress.frame(world->time(), frame, world->particles().size(), particleSteps);
        }
        progress.finish();
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        measurements.write(dir);
        writeStats(dir / "stats.json", *world, wall, particleSteps, lost);
        if (!o.quiet)
            std::printf("%d frames of %u particles in %s (%.1f s wall, %.2f M particle-steps/s)\n", frames + 1,
                        world->particles().size(), dir.string().c_str(), wall, particleSteps / std::max(wall, 1e-9) / 1e6);
    } catch (const std::runtime_error& e) {
        progress.finish();
        std::fprintf(stderr, "tide: %s\n", e.what());
        return kExitRunFailed;
    }
    return kExitOk;
}

}  // namespace tide::cli
