// The `tide` command line, run as a user would: bad scenes, output formats, progress, stats.
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_support.hpp"

namespace {

namespace fs = std::filesystem;
using namespace tide::testing;

const std::string kTide = TIDE_BIN;

/// A small valid scene; `extra` is spliced in as more top-level keys.
std::string smallScene(const std::string& extra = "") {
    return R"({
  "name": "small", "domain": {"min": [0, 0, 0], "max": [0.2, 0.2, 0.2]}, "gravity": [0, -9.81, 0],
  "particle_spacing": 0.02, "end_time": 0.1,
  "materials": [{"name": "water", "density": 1000, "viscosity": 0.001}],
  "blocks": [{"min": [0, 0, 0], "max": [0.1, 0.1, 0.2], "material": "water"}],
  "output": {"fps": 20, "formats": ["vtu"]})" + extra + "\n}\n";
}

/// Checks that OUT/stats.json holds every contract key and lost no particle; returns its text.
std::string expectFullStats(const fs::path& out) {
    std::ifstream file(out / "stats.json");
    std::stringstream stats;
    stats << file.rdbuf();
    for (const char* key : {"particles", "steps", "sim_time", "wall_time", "particle_steps_per_second", "dt_min",
                            "dt_mean", "dt_max", "max_density_error", "avg_density_error", "particles_lost",
                            "threads", "solver", "pressure_iterations_mean", "pressure_unconverged_steps"})
        EXPECT_NE(stats.str().find(std::string("\"") + key + "\":"), std::string::npos) << key;
    EXPECT_NE(stats.str().find("\"particles_lost\": 0"), std::string::npos) << stats.str();
    return stats.str();
}

struct BrokenScene {
    const char* what;
    std::string text;
    const char* field;  ///< must appear in the error message
};

std::string replace(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    if (at == std::string::npos) throw std::logic_error("test bug: no " + from);
    return text.replace(at, from.size(), to);
}

std::vector<BrokenScene> brokenScenes() {
    const std::string ok = smallScene();
    return {
        {"truncated JSON", ok.substr(0, 60), ":2:"},
        {"trailing comma", replace(ok, "\"end_time\": 0.1,", "\"end_time\": 0.1,,"), ":3:"},
        {"not an object", "[1, 2, 3]", "must be an object"},
        {"unknown top-level key", replace(ok, "\"end_time\"", "\"end_tme\": 1, \"end_time\""), "end_tme"},
        {"suggests a close key", replace(ok, "\"gravity\"", "\"gravty\": [0,0,0], \"gravity\""), "did you mean \"gravity\""},
        {"missing domain", replace(ok, "\"domain\"", "\"unused_domain_key_x\""), "domain"},
        {"domain not an object", replace(ok, R"({"min": [0, 0, 0], "max": [0.2, 0.2, 0.2]})", "5"), "domain"},
        {"domain min above max", replace(ok, "\"max\": [0.2, 0.2, 0.2]", "\"max\": [0.2, -0.2, 0.2]"), "domain.max"},
        {"domain flat", replace(ok, "\"max\": [0.2, 0.2, 0.2]", "\"max\": [0.2, 0, 0.2]"), "domain.max"},
        {"domain min two numbers", replace(ok, "\"min\": [0, 0, 0], \"max\": [0.2", "\"min\": [0, 0], \"max\": [0.2"), "domain.min"},
        {"gravity a string", replace(ok, "[0, -9.81, 0]", "\"down\""), "gravity"},
        {"spacing zero", replace(ok, "\"particle_spacing\": 0.02", "\"particle_spacing\": 0"), "particle_spacing"},
        {"spacing negative", replace(ok, "\"particle_spacing\": 0.02", "\"particle_spacing\": -0.1"), "particle_spacing"},
        {"spacing missing", replace(ok, "\"particle_spacing\": 0.02,", ""), "particle_spacing"},
        {"spacing too fine for memory", replace(ok, "\"particle_spacing\": 0.02", "\"particle_spacing\": 0.00005"), "particle_spacing"},
        {"end time negative", replace(ok, "\"end_time\": 0.1", "\"end_time\": -1"), "end_time"},
        {"number beyond double", replace(ok, "\"end_time\": 0.1", "\"end_time\": 1e400"), "end_time: number 1e400 is out of range"},
        {"number beyond double in an array", replace(ok, "\"max\": [0.2, 0.2, 0.2]", "\"max\": [0.2, -1e999, 0.2]"),
         "domain.max[1]: number -1e999 is out of range"},
        {"end time a string", replace(ok, "\"end_time\": 0.1", "\"end_time\": \"soon\""), "end_time"},
        {"end time short of a frame", replace(ok, "\"end_time\": 0.1", "\"end_time\": 0.04"),
         "end_time: 0.04 s is shorter than one frame at output.fps 20 (0.05 s)"},
        {"end time of too many frames", replace(ok, "\"end_time\": 0.1", "\"end_time\": 1e7"),
         "end_time: 1e+07 s at output.fps 20 is 2e+08 frames, more than the 1e+08 a run may write"},
        {"no materials", replace(ok, R"([{"name": "water", "density": 1000, "viscosity": 0.001}])", "[]"), "materials"},
        {"negative density", replace(ok, "\"density\": 1000", "\"density\": -1000"), "materials[0].density"},
        {"density missing", replace(ok, "\"density\": 1000, ", ""), "materials[0].density"},
        {"negative viscosity", replace(ok, "\"viscosity\": 0.001", "\"viscosity\": -2"), "materials[0].viscosity"},
        {"unknown material key", replace(ok, "\"viscosity\": 0.001", "\"viscosity\": 0.001, \"colour\": [1, 0, 0]"), "materials[0].colour"},
        {"colour out of range", replace(ok, "\"viscosity\": 0.001", "\"viscosity\": 0.001, \"color\": [2, 0, 0]"), "materials[0].color"},
        {"material without name", replace(ok, "\"name\": \"water\", ", ""), "materials[0].name"},
        {"block of unknown material", replace(ok, "\"material\": \"water\"}]", "\"material\": \"watr\"}]"), "blocks[0].material"},
        {"block outside the domain", replace(ok, "\"max\": [0.1, 0.1, 0.2]", "\"max\": [0.1, 0.1, 0.5]"), "blocks[0]"},
        {"block min above max", replace(ok, "\"max\": [0.1, 0.1, 0.2]", "\"max\": [0.1, -0.1, 0.2]"), "blocks[0].max"},
        {"block velocity two numbers", replace(ok, "\"material\": \"water\"}]", "\"material\": \"water\", \"velocity\": [1, 2]}]"), "blocks[0].velocity"},
        {"blocks not an array", replace(ok, R"([{"min": [0, 0, 0], "max": [0.1, 0.1, 0.2], "material": "water"}])", "{}"), "blocks"},
        {"obstacle name with a comma", smallScene(R"(, "obstacles": [{"type": "sphere", "center": [0.15, 0.05, 0.1], "radius": 0.02, "name": "a,b"}])"),
         "obstacles[0].name: must be letters, digits, _ or -"},
        {"obstacle name twice", smallScene(R"(, "obstacles": [{"type": "sphere", "center": [0.15, 0.05, 0.1], "radius": 0.02},
            {"type": "sphere", "center": [0.15, 0.15, 0.1], "radius": 0.02, "name": "obstacle0"}])"),
         "obstacles[1].name: \"obstacle0\" is already the name of obstacles[0]"},
        {"load reference two numbers", smallScene(R"(, "obstacles": [{"type": "sphere", "center": [0.15, 0.05, 0.1], "radius": 0.02, "load_reference": [0, 1]}])"),
         "obstacles[0].load_reference"},
        {"body without density or mass", smallScene(R"(, "obstacles": [{"type": "sphere", "center": [0.15, 0.15, 0.1], "radius": 0.02, "dynamic": true}])"),
         "obstacles[0].density: a dynamic body needs exactly one of density"},
        {"body with an unknown axis", smallScene(R"(, "obstacles": [{"type": "sphere", "center": [0.15, 0.15, 0.1], "radius": 0.02, "dynamic": true,
            "density": 500, "constraint": {"free": ["y", "w"]}}])"),
         "obstacles[0].constraint.free[1]: unknown axis \"w\""},
        {"mooring anchor outside the domain", smallScene(R"(, "obstacles": [{"type": "sphere", "center": [0.15, 0.15, 0.1], "radius": 0.02, "dynamic": true,
            "density": 500, "moorings": [{"fairlead": [0.15, 0.13, 0.1], "anchor": [0.15, -0.1, 0.1], "length": 0.1, "stiffness": 100}]}])"),
         "obstacles[0].moorings[0].anchor: must lie inside the domain"},
        {"mooring without stiffness", smallScene(R"(, "obstacles": [{"type": "sphere", "center": [0.15, 0.15, 0.1], "radius": 0.02, "dynamic": true,
            "density": 500, "moorings": [{"fairlead": [0.15, 0.13, 0.1], "anchor": [0.15, 0.0, 0.1], "length": 0.1}]}])"),
         "obstacles[0].moorings[0].stiffness: missing"},
        {"body density without dynamic", smallScene(R"(, "obstacles": [{"type": "sphere", "center": [0.15, 0.15, 0.1], "radius": 0.02, "density": 500}])"),
         "obstacles[0].dynamic: must be true"},
        {"unknown solver", smallScene(R"(, "solver": {"method": "dfsph-ultra"})"), "solver.method"},
        {"unknown solver key", smallScene(R"(, "solver": {"methd": "classic"})"), "solver.methd"},
        {"unknown kernel", smallScene(R"(, "solver": {"kernel": "gaussian"})"), "solver.kernel"},
        {"bad equation of state", smallScene(R"(, "solver": {"equation_of_state": "ideal gas"})"), "solver.equation_of_state"},
        {"cfl above one", smallScene(R"(, "solver": {"cfl": 4})"), "solver.cfl"},
        {"momentum of one", smallScene(R"(, "solver": {"momentum": 1})"), "solver.momentum"},
        {"shifting above one", smallScene(R"(, "solver": {"shifting": 2})"), "solver.shifting"},
        {"shifting with wcsph", smallScene(R"(, "solver": {"method": "wcsph", "shifting": 0.2})"), "solver.shifting"},
        {"difference form below zero", smallScene(R"(, "solver": {"difference_form": -0.5})"), "solver.difference_form"},
        {"difference form with pcisph", smallScene(R"(, "solver": {"method": "pcisph", "difference_form": 0.5})"),
         "solver.difference_form"},
        {"smooth density error as a number", smallScene(R"(, "solver": {"smooth_density_error": 1})"),
         "solver.smooth_density_error"},
        {"smooth density error with pcisph", smallScene(R"(, "solver": {"method": "pcisph", "smooth_density_error": true})"),
         "solver.smooth_density_error"},
        {"negative divergence iterations", smallScene(R"(, "solver": {"min_divergence_iterations": -1})"),
         "solver.min_divergence_iterations"},
        {"divergence warm start above one", smallScene(R"(, "solver": {"divergence_warm_start": 1.5})"),
         "solver.divergence_warm_start"},
        {"divergence warm start with wcsph", smallScene(R"(, "solver": {"method": "wcsph", "divergence_warm_start": 0})"),
         "solver.divergence_warm_start"},
        {"divergence tolerance of zero", smallScene(R"(, "solver": {"max_divergence_error": 0})"),
         "solver.max_divergence_error"},
        {"unknown output format", replace(ok, "[\"vtu\"]", "[\"vtk\"]"), "output.formats[0]"},
        {"fps zero", replace(ok, "\"fps\": 20", "\"fps\": 0"), "output.fps"},
        {"emitter without velocity", smallScene(R"(, "emitters": [{"min": [0, 0.1, 0.05], "max": [0, 0.15, 0.1]}])"), "emitters[0].velocity"},
        {"emitter zero velocity", smallScene(R"(, "emitters": [{"min": [0, 0.1, 0.05], "max": [0, 0.15, 0.1], "velocity": [0, 0, 0]}])"), "emitters[0].velocity"},
        {"emitter ends before start", smallScene(R"(, "emitters": [{"min": [0, 0.1, 0.05], "max": [0, 0.15, 0.1], "velocity": [1, 0, 0], "start": 2, "end": 1}])"), "emitters[0].end"},
        {"emitter outside the domain", smallScene(R"(, "emitters": [{"min": [-1, 0.1, 0.05], "max": [-1, 0.15, 0.1], "velocity": [1, 0, 0]}])"), "emitters[0]"},
        {"unknown obstacle type", smallScene(R"(, "obstacles": [{"type": "cone"}])"), "obstacles[0].type"},
        {"sphere without radius", smallScene(R"(, "obstacles": [{"type": "sphere", "center": [0.1, 0.1, 0.1]}])"), "obstacles[0].radius"},
        {"box obstacle with radius", smallScene(R"(, "obstacles": [{"type": "box", "min": [0, 0, 0], "max": [0.1, 0.1, 0.1], "radius": 1}])"), "obstacles[0].radius"},
        {"cylinder without axis", smallScene(R"(, "obstacles": [{"type": "cylinder", "center": [0.1, 0.1, 0.1], "radius": 0.02, "length": 0.1}])"), "obstacles[0].axis"},
        {"plane with zero normal", smallScene(R"(, "obstacles": [{"type": "plane", "point": [0, 0.05, 0], "normal": [0, 0, 0]}])"), "obstacles[0].normal"},
        {"mesh file missing", smallScene(R"(, "obstacles": [{"type": "mesh", "file": "models/no_such_rock.obj"}])"), "obstacles[0].file: models/no_such_rock.obj"},
        {"unit scale zero", smallScene(R"(, "unit_scale": 0)"), "unit_scale"},
        {"periodic not booleans", replace(ok, "\"max\": [0.2, 0.2, 0.2]}", "\"max\": [0.2, 0.2, 0.2], \"periodic\": [1, 0, 0]}"), "domain.periodic"},
        {"periodic axis too short", replace(replace(ok, "\"max\": [0.2, 0.2, 0.2]}", "\"max\": [0.2, 0.2, 0.2], \"periodic\": [true, false, false]}"),
                                            "\"particle_spacing\": 0.02", "\"particle_spacing\": 0.06"), "domain.periodic"},
        {"unknown viscosity model", smallScene(R"(, "solver": {"viscosity": "moris"})"), "solver.viscosity: unknown viscosity model \"moris\" (did you mean \"morris\"?)"},
        {"wave period negative", smallScene(R"(, "wavemaker": {"type": "piston", "x": 0.05, "depth": 0.1, "wave_height": 0.01, "period": -1})"),
         "wavemaker.period: must be > 0, got -1"},
        {"wave maker type", smallScene(R"(, "wavemaker": {"type": "pistn", "x": 0.05, "depth": 0.1, "wave_height": 0.01, "period": 1})"),
         "wavemaker.type: must be \"piston\", \"flap\" or \"solitary\", got \"pistn\" (did you mean \"piston\"?)"},
        {"wave too long for the tank", smallScene(R"(, "wavemaker": {"type": "piston", "x": 0.05, "depth": 0.1, "wave_height": 0.01, "period": 1})"),
         "wavemaker.period: the wave is too long for the tank"},
        {"wave order", smallScene(R"(, "wavemaker": {"type": "piston", "x": 0.05, "depth": 0.1, "wave_height": 0.01, "period": 1, "order": 3})"),
         "wavemaker.order"},
        {"solitary with a period", smallScene(R"(, "wavemaker": {"type": "solitary", "x": 0.05, "depth": 0.1, "wave_height": 0.01, "period": 1})"),
         "wavemaker.period: a solitary wave has only a wave_height"},
        {"wave maker outside", smallScene(R"(, "wavemaker": {"type": "flap", "x": 3, "depth": 0.1, "wave_height": 0.01, "period": 1})"), "wavemaker.x"},
        {"wave maker unknown key", smallScene(R"(, "wavemaker": {"type": "flap", "x": 0.05, "depth": 0.1, "wave_height": 0.01, "period": 1, "stroke": 2})"),
         "wavemaker.stroke: unknown key"},
        {"regular and irregular", smallScene(R"(, "wavemaker": {"type": "flap", "x": 0.05, "depth": 0.1, "wave_height": 0.01, "period": 1, "spectrum": {"type": "jonswap", "hs": 0.01, "tp": 1}})"),
         "wavemaker: give either spectrum"},
        {"spectrum gamma", smallScene(R"(, "wavemaker": {"type": "flap", "x": 0.05, "depth": 0.1, "spectrum": {"type": "jonswap", "hs": 0.01, "tp": 1, "gamma": 0.5}})"),
         "wavemaker.spectrum.gamma"},
        {"damping flat", smallScene(R"(, "damping": {"x_start": 0.1, "x_end": 0.1})"), "damping.x_end"},
        {"settle time negative", smallScene(R"(, "settle": {"time": -1})"), "settle.time: must be >= 0"},
        {"settle without time", smallScene(R"(, "settle": {})"), "settle.time: missing"},
        {"settle unknown key", smallScene(R"(, "settle": {"seconds": 2})"), "settle.seconds: unknown key"},
        {"settle speed negative", smallScene(R"(, "settle": {"time": 2, "speed": -0.01})"), "settle.speed: must be >= 0"},
        {"gauge without x", smallScene(R"(, "gauges": [{"name": "g1"}])"), "gauges[0].x"},
        {"gauge names repeat", smallScene(R"(, "gauges": [{"name": "g1", "x": 0.1}, {"name": "g1", "x": 0.15}])"), "gauges[1].name"},
        {"probe outside", smallScene(R"(, "probes": [{"name": "p", "position": [0.1, 0.1, 9]}])"), "probes[0].position"},
    };
}

TEST(Cli, BrokenScenesExitTwoNamingTheField) {
    const auto cases = brokenScenes();
    ASSERT_GE(cases.size(), 30u);
    int k = 0;
    for (const BrokenScene& c : cases) {
        const fs::path file = writeScene("broken_" + std::to_string(k++), c.text);
        const Result r = run(kTide + " validate " + file.string());
        EXPECT_EQ(r.exit, 2) << c.what << "\n" << r.output;
        EXPECT_NE(r.output.find(c.field), std::string::npos) << c.what << ": message lacks \"" << c.field << "\"\n" << r.output;
    }
}

TEST(Cli, ValidateDescribesAGoodScene) {
    const Result r = run(kTide + " validate " + writeScene("good", smallScene()).string());
    EXPECT_EQ(r.exit, 0) << r.output;
    EXPECT_NE(r.output.find("250 particles"), std::string::npos) << r.output;  // 5 × 5 × 10
    EXPECT_NE(r.output.find("MiB"), std::string::npos);
}

TEST(Cli, ValidateWarnsWhenTheWaterAtAPaddleIsNotItsDepth) {
    // A block holds whole cells: 0.1 m at 2 cm is 5 of them, 0.11 m would need 5.5.
    const auto flume = [](const char* depth) {
        return replace(replace(smallScene(R"(, "wavemaker": {"type": "piston", "x": 0.05, "depth": )" + std::string(depth) +
                                          R"(, "wave_height": 0.01, "period": 0.5})"),
                               "\"max\": [0.2, 0.2, 0.2]", "\"max\": [0.6, 0.3, 0.06]"),
                       "\"max\": [0.1, 0.1, 0.2]", "\"max\": [0.6, 0.1, 0.06]");
    };
    const Result right = run(kTide + " validate " + writeScene("paddle_right", flume("0.1")).string());
    EXPECT_EQ(right.exit, 0) << right.output;
    EXPECT_EQ(right.output.find("warning"), std::string::npos) << right.output;
    const Result off = run(kTide + " validate " + writeScene("paddle_off", flume("0.11")).string());
    EXPECT_EQ(off.exit, 0) << off.output;
    EXPECT_NE(off.output.find("warning: wavemaker: depth 0.11 m, but blocks[0] holds water 0.1 m deep"), std::string::npos)
        << off.output;
}

TEST(Cli, ShippedPoiseuilleChannelRunsOnPeriodicAxes) {
    const std::string scene = std::string(TIDE_SCENES_DIR) + "/poiseuille.json";
    const Result validate = run(kTide + " validate " + scene);
    EXPECT_EQ(validate.exit, 0) << validate.output;
    EXPECT_NE(validate.output.find("periodic in x, z"), std::string::npos) << validate.output;
    const fs::path out = scratch("poiseuille_out");
    const Result r = run(kTide + " run " + scene + " --quiet --end-time 0.05 --out " + out.string());
    ASSERT_EQ(r.exit, 0) << r.output;
    expectFullStats(out);  // particles_lost 0 at every frame
}

TEST(Cli, BadFlagsExitTwo) {
    EXPECT_EQ(run(kTide + " run").exit, 2);
    EXPECT_EQ(run(kTide + " frobnicate").exit, 2);
    const fs::path scene = writeScene("flags", smallScene());
    EXPECT_EQ(run(kTide + " run " + scene.string() + " --format vtk").exit, 2);
    EXPECT_EQ(run(kTide + " run " + scene.string() + " --end-time -1").exit, 2);
    EXPECT_EQ(run(kTide + " run " + scene.string() + " --solver nope --out " + scratch("x").string()).exit, 2);
    const Result help = run(kTide + " run --help");
    EXPECT_EQ(help.exit, 0);
    for (const char* flag : {"--out", "--end-time", "--threads", "--format", "--solver", "--force", "--quiet"})
        EXPECT_NE(help.output.find(flag), std::string::npos) << flag;
}

// `tide render` started by mpirun on several ranks would draw the whole scene into the same
// folder from every rank: refused (exit 2 from each rank) before anything is written. The
// launcher's variable alone stands in for mpirun here. (`mpirun tide run` splits the run:
// tests/mpi/run_split_identical.sh.)
TEST(Cli, SeveralMpiRanksAreRefusedByRender) {
    const fs::path scene = writeScene("mpi_ranks", smallScene());
    const fs::path out = scratch("mpi_ranks_out");
    const Result r = run("OMPI_COMM_WORLD_SIZE=3 " + kTide + " render " + scene.string() + " --quiet --out " + out.string());
    EXPECT_EQ(r.exit, 2) << r.output;
    EXPECT_NE(r.output.find("one of 3 MPI ranks"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
    // One rank is a plain run.
    const Result one = run("OMPI_COMM_WORLD_SIZE=1 " + kTide + " validate " + scene.string());
    EXPECT_EQ(one.exit, 0) << one.output;
}

// An end time short of frame 1 would simulate nothing: refused by name before the output folder
// is touched. One between two frames runs to the frame before it (frame k lands on k/fps) and
// says so; before, both ran silently (0.05 s at 10 fps: 0 steps, exit 0).
TEST(Cli, EndTimeShortOfAFrameIsRefusedAndOneBetweenFramesWarns) {
    const fs::path scene = writeScene("end_time", smallScene());
    const fs::path out = scratch("end_time_out");
    const Result refused = run(kTide + " run " + scene.string() + " --quiet --end-time 0.03 --out " + out.string());
    EXPECT_EQ(refused.exit, 2);
    EXPECT_NE(refused.output.find("--end-time: 0.03 s is shorter than one frame at output.fps 20 (0.05 s)"),
              std::string::npos)
        << refused.output;
    EXPECT_FALSE(fs::exists(out));
    const Result render = run(kTide + " render " + scene.string() + " --end-time 0.03 --out " + scratch("end_time_render").string());
    EXPECT_EQ(render.exit, 2) << render.output;
    EXPECT_NE(render.output.find("--end-time: 0.03 s"), std::string::npos) << render.output;

    const Result between = run(kTide + " run " + scene.string() + " --quiet --end-time 0.12 --out " + out.string());
    ASSERT_EQ(between.exit, 0) << between.output;
    EXPECT_NE(between.output.find("end time 0.12 s is not a whole number of frames at output.fps 20: the run stops at "
                                  "frame 2, t = 0.1 s"),
              std::string::npos)
        << between.output;
    EXPECT_TRUE(fs::exists(out / "frame_00002.vtu"));
    EXPECT_FALSE(fs::exists(out / "frame_00003.vtu"));
    const std::string stats = expectFullStats(out);
    EXPECT_NE(stats.find("\"sim_time\": 0.1"), std::string::npos) << stats;
    // A whole number of frames says nothing.
    const Result whole = run(kTide + " run " + scene.string() + " --quiet --force --end-time 0.15 --out " + out.string());
    ASSERT_EQ(whole.exit, 0) << whole.output;
    EXPECT_EQ(whole.output.find("whole number of frames"), std::string::npos) << whole.output;
}

TEST(Cli, RunWritesEveryFormatAndStats) {
    const fs::path scene = writeScene("formats", smallScene());
    const fs::path out = scratch("formats_out");
    const Result r = run(kTide + " run " + scene.string() + " --out " + out.string() + " --format vtu,ply,csv,obj");
    ASSERT_EQ(r.exit, 0) << r.output;
    // 0.1 s at 20 fps: frames 0..2, one plain progress line each (not a terminal here).
    for (int f = 0; f <= 2; ++f)
        for (const char* ext : {"vtu", "ply", "csv", "obj"}) {
            char name[32];
            std::snprintf(name, sizeof name, "frame_%05d.%s", f, ext);
            EXPECT_TRUE(fs::exists(out / name)) << name;
        }
    EXPECT_FALSE(fs::exists(out / "frame_00003.vtu"));
    EXPECT_NE(r.output.find("frame 2/2"), std::string::npos) << r.output;

    std::ifstream csv(out / "frame_00002.csv");
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line, "x,y,z,vx,vy,vz,density,pressure,material");
    int rows = 0;
    while (std::getline(csv, line)) {
        double v[9];
        ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", v, v + 1, v + 2, v + 3, v + 4, v + 5,
                              v + 6, v + 7, v + 8), 9) << line;
        EXPECT_GT(v[6], 500.0);   // density
        EXPECT_LE(v[1], 0.2);     // inside the box
        ++rows;
    }
    EXPECT_EQ(rows, 250);

    std::ifstream ply(out / "frame_00002.ply", std::ios::binary);
    std::string header;
    while (std::getline(ply, line) && line != "end_header") header += line + "\n";
    EXPECT_EQ(header.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u) << header;
    EXPECT_NE(header.find("element vertex 250\n"), std::string::npos) << header;

    // The surface mesh: one object named after the material, read by meshio as triangles
    // that enclose about the water's volume (250 particles of 2 cm: 2e-3 m³, less the rounded
    // edges' ~7 %; measured 1.95e-3).
    std::ifstream obj(out / "frame_00002.obj");
    std::string objects;
    while (std::getline(obj, line))
        if (line.rfind("o ", 0) == 0) objects += line + "\n";
    EXPECT_EQ(objects, "o water\n");
    const std::string checkObj = "/usr/bin/python3 -c \""
        "import meshio, numpy, sys\n"
        "m = meshio.read(sys.argv[1])\n"
        "t = m.cells_dict['triangle']\n"
        "p = m.points[t]\n"
        "v = numpy.einsum('ij,ij->i', p[:, 0], numpy.cross(p[:, 1], p[:, 2])).sum() / 6\n"
        "assert len(t) > 100 and 1.7e-3 < v < 2.1e-3, (len(t), v)\n"
        "print('obj ok', len(t), v)\" " + (out / "frame_00002.obj").string();
    const Result pyObj = run(checkObj);
    EXPECT_EQ(pyObj.exit, 0) << pyObj.output;

    // The VTU frames and the PVD series load in a real reader (Debian's python3-meshio).
    const std::string check = "/usr/bin/python3 -c \""
        "import meshio, xml.etree.ElementTree as ET, os, sys\n"
        "d = sys.argv[1]\n"
        "sets = ET.parse(os.path.join(d, 'frames.pvd')).getroot().find('Collection').findall('DataSet')\n"
        "assert [round(float(s.get('timestep')), 6) for s in sets] == [0.0, 0.05, 0.1], sets\n"
        "for s in sets:\n"
        "    m = meshio.read(os.path.join(d, s.get('file')))\n"
        "    assert m.points.shape == (250, 3), m.points.shape\n"
        "    assert set(['velocity', 'density', 'pressure', 'material']) <= set(m.point_data), m.point_data.keys()\n"
        "    assert (m.point_data['density'] > 500).all()\n"
        "print('vtu ok')\" " + out.string();
    const Result py = run(check);
    EXPECT_EQ(py.exit, 0) << py.output;

    const std::string stats = expectFullStats(out);
    EXPECT_NE(stats.find("\"sim_time\": 0.1"), std::string::npos) << stats;
}

// settle.time: the pre-roll runs before frame 0, which then shows the water at rest (the block
// was thrown at 0.3 m/s; without the pre-roll frame 0 holds that velocity).
TEST(Cli, SettleRunsBeforeTheFirstFrame) {
    std::string text = smallScene(R"(, "settle": {"time": 0.1})");
    text = replace(text, "\"material\": \"water\"}]", "\"material\": \"water\", \"velocity\": [0.3, 0, 0]}]");
    text = replace(text, "\"formats\": [\"vtu\"]", "\"formats\": [\"csv\"]");
    const fs::path out = scratch("settle_out");
    const Result r = run(kTide + " run " + writeScene("settle", text).string() + " --out " + out.string());
    ASSERT_EQ(r.exit, 0) << r.output;
    EXPECT_NE(r.output.find("settled for 0.1 s"), std::string::npos) << r.output;
    std::ifstream csv(out / "frame_00000.csv");
    std::string line;
    std::getline(csv, line);
    int rows = 0;
    while (std::getline(csv, line)) {
        double v[9];
        ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", v, v + 1, v + 2, v + 3, v + 4, v + 5,
                              v + 6, v + 7, v + 8), 9) << line;
        EXPECT_EQ(v[3], 0.0) << line;
        ++rows;
    }
    EXPECT_EQ(rows, 250);
    const std::string stats = expectFullStats(out);
    EXPECT_NE(stats.find("\"sim_time\": 0.1"), std::string::npos) << stats;  // the pre-roll is not run time
}

TEST(Cli, RefusesAnotherRunsFolderUnlessForced) {
    const fs::path scene = writeScene("force", smallScene());
    const fs::path out = scratch("force_out");
    ASSERT_EQ(run(kTide + " run " + scene.string() + " --quiet --end-time 0.05 --out " + out.string()).exit, 0);
    const auto before = fs::last_write_time(out / "frame_00001.vtu");
    const Result refused = run(kTide + " run " + scene.string() + " --quiet --out " + out.string());
    EXPECT_EQ(refused.exit, 2);
    EXPECT_NE(refused.output.find("--force"), std::string::npos) << refused.output;
    EXPECT_EQ(fs::last_write_time(out / "frame_00001.vtu"), before);  // nothing touched
    std::ofstream(out / "notes.txt") << "mine";
    std::ofstream(out / "gauges.csv") << "time,old\n0,0.1\n";  // a wave run's, this scene has no gauges
    EXPECT_EQ(run(kTide + " run " + scene.string() + " --quiet --force --out " + out.string()).exit, 0);
    EXPECT_TRUE(fs::exists(out / "notes.txt"));  // --force replaces only tide's own files
    EXPECT_FALSE(fs::exists(out / "gauges.csv"));  // no stale measurements beside the new frames
    EXPECT_TRUE(fs::exists(out / "frame_00002.vtu"));
}

TEST(Cli, AFolderWithOnlyGaugesHoldsAnotherRun) {
    const fs::path out = scratch("gauges_only_out");
    fs::create_directories(out);
    std::ofstream(out / "gauges.csv") << "time,g1\n0,0.3\n";
    const Result refused = run(kTide + " run " + writeScene("gauges_only", smallScene()).string() + " --quiet --out " + out.string());
    EXPECT_EQ(refused.exit, 2);
    EXPECT_NE(refused.output.find("holds another run"), std::string::npos) << refused.output;
}

TEST(Cli, ShowsAProgressBarOnATerminal) {
    const fs::path scene = writeScene("tty", smallScene());
    const fs::path out = scratch("tty_out");
    // `script` gives the command a pseudo-terminal.
    const Result r = run("script -qec '" + kTide + " run " + scene.string() + " --out " + out.string() + "' /dev/null");
    ASSERT_EQ(r.exit, 0) << r.output;
    EXPECT_NE(r.output.find("\r["), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("ETA"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("particle-steps/s"), std::string::npos) << r.output;
}

TEST(Cli, ShippedDamBreakShowsProgressAndFullStats) {
    const fs::path out = scratch("dam_break_out");
    const std::string scene = std::string(TIDE_SCENES_DIR) + "/dam_break.json";
    const Result r = run("script -qec '" + kTide + " run " + scene + " --end-time 0.04 --out " + out.string() +
                         "' /dev/null");
    ASSERT_EQ(r.exit, 0) << r.output;
    EXPECT_NE(r.output.find("\r["), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("frame 1/1"), std::string::npos) << r.output;
    const std::string stats = expectFullStats(out);
}

TEST(Cli, OpenMeshExitsTwoNamingTheFieldAndFile) {
    // A cube without its top: not a solid. The mesh path is relative to the scene file.
    const fs::path scene = writeScene("open_mesh", smallScene(R"(, "obstacles": [{"type": "mesh", "file": "lidless.obj"}])"));
    std::ofstream(scene.parent_path() / "lidless.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                                          "f 1 4 3 2\nf 1 2 6 5\nf 3 4 8 7\nf 1 5 8 4\nf 2 3 7 6\n";
    for (const std::string& command : {" validate " + scene.string(), " run " + scene.string() + " --out " + scratch("open_mesh_out").string()}) {
        const Result r = run(kTide + command);
        EXPECT_EQ(r.exit, 2) << command << r.output;
        EXPECT_NE(r.output.find("obstacles[0].file: lidless.obj"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("not closed"), std::string::npos) << r.output;
    }
}

TEST(Cli, ShippedObstacleDamBreakLosesNoParticle) {
    const fs::path out = scratch("dam_break_obstacles_out");
    const std::string scene = std::string(TIDE_SCENES_DIR) + "/dam_break_obstacles.json";
    const Result validate = run(kTide + " validate " + scene);
    EXPECT_EQ(validate.exit, 0) << validate.output;
    EXPECT_NE(validate.output.find("mesh of 320 triangles"), std::string::npos) << validate.output;
    const Result r = run(kTide + " run " + scene + " --quiet --end-time 0.1 --out " + out.string());
    ASSERT_EQ(r.exit, 0) << r.output;
    expectFullStats(out);  // particles_lost 0 at every frame
}

TEST(Cli, ShippedStirredTankListsItsMotionAndLosesNoParticle) {
    const fs::path out = scratch("stirred_tank_out");
    const std::string scene = std::string(TIDE_SCENES_DIR) + "/stirred_tank.json";
    const Result validate = run(kTide + " validate " + scene);
    EXPECT_EQ(validate.exit, 0) << validate.output;
    EXPECT_NE(validate.output.find("moving   obstacles[0]: rotation about [0, 1, 0] through [0.2, 0, 0.2] m, 4 rad/s"),
              std::string::npos) << validate.output;
    const Result r = run(kTide + " run " + scene + " --quiet --end-time 0.1 --out " + out.string());
    ASSERT_EQ(r.exit, 0) << r.output;
    expectFullStats(out);  // particles_lost 0 at every frame
}

// A pressure solve capped short of its tolerance leaves the water compressed: the run goes on,
// says so on stderr once and counts those steps in stats.json.
TEST(Cli, PressureSolvesThatStopShortAreReportedAndCounted) {
    const fs::path out = scratch("unconverged_out");
    const std::string capped = smallScene(R"(, "solver": {"momentum": 0, "min_iterations": 0, "max_iterations": 1})");
    const Result r = run(kTide + " run " + writeScene("unconverged", capped).string() + " --quiet --out " + out.string());
    ASSERT_EQ(r.exit, 0) << r.output;
    EXPECT_NE(r.output.find("warning: the pressure solve stopped short of its density tolerance in "), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("(solver.max_iterations 1)"), std::string::npos) << r.output;
    const std::string stats = expectFullStats(out);
    EXPECT_EQ(stats.find("\"pressure_unconverged_steps\": 0"), std::string::npos) << stats;

    const fs::path plainOut = scratch("converged_out");
    const Result plain = run(kTide + " run " + writeScene("converged", smallScene()).string() + " --quiet --out " +
                             plainOut.string());
    ASSERT_EQ(plain.exit, 0) << plain.output;
    EXPECT_EQ(plain.output.find("warning"), std::string::npos) << plain.output;
    EXPECT_NE(expectFullStats(plainOut).find("\"pressure_unconverged_steps\": 0"), std::string::npos);
}

TEST(Cli, DivergenceExitsOneAndKeepsEarlierFrames) {
    // A time step forced 40× beyond the viscous stability limit: the fluid collapses.
    const std::string exploding = replace(smallScene(R"(, "solver": {"min_dt": 0.01, "max_dt": 0.01})"),
                                          "\"viscosity\": 0.001", "\"viscosity\": 1000000");
    const fs::path out = scratch("diverge_out");
    const Result r = run(kTide + " run " + writeScene("diverge", exploding).string() + " --quiet --out " + out.string());
    EXPECT_EQ(r.exit, 1) << r.output;
    EXPECT_NE(r.output.find("diverged"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("particle"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(out / "frame_00000.vtu"));
}

TEST(Cli, WaveGaugesAndProbesAreWrittenAsCsv) {
    const std::string scene = R"({
  "name": "tiny flume", "domain": {"min": [0, 0, 0], "max": [1.2, 0.3, 0.12], "periodic": [false, false, true]},
  "particle_spacing": 0.03, "end_time": 0.2,
  "materials": [{"name": "water", "density": 1000}],
  "wavemaker": {"type": "piston", "x": 0.1, "depth": 0.15, "wave_height": 0.02, "period": 0.8, "ramp_time": 0.4},
  "damping": {"x_start": 0.9, "x_end": 1.2},
  "gauges": [{"name": "near", "x": 0.4, "z": 0.06}, {"name": "far", "x": 0.8}],
  "probes": [{"name": "bed", "position": [0.5, 0.03, 0.06]}],
  "blocks": [{"min": [0.1, 0, 0], "max": [1.2, 0.15, 0.12]}],
  "output": {"fps": 10, "formats": ["csv"]}
}
)";
    const fs::path out = scratch("waves_out");
    const Result r = run(kTide + " run " + writeScene("waves", scene).string() + " --quiet --force --out " + out.string());
    ASSERT_EQ(r.exit, 0) << r.output;
    std::ifstream gauges(out / "gauges.csv"), probes(out / "probes.csv");
    std::string line;
    std::getline(gauges, line);
    EXPECT_EQ(line, "time,near,far");
    int rows = 0;
    while (std::getline(gauges, line)) {
        ++rows;
        const double near = std::stod(line.substr(line.find(',') + 1));
        EXPECT_NEAR(near, 0.15, 0.02) << line;  // the still level, give or take the first wave
    }
    EXPECT_EQ(rows, 3);  // t = 0, 0.1, 0.2: one row per frame
    std::getline(probes, line);
    EXPECT_EQ(line, "time,bed_p,bed_vx,bed_vy,bed_vz");
    rows = 0;
    while (std::getline(probes, line)) ++rows;
    EXPECT_EQ(rows, 3);
    expectFullStats(out);
}

// forces.csv (a contract): time, then each obstacle's force and moment under its name, then
// the wave maker's and the walls'; one row per frame, each the mean load over its frame.
TEST(Cli, LoadsOnObstaclesWallsAndPaddlesAreWrittenAsForcesCsv) {
    const std::string scene = R"({
  "name": "loads", "domain": {"min": [0, 0, 0], "max": [0.8, 0.3, 0.12], "periodic": [false, false, true]},
  "particle_spacing": 0.03, "end_time": 0.2,
  "materials": [{"name": "water", "density": 1000}],
  "wavemaker": {"type": "piston", "x": 0.1, "depth": 0.15, "wave_height": 0.02, "period": 0.6, "ramp_time": 0.4},
  "obstacles": [{"type": "box", "min": [0.5, 0, 0], "max": [0.56, 0.09, 0.12], "name": "step"},
                {"type": "cylinder", "center": [0.7, 0.15, 0.06], "axis": [0, 1, 0], "radius": 0.03, "length": 0.3}],
  "blocks": [{"min": [0.1, 0, 0], "max": [0.8, 0.15, 0.12]}],
  "output": {"fps": 10, "formats": ["csv"]}
}
)";
    const fs::path out = scratch("loads_out");
    const Result r = run(kTide + " run " + writeScene("loads", scene).string() + " --quiet --force --out " + out.string());
    ASSERT_EQ(r.exit, 0) << r.output;
    std::ifstream forces(out / "forces.csv");
    std::string header;
    std::getline(forces, header);
    EXPECT_EQ(header.rfind("time,step_fx,step_fy,step_fz,step_mx,step_my,step_mz,obstacle1_fx,obstacle1_fy,obstacle1_fz,"
                           "obstacle1_mx,obstacle1_my,obstacle1_mz,wavemaker0_fx,",
                           0),
              0u)
        << header;
    // Walls across z are periodic: none there.
    EXPECT_NE(header.find(",wall_ymin_fy,"), std::string::npos) << header;
    EXPECT_EQ(header.find("wall_zmin"), std::string::npos) << header;
    std::vector<std::vector<double>> rows;
    for (std::string line; std::getline(forces, line);) {
        std::vector<double> row;
        std::stringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
        rows.push_back(row);
    }
    ASSERT_EQ(rows.size(), 3u);  // t = 0, 0.1, 0.2
    const std::size_t columns = static_cast<std::size_t>(std::count(header.begin(), header.end(), ',')) + 1;
    for (const auto& row : rows) EXPECT_EQ(row.size(), columns);
    // Water 0.15 m deep pushes the step (0.09 m tall) down and the floor carries most of the weight.
    EXPECT_LT(rows[2][2], 0.0);
    EXPECT_NEAR(rows[1][0], 0.1, 1e-12);
}

// bodies.csv (a contract): time, then each dynamic body's centre of mass and orientation.
TEST(Cli, FloatingBodiesAreWrittenAsBodiesCsv) {
    const fs::path out = scratch("bodies_out");
    const fs::path scene = writeScene("bodies", smallScene(R"(, "obstacles": [{"type": "box", "name": "crate", "min": [0.12, 0.12, 0.06],
        "max": [0.18, 0.18, 0.14], "dynamic": true, "density": 2000, "constraint": {"free": ["y"]}}])"));
    const Result r = run(kTide + " run " + scene.string() + " --quiet --force --out " + out.string());
    ASSERT_EQ(r.exit, 0) << r.output;
    std::ifstream bodies(out / "bodies.csv");
    std::string line;
    std::getline(bodies, line);
    EXPECT_EQ(line.rfind("time,crate_x,crate_y,crate_z,crate_qw,crate_qx,crate_qy,crate_qz,crate_vx,", 0), 0u) << line;
    std::vector<std::string> rows;
    while (std::getline(bodies, line)) rows.push_back(line);
    ASSERT_EQ(rows.size(), 3u);  // t = 0, 0.05, 0.1
    // Twice as dense as water, dropped in the air: it falls, ½ g t² = 4.9 cm in 0.1 s.
    const auto y = [](const std::string& row) {
        std::stringstream cells(row);
        std::string cell;
        for (int k = 0; k < 3; ++k) std::getline(cells, cell, ',');
        return std::stod(cell);
    };
    EXPECT_NEAR(y(rows[0]) - y(rows[2]), 0.5 * 9.81 * 0.01, 0.005);
}

// A mooring line's tension is a bodies.csv column, `<line>_tension`: a crate hanging in the air
// from a stiff line carries its weight in it.
TEST(Cli, MooringTensionsAreWrittenToBodiesCsv) {
    const fs::path out = scratch("moorings_out");
    // 0.06 × 0.06 × 0.08 m at 500 kg/m³: 0.144 kg, 1.413 N; the line (10⁴ N/m, damped) stretches 0.14 mm.
    const fs::path scene = writeScene("moorings", smallScene(R"(, "obstacles": [{"type": "box", "name": "crate", "min": [0.12, 0.12, 0.06],
        "max": [0.18, 0.18, 0.14], "dynamic": true, "density": 500, "constraint": {"free": ["y"]},
        "moorings": [{"name": "line", "fairlead": [0.15, 0.18, 0.1], "anchor": [0.15, 0.19, 0.1], "length": 0.01,
                      "stiffness": 10000, "damping": 20}]}])"));
    const Result r = run(kTide + " run " + scene.string() + " --quiet --force --out " + out.string());
    ASSERT_EQ(r.exit, 0) << r.output;
    std::ifstream bodies(out / "bodies.csv");
    std::string line;
    std::getline(bodies, line);
    ASSERT_GE(line.size(), std::string(",line_tension").size());
    EXPECT_EQ(line.substr(line.size() - std::string(",line_tension").size()), ",line_tension") << line;
    std::string last;
    while (std::getline(bodies, line)) last = line;
    const double tension = std::stod(last.substr(last.rfind(',') + 1));
    EXPECT_NEAR(tension, 500.0 * 0.06 * 0.06 * 0.08 * 9.81, 0.01 * 1.413) << last;
}

TEST(Cli, ShippedScenesValidate) {
    for (const auto& entry : fs::directory_iterator(TIDE_SCENES_DIR)) {
        if (entry.path().extension() != ".json" || entry.path().filename() == "scene.schema.json") continue;
        const Result r = run(kTide + " validate " + entry.path().string());
        EXPECT_EQ(r.exit, 0) << entry.path() << "\n" << r.output;
    }
}

TEST(Cli, ShippedScenesMatchTheSchema) {
    // Debian's python3-jsonschema checks scene.schema.json itself and every shipped scene.
    const std::string check = "/usr/bin/python3 -c \""
        "import glob, json, os, sys, jsonschema\n"
        "d = sys.argv[1]\n"
        "schema = json.load(open(os.path.join(d, 'scene.schema.json')))\n"
        "jsonschema.Draft202012Validator.check_schema(schema)\n"
        "v = jsonschema.Draft202012Validator(schema)\n"
        "bad = [(f, e.message) for f in sorted(glob.glob(os.path.join(d, '*.json'))) if not f.endswith('schema.json')\n"
        "       for e in v.iter_errors(json.load(open(f)))]\n"
        "assert not bad, bad\n"
        "print('schema ok')\" " + std::string(TIDE_SCENES_DIR);
    const Result r = run(check);
    EXPECT_EQ(r.exit, 0) << r.output;
}

}  // namespace
