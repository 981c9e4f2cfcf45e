// libFuzzer target: the checkpoint loader. A mutated file almost never keeps its CRC-32, so
// half the inputs get their checksum fixed first: the fuzzer then reaches the decoder's
// counts and the World's checks of what it decoded (restoreState, and a step from it).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include <tide/io/checkpoint.hpp>

#include "fuzz_world.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string bytes(reinterpret_cast<const char*>(data), size);
    constexpr std::size_t kHeader = 28, kCrcAt = 24;
    if (size > kHeader && (data[0] & 1u)) {  // the byte is 'T' (odd) in real files
        const std::uint32_t crc = tide::io::crc32(std::string_view(bytes).substr(kHeader));
        std::memcpy(bytes.data() + kCrcAt, &crc, sizeof crc);
    }
    tide::io::Checkpoint checkpoint;
    try {
        checkpoint = tide::io::decodeCheckpoint(bytes, "fuzz");
    } catch (const tide::io::CheckpointError&) {
        return 0;
    }
    static tide::World world = tide::fuzzing::smallWorld();
    static const tide::WorldState initial = world.saveState();
    try {
        world.restoreState(std::move(checkpoint.world));
    } catch (const std::invalid_argument&) {
        return 0;
    }
    try {
        world.step(1.0);
    } catch (const tide::DivergenceError&) {
    }
    world.restoreState(initial);  // the next input starts clean (also after a divergence)
    return 0;
}
