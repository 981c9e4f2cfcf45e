// Whole-simulation benchmarks: issue 8's dam break (scenes/bench_dam_break.json) at ~50k,
// ~200k and ~800k fluid particles for dfsph and wcsph, SPlisHSPlasH's own DamBreakModel scene
// (scenes/bench_dam_break_model.json), and the seed's jet demo. Each scenario
// runs in its own process (so its peak memory is its own), prints one table row, and the rows
// are appended to bench/results/<cpu model>.csv with the git revision.
//
//   tide_scenarios [--seconds S] [--threads T] [--only NAME] [--solver SOLVER] [--csv FILE]
//
// S simulated seconds per scenario (default 0.1; SPlisHSPlasH's figures are for 1 s).
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <tide/io/exporters.hpp>
#include <tide/io/scene.hpp>
#include <tide/world.hpp>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Scenario {
    std::string name;
    std::string scene;        ///< relative to the source tree
    std::string solver;       ///< empty: the scene's
    float spacing = 0.0f;     ///< m; 0: the scene's
    float soundSpeed = 0.0f;  ///< m/s; 0: the solver's default
    float maxDt = 0.0f;       ///< s; 0: the scene's
};

/// SPlisHSPlasH's spacings (2 × particle radius 0.0132, 0.0084) give 37³ and 59³ particles
/// in the 1 m³ block; 93³ ≈ 800k. Its WCSPH runs stiffness 50000 (Tait, γ = 7: c = √(7·50000/1000)
/// = 18.7 m/s) at a fixed 0.5 ms.
const std::vector<Scenario> kScenarios = {
    {"dam_break_50k", "scenes/bench_dam_break.json", "dfsph", 0.0264f, 0.0f, 0.0f},
    {"dam_break_200k", "scenes/bench_dam_break.json", "dfsph", 0.0168f, 0.0f, 0.0f},
    {"dam_break_800k", "scenes/bench_dam_break.json", "dfsph", 0.01075f, 0.0f, 0.0f},
    {"dam_break_50k", "scenes/bench_dam_break.json", "wcsph", 0.0264f, 18.7f, 5e-4f},
    {"dam_break_200k", "scenes/bench_dam_break.json", "wcsph", 0.0168f, 18.7f, 5e-4f},
    // SPlisHSPlasH's DamBreakModel (viscous, block off the walls): its jets die out, so its
    // steps are longer than the water corner's (docs/performance.md § The time step).
    {"dam_break_model_50k", "scenes/bench_dam_break_model.json", "dfsph", 0.0f, 0.0f, 0.0f},
    {"dam_break_model_200k", "scenes/bench_dam_break_model.json", "dfsph", 0.0168f, 0.0f, 0.0f},
    {"jets", "scenes/jets.json", "", 0.0f, 0.0f, 0.0f},
    // The seed's four-material demo (demo 4: heavy oil, light oil, light water and water layer
    // by density), 20,000 particles from the start: issue 8's interactive target.
    {"four_materials", "scenes/many_materials.json", "", 0.0f, 0.0f, 0.0f},
    // The default scene (make demo): a paddle's waves breaking on a 1:10 slope, 1.5 cm, one
    // slice 4 spacings wide with periodic sides.
    {"beach", "scenes/beach.json", "", 0.0f, 0.0f, 0.0f},
};

std::string shellOutput(const std::string& command) {
    std::string out;
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[4096];
        while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
        pclose(pipe);
    }
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
    return out;
}

/// Runs one scenario in this process and prints its figures as one JSON line.
int runOne(const Scenario& s, double seconds, int threads) try {
    tide::io::Scene scene = tide::io::loadScene(fs::path(TIDE_SOURCE_DIR) / s.scene);
    if (!s.solver.empty()) scene.world.solver.method = s.solver;
    if (s.spacing > 0.0f) {
        scene.world.particleSpacing = s.spacing;
        scene.world.capacity = tide::WorldDef{}.capacity;  // the parser sized it for the scene's spacing
    }
    if (s.soundSpeed > 0.0f) scene.world.solver.soundSpeed = s.soundSpeed;
    if (s.maxDt > 0.0f) scene.world.solver.maxDt = s.maxDt;
    scene.world.threads = threads;
    tide::World world = tide::io::buildWorld(scene);
    const fs::path frames = fs::temp_directory_path() / ("tide_bench_" + std::to_string(getpid()));
    fs::create_directories(frames);
    double outputSeconds = 0.0;
    std::uint64_t particleSteps = 0;
    int frame = 0;
    const auto start = std::chrono::steady_clock::now();
    const double frameLength = 1.0 / scene.output.fps;
    while (world.time() < seconds - 1e-9) {
        world.advance(std::min(frameLength, seconds - world.time()), [&] { particleSteps += world.particles().size(); });
        const auto before = std::chrono::steady_clock::now();
        tide::io::writeFrame(frames / ("frame_" + std::to_string(frame++) + ".vtu"), tide::io::Format::Vtu,
                             world.particles());
        outputSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fs::remove_all(frames);
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const tide::WorldStats& st = world.stats();
    const auto& ph = st.phaseSeconds;
    const double perStep = 1e9 / static_cast<double>(std::max<std::uint64_t>(particleSteps, 1));
    const double n = world.particles().size();
    const json row = {
        {"scene", s.name},
        {"solver", scene.world.solver.method},
        {"particles", n},
        {"threads", world.threads()},
        {"sim_seconds", world.time()},
        {"wall_seconds", wall},
        {"particle_steps_per_s", static_cast<double>(particleSteps) / wall},
        {"sim_s_per_wall_s", world.time() / wall},
        {"mean_dt_ms", 1e3 * st.dtSum / static_cast<double>(std::max<std::uint64_t>(st.steps, 1))},
        {"iterations_per_step",
         static_cast<double>(st.pressureIterationsSum) / static_cast<double>(std::max<std::uint64_t>(st.steps, 1))},
        {"max_mean_compression", st.maxMeanCompression},
        {"ns_neighbors", ph.neighborSearch * perStep},
        {"ns_density", ph.density * perStep},
        {"ns_pressure", ph.pressureSolve * perStep},
        {"ns_forces", ph.nonPressureForces * perStep},
        {"ns_integration", ph.integration * perStep},
        {"ns_output", outputSeconds * perStep},
        {"peak_bytes_per_particle", static_cast<double>(usage.ru_maxrss) * 1024.0 / std::max(n, 1.0)},
    };
    std::cout << row.dump() << std::endl;
    return 0;
} catch (const std::exception& e) {
    std::cout << "error: " << e.what() << std::endl;
    return 1;
}

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) {
            std::string model = line.substr(line.find(':') + 2);
            for (char& c : model)
                if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
            return model;
        }
    return "unknown_cpu";
}

const std::vector<std::string> kColumns = {"scene", "solver", "particles", "threads", "particle_steps_per_s",
                                           "sim_s_per_wall_s", "mean_dt_ms", "iterations_per_step",
                                           "max_mean_compression", "ns_neighbors", "ns_density", "ns_pressure",
                                           "ns_forces", "ns_integration", "ns_output", "peak_bytes_per_particle"};

std::string cell(const json& v) {
    if (v.is_string()) return v.get<std::string>();
    char buffer[32];
    const double d = v.get<double>();
    std::snprintf(buffer, sizeof buffer, d >= 100.0 || d == static_cast<long long>(d) ? "%.0f" : "%.4g", d);
    return buffer;
}

/// Table column width: the header's, at least 8.
int width(const std::string& column) { return static_cast<int>(std::max<std::size_t>(column.size(), 8)); }

}  // namespace

int main(int argc, char** argv) {
    double seconds = 0.1;
    int threads = 0;
    std::string only, solver, csv;
    int one = -1;
    CLI::App app{"Whole-simulation benchmarks: one row per scenario, appended to bench/results/<cpu model>.csv"};
    app.add_option("--seconds", seconds, "simulated seconds per scenario")->capture_default_str()->check(CLI::PositiveNumber);
    app.add_option("--threads", threads, "worker threads (0: all cores)")->check(CLI::NonNegativeNumber);
    app.add_option("--only", only, "scenarios whose name contains NAME, or whose solver is NAME");
    app.add_option("--solver", solver, "only the dam breaks of this solver (the seed's demos run their scenes')")
        ->check(CLI::IsMember({"dfsph", "wcsph"}));
    app.add_option("--csv", csv, "results file (default: bench/results/<cpu model>.csv)");
    app.add_option("--one", one, "run scenario K in this process and print its row as JSON (internal)")
        ->check(CLI::Range(0, static_cast<int>(kScenarios.size()) - 1))
        ->group("");
    CLI11_PARSE(app, argc, argv);
    if (one >= 0) return runOne(kScenarios.at(static_cast<std::size_t>(one)), seconds, threads);

    if (csv.empty()) csv = std::string(TIDE_SOURCE_DIR) + "/bench/results/" + cpuModel() + ".csv";
    // The checkout's commit, "-dirty" when its tracked files other than the results differ from
    // it (the binary may hold work not committed yet; a binary built from another tree is not
    // detectable here). The rows this runner appends to bench/results/ do not make it dirty.
    const std::string git = "git -C " + std::string(TIDE_SOURCE_DIR);
    const std::string head = shellOutput(git + " rev-parse --short=7 HEAD 2>/dev/null");
    const std::string revision =
        head.empty() ? "unknown"
                     : head + shellOutput(git + " diff --quiet HEAD -- . ':(exclude)bench/results' 2>/dev/null || echo -dirty");
    const bool fresh = !fs::exists(csv);
    fs::create_directories(fs::path(csv).parent_path());
    std::ofstream out(csv, std::ios::app);
    if (fresh) {
        out << "date,revision,seconds";
        for (const auto& c : kColumns) out << "," << c;
        out << "\n";
    }
    for (const auto& c : kColumns) std::printf("%*s ", width(c), c.c_str());
    std::printf("\n");
    const std::string date = shellOutput("date -u +%Y-%m-%dT%H:%M:%SZ");
    const std::string self = fs::read_symlink("/proc/self/exe").string();  // the shell's own otherwise
    int failures = 0;
    for (std::size_t k = 0; k < kScenarios.size(); ++k) {
        if (!only.empty() && kScenarios[k].name.find(only) == std::string::npos && kScenarios[k].solver != only) continue;
        if (!solver.empty() && kScenarios[k].solver != solver) continue;
        const std::string line = shellOutput(self + " --one " + std::to_string(k) + " --seconds " +
                                             std::to_string(seconds) + " --threads " + std::to_string(threads));
        json row;
        try {
            row = json::parse(line);
        } catch (const std::exception&) {
            std::fprintf(stderr, "%s (%s): failed: %s\n", kScenarios[k].name.c_str(), kScenarios[k].solver.c_str(), line.c_str());
            ++failures;
            continue;
        }
        out << date << "," << revision << "," << seconds;
        for (const auto& c : kColumns) {
            std::printf("%*s ", width(c), cell(row[c]).c_str());
            out << "," << cell(row[c]);
        }
        std::printf("\n");
        std::fflush(stdout);
        out << "\n";
        out.flush();
    }
    std::printf("(ns per particle-step by phase; rows appended to %s)\n", csv.c_str());
    return failures == 0 ? 0 : 1;
}
