// `tide`: run, validate and export SPH fluid scenes from the command line.
#include <CLI/CLI.hpp>

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
    runApp->add_option("--format", run.formats, "Frame formats, comma separated: vtu, ply, csv (default: the scene's)")
        ->delimiter(',')
        ->check(CLI::IsMember({"vtu", "ply", "csv"}));
    runApp->add_option("--solver", run.solver, "Solver, overriding the scene's solver.method");
    runApp->add_flag("--force", run.force, "Write into a folder that holds another run, replacing its frames");
    runApp->add_flag("--quiet", run.quiet, "No progress output");
    runApp->footer("On a terminal a progress bar shows simulated time, frame, particles, particle-steps/s and\n"
                   "the time left; otherwise one line per frame. Frame k (time k/fps) is written as\n"
                   "OUT/frame_NNNNN.<format>, with OUT/frames.pvd for ParaView and OUT/stats.json at the end.\n"
                   "Exit codes: 0 success, 1 the run failed (e.g. diverged), 2 bad input.");

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
    if (*runApp) return runCommand(run);
    return validateCommand(validateScene);
}
