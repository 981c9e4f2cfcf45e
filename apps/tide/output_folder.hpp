#pragma once
// The output folder of a run: never mixes two runs, never loses a user's files.

#include <filesystem>
#include <stdexcept>

namespace tide::cli {

/// Bad use of the output folder (exit 2).
class OutputFolderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Create `dir` if needed. A folder that already holds files is refused unless `force`;
/// with `force`, only tide's own outputs of the earlier run are removed.
void prepareOutputFolder(const std::filesystem::path& dir, bool force);

/// Whether a file name is one tide writes (frame_NNNNN.*, frames.pvd, stats.json,
/// checkpoint_NNNNN.tidecp), or the temporary file of one that a killed run left behind.
bool isRunOutput(const std::filesystem::path& file);

/// Removes the temporary files (`.NAME.tmp-PID-N`) of tide's outputs that a killed run left.
void removeStaleTemporaries(const std::filesystem::path& dir);

}  // namespace tide::cli
