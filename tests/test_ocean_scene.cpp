// The scene key "ocean" (issue 43's contract): parsed into OceanDef, every problem named by its
// JSON path, and the schema agreeing with the parser.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include <tide/io/scene.hpp>
#include <tide/ocean.hpp>

#include "cli_support.hpp"

namespace {

using namespace tide;

// A 6 m × 1.2 m × 4 m near field (the flume of acceptance item 3 is 0.7 m deep).
std::string sceneWith(const std::string& ocean, const std::string& extra = "") {
    return R"({"domain": {"min": [0, 0, 0], "max": [6, 1.2, 4]}, "particle_spacing": 0.1,
  "end_time": 0.1, "materials": [{"name": "water", "density": 1000}])" + extra + R"(, "ocean": )" + ocean + "}";
}

io::Scene parse(const std::string& text) { return io::parseScene(text, "ocean.json", "."); }

std::vector<std::string> problemsOf(const std::string& text) {
    try {
        parse(text);
    } catch (const io::SceneError& e) {
        return e.problems;
    }
    return {};
}

TEST(OceanScene, ReadsEveryContractKey) {
    const io::Scene scene = parse(sceneWith(R"({"depth": 0.7, "zone_width": 1.5, "open_sides": ["-x", "+z"],
        "waves": {"type": "jonswap", "hs": 0.1, "tp": 3, "direction": 30, "spreading": 10, "gamma": 3.3,
                  "seed": 12, "components": 48, "directions": 8}})"));
    ASSERT_TRUE(scene.ocean.has_value());
    const OceanDef& o = *scene.ocean;
    EXPECT_EQ(o.depth, 0.7);
    EXPECT_EQ(o.zoneWidth, 1.5);
    EXPECT_EQ(o.openSides, (std::vector<OceanSide>{OceanSide::MinusX, OceanSide::PlusZ}));
    EXPECT_EQ(o.waves.type, OceanWavesDef::Type::Jonswap);
    EXPECT_EQ(o.waves.hs, 0.1);
    EXPECT_EQ(o.waves.tp, 3.0);
    EXPECT_EQ(o.waves.direction, 30.0);
    EXPECT_EQ(o.waves.spreading, 10.0);
    EXPECT_EQ(o.waves.gamma, 3.3);
    EXPECT_EQ(o.waves.seed, 12u);
    EXPECT_EQ(o.waves.components, 48);
    EXPECT_EQ(o.waves.directions, 8);
}

TEST(OceanScene, DefaultsAndRegularWaves) {
    const io::Scene scene = parse(sceneWith(R"({"depth": 0.7, "waves": {"type": "regular", "height": 0.16, "period": 2}})"));
    ASSERT_TRUE(scene.ocean.has_value());
    const OceanDef& o = *scene.ocean;
    EXPECT_EQ(o.waves.type, OceanWavesDef::Type::Regular);
    EXPECT_EQ(o.waves.height, 0.16);
    EXPECT_EQ(o.waves.period, 2.0);
    EXPECT_EQ(o.waves.direction, 0.0);
    EXPECT_FALSE(o.waves.spreading.has_value());  // long-crested
    EXPECT_FALSE(o.waves.gamma.has_value());
    EXPECT_EQ(o.zoneWidth, 0.0);                   // one peak wavelength
    EXPECT_TRUE(o.openSides.empty());
    EXPECT_FALSE(parse(sceneWith(R"({"depth": 0.5, "waves": {"type": "pierson_moskowitz", "hs": 0.1, "tp": 2}})")).ocean->waves.gamma);
}

TEST(OceanScene, UnitScaleAppliesToLengths) {
    const std::string text = R"({"unit_scale": 0.01, "domain": {"min": [0, 0, 0], "max": [600, 120, 400]},
      "particle_spacing": 10, "end_time": 0.1, "materials": [{"name": "water", "density": 1000}],
      "ocean": {"depth": 70, "zone_width": 150, "waves": {"type": "jonswap", "hs": 10, "tp": 3}}})";
    const OceanDef o = *parse(text).ocean;
    // The scene holds unit_scale as a float (0.01f = 0.0099999998): lengths carry its 1e-7.
    EXPECT_NEAR(o.depth, 0.7, 1e-7 * 0.7);
    EXPECT_NEAR(o.zoneWidth, 1.5, 1e-7 * 1.5);
    EXPECT_NEAR(o.waves.hs, 0.1, 1e-7 * 0.1);
    EXPECT_EQ(o.waves.tp, 3.0);  // periods are not lengths
}

TEST(OceanScene, ProblemsNameTheirJsonPath) {
    const auto one = [](const std::string& ocean, const std::string& extra = "") {
        const auto problems = problemsOf(sceneWith(ocean, extra));
        EXPECT_EQ(problems.size(), 1u) << ocean;
        return problems.empty() ? std::string() : problems.front();
    };
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "jonswap", "hs": -1, "tp": 3}})"),
              "ocean.waves.hs: must be > 0, got -1");
    EXPECT_EQ(one(R"({"waves": {"type": "jonswap", "hs": 0.1, "tp": 3}})"), "ocean.depth: missing (required)");
    EXPECT_EQ(one(R"({"depth": 0.7})"), "ocean.waves: missing (required)");
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "jonswop", "hs": 0.1, "tp": 3}})"),
              "ocean.waves.type: must be \"regular\", \"jonswap\" or \"pierson_moskowitz\", got \"jonswop\" (did you mean \"jonswap\"?)");
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "jonswap", "hs": 0.1, "tp": 3, "spreding": 10}})"),
              "ocean.waves.spreding: unknown key (did you mean \"spreading\"?)");
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "regular", "height": 0.1, "period": 2, "hs": 0.1}})"),
              "ocean.waves.hs: does not apply to regular waves");
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "jonswap", "hs": 0.1, "tp": 3, "period": 2}})"),
              "ocean.waves.period: does not apply to a spectrum (type \"jonswap\")");
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "pierson_moskowitz", "hs": 0.1, "tp": 3, "gamma": 2}})"),
              "ocean.waves.gamma: applies to a jonswap spectrum (pierson_moskowitz has gamma 1)");
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "jonswap", "hs": 0.1, "tp": 3, "gamma": 9}})"),
              "ocean.waves.gamma: must be >= 1 and <= 7, got 9");
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "jonswap", "hs": 0.1, "tp": 3, "spreading": 0}})"),
              "ocean.waves.spreading: must be > 0 and <= 1000, got 0");
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "jonswap", "hs": 0.1, "tp": 3, "direction": 400}})"),
              "ocean.waves.direction: must be >= -360 and <= 360, got 400");
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "jonswap", "hs": 0.1, "tp": 3, "components": 12.5}})"),
              "ocean.waves.components: must be a whole number, got 12.5");
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "jonswap", "hs": 0.1, "tp": 3, "directions": 4}})"),
              "ocean.waves.directions: must be 0 or 1 for a long-crested sea (no spreading), got 4");
    EXPECT_EQ(one(R"({"depth": 0.7, "open_sides": ["+x", "x"], "waves": {"type": "jonswap", "hs": 0.1, "tp": 3}})"),
              "ocean.open_sides[1]: must be \"-x\", \"+x\", \"-z\" or \"+z\", got \"x\" (did you mean \"-x\"?)");
    EXPECT_EQ(one(R"({"depth": 0.7, "open_sides": ["+x", "+x"], "waves": {"type": "jonswap", "hs": 0.1, "tp": 3}})"),
              "ocean.open_sides[1]: is listed twice, got +x");
    EXPECT_EQ(one(R"({"depth": 2, "waves": {"type": "jonswap", "hs": 0.1, "tp": 3}})"),
              "ocean.depth: must not exceed the domain height 1.2, got 2");
    // A domain top under the crests is a lid on the waves (1.2 m tall: 0.05 m above 1.15 m of water).
    EXPECT_EQ(one(R"({"depth": 1.15, "waves": {"type": "jonswap", "hs": 0.1, "tp": 3}})"),
              "domain.max[1]: the domain's top stands 0.05 m above the ocean's still water, under its crests "
              "(about 0.1 m: Hs); raise it by 0.05 m or more");
    EXPECT_EQ(one(R"({"depth": 1.05, "waves": {"type": "regular", "height": 0.2, "period": 3}})"),
              "domain.max[1]: the domain's top stands 0.15 m above the ocean's still water, under its crests "
              "(about 0.2 m: the wave height); raise it by 0.05 m or more");
    // Stokes' order: regular waves only, 1 to 5, and a wave the theory holds.
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "jonswap", "hs": 0.1, "tp": 3, "order": 5}})"),
              "ocean.waves.order: applies to regular waves (a spectrum is a linear sea)");
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "regular", "height": 0.16, "period": 2, "order": 7}})"),
              "ocean.waves.order: must be >= 1 and <= 5, got 7");
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "regular", "height": 0.16, "period": 2, "order": 2.5}})"),
              "ocean.waves.order: must be a whole number, got 2.5");
    EXPECT_NE(one(R"({"depth": 0.3, "waves": {"type": "regular", "height": 0.1, "period": 4, "order": 5}})")
                  .find("ocean.waves.order: 5 (Stokes' theory, Fenton 1985) does not converge"),
              std::string::npos);
    EXPECT_TRUE(problemsOf(sceneWith(R"({"depth": 0.7, "waves": {"type": "regular", "height": 0.16, "period": 2, "order": 5}})"))
                    .empty());
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "regular", "height": 0.16, "period": 2, "mean_current": "drift"}})"),
              "ocean.waves.mean_current: must be \"return\" or \"none\", got \"drift\"");
    EXPECT_EQ(one(R"({"depth": 0.7, "waves": {"type": "jonswap", "hs": 0.1, "tp": 3, "mean_current": "none"}})"),
              "ocean.waves.mean_current: applies to regular waves (a spectrum is a linear sea)");
    EXPECT_EQ(parse(sceneWith(R"({"depth": 0.7, "waves": {"type": "regular", "height": 0.16, "period": 2, "mean_current": "return"}})"))
                  .ocean->waves.meanCurrent,
              OceanWavesDef::MeanCurrent::Return);
}

TEST(OceanScene, RefusesZonesWiderThanTheRegionAndOpenSidesThatCannotBe) {
    const auto one = [](const std::string& ocean, const std::string& extra = "") {
        const auto problems = problemsOf(sceneWith(ocean, extra));
        EXPECT_EQ(problems.size(), 1u) << ocean;
        return problems.empty() ? std::string() : problems.front();
    };
    const std::string sea = R"("waves": {"type": "regular", "height": 0.16, "period": 2})";
    // Both x faces take 2 × 3.5 m of the 6 m domain.
    EXPECT_EQ(one(R"({"depth": 0.7, "zone_width": 3.5, "open_sides": ["-x", "+x"], )" + sea + "}"),
              "ocean.zone_width: its zone (zone_width 3.5, twice: both faces of x) is wider than the domain's 6 along x");
    EXPECT_TRUE(problemsOf(sceneWith(R"({"depth": 0.7, "zone_width": 3.5, "open_sides": ["-x"], )" + sea + "}")).empty());
    // The default width is a peak wavelength (4.6 m at T = 2 s on 0.7 m), wider than the 4 m along z.
    OceanDef flume;
    flume.depth = 0.7;
    flume.waves.type = OceanWavesDef::Type::Regular;
    flume.waves.height = 0.16;
    flume.waves.period = 2.0;
    const double wavelength = oceanPeakWavelength(flume);
    EXPECT_GT(wavelength, 4.0);
    std::ostringstream expected;
    expected << "ocean.open_sides[0]: its zone (zone_width " << wavelength
             << ", one peak wavelength along z) is wider than the domain's 4 along z";
    EXPECT_EQ(one(R"({"depth": 0.7, "open_sides": ["+z"], )" + sea + "}"), expected.str());
    EXPECT_EQ(one(R"({"depth": 0.7, "zone_width": 1, "open_sides": ["-x"], )" + sea + "}",
                  R"(, "wavemaker": {"type": "piston", "x": 0.2, "depth": 0.7, "wave_height": 0.1, "period": 2})"),
              "ocean.open_sides[0]: -x has the wave maker (wavemaker) on it: a side is either open or a paddle");
    const std::string periodic = R"({"domain": {"min": [0, 0, 0], "max": [6, 1.2, 4], "periodic": [false, false, true]},
      "particle_spacing": 0.1, "end_time": 0.1, "materials": [{"name": "water", "density": 1000}],
      "ocean": {"depth": 0.7, "zone_width": 1, "open_sides": ["-z"], )" + sea + "}}";
    const auto problems = problemsOf(periodic);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0], "ocean.open_sides[0]: -z is on the periodic z axis (domain.periodic): it cannot also be open");
}

TEST(OceanScene, SpreadingAndDirectionsOutOfRangeAreNamed) {
    const auto one = [](const std::string& waves) {
        const auto problems = problemsOf(sceneWith(R"({"depth": 0.7, "waves": )" + waves + "}"));
        EXPECT_EQ(problems.size(), 1u) << waves;
        return problems.empty() ? std::string() : problems.front();
    };
    EXPECT_EQ(one(R"({"type": "jonswap", "hs": 0.1, "tp": 3, "spreading": 2000})"),
              "ocean.waves.spreading: must be > 0 and <= 1000, got 2000");
    EXPECT_EQ(one(R"({"type": "jonswap", "hs": 0.1, "tp": 3, "spreading": 10, "directions": 500})"),
              "ocean.waves.directions: must be >= 0 and <= 360, got 500");
    EXPECT_EQ(one(R"({"type": "jonswap", "hs": 0.1, "tp": 3, "direction": -400})"),
              "ocean.waves.direction: must be >= -360 and <= 360, got -400");
    EXPECT_EQ(one(R"({"type": "regular", "height": 0.1, "period": 2, "spreading": 10})"),
              "ocean.waves.spreading: does not apply to regular waves");
}

TEST(OceanScene, GaugesOutsideTheDomainReadTheFarField) {
    const std::string gauges = R"(, "gauges": [{"name": "far", "x": -20, "z": 2}])";
    // Without an ocean a gauge outside the domain is an error; with one it reads the sea.
    const auto problems = problemsOf(R"({"domain": {"min": [0, 0, 0], "max": [6, 1.2, 4]}, "particle_spacing": 0.1,
  "end_time": 0.1, "materials": [{"name": "water", "density": 1000}])" + gauges + "}");
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems.front(), "gauges[0]: (x, z) = (-20, 2) lies outside the domain");
    const io::Scene scene = parse(sceneWith(R"({"depth": 0.7, "open_sides": ["-x"], "zone_width": 1,
        "waves": {"type": "regular", "height": 0.1, "period": 2}})", gauges));
    ASSERT_EQ(scene.gauges.size(), 1u);
    EXPECT_EQ(scene.gauges.front().x, -20.0f);
}

constexpr const char* kSea = R"({"depth": 0.7, "waves": {"type": "regular", "height": 0.16, "period": 2}})";

TEST(OceanScene, FarFieldOfObjFramesIsReadAndItsProblemsNamed) {
    const io::Scene scene = parse(sceneWith(kSea, R"(, "output": {"formats": ["obj"], "far_field": {"extent": 3, "spacing": 0.2}})"));
    EXPECT_TRUE(scene.output.farField);
    EXPECT_EQ(scene.output.farFieldExtent, 3.0);
    EXPECT_EQ(scene.output.farFieldSpacing, 0.2);
    const io::Scene defaults = parse(sceneWith(kSea));
    EXPECT_TRUE(defaults.output.farField);
    EXPECT_EQ(defaults.output.farFieldExtent, 0.0);  // io::defaultFarFieldExtent
    EXPECT_FALSE(parse(sceneWith(kSea, R"(, "output": {"far_field": false})")).output.farField);

    const auto negative = problemsOf(sceneWith(kSea, R"(, "output": {"far_field": {"spacing": -0.1}})"));
    ASSERT_EQ(negative.size(), 1u);
    EXPECT_NE(negative[0].find("output.far_field.spacing"), std::string::npos) << negative[0];
    EXPECT_NE(negative[0].find("-0.1"), std::string::npos) << negative[0];
    const auto noOcean = problemsOf(R"({"domain": {"min": [0, 0, 0], "max": [1, 1, 1]}, "particle_spacing": 0.1, "end_time": 0.1,
        "materials": [{"name": "water", "density": 1000}], "output": {"far_field": {"extent": 3}}})");
    ASSERT_EQ(noOcean.size(), 1u);
    EXPECT_NE(noOcean[0].find("output.far_field"), std::string::npos) << noOcean[0];
}

TEST(OceanScene, SchemaAgreesWithTheParser) {
    // Debian's python3-jsonschema: scenes the parser takes pass the schema, and the contract
    // mistakes it refuses fail it.
    struct Case {
        std::string ocean;
        bool ok;
        std::string extra;  ///< other top-level keys
    };
    const std::vector<Case> cases = {
        {R"({"depth": 0.7, "zone_width": 1.5, "open_sides": ["-x", "+z"], "waves": {"type": "jonswap", "hs": 0.1,
            "tp": 3, "direction": 30, "spreading": 10, "gamma": 3.3, "seed": 12, "components": 48, "directions": 8}})", true, ""},
        {R"({"depth": 0.7, "waves": {"type": "regular", "height": 0.16, "period": 2}})", true, ""},
        {R"({"depth": 0.7, "waves": {"type": "regular", "height": 0.16, "period": 2, "hs": 1}})", false, ""},
        {R"({"depth": 0.7, "waves": {"type": "jonswap", "hs": 0.1, "tp": 3, "period": 2}})", false, ""},
        {R"({"depth": 0.7, "waves": {"type": "jonswap", "hs": 0.1}})", false, ""},
        {R"({"depth": 0.7, "open_sides": ["x"], "waves": {"type": "jonswap", "hs": 0.1, "tp": 3}})", false, ""},
        {R"({"depth": 0.7, "waves": {"type": "jonswap", "hs": 0.1, "tp": 3, "spread": 2}})", false, ""},
        {kSea, true, R"(, "output": {"formats": ["obj"], "far_field": {"extent": 3, "spacing": 0.2}})"},
        {kSea, true, R"(, "output": {"far_field": false})"},
        {kSea, false, R"(, "output": {"far_field": {"extent": 0}})"},
        {kSea, false, R"(, "output": {"far_field": {"reach": 3}})"},
    };
    const auto dir = std::filesystem::temp_directory_path() / ("tide_ocean_schema_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const std::string text = sceneWith(cases[i].ocean, cases[i].extra);
        EXPECT_EQ(problemsOf(text).empty(), cases[i].ok) << text;
        std::ofstream(dir / (std::to_string(i) + ".json")) << text;
    }
    const std::string command = "/usr/bin/python3 -c \"import json, sys, jsonschema\n"
                                "v = jsonschema.Draft202012Validator(json.load(open(sys.argv[1])))\n"
                                "for f in sys.argv[2:]: print(1 if v.is_valid(json.load(open(f))) else 0, end='')\" " +
                                std::string(TIDE_SCENES_DIR) + "/scene.schema.json";
    std::string files;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        files += ' ';  // appended piecewise: " " + std::string trips GCC 12's false -Wrestrict
        files += (dir / (std::to_string(i) + ".json")).string();
    }
    FILE* pipe = popen((command + files).c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string verdicts;
    for (int c; (c = std::fgetc(pipe)) != EOF;) verdicts += static_cast<char>(c);
    EXPECT_EQ(pclose(pipe), 0);
    std::string expected;
    for (const auto& c : cases) expected += c.ok ? '1' : '0';
    EXPECT_EQ(verdicts, expected);
    std::filesystem::remove_all(dir);
}

TEST(OceanScene, ValidateReportsTheWavesAndWarnsWhenTooCoarse) {
    // `tide validate`: the peak wavelength, particles per wave height and zone widths.
    const auto dir = tide::testing::scratch("ocean_validate");
    std::filesystem::create_directories(dir);
    const auto write = [&](const std::string& name, double spacing) {
        std::string text = sceneWith(R"({"depth": 0.7, "zone_width": 1.5, "open_sides": ["-x", "+z"],
            "waves": {"type": "regular", "height": 0.16, "period": 2, "direction": 30}})");
        text.replace(text.find("0.1,"), 4, std::to_string(spacing) + ",");  // the particle spacing
        std::ofstream(dir / name) << text;
        return (dir / name).string();
    };
    OceanDef flume;
    flume.depth = 0.7;
    flume.waves.type = OceanWavesDef::Type::Regular;
    flume.waves.height = 0.16;
    flume.waves.period = 2.0;
    char wavelength[64];
    std::snprintf(wavelength, sizeof wavelength, "peak wavelength %.3g m", oceanPeakWavelength(flume));

    const tide::testing::Result fine = tide::testing::run(std::string(TIDE_BIN) + " validate " + write("fine.json", 0.01));
    EXPECT_EQ(fine.exit, 0) << fine.output;
    EXPECT_NE(fine.output.find("ocean      depth 0.7 m: regular, H 0.16 m, T 2 s, towards 30 deg, Stokes order 5 (Fenton 1985), "
                               "no mean current"),
              std::string::npos)
        << fine.output;
    EXPECT_NE(fine.output.find(wavelength), std::string::npos) << fine.output;
    EXPECT_NE(fine.output.find("16.0 particles per wave height"), std::string::npos) << fine.output;
    EXPECT_NE(fine.output.find("zones    1.5 m on -x, +z"), std::string::npos) << fine.output;
    EXPECT_NE(fine.output.find("fills the domain to 0.7 m in 70 layers of 0.01 m"), std::string::npos) << fine.output;
    EXPECT_EQ(fine.output.find("warning"), std::string::npos) << fine.output;

    const tide::testing::Result coarse = tide::testing::run(std::string(TIDE_BIN) + " validate " + write("coarse.json", 0.04));
    EXPECT_EQ(coarse.exit, 0) << coarse.output;
    EXPECT_NE(coarse.output.find("warning: ocean: 4.0 particles per wave height"), std::string::npos) << coarse.output;
    std::filesystem::remove_all(dir.parent_path());
}

}  // namespace
