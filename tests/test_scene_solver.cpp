// Scene files' solver keys that the World takes as they are: the kernel and the support
// that goes with it, the divergence solve's own tolerance, particle shifting and the difference form.
#include <string>

#include <gtest/gtest.h>

#include <tide/io/scene.hpp>
#include <tide/world.hpp>

namespace {

using namespace tide;

io::Scene parseWithSolver(const std::string& solver) {
    const std::string text = R"({"domain": {"min": [0, 0, 0], "max": [0.2, 0.2, 0.2]}, "particle_spacing": 0.02,
  "end_time": 0.1, "materials": [{"name": "water", "density": 1000}],
  "blocks": [{"min": [0, 0, 0], "max": [0.1, 0.1, 0.1], "material": "water"}], "solver": )" + solver + "}";
    return io::parseScene(text, "solver.json", ".");
}

TEST(SceneSolver, KernelChoosesItsSupportUnlessTheSceneSetsOne) {
    const io::Scene cubic = parseWithSolver(R"({"kernel": "cubic_spline"})");
    EXPECT_EQ(cubic.world.solver.kernel, KernelShape::CubicSpline);
    EXPECT_EQ(cubic.world.supportRatio, 2.0f);
    const io::Scene wendland = parseWithSolver(R"({"kernel": "wendland_c2"})");
    EXPECT_EQ(wendland.world.solver.kernel, KernelShape::WendlandC2);
    EXPECT_EQ(wendland.world.supportRatio, kWendlandSupportRatio);
    const io::Scene narrow = parseWithSolver(R"({"kernel": "wendland_c2", "support_ratio": 2.5})");
    EXPECT_EQ(narrow.world.supportRatio, 2.5f);
    EXPECT_EQ(parseWithSolver("{}").world.solver.kernel, KernelShape::CubicSpline);
    EXPECT_EQ(parseWithSolver("{}").world.supportRatio, kCubicSplineSupportRatio);
}

io::Scene parse2D(const std::string& solver) {
    const std::string text = R"({"dimensions": 2, "domain": {"min": [0, 0], "max": [0.4, 0.2]}, "gravity": [0, -9.81],
  "particle_spacing": 0.02, "end_time": 0.1, "materials": [{"name": "water", "density": 1000}],
  "blocks": [{"min": [0, 0], "max": [0.2, 0.1], "material": "water"}], "solver": )" + solver + "}";
    return io::parseScene(text, "solver2d.json", ".");
}

// A 2D scene gets Wendland C2 at 3 spacings (25 neighbours, where the cubic spline at 2 has 9);
// the classic solver keeps Müller's kernels at 2; a kernel or a support the scene sets stays.
TEST(SceneSolver, A2DSceneGetsWendlandAtThreeSpacingsUnlessItChoosesAKernel) {
    const io::Scene plain = parse2D("{}");
    EXPECT_EQ(plain.world.solver.kernel, KernelShape::WendlandC2);
    EXPECT_EQ(plain.world.supportRatio, kWendlandSupportRatio);
    const io::Scene cubic = parse2D(R"({"kernel": "cubic_spline"})");
    EXPECT_EQ(cubic.world.solver.kernel, KernelShape::CubicSpline);
    EXPECT_EQ(cubic.world.supportRatio, kCubicSplineSupportRatio);
    EXPECT_EQ(parse2D(R"({"support_ratio": 2.5})").world.supportRatio, 2.5f);
    const io::Scene classic = parse2D(R"({"method": "classic"})");
    EXPECT_EQ(classic.world.solver.kernel, KernelShape::CubicSpline);
    EXPECT_EQ(classic.world.supportRatio, kCubicSplineSupportRatio);
    World world(plain.world);  // the World resolves the same way from its own def
    WorldDef def = plain.world;
    def.solver.kernel = KernelShape::Automatic;
    def.supportRatio = 0.0f;
    EXPECT_FLOAT_EQ(World(def).supportRadius(), world.supportRadius());
    EXPECT_EQ(World(def).def().solver.kernel, KernelShape::WendlandC2);
}

TEST(SceneSolver, DivergenceToleranceDefaultsToTheDensitys) {
    EXPECT_LT(parseWithSolver("{}").world.solver.maxDivergenceError, 0.0f);  // follows max_density_error
    EXPECT_EQ(parseWithSolver(R"({"max_divergence_error": 0.001})").world.solver.maxDivergenceError, 0.001f);
}

// Unset, shifting and the difference form are automatic: on in a world with a wave maker,
// off elsewhere (World::addWaveMaker; test_wave_gauges.cpp WaveNumerics.*).
TEST(SceneSolver, ShiftingIsAutomaticUnlessTheSceneSetsIt) {
    EXPECT_LT(parseWithSolver("{}").world.solver.shifting, 0.0f);
    EXPECT_EQ(parseWithSolver(R"({"shifting": 0})").world.solver.shifting, 0.0f);
    EXPECT_EQ(parseWithSolver(R"({"shifting": 0.2})").world.solver.shifting, 0.2f);
}

TEST(SceneSolver, DivergenceWarmStartIsHalfUnlessTheSceneSetsIt) {
    EXPECT_EQ(parseWithSolver("{}").world.solver.divergenceWarmStart, 0.5f);
    EXPECT_EQ(parseWithSolver(R"({"divergence_warm_start": 0})").world.solver.divergenceWarmStart, 0.0f);
}

TEST(SceneSolver, SmoothDensityErrorIsAutomaticUnlessTheSceneSetsIt) {
    EXPECT_FALSE(parseWithSolver("{}").world.solver.smoothDensityError.has_value());  // automatic
    EXPECT_EQ(parseWithSolver(R"({"smooth_density_error": true})").world.solver.smoothDensityError, std::optional<bool>(true));
    EXPECT_EQ(parseWithSolver(R"({"smooth_density_error": false})").world.solver.smoothDensityError, std::optional<bool>(false));
}

TEST(SceneSolver, DifferenceFormIsAutomaticUnlessTheSceneSetsIt) {
    EXPECT_LT(parseWithSolver("{}").world.solver.differenceForm, 0.0f);
    EXPECT_EQ(parseWithSolver(R"({"difference_form": 0})").world.solver.differenceForm, 0.0f);
    EXPECT_EQ(parseWithSolver(R"({"difference_form": 0.5})").world.solver.differenceForm, 0.5f);
}

}  // namespace

namespace {

std::string parseError(const std::string& solver) {
    try {
        parseWithSolver(solver);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

TEST(SceneSolver, PbfTakesItsIterationsAndRefusesThemOutOfRangeByName) {
    const io::Scene pbf = parseWithSolver(R"({"method": "pbf", "constraint_iterations": 6, "vorticity": 0.1})");
    EXPECT_EQ(pbf.world.solver.method, "pbf");
    EXPECT_EQ(pbf.world.solver.constraintIterations, 6);
    EXPECT_EQ(pbf.world.solver.vorticity, 0.1f);
    EXPECT_EQ(parseWithSolver(R"({"method": "pbf"})").world.solver.constraintIterations, 4);
    for (const char* bad : {"0", "101", "2.5"}) {
        const std::string message = parseError(std::string(R"({"method": "pbf", "constraint_iterations": )") + bad + "}");
        EXPECT_NE(message.find("solver.constraint_iterations"), std::string::npos) << bad << ": " << message;
    }
    EXPECT_NE(parseError(R"({"method": "pbf", "vorticity": -1})").find("solver.vorticity"), std::string::npos);
}

}  // namespace
