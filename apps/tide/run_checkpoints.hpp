#pragma once
// `tide run --checkpoint-every N` and `--resume DIR`: the checkpoint files of an output folder
// and the run's own progress stored in them (the World's state is tide::io's to encode).
//
// Files are OUT/checkpoint_NNNNN.tidecp, NNNNN the frame written just before. The newest two
// are kept: the newest to resume from, the one before in case the newest is found damaged
// (resuming refuses a damaged file rather than silently going back further).
//
// A run split among N processes (mpirun) writes one file per rank: rank K > 0 its particles
// as OUT/checkpoint_NNNNN_rK.tidecp, then rank 0 OUT/checkpoint_NNNNN.tidecp with its own and
// the run's progress, which names the N pieces. The main file appears last, so a listed
// checkpoint has all its pieces; resuming on any number of ranks (or without mpirun) joins them.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <tide/world.hpp>

namespace tide::cli {

/// What the run loop needs, besides the World, to continue as if never stopped.
struct RunProgress {
    int frame = 0;                     ///< the last frame written
    std::uint64_t particleSteps = 0;
    std::uint32_t lost = 0;            ///< most particles outside the container at a frame
    double wallSeconds = 0.0;          ///< wall time spent so far, for stats.json
    std::string gaugeRows, probeRows;  ///< Measurements' rows so far
    std::string forceRows;             ///< forces.csv's rows so far (absent from older checkpoints: none)
    std::string bodyRows;              ///< bodies.csv's rows so far (the same)
    std::uint32_t sceneCrc = 0;        ///< CRC-32 of the scene file: a checkpoint fits only its scene
    std::string solver;                ///< the solver the run used (--solver may override the scene's)
    // The run's command-line choices: a resumed run keeps them unless given again.
    int checkpointEvery = 0;           ///< --checkpoint-every
    double endTime = 0.0;              ///< s, the scene's or --end-time
    std::vector<std::string> formats;  ///< frame formats, the scene's or --format
    int pieces = 1;                    ///< files the World's state is in: the ranks that wrote it
};

/// The application block of a checkpoint (JSON text) and back; decode throws
/// std::runtime_error naming what is missing.
std::string encodeRunProgress(const RunProgress& progress);
RunProgress decodeRunProgress(const std::string& text);

std::filesystem::path checkpointFile(const std::filesystem::path& dir, int frame);
/// Rank `rank`'s piece of a split run's checkpoint (rank > 0; rank 0's is checkpointFile).
std::filesystem::path checkpointPiece(const std::filesystem::path& dir, int frame, int rank);
/// Checkpoint files in `dir`, newest (highest frame) first.
std::vector<std::filesystem::path> listCheckpoints(const std::filesystem::path& dir);
/// Removes all checkpoints but the newest two, with their pieces, and pieces left by a run
/// stopped before their main file was written.
void pruneCheckpoints(const std::filesystem::path& dir);

/// A split run's state joined from its pieces: `main` (rank 0's) with every piece's particles
/// appended, ordered by id. Throws std::runtime_error naming the piece that does not belong
/// (another time or step).
WorldState joinCheckpointPieces(WorldState main, const std::vector<WorldState>& pieces);

}  // namespace tide::cli
