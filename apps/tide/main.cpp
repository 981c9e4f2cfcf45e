// `tide`: run, validate and export SPH fluid scenes from the command line.
#include <CLI/CLI.hpp>

#include <iostream>

#include "comm/communicator.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
    using namespace tide::cli;
    CLI::App app{"tide: an SPH fluid simulator. Runs scenes described in JSON files (docs/scene-format.md)\n"
                 "and writes frames that ParaView, Blender or Houdini read.",
                 "tide"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "tide 0.1.0");

    RunOptions run;
    CLI::App* runApp = app.add_subcommand("run", "Simulate a scene and write its frames, frames.pvd and stats.json");
    runApp->add_option("scene", run.scene, "Scene file (JSON)")->required();
    runApp->add_option("--out", run.out, "Output folder (default: out/<scene file name>)");
    runApp->add_option("--end-time", run.endTime, "Simulated seconds, overriding the scene's end_time")
        ->check(CLI::PositiveNumber);
    runApp->add_option("--threads", run.threads, "Worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
    runApp->add_option("--format", run.formats,
                       "Frame formats, comma separated: vtu, ply, csv, obj (the fluid's surface mesh) (default: the scene's)")
        ->delimiter(',')
        ->check(CLI::IsMember({"vtu", "ply", "csv", "obj"}));
    runApp->add_option("--solver", run.solver, "Solver, overriding the scene's solver.method");
    runApp->add_flag("--force", run.force, "Write into a folder that holds another run, replacing its frames");
    runApp->add_flag("--quiet", run.quiet, "No progress output");
    runApp->add_option("--checkpoint-every", run.checkpointEvery,
                       "Write OUT/checkpoint_NNNNN.tidecp every N frames (the newest two are kept); under mpirun each\n"
                       "rank K > 0 adds its piece checkpoint_NNNNN_rK.tidecp, and any number of ranks can resume")
        ->check(CLI::Range(1, 1 << 30));
    runApp->add_option("--resume", run.resume,
                       "Continue the stopped run in this folder from its newest checkpoint (same scene; it keeps its\n"
                       "end time, formats, solver and checkpoint interval unless given again); its frames come out\n"
                       "bit-identical to an uninterrupted run's");
    runApp->add_option("--rebalance-every", run.rebalanceEvery,
                       "Under mpirun: cut the ranks' boxes again every N steps (default 0: only when the load drifts,\n"
                       "see --rebalance-above); results do not change, only which rank steps which particle")
        ->check(CLI::Range(0, 1 << 30));
    runApp->add_option("--rebalance-above", run.rebalanceAbove,
                       "Under mpirun: cut the boxes again when the busiest rank owns this many times the mean number\n"
                       "of particles (default 1.2)")
        ->check(CLI::Range(1.0, 1e9));
    runApp->add_flag("--gather", run.gather,
                     "Under mpirun: VTU frames gathered into one frame_NNNNN.vtu instead of a piece per rank and a .pvtu");
    runApp->footer("On a terminal a progress bar shows simulated time, frame, particles, particle-steps/s and\n"
                   "the time left; otherwise one line per frame. Frame k (time k/fps) is written as\n"
                   "OUT/frame_NNNNN.<format>, with OUT/frames.pvd for ParaView and OUT/stats.json at the end.\n"
                   "Every step is checked for NaN/Inf and runaway speeds; a diverged run stops naming the step,\n"
                   "time, particle and quantity, keeping the frames and checkpoints written before.\n"
                   "Under `mpirun -np N` the scene is split among the N processes and every N writes the same\n"
                   "frames (CSV, PLY and OBJ gathered into one file; VTU a piece per rank and frame_NNNNN.pvtu).\n"
                   "Exit codes: 0 success, 1 the run failed (e.g. diverged), 2 bad input (also a damaged checkpoint).");

    RenderOptions render;
    CLI::App* renderApp = app.add_subcommand("render", "Simulate a scene and draw its frames as PNG images (no display needed)");
    renderApp->add_option("scene", render.scene, "Scene file (JSON)")->required();
    renderApp->add_option("--out", render.out, "Output folder (default: out/<scene file name>_render)");
    renderApp->add_option("--width", render.width, "Image width, pixels")->check(CLI::Range(16, 8192));
    renderApp->add_option("--height", render.height, "Image height, pixels")->check(CLI::Range(16, 8192));
    renderApp->add_option("--video", render.video, "Also encode the frames as this MP4 file (needs ffmpeg)");
    renderApp->add_option("--mode", render.mode, "surface (water surface) or particles (lit spheres)")
        ->check(CLI::IsMember({"surface", "particles"}));
    renderApp->add_option("--color-by", render.colorBy, "Particles mode: material, speed, density or pressure")
        ->check(CLI::IsMember({"material", "speed", "density", "pressure"}));
    renderApp->add_option("--end-time", render.endTime, "Simulated seconds, overriding the scene's end_time")
        ->check(CLI::PositiveNumber);
    renderApp->add_option("--threads", render.threads, "Worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
    renderApp->add_flag("--force", render.force, "Write into a folder that holds another run, replacing its frames");
    renderApp->add_flag("--quiet", render.quiet, "No progress output");
    renderApp->footer("Frame k (time k/output.fps) is drawn as OUT/frame_NNNNN.png, seen from the scene's camera\n"
                      "(\"camera\": {\"eye\", \"target\", \"fov\"}) or from a 3/4 view of the container. Renders\n"
                      "offscreen with EGL (Mesa's software llvmpipe when there is no GPU).\n"
                      "Exit codes: 0 success, 1 the render failed, 2 bad input.");

    std::string validateScene;
    CLI::App* validateApp = app.add_subcommand("validate", "Check a scene and print what it would simulate");
    validateApp->add_option("scene", validateScene, "Scene file (JSON)")->required();

    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {  // --help, --version
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return kExitBadInput;
    }
    // Every rank of `mpirun -np N tide render` would draw the whole scene into the same files.
    if (*renderApp && tide::comm::launcherRankCount() > 1) {
        std::cerr << "tide: render started as one of " << tide::comm::launcherRankCount()
                  << " MPI ranks; it draws in one process. Run it without mpirun (`mpirun tide run` splits a run).\n";
        return kExitBadInput;
    }
    // `mpirun -np N tide run`: the scene split among the N ranks (N = 1 included, so that every N
    // writes the same frames); a plain `tide run` steps it in this process alone.
    if (*runApp && tide::comm::startedByMpiLauncher()) {
        if (!tide::comm::mpiBuilt()) {
            if (tide::comm::launcherRankCount() == 1) return runCommand(run);
            std::cerr << "tide: started as one of " << tide::comm::launcherRankCount()
                      << " MPI ranks, but built without MPI (-DTIDE_WITH_MPI=OFF). Run it without mpirun.\n";
            return kExitBadInput;
        }
        std::unique_ptr<tide::comm::Communicator> comm = tide::comm::makeMpiCommunicator(&argc, &argv);
        return runCommand(run, comm.get());
    }
    if (*runApp) return runCommand(run);
    if (*renderApp) return renderCommand(render);
    return validateCommand(validateScene);
}
