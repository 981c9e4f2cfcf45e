#pragma once
// What each fuzz target does with one input, shared by the libFuzzer entry points and by
// tests/test_fuzz_regressions.cpp, which replays every file in fuzz/regressions/ in the
// ordinary test build (a crash the fuzzer once found stays fixed).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include <tide/io/checkpoint.hpp>
#include <tide/io/scene.hpp>

#include "fuzz_world.hpp"

namespace tide::fuzzing {

/// Any bytes must give a Scene or a SceneError, nothing else; small scenes are then built.
inline void parseSceneBytes(std::string_view text, const std::filesystem::path& scenesDir) {
    io::Scene scene;
    try {
        scene = io::parseScene(text, "fuzz", scenesDir);
    } catch (const io::SceneError&) {
        return;
    }
    // Building allocates for every particle: only scenes a test would build.
    if (io::estimate(scene).bytes > (std::uint64_t{16} << 20)) return;
    try {
        World world = io::buildWorld(scene);
        (void)world.particles().size();
    } catch (const io::SceneError&) {
    } catch (const std::invalid_argument&) {
    }
}

/// Decodes bytes as a checkpoint and restores and steps what decodes. A mutated file almost
/// never keeps its CRC-32, so inputs whose first byte is odd ('T' of a real file is) get
/// their checksum fixed first: the fuzzer then reaches the decoder's counts and the World's
/// checks of what it decoded.
inline void loadCheckpointBytes(std::string_view input) {
    std::string bytes(input);
    constexpr std::size_t kHeader = 28, kCrcAt = 24;
    if (bytes.size() > kHeader && (static_cast<unsigned char>(bytes[0]) & 1u)) {
        const std::uint32_t crc = io::crc32(std::string_view(bytes).substr(kHeader));
        std::memcpy(bytes.data() + kCrcAt, &crc, sizeof crc);
    }
    io::Checkpoint checkpoint;
    try {
        checkpoint = io::decodeCheckpoint(bytes, "fuzz");
    } catch (const io::CheckpointError&) {
        return;
    }
    static World world = smallWorld();
    static const WorldState initial = world.saveState();
    try {
        world.restoreState(std::move(checkpoint.world));
    } catch (const std::invalid_argument&) {
        return;
    }
    try {
        world.step(1.0);
    } catch (const DivergenceError&) {
    }
    world.restoreState(initial);  // the next input starts clean (also after a divergence)
}

}  // namespace tide::fuzzing
