// `tide run` survives being killed and refuses damaged checkpoints: SIGKILL mid-step and mid-write
// (on events of the run, never on a clock) leaves only complete frames and --resume ends bit-identical to a clean run; flipped or cut
// checkpoint bytes exit 2 touching nothing; an unstable scene stops naming step and particle.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "cli_support.hpp"

extern char** environ;

namespace {

using namespace tide::testing;

const std::string kTide = TIDE_BIN;

/// ~1700 particles (a dam break, an emitter, a gauge): 8 frames in a few seconds.
const char* kScene = R"({
  "name": "recovery", "domain": {"min": [0, 0, 0], "max": [0.9, 0.5, 0.3]},
  "particle_spacing": 0.025, "end_time": 0.4,
  "solver": {"method": "dfsph"},
  "materials": [{"name": "water", "density": 1000}],
  "blocks": [{"min": [0, 0, 0], "max": [0.3, 0.3, 0.3], "material": "water"}],
  "emitters": [{"min": [0.6, 0.35, 0.1], "max": [0.6, 0.4, 0.2], "velocity": [-1, 0, 0], "material": "water", "end": 0.3}],
  "gauges": [{"name": "g", "x": 0.5, "z": 0.15}],
  "output": {"fps": 20, "formats": ["vtu", "csv"]}
}
)";

std::string slurp(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Every visible file of a folder (name → bytes); temporaries start with a dot.
std::map<std::string, std::string> visibleFiles(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name[0] != '.') files[name] = slurp(entry.path());
    }
    return files;
}

/// Starts `tide args...` and returns its pid (output discarded).
pid_t spawnTide(const std::vector<std::string>& args) {
    std::vector<std::string> all{kTide};
    all.insert(all.end(), args.begin(), args.end());
    all.emplace_back("--quiet");
    std::vector<char*> argv;
    for (std::string& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = -1;
    EXPECT_EQ(posix_spawn(&pid, kTide.c_str(), &actions, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    return pid;
}

/// A moment of a run to kill it at: when the file `name` appears in `dir` (the run renamed it
/// into place), or, for `prefix`, while a temporary file starting with it is being written.
struct KillEvent {
    std::string name;    ///< a finished file, e.g. checkpoint_00003.tidecp
    std::string prefix;  ///< a file being written, e.g. ".frame_00004" (empty: none)
};

/// Whether `event` has happened in `dir`.
bool happened(const fs::path& dir, const KillEvent& event) {
    std::error_code ec;
    if (fs::exists(dir / event.name, ec)) return true;
    if (event.prefix.empty()) return false;
    for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
        if (it->path().filename().string().rfind(event.prefix, 0) == 0) return true;
    return false;
}

/// Kills `pid` with SIGKILL as soon as `event` happens, unless the run ended first; returns
/// whether it was killed. The moment depends on what the run does, not on a clock: a loaded
/// machine slows the run and the watch alike. The watch polls without sleeping longer than a
/// millisecond, and each event leaves at least two frames of work after it, so the run cannot
/// end unseen.
bool killOn(pid_t pid, const fs::path& dir, const KillEvent& event) {
    int status = 0;
    while (!happened(dir, event)) {
        if (waitpid(pid, &status, WNOHANG) == pid) return false;
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    return WIFSIGNALED(status);
}

struct CleanRun {
    fs::path scene;
    std::map<std::string, std::string> files;
    double seconds;
};

const CleanRun& cleanRun() {
    static const CleanRun clean = [] {
        CleanRun c;
        c.scene = writeScene("recovery", kScene);
        const fs::path out = scratch("recovery_clean");
        const auto start = std::chrono::steady_clock::now();
        const Result r = run(kTide + " run " + c.scene.string() + " --quiet --threads 2 --out " + out.string());
        c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_EQ(r.exit, 0) << r.output;
        c.files = visibleFiles(out);
        c.files.erase("stats.json");  // holds the wall time
        return c;
    }();
    return clean;
}

TEST(RunRecovery, KilledAtRandomMomentsResumesToTheCleanRunsFiles) {
    const CleanRun& clean = cleanRun();
    ASSERT_EQ(clean.files.count("frame_00008.vtu"), 1u);
    const fs::path out = scratch("recovery_killed");
    // Four kills, each on an event of the run rather than after a delay: two just as a
    // checkpoint lands (the run is then stepping), two while a frame's temporary file is being
    // written (when that is too quick to catch, as the frame lands). Frames run to 8.
    const std::vector<KillEvent> events{{"checkpoint_00001.tidecp", ""},
                                        {"frame_00003.vtu", ".frame_00003"},
                                        {"checkpoint_00005.tidecp", ""},
                                        {"frame_00006.csv", ".frame_00006.csv"}};
    int kills = 0, sessions = 0, resumes = 0;
    bool finished = false;
    while (!finished && sessions < 12) {
        std::vector<std::string> args{"run", clean.scene.string(), "--threads", sessions % 2 ? "1" : "2"};
        const bool haveCheckpoint = fs::exists(out) && !visibleFiles(out).empty() &&
                                    [&] { for (const auto& f : visibleFiles(out)) if (f.first.rfind("checkpoint_", 0) == 0) return true; return false; }();
        if (haveCheckpoint) {
            args.insert(args.end(), {"--resume", out.string()});  // keeps checkpointing every frame
            ++resumes;
        } else {
            args.insert(args.end(), {"--out", out.string(), "--force", "--checkpoint-every", "1"});
        }
        ++sessions;
        const pid_t pid = spawnTide(args);
        ASSERT_GT(pid, 0);
        if (kills < static_cast<int>(events.size()) && killOn(pid, out, events[kills])) {
            ++kills;
            // Only complete frames: each one present is byte for byte the clean run's.
            for (const auto& [name, bytes] : visibleFiles(out)) {
                if (name.rfind("frame_0", 0) != 0) continue;
                ASSERT_EQ(clean.files.count(name), 1u) << name;
                EXPECT_TRUE(bytes == clean.files.at(name)) << name << " differs after kill " << kills;
            }
            continue;
        }
        int status = 0;
        waitpid(pid, &status, 0);
        ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "session " << sessions;
        finished = true;
    }
    ASSERT_TRUE(finished);
    std::printf("%d sessions, %d killed, %d resumed (clean run %.2f s)\n", sessions, kills, resumes, clean.seconds);
    EXPECT_EQ(kills, 4) << "a run ended before its kill event was seen";
    EXPECT_EQ(resumes, 4);
    std::map<std::string, std::string> resumed = visibleFiles(out);
    resumed.erase("stats.json");
    for (auto it = resumed.begin(); it != resumed.end();)  // the last two checkpoints stay
        it = it->first.rfind("checkpoint_", 0) == 0 ? resumed.erase(it) : std::next(it);
    ASSERT_EQ(resumed.size(), clean.files.size());
    for (const auto& [name, bytes] : clean.files) EXPECT_TRUE(resumed[name] == bytes) << name << " differs from the clean run";
    for (const auto& entry : fs::directory_iterator(out))
        EXPECT_NE(entry.path().filename().string()[0], '.') << "left behind: " << entry.path();
}

TEST(RunRecovery, DamagedCheckpointsAreRefusedTouchingNothing) {
    const CleanRun& clean = cleanRun();
    const fs::path out = scratch("recovery_damaged");
    const Result first = run(kTide + " run " + clean.scene.string() + " --quiet --end-time 0.2 --checkpoint-every 2 --out " +
                             out.string());
    ASSERT_EQ(first.exit, 0) << first.output;
    const fs::path newest = out / "checkpoint_00004.tidecp";
    ASSERT_TRUE(fs::exists(newest));
    EXPECT_TRUE(fs::exists(out / "checkpoint_00002.tidecp"));
    const std::string good = slurp(newest);
    for (const std::size_t at : {std::size_t{3}, std::size_t{30}, good.size() / 2, good.size() - 2}) {
        std::string bad = good;
        bad[at] = static_cast<char>(bad[at] ^ 0xFF);
        std::ofstream(newest, std::ios::binary | std::ios::trunc) << bad;
        const auto before = visibleFiles(out);
        const auto stamp = fs::last_write_time(out / "frame_00004.vtu");
        const Result r = run(kTide + " run " + clean.scene.string() + " --resume " + out.string());
        EXPECT_EQ(r.exit, 2) << "byte " << at << "\n" << r.output;
        EXPECT_NE(r.output.find("checkpoint_00004.tidecp"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("nothing was changed"), std::string::npos) << r.output;
        EXPECT_TRUE(visibleFiles(out) == before) << "byte " << at;
        EXPECT_EQ(fs::last_write_time(out / "frame_00004.vtu"), stamp);
    }
    std::ofstream(newest, std::ios::binary | std::ios::trunc) << good.substr(0, good.size() - 100);
    const Result cut = run(kTide + " run " + clean.scene.string() + " --resume " + out.string());
    EXPECT_EQ(cut.exit, 2) << cut.output;
    EXPECT_NE(cut.output.find("truncated"), std::string::npos) << cut.output;
    EXPECT_NE(cut.output.find("checkpoint_00002.tidecp remains"), std::string::npos) << cut.output;

    // Another scene's checkpoint, or none at all, are refused too.
    std::ofstream(newest, std::ios::binary | std::ios::trunc) << good;
    const fs::path other = writeScene("recovery_other", std::string(kScene).replace(std::string(kScene).find("\"x\": 0.5"), 8, "\"x\": 0.45"));
    const Result wrongScene = run(kTide + " run " + other.string() + " --resume " + out.string());
    EXPECT_EQ(wrongScene.exit, 2) << wrongScene.output;
    EXPECT_NE(wrongScene.output.find("another version of the scene"), std::string::npos) << wrongScene.output;
    const Result empty = run(kTide + " run " + clean.scene.string() + " --resume " + scratch("recovery_none").string());
    EXPECT_EQ(empty.exit, 2) << empty.output;
}

// `tide run SCENE --resume DIR` alone continues the run as it was started: its end time,
// formats and checkpoint interval, not the scene's.
TEST(RunRecovery, AResumedRunKeepsItsEndTimeFormatsAndInterval) {
    const CleanRun& clean = cleanRun();
    const fs::path out = scratch("recovery_flags");
    const Result first = run(kTide + " run " + clean.scene.string() +
                             " --quiet --end-time 0.2 --format csv --checkpoint-every 3 --out " + out.string());
    ASSERT_EQ(first.exit, 0) << first.output;
    fs::remove(out / "frame_00004.csv");  // as if killed after the checkpoint of frame 3
    fs::remove(out / "stats.json");
    const Result resumed = run(kTide + " run " + clean.scene.string() + " --quiet --resume " + out.string());
    ASSERT_EQ(resumed.exit, 0) << resumed.output;
    EXPECT_TRUE(fs::exists(out / "frame_00004.csv"));
    EXPECT_TRUE(fs::exists(out / "stats.json"));
    EXPECT_FALSE(fs::exists(out / "frame_00005.csv")) << "ran on to the scene's end time";
    EXPECT_FALSE(fs::exists(out / "frame_00004.vtu")) << "wrote the scene's format";
    EXPECT_TRUE(visibleFiles(out)["frame_00004.csv"] == clean.files.at("frame_00004.csv"));
    const Result other = run(kTide + " run " + clean.scene.string() + " --quiet --solver wcsph --resume " + out.string());
    EXPECT_EQ(other.exit, 2) << other.output;
    EXPECT_NE(other.output.find("written by the dfsph solver, --solver asks for wcsph"), std::string::npos) << other.output;
}

TEST(RunRecovery, AHugeTimeStepIsStoppedWithAPreciseMessage) {
    const fs::path scene = writeScene("unstable", R"({
  "name": "unstable", "domain": {"min": [0, 0, 0], "max": [0.4, 0.4, 0.4]},
  "particle_spacing": 0.02, "end_time": 1,
  "solver": {"method": "wcsph", "min_dt": 0.05, "max_dt": 0.05},
  "materials": [{"name": "water", "density": 1000}],
  "blocks": [{"min": [0, 0, 0], "max": [0.2, 0.2, 0.4], "material": "water"}],
  "output": {"fps": 40, "formats": ["csv"]}
}
)");
    const fs::path out = scratch("unstable_out");
    const Result r = run(kTide + " run " + scene.string() + " --quiet --checkpoint-every 1 --out " + out.string());
    EXPECT_EQ(r.exit, 1) << r.output;
    // "diverged at step 2 (t = 0.05 s, dt = 0.025 s): particle 28 (id 28) has a runaway speed of 8.8 m/s, above 6.4 m/s"
    for (const char* part : {"diverged at step 2 (t = 0.05 s, dt = 0.025 s): particle ", "runaway speed of ",
                             "above 6.4 m/s", "frames up to 1 and checkpoint_00001.tidecp are kept"})
        EXPECT_NE(r.output.find(part), std::string::npos) << part << "\n" << r.output;
    EXPECT_TRUE(fs::exists(out / "frame_00001.csv"));
    EXPECT_FALSE(fs::exists(out / "frame_00002.csv"));
    EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
}

}  // namespace
