// The ocean's definition structs: defaults and errors that name the field and the value.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include <tide/ocean.hpp>

namespace {

using namespace tide;

OceanDef goodOcean() {
    OceanDef def;
    def.depth = 0.7;
    def.waves.hs = 0.1;
    def.waves.tp = 3.0;
    def.openSides = {OceanSide::MinusX, OceanSide::PlusX};
    return def;
}

std::string errorOf(const OceanDef& def) {
    try {
        validateOcean(def);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

TEST(OceanDefs, AcceptsAGoodSea) {
    EXPECT_EQ(errorOf(goodOcean()), "");
    OceanDef regular = goodOcean();
    regular.waves.type = OceanWavesDef::Type::Regular;
    regular.waves.height = 0.16;
    regular.waves.period = 2.0;
    EXPECT_EQ(errorOf(regular), "");
}

TEST(OceanDefs, ErrorsNameTheFieldAndTheValue) {
    OceanDef def = goodOcean();
    def.waves.hs = -1.0;
    EXPECT_EQ(errorOf(def), "ocean.waves.hs: must be > 0, got -1");
    def = goodOcean();
    def.depth = 0.0;
    EXPECT_EQ(errorOf(def), "ocean.depth: must be > 0, got 0");
    def = goodOcean();
    def.waves.tp = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(errorOf(def), "ocean.waves.tp: must be > 0, got nan");
    def = goodOcean();
    def.waves.gamma = 12.0;
    EXPECT_EQ(errorOf(def), "ocean.waves.gamma: must be in [1, 7], got 12");
    def = goodOcean();
    def.waves.spreading = -2.0;
    EXPECT_EQ(errorOf(def), "ocean.waves.spreading: must be in (0, 1000], got -2");
    def = goodOcean();
    def.waves.direction = 400.0;
    EXPECT_EQ(errorOf(def), "ocean.waves.direction: must be in [-360, 360], got 400");
    def = goodOcean();
    def.waves.components = 0;
    EXPECT_EQ(errorOf(def), "ocean.waves.components: must be in [1, 4096], got 0");
    def = goodOcean();
    def.waves.directions = 4;
    EXPECT_EQ(errorOf(def), "ocean.waves.directions: must be 0 or 1 for a long-crested sea (no spreading), got 4");
    def = goodOcean();
    def.zoneWidth = -3.0;
    EXPECT_EQ(errorOf(def), "ocean.zone_width: must be >= 0 (0: one peak wavelength), got -3");
    def = goodOcean();
    def.openSides.push_back(OceanSide::MinusX);
    EXPECT_EQ(errorOf(def), "ocean.open_sides[2]: is listed twice, got -x");
    def = goodOcean();
    def.waves.type = OceanWavesDef::Type::Regular;
    def.waves.height = 0.1;
    def.waves.period = 0.0;
    EXPECT_EQ(errorOf(def), "ocean.waves.period: must be > 0, got 0");
    def.waves.period = 2.0;
    def.waves.spreading = 10.0;
    EXPECT_EQ(errorOf(def), "ocean.waves.spreading: applies to spectra, not to regular waves, got 10");
    def = goodOcean();
    def.waves.type = OceanWavesDef::Type::PiersonMoskowitz;
    def.waves.gamma = 3.3;
    EXPECT_EQ(errorOf(def), "ocean.waves.gamma: applies to a jonswap spectrum (pierson_moskowitz has gamma 1), got 3.3");
}

TEST(OceanDefs, SideNamesAreTheSceneKeys) {
    EXPECT_STREQ(oceanSideName(OceanSide::MinusX), "-x");
    EXPECT_STREQ(oceanSideName(OceanSide::PlusX), "+x");
    EXPECT_STREQ(oceanSideName(OceanSide::MinusZ), "-z");
    EXPECT_STREQ(oceanSideName(OceanSide::PlusZ), "+z");
}

}  // namespace
