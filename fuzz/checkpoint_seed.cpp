// Writes seed checkpoints for fuzz_checkpoint: the fuzz world after 0, 3 and 8 steps.
#include <cstdio>
#include <filesystem>
#include <string>

#include <tide/io/checkpoint.hpp>

#include "fuzz_world.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: checkpoint_seed CORPUS_DIR\n");
        return 2;
    }
    std::filesystem::create_directories(argv[1]);
    tide::World world = tide::fuzzing::smallWorld();
    int taken = 0;
    for (const int steps : {0, 3, 8}) {
        for (; taken < steps; ++taken) world.step(1.0);
        tide::io::writeCheckpoint(std::filesystem::path(argv[1]) / ("seed_" + std::to_string(steps) + ".tidecp"),
                                  world.saveState(), "{\"frame\": 1}");
    }
    return 0;
}
