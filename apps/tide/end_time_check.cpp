// The end time `tide run` and `tide render` simulate to, checked against the scene's frames.
#include <cstdio>
#include <string>

#include <tide/io/scene.hpp>

#include "commands.hpp"

namespace tide::cli {

bool checkEndTime(const io::Scene& scene, bool fromFlag, const std::string& file) {
    if (const std::string problem = io::endTimeProblem(scene); !problem.empty()) {
        if (fromFlag) std::fprintf(stderr, "--end-time: %s\n", problem.c_str());
        else std::fprintf(stderr, "%s: end_time: %s\n", file.c_str(), problem.c_str());
        return false;
    }
    if (const std::string between = io::endTimeBetweenFrames(scene); !between.empty())
        std::fprintf(stderr, "tide: warning: end time %s\n", between.c_str());
    return true;
}

}  // namespace tide::cli
