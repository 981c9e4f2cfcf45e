#pragma once
// The `tide` command line: its subcommands and their options.

#include <optional>
#include <string>
#include <vector>

namespace tide::io {
struct Scene;
}
namespace tide::comm {
class Communicator;
}

namespace tide::cli {

/// Exit codes: 0 success, 1 a run that failed (e.g. diverged), 2 bad input.
inline constexpr int kExitOk = 0;
inline constexpr int kExitRunFailed = 1;
inline constexpr int kExitBadInput = 2;

struct RunOptions {
    std::string scene;
    std::string out;                      ///< empty: out/<scene file stem>
    std::optional<double> endTime;
    int threads = 0;
    std::vector<std::string> formats;     ///< empty: the scene's
    std::string solver;                   ///< empty: the scene's
    bool force = false;
    bool quiet = false;
    int checkpointEvery = 0;              ///< frames between checkpoints; 0: none
    std::string resume;                   ///< output folder of a stopped run to continue; empty: a new run
    bool gather = false;                  ///< split run: VTU frames gathered into one file, not a piece per rank
    int rebalanceEvery = 0;               ///< split run: re-cut the ranks' boxes every N steps; 0: when the load drifts
    double rebalanceAbove = 1.2;          ///< split run: re-cut when the busiest rank owns this times the mean
};

struct RenderOptions {
    std::string scene;
    std::string out;                      ///< empty: out/<scene file stem>_render
    int width = 960;
    int height = 540;
    std::string video;                    ///< empty: PNG frames only
    std::string mode = "surface";         ///< surface, particles
    std::string colorBy = "material";     ///< material, speed, density, pressure
    std::optional<double> endTime;
    int threads = 0;
    bool force = false;
    bool quiet = false;
};

/// With `comm`, the run split among its ranks (`mpirun -np N tide run`; every rank calls it).
int runCommand(const RunOptions& options, comm::Communicator* comm = nullptr);
int renderCommand(const RenderOptions& options);
/// Prints each problem of a bad scene on stderr, prefixed with the file unless it already is.
void reportSceneProblems(const std::string& file, const std::vector<std::string>& problems);
int validateCommand(const std::string& scene);
/// The scene's end time after --end-time (`fromFlag`) or a resumed run's: false, saying why on
/// stderr, when it reaches no frame after frame 0 or asks for more than io::kMaxFrames; true,
/// with a warning when it falls between frames (the run stops at the last frame before it).
bool checkEndTime(const io::Scene& scene, bool fromFlag, const std::string& file);

}  // namespace tide::cli
