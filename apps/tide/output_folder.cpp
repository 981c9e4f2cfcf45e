#include "output_folder.hpp"

#include <regex>
#include <string>
#include <vector>

namespace tide::cli {

namespace fs = std::filesystem;

namespace {
/// What `tide run` and `tide render` write: frames (and rendered images), the series file,
/// stats, gauges and probes, checkpoints. --force replaces these and nothing else.
bool isFinishedOutput(const std::string& name) {
    static const std::regex frame(R"(frame_\d{5,}\.(vtu|ply|csv|obj|png))");
    static const std::regex checkpoint(R"(checkpoint_\d{5,}\.tidecp)");
    return name == "frames.pvd" || name == "stats.json" || name == "gauges.csv" || name == "probes.csv" ||
           std::regex_match(name, frame) || std::regex_match(name, checkpoint);
}

/// The temporary name io::writeFileAtomically gives an output: `.NAME.tmp-PID-N`.
bool isTemporaryOutput(const std::string& name) {
    static const std::regex temporary(R"(\.(.+)\.tmp-\d+-\d+)");
    std::smatch m;
    return std::regex_match(name, m, temporary) && isFinishedOutput(m[1].str());
}
}  // namespace

bool isRunOutput(const fs::path& file) {
    const std::string name = file.filename().string();
    return isFinishedOutput(name) || isTemporaryOutput(name);
}

void removeStaleTemporaries(const fs::path& dir) {
    std::error_code ec;
    std::vector<fs::path> stale;
    for (const auto& entry : fs::directory_iterator(dir, ec))
        if (isTemporaryOutput(entry.path().filename().string())) stale.push_back(entry.path());
    for (const fs::path& file : stale) fs::remove(file, ec);
}

void prepareOutputFolder(const fs::path& dir, bool force) {
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw OutputFolderError("--out " + dir.string() + ": exists and is not a folder");
    fs::create_directories(dir, ec);
    if (ec) throw OutputFolderError("--out " + dir.string() + ": cannot create the folder (" + ec.message() + ")");
    std::vector<fs::path> ours;
    bool others = false;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (isRunOutput(entry.path())) ours.push_back(entry.path());
        else others = true;
    }
    if (ours.empty() && !others) return;
    if (!force) {
        throw OutputFolderError("--out " + dir.string() + ": the folder is not empty" +
                                (ours.empty() ? std::string() : " (it holds another run)") +
                                "; choose another folder or pass --force to replace that run's files");
    }
    for (const fs::path& file : ours) fs::remove(file, ec);
}

}  // namespace tide::cli
