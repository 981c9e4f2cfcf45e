// Every input in fuzz/regressions/ (crashes and sanitizer findings of the fuzzers, kept once
// fixed) replayed through the fuzz targets' code in the ordinary build.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "fuzz_bodies.hpp"

namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(FuzzRegressions, CheckpointInputsLoadOrAreRefused) {
    int replayed = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(TIDE_FUZZ_DIR) / "regressions" / "checkpoint")) {
        SCOPED_TRACE(entry.path().string());
        tide::fuzzing::loadCheckpointBytes(slurp(entry.path()));
        ++replayed;
    }
    EXPECT_GE(replayed, 1);
}

TEST(FuzzRegressions, SceneInputsParseOrAreRefused) {
    for (const auto& entry : fs::directory_iterator(fs::path(TIDE_FUZZ_DIR) / "regressions" / "scene")) {
        SCOPED_TRACE(entry.path().string());
        tide::fuzzing::parseSceneBytes(slurp(entry.path()), TIDE_SCENES_DIR);
    }
}

// The first finding (UBSan): a checkpoint of an empty world made the decoder memcpy into the
// null data() of an empty vector.
TEST(FuzzRegressions, AnEmptyWorldsCheckpointRoundTrips) {
    tide::WorldDef def;
    tide::World empty(def);
    empty.addMaterial({});
    const tide::io::Checkpoint c = tide::io::decodeCheckpoint(tide::io::encodeCheckpoint(empty.saveState(), ""), "empty");
    EXPECT_EQ(c.world.particles.size(), 0u);
    EXPECT_TRUE(c.application.empty());
}

}  // namespace
