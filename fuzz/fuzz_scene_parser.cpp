// libFuzzer target: the scene parser, the size estimate and building small scenes (see fuzz_bodies.hpp).
#include "fuzz_bodies.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    tide::fuzzing::parseSceneBytes({reinterpret_cast<const char*>(data), size}, TIDE_SCENES_DIR);
    return 0;
}
