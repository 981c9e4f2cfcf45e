// libFuzzer target: the checkpoint loader (see fuzz_bodies.hpp).
#include "fuzz_bodies.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    tide::fuzzing::loadCheckpointBytes({reinterpret_cast<const char*>(data), size});
    return 0;
}
