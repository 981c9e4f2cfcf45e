// `tide run`: simulate a scene, writing frame k at simulated time k/fps, then gauges.csv and
// probes.csv (when the scene has gauges or probes) and stats.json. With --checkpoint-every it
// also writes checkpoints, from which --resume continues bit for bit. Under mpirun the World is
// split among the ranks (core/world_distributed.hpp) and rank 0 writes what one process would.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <fstream>
#include <regex>
#include <sstream>

#include <fcntl.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <tide/io/checkpoint.hpp>
#include <tide/io/exporters.hpp>
#include <tide/io/scene.hpp>

#include "comm/communicator.hpp"
#include "commands.hpp"
#include "core/world_distributed.hpp"
#include "measurements.hpp"
#include "output_folder.hpp"
#include "progress.hpp"
#include "run_checkpoints.hpp"

namespace tide::cli {

namespace fs = std::filesystem;

namespace {

std::string frameName(int frame, io::Format format) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%05d.%s", frame, std::string(io::extension(format)).c_str());
    return name;
}

/// A split run's processes, for stats.json.
struct RanksReport {
    int ranks = 1;
    RankCounts counts;
    std::uint64_t stepsRun = 0;  ///< steps this process ran (the traffic counts are its own)
};

void writeStats(const fs::path& file, const World& world, std::uint64_t particles, double wall,
                std::uint64_t particleSteps, std::uint32_t lost, const std::optional<RanksReport>& ranks) {
    const WorldStats& s = world.stats();
    nlohmann::ordered_json j;
    j["particles"] = particles;
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
    j["divergence_iterations_mean"] =
        s.steps ? static_cast<double>(s.divergenceIterationsSum) / static_cast<double>(s.steps) : 0.0;
    j["pressure_unconverged_steps"] = s.unconvergedSolves;
    if (world.hasOcean()) {
        // The coupling zones' bookkeeping (issue 43): what they added and removed, and their
        // share of the steps' wall time.
        const PhaseSeconds& p = s.phaseSeconds;
        const double steps = p.neighborSearch + p.density + p.pressureSolve + p.nonPressureForces + p.integration + p.coupling;
        j["ocean_particles_added"] = s.oceanAdded;
        j["ocean_particles_removed"] = s.oceanRemoved;
        j["ocean_coupling_share"] = steps > 0.0 ? p.coupling / steps : 0.0;
    }
    if (ranks) {
        // Issue 47's report: each process's share and the imbalance (largest over mean).
        j["ranks"] = ranks->ranks;
        j["rank_particles"] = ranks->counts.owned;
        j["rank_ghosts"] = ranks->counts.ghosts;
        double most = 0.0, total = 0.0;
        for (const std::uint64_t n : ranks->counts.owned) {
            most = std::max(most, static_cast<double>(n));
            total += static_cast<double>(n);
        }
        j["load_imbalance"] = total > 0.0 ? most * ranks->ranks / total : 1.0;
        // What each rank sent the others in the steps' exchanges (migration, ghosts, ghost
        // refreshes inside the pressure solve), over the steps this process ran.
        const double steps = static_cast<double>(std::max<std::uint64_t>(ranks->stepsRun, 1));
        j["rank_bytes_sent"] = ranks->counts.bytesSent;
        j["rank_messages_sent"] = ranks->counts.messagesSent;
        std::vector<double> perStep;
        for (const std::uint64_t b : ranks->counts.bytesSent) perStep.push_back(static_cast<double>(b) / steps);
        j["rank_bytes_per_step"] = perStep;
        j["rebalances"] = ranks->counts.rebalances;
    }
    io::writeFileAtomically(file, [&](std::ostream& out) { out << j.dump(2) << '\n'; });
}

/// CRC-32 of the scene file's bytes (0 if it cannot be read: loading it already worked).
std::uint32_t sceneCrc(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return io::crc32(text.str());
}

/// Bad input found while resuming: the message for stderr (exit 2).
struct ResumeError {
    std::string message;
};

/// The newest checkpoint of a stopped run and the run's progress in it.
struct Resumption {
    fs::path file;
    io::Checkpoint checkpoint;
    RunProgress progress;
};

/// Reads and checks the newest checkpoint in `dir`; throws ResumeError, changing nothing,
/// when there is none or it is damaged.
Resumption loadNewestCheckpoint(const fs::path& dir) {
    const std::string flag = "--resume " + dir.string();
    if (!fs::is_directory(dir)) throw ResumeError{flag + ": not a folder"};
    const std::vector<fs::path> files = listCheckpoints(dir);
    if (files.empty())
        throw ResumeError{flag + ": no checkpoint (checkpoint_NNNNN.tidecp) in it; a run writes them with --checkpoint-every N"};
    const std::string older = files.size() > 1 ? "; the older " + files[1].filename().string() +
                                                     " remains: remove the damaged file to resume from it"
                                               : "";
    Resumption r{files[0], {}, {}};
    try {
        r.checkpoint = io::readCheckpoint(files[0]);
        r.progress = decodeRunProgress(r.checkpoint.application);
        if (r.progress.pieces > 1) {  // a split run's: the other ranks' particles
            std::vector<WorldState> pieces;
            for (int rank = 1; rank < r.progress.pieces; ++rank) {
                const fs::path piece = checkpointPiece(dir, r.progress.frame, rank);
                if (!fs::exists(piece))
                    throw std::runtime_error(piece.string() + ": missing (" + files[0].filename().string() + " was written by " +
                                             std::to_string(r.progress.pieces) + " ranks, one file each)");
                pieces.push_back(io::readCheckpoint(piece).world);
            }
            try {
                r.checkpoint.world = joinCheckpointPieces(std::move(r.checkpoint.world), pieces);
            } catch (const std::runtime_error& e) {
                throw std::runtime_error(files[0].string() + ": " + e.what());
            }
        }
    } catch (const std::exception& e) {
        throw ResumeError{std::string(e.what()) + "; refusing to resume, nothing was changed" + older};
    }
    return r;
}

/// A split run's failure on this rank alone (a divergence it found, a piece it could not write):
/// says why on the real stderr and ends every rank, which would otherwise wait for it.
[[noreturn]] void abortRanks(comm::Communicator& comm, int realStderr, int code, const std::string& message) {
    const std::string line = "tide: rank " + std::to_string(comm.rank()) + ": " + message + "\n";
    (void)!::write(realStderr, line.data(), line.size());
    comm.abort(code);
    std::_Exit(code);  // not reached: abort ends the job (g++ does not see [[noreturn]] through the virtual call)
}

std::string pieceName(int frame, int rank) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%05d_r%d.vtu", frame, rank);
    return name;
}

std::string pvtuName(int frame) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%05d.pvtu", frame);
    return name;
}

/// The far field's mesh an obj frame of an ocean scene carries (3D; output.far_field), or none.
std::optional<io::FarFieldMeshDef> farFieldMesh(const io::Scene& scene) {
    const bool obj = std::find(scene.output.formats.begin(), scene.output.formats.end(), io::Format::Obj) != scene.output.formats.end();
    if (!obj || !scene.ocean || !scene.output.farField || scene.world.dimensions != 3) return std::nullopt;
    return io::farFieldMeshFor(*scene.ocean, scene.world, scene.output.farFieldExtent, scene.output.farFieldSpacing);
}

/// A split run's frame: every rank's own particles gathered on rank 0, which writes the file
/// one process would (rows ordered by id); VTU (unless `gather`) as a piece per rank, each
/// written by its rank, and the .pvtu naming them. Collective.
void writeSplitFrame(comm::Communicator& comm, const World& world, const fs::path& dir, int frame,
                     const std::vector<io::Format>& formats, const io::SurfaceMeshDef& surface, bool gather, int realStderr) {
    const bool pieces = !gather && std::find(formats.begin(), formats.end(), io::Format::Vtu) != formats.end();
    const bool gathered = std::any_of(formats.begin(), formats.end(), [&](io::Format f) { return f != io::Format::Vtu || gather; });
    if (pieces) {
        try {
            io::writeFrame(dir / pieceName(frame, comm.rank()), io::Format::Vtu, ownedParticles(world), surface);
        } catch (const std::exception& e) {
            abortRanks(comm, realStderr, kExitRunFailed, e.what());
        }
        // The .pvtu appears only once every piece it names is written: a reader that
        // waits for it (a watcher, a pipeline's next stage) never opens a missing piece.
        comm.barrier();
        if (comm.rank() == 0) {
            std::vector<std::string> names;
            for (int r = 0; r < comm.size(); ++r) names.push_back(pieceName(frame, r));
            io::writePvtu(dir / pvtuName(frame), names);
        }
    }
    if (!gathered) return;
    const ParticleStore all = gatherOwnedParticles(world, comm);
    if (comm.rank() != 0) return;
    for (const io::Format format : formats)
        if (format != io::Format::Vtu || gather) io::writeFrame(dir / frameName(frame, format), format, all, surface);
}

/// A split run's checkpoint: each rank K > 0 writes its piece, then (once all are written)
/// rank 0 its own with the run's progress, and prunes. Collective.
void writeSplitCheckpoint(comm::Communicator& comm, const World& world, const fs::path& dir, int frame,
                          const std::string& progress, int realStderr) {
    try {
        if (comm.rank() > 0) io::writeCheckpoint(checkpointPiece(dir, frame, comm.rank()), world.saveState(), "");
    } catch (const std::exception& e) {
        abortRanks(comm, realStderr, kExitRunFailed, e.what());
    }
    comm.barrier();
    if (comm.rank() != 0) return;
    io::writeCheckpoint(checkpointFile(dir, frame), world.saveState(), progress);
    pruneCheckpoints(dir);
}

}  // namespace

int runCommand(const RunOptions& o, comm::Communicator* comm) {
    const bool split = comm != nullptr;
    const bool lead = !split || comm->rank() == 0;  // prints and writes the run's files
    int realStderr = STDERR_FILENO;
    if (!lead) {  // the other ranks say only what is theirs alone (abortRanks)
        realStderr = ::dup(STDERR_FILENO);
        const int devNull = ::open("/dev/null", O_WRONLY);
        if (devNull >= 0) {
            ::dup2(devNull, STDOUT_FILENO);
            ::dup2(devNull, STDERR_FILENO);
            ::close(devNull);
        }
    }
    io::Scene scene;
    try {
        scene = io::loadScene(o.scene);
    } catch (const io::SceneError& e) {
        reportSceneProblems(o.scene, e.problems);
        return kExitBadInput;
    }
    const bool resuming = !o.resume.empty();
    std::optional<Resumption> resumed;
    int unreadable = kExitOk;
    try {
        if (resuming) resumed = loadNewestCheckpoint(o.resume);
    } catch (const ResumeError& e) {
        std::fprintf(stderr, "tide: %s\n", e.message.c_str());
        unreadable = kExitBadInput;
    }
    // Every rank reads every piece; should one fail alone, all still end with its code.
    if (split) unreadable = static_cast<int>(comm->max(unreadable));
    if (unreadable != kExitOk) return unreadable;
    // A resumed run keeps the choices it was started with, unless they are given again.
    const double sceneEndTime = scene.endTime;
    if (o.endTime) scene.endTime = *o.endTime;
    else if (resumed) scene.endTime = resumed->progress.endTime;
    if (!checkEndTime(scene, o.endTime.has_value(), o.scene)) return kExitBadInput;
    const std::string solver = !o.solver.empty() ? o.solver : resumed ? resumed->progress.solver : scene.world.solver.method;
    if (solver != scene.world.solver.method) {
        const auto known = solverNames();
        if (std::find(known.begin(), known.end(), solver) == known.end()) {
            std::fprintf(stderr, "--solver: unknown solver \"%s\"\n", solver.c_str());
            return kExitBadInput;
        }
        scene.world.solver.method = solver;
    }
    const std::vector<std::string>& formats = !o.formats.empty() ? o.formats
                                              : resumed                ? resumed->progress.formats
                                                                       : std::vector<std::string>{};
    if (!formats.empty()) {
        scene.output.formats.clear();
        for (const std::string& name : formats)
            if (auto f = io::parseFormat(name);
                f && std::find(scene.output.formats.begin(), scene.output.formats.end(), *f) == scene.output.formats.end())
                scene.output.formats.push_back(*f);
    }
    scene.world.threads = o.threads;
    if (resuming && !o.out.empty() && fs::weakly_canonical(o.out) != fs::weakly_canonical(o.resume)) {
        std::fprintf(stderr, "--out %s: a resumed run writes into its own folder (--resume %s); drop --out\n",
                     o.out.c_str(), o.resume.c_str());
        return kExitBadInput;
    }
    const fs::path dir = resuming ? fs::path(o.resume)
                         : o.out.empty() ? fs::path("out") / fs::path(o.scene).stem()
                                         : fs::path(o.out);

    // A longer end time lets emitters emit more: size the world for it, and refuse up front
    // what this machine cannot hold.
    if (scene.endTime != sceneEndTime)
        if (const std::string shortfall = io::memoryShortfall(scene); !shortfall.empty()) {
            std::fprintf(stderr, "%s: end time %g s: %s\n", o.scene.c_str(), scene.endTime, shortfall.c_str());
            return kExitBadInput;
        }
    scene.world.capacity = static_cast<std::uint32_t>(
        std::min<std::uint64_t>(io::estimate(scene).totalParticles + 1, 0xfffffff0ull));

    std::optional<World> world;
    RunProgress done;  // what earlier sessions of this run did (nothing for a new run)
    const std::uint32_t crc = sceneCrc(o.scene);
    int failure = kExitOk;  // every rank must agree before the first step, which they take together
    try {
        world.emplace(io::buildWorld(scene));
        if (resumed) {
            done = resumed->progress;
            const std::string file = resumed->file.string();
            if (done.sceneCrc != crc)
                throw ResumeError{file + ": written for another version of the scene file (its CRC-32 differs); "
                                  "resume with the scene the run started with"};
            if (done.solver != solver)
                throw ResumeError{file + ": written by the " + done.solver + " solver, --solver asks for " + solver};
            try {
                world->restoreState(std::move(resumed->checkpoint.world));
            } catch (const std::invalid_argument& e) {
                throw ResumeError{file + ": " + e.what()};
            }
            if (lead) removeStaleTemporaries(dir);  // a killed run's half-written files
        }
        if (split) distributeWorld(*world, *comm, DistributionOptions{o.rebalanceEvery, o.rebalanceAbove});  // the same refusals on every rank, before any file
        if (!resumed && lead) prepareOutputFolder(dir, o.force);
    } catch (const io::SceneError& e) {
        reportSceneProblems(o.scene, e.problems);
        failure = kExitBadInput;
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "%s: %s\n", o.scene.c_str(), e.what());
        failure = kExitBadInput;
    } catch (const OutputFolderError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        failure = kExitBadInput;
    } catch (const ResumeError& e) {
        std::fprintf(stderr, "tide: %s\n", e.message.c_str());
        failure = kExitBadInput;
    }
    if (split) failure = static_cast<int>(comm->max(failure));
    if (failure != kExitOk) return failure;
    // Every particle, on every rank (a split run's own particles add up to it; emitters and
    // an ocean's zones change it, so it is counted again after each step).
    const auto countParticles = [&]() -> std::uint64_t {
        return split ? static_cast<std::uint64_t>(comm->sum(static_cast<std::int64_t>(ownedIndices(*world).size())))
                     : world->particles().size();
    };
    std::uint64_t totalParticles = countParticles();

    const int frames = io::framesAfterTheFirst(scene);
    const int checkpointEvery = o.checkpointEvery > 0 ? o.checkpointEvery : done.checkpointEvery;
    std::vector<std::string> formatNames;
    for (const io::Format f : scene.output.formats) formatNames.emplace_back(io::extension(f));
    // The pre-roll (settle.time) before frame 0, outside the run's wall time. A resumed run
    // continues from its checkpoint, settled already.
    if (!resuming && scene.settleTime > 0.0) {
        try {
            settleAndReport(*world, scene.settleTime, scene.settleSpeed, o.quiet);
        } catch (const DivergenceError& e) {
            char text[512];
            std::snprintf(text, sizeof text, "the simulation diverged while settling (settle.time %g s) at %s; no frame was written",
                          scene.settleTime, e.what());
            if (split) abortRanks(*comm, realStderr, kExitRunFailed, text);
            std::fprintf(stderr, "tide: %s\n", text);
            return kExitRunFailed;
        }
    }
    const int firstFrame = resuming ? done.frame + 1 : 0;
    const auto start = std::chrono::steady_clock::now();
    const auto wallSoFar = [&] {
        return done.wallSeconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    Progress progress(scene.endTime, frames, o.quiet || !lead);
    io::PvdWriter pvd(dir / "frames.pvd");
    const bool vtu = std::find(scene.output.formats.begin(), scene.output.formats.end(), io::Format::Vtu) !=
                     scene.output.formats.end();
    // The frames before a resumption, as written: a split run's .pvtu or one .vtu.
    if (vtu)
        for (int frame = 0; frame < firstFrame; ++frame)
            pvd.add(frame / scene.output.fps,
                    fs::exists(dir / pvtuName(frame)) ? pvtuName(frame) : frameName(frame, io::Format::Vtu));
    std::uint64_t particleSteps = done.particleSteps;
    std::uint64_t sessionSteps = 0;  // this session's, for the progress rate
    std::uint64_t stepsRun = 0;      // this session's steps
    std::uint32_t lost = done.lost;
    bool reportedFull = false;
    Measurements measurements(scene);
    measurements.restoreRows(done.gaugeRows, done.probeRows, done.forceRows, done.bodyRows);
    io::SurfaceMeshDef surface{scene.world.particleSpacing, {}, scene.world.threads, {}};  // the obj format's
    for (const MaterialDef& m : scene.materials) surface.materialNames.push_back(m.name);
    surface.farField = farFieldMesh(scene);
    int lastFrame = firstFrame - 1;
    try {
        for (int frame = firstFrame; frame <= frames; ++frame) {
            if (frame > 0) {
                const double target = frame / scene.output.fps;
                world->advance(target - world->time(), [&] {
                    if (split && (!scene.emitters.empty() || scene.ocean)) totalParticles = countParticles();
                    const std::uint64_t n = split ? totalParticles : world->particles().size();
                    particleSteps += n;
                    sessionSteps += n;
                    ++stepsRun;
                    progress.step(world->time(), frame, static_cast<std::uint32_t>(n), sessionSteps);
                });
            }
            if (surface.farField) surface.farField->time = world->time(), surface.farField->ramp = world->oceanRamp();
            if (split) {
                writeSplitFrame(*comm, *world, dir, frame, scene.output.formats, surface, o.gather, realStderr);
            } else {
                for (io::Format format : scene.output.formats)
                    io::writeFrame(dir / frameName(frame, format), format, world->particles(), surface);
            }
            if (vtu && lead) {
                pvd.add(frame / scene.output.fps, split && !o.gather ? pvtuName(frame) : frameName(frame, io::Format::Vtu));
                pvd.write();
            }
            measurements.sample(*world, world->time(), split ? comm : nullptr);
            lost = std::max(lost, world->countEscapedParticles());
            lastFrame = frame;
            if (!reportedFull && world->stats().emitterCapacityHits > 0) {
                reportedFull = true;  // once: an emitter at capacity would say it every layer
                progress.finish();
                std::fprintf(stderr, "tide: warning: the world is full (%u particles, its capacity): emitters stop emitting\n",
                             world->def().capacity);
            }
            if (checkpointEvery > 0 && frame > 0 && frame % checkpointEvery == 0) {
                const RunProgress now{frame,
                                      particleSteps,
                                      lost,
                                      wallSoFar(),
                                      measurements.gaugeRows(),
                                      measurements.probeRows(),
                                      measurements.forceRows(),
                                      measurements.bodyRows(),
                                      crc,
                                      scene.world.solver.method,
                                      checkpointEvery,
                                      scene.endTime,
                                      formatNames,
                                      split ? comm->size() : 1};
                if (split) {
                    writeSplitCheckpoint(*comm, *world, dir, frame, encodeRunProgress(now), realStderr);
                } else {
                    io::writeCheckpoint(checkpointFile(dir, frame), world->saveState(), encodeRunProgress(now));
                    pruneCheckpoints(dir);
                }
            }
            progress.frame(world->time(), frame, split ? static_cast<std::uint32_t>(totalParticles) : world->particles().size(),
                           sessionSteps);
        }
        progress.finish();
        const double wall = wallSoFar();
        std::optional<RanksReport> ranks;
        if (split) ranks = RanksReport{comm->size(), gatherRankCounts(*world, *comm), stepsRun};
        if (lead) {
            measurements.write(dir);
            writeStats(dir / "stats.json", *world, split ? totalParticles : world->particles().size(), wall, particleSteps,
                       lost, ranks);
        }
        if (const WorldStats& s = world->stats(); s.unconvergedSolves > 0)
            std::fprintf(stderr,
                         "tide: warning: the pressure solve stopped short of its density tolerance in %llu of %llu steps "
                         "(solver.max_iterations %d): the water was compressed beyond solver.max_density_error there; "
                         "raise solver.max_iterations or shorten solver.max_dt\n",
                         static_cast<unsigned long long>(s.unconvergedSolves), static_cast<unsigned long long>(s.steps),
                         world->def().solver.maxIterations);
        if (!o.quiet)
            std::printf("%d frames of %llu particles in %s (%.1f s wall, %.2f M particle-steps/s)\n", frames + 1,
                        static_cast<unsigned long long>(split ? totalParticles : world->particles().size()),
                        dir.string().c_str(), wall, particleSteps / std::max(wall, 1e-9) / 1e6);
    } catch (const DivergenceError& e) {
        if (split)
            abortRanks(*comm, realStderr, kExitRunFailed,
                       std::string("the simulation diverged at ") + e.what() + "; frames up to " +
                           std::to_string(lastFrame) + " are kept in " + dir.string());
        progress.finish();
        measurements.write(dir);  // the rows up to the last good frame
        const std::vector<fs::path> checkpoints = listCheckpoints(dir);
        std::fprintf(stderr, "tide: the simulation diverged at %s; frames up to %d%s are kept in %s\n", e.what(), lastFrame,
                     checkpoints.empty() ? "" : (" and " + checkpoints[0].filename().string()).c_str(),
                     dir.string().c_str());
        return kExitRunFailed;
    } catch (const std::runtime_error& e) {
        if (split) abortRanks(*comm, realStderr, kExitRunFailed, e.what());
        progress.finish();
        std::fprintf(stderr, "tide: %s\n", e.what());
        return kExitRunFailed;
    }
    return kExitOk;
}

}  // namespace tide::cli
