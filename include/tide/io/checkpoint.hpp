#pragma once
/// \file
/// Checkpoints: a World's complete evolving state (tide::WorldState) plus an opaque block of
/// the application's own (the CLI keeps its frame counter and measurements there), in one
/// binary file with a format version and a CRC-32 over everything after the header.
///
/// Layout (little-endian):
///   "TIDECKPT" | u32 version | u32 0x01020304 (byte order) | u64 payload bytes | u32 CRC-32 of the payload
///   payload: time, sound speed, reorder counter, WorldStats field by field, particle count and
///   next id, every ParticleStore array raw, emitters (active, travelled), solver scalars,
///   application bytes.
/// A file is written atomically (temporary file, fsync, rename): a reader sees an old
/// checkpoint or a new one, never half of one. Reading checks the header, the size and the
/// checksum before decoding anything, and decoding checks every count against the bytes
/// left, so a damaged file throws CheckpointError and never yields a half-loaded state.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include <tide/world.hpp>

namespace tide::io {

/// The format version written (2: dye concentration per particle; 3: the count of
/// unconverged pressure solves in the stats; 4: the divergence solve's iteration sum after
/// the stats' phase times; 5: the floating bodies' state after the solver's scalars; 6: the wave makers' active absorption after the bodies'; 7: the particles an ocean's zones
/// added and removed, after the wave makers': its refill follows them); it reads back to
/// kOldestCheckpointVersion and refuses the others.
inline constexpr std::uint32_t kCheckpointVersion = 7;
inline constexpr std::uint32_t kOldestCheckpointVersion = 2;

/// A checkpoint that cannot be used; what() names the file and the problem.
class CheckpointError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// What a checkpoint holds.
struct Checkpoint {
    WorldState world;
    std::string application;  ///< the writer's own bytes, returned as written
};

/// The file's bytes for a state and an application block.
[[nodiscard]] std::string encodeCheckpoint(const WorldState& world, std::string_view application);
/// Decodes bytes written by encodeCheckpoint; `source` names them in messages. Throws
/// CheckpointError for a wrong magic, version, byte order, size or checksum, or any count
/// that does not fit the bytes.
[[nodiscard]] Checkpoint decodeCheckpoint(std::string_view bytes, const std::string& source);

/// Writes a checkpoint file atomically. Throws std::runtime_error on failure (the file keeps
/// its earlier content).
void writeCheckpoint(const std::filesystem::path& file, const WorldState& world, std::string_view application);
/// Reads and decodes a checkpoint file. Throws CheckpointError (also for an unreadable file).
[[nodiscard]] Checkpoint readCheckpoint(const std::filesystem::path& file);

/// CRC-32 (IEEE 802.3, the one zlib and PNG use) of `bytes`, continuing from `crc`.
[[nodiscard]] std::uint32_t crc32(std::string_view bytes, std::uint32_t crc = 0);

}  // namespace tide::io
