// The true 2D mode (WorldDef::dimensions = 2): hydrostatics, the Koshizuka & Oka 1996 dam
// break, particles that never leave the plane, every solver, determinism across thread
// counts and bit-identical checkpoint resume, and the refusals of what 2D does not take.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <tide/io/checkpoint.hpp>
#include <tide/io/scene.hpp>
#include <tide/world.hpp>

namespace {

using namespace tide;

constexpr float kG = 9.81f;

WorldDef planarDef(const glm::vec2& size, float spacing, const std::string& solver = "dfsph", int threads = 1) {
    WorldDef def;
    def.dimensions = 2;
    def.domainMin = {0.0f, 0.0f, 0.0f};
    def.domainMax = {size.x, size.y, 0.0f};
    def.particleSpacing = spacing;
    def.solver.method = solver;
    def.threads = threads;
    return def;
}

bool allInPlane(const World& world) {
    const ParticleStore& p = world.particles();
    for (std::uint32_t i = 0; i < p.size(); ++i)
        if (p.position[i].z != 0.0f || p.velocity[i].z != 0.0f) return false;
    return true;
}

/// The time-averaged pressure against ρ g d in a tank 0.3 m deep, 0.4 m wide, at 1 cm, in
/// depth bins one spacing thick across the middle half of the width, as the 3D tanks of
/// test_incompressible_solvers.cpp: 1.5 s from the lattice, then 4 s averaged. The 2D tank
/// keeps sloshing (0.1 m/s at its surface), and 0.5 s averages of its deep half scattered by
/// ±0.5 % (1.0059–1.0112 between solver settings); over 4 s, 1.0066 with the cubic spline at
/// 2 spacings, 0.9958 with the 2D default, Wendland C2 at 3 (max speed 0.077 m/s).
struct PlanarTank {
    std::vector<double> ratio;  ///< p̄/(ρ g d) per bin, from the top of the interior down
    double deepRatio = 0.0;     ///< over the lower half of the interior
    float maxSpeed = 0.0f;
    double solidsWeight = 0.0;  ///< mean vertical load on the solids over the weight, both per metre of width
};

PlanarTank planarTank(const std::string& solver, float s = 0.01f) {
    const float depth = 0.3f, width = 0.4f;
    World world(planarDef({width, 0.45f}, s, solver));
    world.addMaterial(MaterialDef{});
    EXPECT_EQ(world.addBlock({{0, 0, 0}, {width, depth, 0}, {0, 0, 0}, 0}), AddStatus::Added);
    EXPECT_EQ(world.particles().size(), static_cast<std::uint32_t>(std::lround(width / s) * std::lround(depth / s)));
    // A particle carries ρ0 s² per metre of width (on the lattice the kernel sum is ≈ 1/s²).
    EXPECT_NEAR(world.particleMass(0), 1000.0f * s * s, 0.02f * 1000.0f * s * s);
    world.advance(1.5);
    // The interior: a kernel support from the surface and the floor at least, as the 3D tanks.
    const float margin = std::max(0.04f, world.supportRadius());
    const int bins = static_cast<int>(std::lround((depth - 2.0f * margin) / s));
    std::vector<double> sum(static_cast<std::size_t>(bins), 0.0), count(static_cast<std::size_t>(bins), 0.0);
    PlanarTank out;
    (void)world.takeMeanSolidLoads();
    for (int sample = 0; sample < 160; ++sample) {
        world.advance(0.025, [&] { out.maxSpeed = std::max(out.maxSpeed, world.stats().maxSpeed); });
        const ParticleStore& p = world.particles();
        for (std::uint32_t i = 0; i < p.size(); ++i) {
            const glm::vec3 x = p.position[i];
            if (x.x < 0.25f * width || x.x > 0.75f * width) continue;
            const int bin = static_cast<int>(std::floor((depth - x.y - margin) / s));
            if (bin < 0 || bin >= bins) continue;
            sum[static_cast<std::size_t>(bin)] += p.pressure[i] / (1000.0 * kG * (depth - x.y));
            count[static_cast<std::size_t>(bin)] += 1.0;
        }
    }
    double deep = 0.0, deepCount = 0.0;
    std::printf("%s 2D: p / (rho g d) by depth:", solver.c_str());
    for (int b = 0; b < bins; ++b) {
        const double r = sum[static_cast<std::size_t>(b)] / count[static_cast<std::size_t>(b)];
        out.ratio.push_back(r);
        std::printf(" %.4f", r);
        if (2 * b >= bins) {
            deep += sum[static_cast<std::size_t>(b)];
            deepCount += count[static_cast<std::size_t>(b)];
        }
    }
    out.deepRatio = deep / deepCount;
    // Loads are per metre of width in 2D: the walls carry the water's weight, ρ g d w (N/m).
    double vertical = 0.0;
    for (const SolidLoad& load : world.takeMeanSolidLoads()) vertical -= load.force().y;
    out.solidsWeight = vertical / (world.totalMass() * kG);
    EXPECT_NEAR(world.totalMass(), 1000.0 * depth * width, 0.02 * 1000.0 * depth * width);
    const WorldStats& stats = world.stats();
    std::printf("\n%s 2D: lower half %.4f, max speed %.4f m/s, load on the solids / weight %.4f; %llu steps, %.1f "
                "iterations a step, %llu unconverged\n",
                solver.c_str(), out.deepRatio, out.maxSpeed, out.solidsWeight, static_cast<unsigned long long>(stats.steps),
                static_cast<double>(stats.pressureIterationsSum) / static_cast<double>(stats.steps),
                static_cast<unsigned long long>(stats.unconvergedSolves));
    EXPECT_TRUE(allInPlane(world));
    EXPECT_EQ(world.countEscapedParticles(), 0u);
    return out;
}

TEST(World2D, DfsphHydrostaticTankMatchesRhoGH) {
    const PlanarTank t = planarTank("dfsph");
    EXPECT_NEAR(t.deepRatio, 1.0, 0.01);
    for (const double r : t.ratio) EXPECT_NEAR(r, 1.0, 0.05);
    EXPECT_LT(t.maxSpeed, 0.15f);
    EXPECT_NEAR(t.solidsWeight, 1.0, 0.02);
}

// pcisph at 2 cm, the 3D pcisph tank's resolution and criterion (every bin within 5 % of ρgd):
// its solve takes 85–91 iterations a step in 2D with the cubic spline (dfsph 20), so at 1 cm the
// run takes ~100 s (there the lower half reads +0.6 %; at 2 cm +2.2 %, bins of 11 particles'
// rows). With the 2D default (Wendland C2 at 3 spacings) 69 iterations, lower half +0.4 %.
TEST(World2D, PcisphHydrostaticTankMatchesRhoGH) {
    const PlanarTank t = planarTank("pcisph", 0.02f);
    for (const double r : t.ratio) EXPECT_NEAR(r, 1.0, 0.05);
    EXPECT_NEAR(t.solidsWeight, 1.0, 0.02);
}

/// Koshizuka & Oka 1996's column, L = 0.146 m wide and 2L high in a tank 4L long, at L/`cells`:
/// the surge front (the largest x of a particle on the floor's first rows, plus the half
/// spacing its volume reaches) at T = t √(2g/L). `slice`: the 3D solver on a periodic slice
/// 4 spacings thick instead of the 2D mode (examples/python/dam_break_surge.py's set-up).
std::vector<std::pair<double, double>> surgeFront(const std::string& solver, int cells, const std::vector<double>& times,
                                                  bool slice = false) {
    const float L = 0.146f, s = L / static_cast<float>(cells);
    WorldDef def = planarDef({4.0f * L, 3.0f * L}, s, solver);
    if (slice) {
        def.dimensions = 3;
        def.domainMax.z = 4.0f * s;
        def.periodic.z = true;
    }
    World world(def);
    world.addMaterial(MaterialDef{});
    world.addBlock({{0, 0, 0}, {L, 2.0f * L, def.domainMax.z}, {0, 0, 0}, 0});
    const double tScale = std::sqrt(2.0 * kG / L);
    std::vector<std::pair<double, double>> out;
    for (const double T : times) {
        world.advance(T / tScale - world.time());
        const ParticleStore& p = world.particles();
        float front = 0.0f;
        for (std::uint32_t i = 0; i < p.size(); ++i)
            if (p.position[i].y < 3.0f * s) front = std::max(front, p.position[i].x + 0.5f * s);
        out.emplace_back(T, front / L);
    }
    if (!slice) {
        EXPECT_TRUE(allInPlane(world));
    }
    EXPECT_EQ(world.countEscapedParticles(), 0u);
    return out;
}

/// The experiment's Z(T) (/work/shared/validation/dam_break_koshizuka_oka_1996_surge_front_exp.csv),
/// linearly interpolated.
double koshizukaOka(double T) {
    static const double rows[][2] = {{0, 1},         {0.381, 1.111}, {0.769, 1.252}, {1.153, 1.505}, {1.537, 1.892},
                                     {1.935, 2.241}, {2.323, 2.615}, {2.719, 3.003}, {3.096, 3.624}};
    for (std::size_t k = 1; k < std::size(rows); ++k)
        if (T <= rows[k][0])
            return rows[k - 1][1] + (T - rows[k - 1][0]) / (rows[k][0] - rows[k - 1][0]) * (rows[k][1] - rows[k - 1][1]);
    return rows[std::size(rows) - 1][1];
}

// The 2D mode is the 3D solver's physics without the third dimension: its surge front is the
// periodic slice's (within 2 % of Z at L/20; measured −0.2 %, +0.5 %, +1.4 % at T = 0.8, 1.5,
// 2.3). Against the experiment both run ahead once the column has collapsed: at L/40 the 2D
// front reads −1.3 % at T = 0.38, then +14 % at T = 1.9 and +21 % at 2.7, the slice's figures
// to the percent (docs/python.md). Issue 42's 5 % holds only for T ≲ 0.4 (free-slip walls and
// no gate, where the experiment's front was held back).
TEST(World2D, DamBreakSurgeFrontIsThePeriodicSlices) {
    const std::vector<double> times = {0.769, 1.537, 2.323};
    const auto planar = surgeFront("dfsph", 20, times);
    const auto slice = surgeFront("dfsph", 20, times, true);
    for (std::size_t k = 0; k < times.size(); ++k) {
        std::printf("T = %.3f: Z 2D %.3f, periodic 3D slice %.3f, experiment %.3f\n", times[k], planar[k].second,
                    slice[k].second, koshizukaOka(times[k]));
        EXPECT_NEAR(planar[k].second / slice[k].second, 1.0, 0.02) << "T = " << times[k];
    }
}

TEST(World2D, DamBreakSurgeFrontAgainstKoshizukaOka1996) {
    const auto front = surgeFront("dfsph", 40, {0.381, 1.935, 2.719});
    for (const auto& [T, Z] : front)
        std::printf("T = %.3f: Z = %.3f, experiment %.3f (%+.1f %%)\n", T, Z, koshizukaOka(T), 100.0 * (Z / koshizukaOka(T) - 1.0));
    EXPECT_NEAR(front[0].second / koshizukaOka(front[0].first), 1.0, 0.05);  // the collapse's start
    // Later, ahead of the experiment by the 3D slice's margin (14–21 %), not beyond.
    for (std::size_t k = 1; k < front.size(); ++k) {
        EXPECT_GT(front[k].second / koshizukaOka(front[k].first), 1.0);
        EXPECT_LT(front[k].second / koshizukaOka(front[k].first), 1.25);
    }
}

// Every solver runs the 2D column: in the plane, no escapes, and the front moving out.
TEST(World2D, EverySolverRunsTheColumn) {
    for (const std::string solver : {"classic", "wcsph", "pcisph", "dfsph", "pbf"}) {
        const auto front = surgeFront(solver, 20, {1.0});
        std::printf("%s: Z(T = 1) = %.3f\n", solver.c_str(), front[0].second);
        EXPECT_GT(front[0].second, 1.2) << solver;
        EXPECT_LT(front[0].second, 2.0) << solver;
    }
}

// Frames carry z = 0 exactly: walls, a circle, a polygon, a plane, a box, an emitter and a
// piston, with the particles written out as the VTU writer sees them.
TEST(World2D, EverythingStaysInThePlane) {
    World world(planarDef({1.0f, 0.4f}, 0.01f));
    world.addMaterial(MaterialDef{});
    WaveMakerDef paddle;
    paddle.x = 0.05f;
    paddle.depth = 0.15f;
    paddle.waveHeight = 0.02f;
    paddle.period = 0.8f;
    paddle.rampTime = 0.2f;
    world.addWaveMaker(paddle);
    ObstacleDef circle;
    circle.shape = ObstacleDef::Shape::Circle;
    circle.center = {0.5f, 0.05f, 0.0f};
    circle.radius = 0.04f;
    world.addObstacle(circle);
    ObstacleDef polygon;
    polygon.shape = ObstacleDef::Shape::Polygon;
    polygon.polygon = {{0.7f, 0.0f}, {1.0f, 0.0f}, {1.0f, 0.12f}};
    world.addObstacle(polygon);
    ObstacleDef box;
    box.min = {0.3f, 0.0f, 0.0f};
    box.max = {0.34f, 0.03f, 0.0f};
    world.addObstacle(box);
    EXPECT_EQ(world.addBlock({{0.05f, 0, 0}, {1.0f, 0.15f, 0}, {0, 0, 0}, 0}), AddStatus::Added);
    EmitterDef emitter;
    emitter.min = {0.4f, 0.3f, 0.0f};
    emitter.max = {0.44f, 0.3f, 0.0f};
    emitter.velocity = {0.0f, -0.5f, 0.0f};
    world.addEmitter(emitter);
    const std::uint32_t before = world.particles().size();
    world.advance(0.5);
    EXPECT_GT(world.particles().size(), before);  // the emitter added particles
    EXPECT_TRUE(allInPlane(world));
    EXPECT_EQ(world.countEscapedParticles(), 0u);
    // Nothing inside the solids: the circle's and polygon's distance keeps them out.
    const ParticleStore& p = world.particles();
    for (std::uint32_t i = 0; i < p.size(); ++i)
        EXPECT_GT(glm::length(glm::vec2(p.position[i]) - glm::vec2(0.5f, 0.05f)), 0.04f) << i;
}

/// One and two threads, bit for bit, on a 2D column big enough for the threaded paths.
std::vector<glm::vec3> planarRun(int threads, const std::string& solver) {
    const float L = 0.146f, s = L / 46.0f;  // 4232 particles: over the threaded paths' 4096
    World world(planarDef({4.0f * L, 3.0f * L}, s, solver, threads));
    world.addMaterial(MaterialDef{});
    world.addBlock({{0, 0, 0}, {L, 2.0f * L, 0}, {0, 0, 0}, 0});
    EXPECT_GT(world.particles().size(), 4096u);
    for (int k = 0; k < 30; ++k) world.step(1.0);  // crosses a reorder (every 25 steps)
    const ParticleStore& p = world.particles();
    std::vector<glm::vec3> byId(2 * p.size());
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        byId[p.id[i]] = p.position[i];
        byId[p.size() + p.id[i]] = p.velocity[i];
    }
    return byId;
}

TEST(Determinism2D, OneAndTwoThreadsAreBitIdentical) {
    for (const std::string solver : {"dfsph"}) {
        const auto one = planarRun(1, solver), two = planarRun(2, solver);
        ASSERT_EQ(one.size(), two.size());
        EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(glm::vec3)), 0) << solver;
    }
}

TEST(Checkpoint2D, ResumesBitIdentically) {
    const auto make = [] {
        World world(planarDef({0.5f, 0.3f}, 0.01f, "dfsph", 2));
        world.addMaterial(MaterialDef{});
        world.addBlock({{0, 0, 0}, {0.15f, 0.2f, 0}, {0, 0, 0}, 0});
        return world;
    };
    World uninterrupted = make();
    for (int k = 0; k < 31; ++k) uninterrupted.step(1.0);  // 31 + 20 steps cross a reorder
    const std::string bytes = io::encodeCheckpoint(uninterrupted.saveState(), "test");
    for (int k = 0; k < 20; ++k) uninterrupted.step(1.0);
    World resumed = make();
    resumed.restoreState(io::decodeCheckpoint(bytes, "memory").world);
    for (int k = 0; k < 20; ++k) resumed.step(1.0);
    const ParticleStore& a = uninterrupted.particles();
    const ParticleStore& b = resumed.particles();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.position.data(), b.position.data(), a.size() * sizeof(glm::vec3)), 0);
    EXPECT_EQ(std::memcmp(a.velocity.data(), b.velocity.data(), a.size() * sizeof(glm::vec3)), 0);
    EXPECT_EQ(std::memcmp(a.pressure.data(), b.pressure.data(), a.size() * sizeof(float)), 0);
    EXPECT_EQ(uninterrupted.time(), resumed.time());
    EXPECT_TRUE(allInPlane(resumed));
}

/// The message of the std::invalid_argument `f` throws ("" if none).
template <class F>
std::string refusal(F&& f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

TEST(World2D, RefusesWhatIsNotPlanar) {
    WorldDef bad = planarDef({1, 1}, 0.02f);
    bad.dimensions = 4;
    EXPECT_NE(refusal([&] { World w(bad); }).find("dimensions: must be 2 or 3, got 4"), std::string::npos);
    bad = planarDef({1, 1}, 0.02f);
    bad.gravity = {0, -9.81f, 1};
    EXPECT_NE(refusal([&] { World w(bad); }).find("gravity"), std::string::npos);
    World world(planarDef({1, 1}, 0.02f));
    world.addMaterial(MaterialDef{});
    ObstacleDef sphere;
    sphere.shape = ObstacleDef::Shape::Sphere;
    sphere.radius = 0.1f;
    EXPECT_NE(refusal([&] { world.addObstacle(sphere); }).find("\"sphere\" is a 3D shape"), std::string::npos);
    ObstacleDef cylinder;
    cylinder.shape = ObstacleDef::Shape::Cylinder;
    cylinder.radius = cylinder.length = 0.1f;
    EXPECT_NE(refusal([&] { world.addObstacle(cylinder); }).find("\"cylinder\" is a 3D shape"), std::string::npos);
    EXPECT_NE(refusal([&] { world.addBlock({{0, 0, 0}, {0.2f, 0.2f, 0}, {0, 0, 1}, 0}); }).find("block.velocity"),
              std::string::npos);
    ObstacleDef crossed;
    crossed.shape = ObstacleDef::Shape::Polygon;
    crossed.polygon = {{0, 0}, {0.3f, 0.2f}, {0.3f, 0}, {0, 0.1f}};  // edges 0 and 2 cross at (0.1, 0.067)
    EXPECT_NE(refusal([&] { world.addObstacle(crossed); }).find("cross"), std::string::npos);
    World solid(WorldDef{});
    ObstacleDef circle;
    circle.shape = ObstacleDef::Shape::Circle;
    circle.radius = 0.1f;
    EXPECT_NE(refusal([&] { solid.addObstacle(circle); }).find("\"circle\" is a 2D shape"), std::string::npos);
}

/// The problems parseScene reports for `text` (empty when it parses).
std::string sceneProblems(const std::string& text) {
    try {
        io::parseScene(text, "scene.json", ".");
    } catch (const io::SceneError& e) {
        std::string all;
        for (const auto& p : e.problems) all += p + "\n";
        return all;
    }
    return "";
}

const char* kPlanarScene = R"({"dimensions": 2, "domain": {"min": [0, 0], "max": [0.5, 0.4]}, "gravity": [0, -9.81],
  "particle_spacing": 0.01, "end_time": 0.1, "materials": [{"name": "water", "density": 1000}],
  "blocks": [{"min": [0, 0], "max": [0.2, 0.2], "material": "water"}],
  "obstacles": [%s], "probes": [{"name": "p", "position": [0.1, 0.05]}], "gauges": [{"name": "g", "x": 0.3}]})";

std::string planarScene(const std::string& obstacles) {
    std::string text = kPlanarScene;
    text.replace(text.find("%s"), 2, obstacles);
    return text;
}

TEST(Scene2D, ParsesTwoComponentVectorsAndPlanarShapes) {
    const std::string text = planarScene(R"({"type": "circle", "center": [0.35, 0.05], "radius": 0.03},
        {"type": "polygon", "points": [[0.4, 0], [0.5, 0], [0.5, 0.1]]}, {"type": "box", "min": [0.25, 0], "max": [0.28, 0.02]},
        {"type": "plane", "point": [0, 0.01], "normal": [0, 1]})");
    const io::Scene scene = io::parseScene(text, "scene.json", ".");
    EXPECT_EQ(scene.world.dimensions, 2);
    EXPECT_EQ(scene.world.domainMax, glm::vec3(0.5f, 0.4f, 0.0f));
    EXPECT_EQ(scene.obstacles.size(), 4u);
    EXPECT_EQ(scene.obstacles[1].polygon.size(), 3u);
    EXPECT_EQ(scene.probes[0].position.z, 0.0f);
    World world = io::buildWorld(scene);
    world.advance(0.05);
    EXPECT_TRUE(allInPlane(world));
}

TEST(Scene2D, RefusesBadDimensionsAndVectorsNamingThePath) {
    std::string text = planarScene("");
    EXPECT_NE(sceneProblems(std::string(text).replace(text.find("\"dimensions\": 2"), 15, "\"dimensions\": 4"))
                  .find("dimensions: must be 2 or 3, got 4"),
              std::string::npos);
    EXPECT_NE(sceneProblems(std::string(text).replace(text.find("[0, -9.81]"), 10, "[0, -9.81, 0]"))
                  .find("gravity: must be an array of 2 numbers [x, y] (the scene is 2D), got [0,-9.81,0]"),
              std::string::npos);
    // A 3D scene with a 2-vector.
    const std::string threeD = R"({"domain": {"min": [0, 0, 0], "max": [1, 1, 1]}, "gravity": [0, -9.81],
        "particle_spacing": 0.05, "end_time": 0.1, "materials": [{"name": "water", "density": 1000}]})";
    EXPECT_NE(sceneProblems(threeD).find("gravity: must be an array of 3 numbers (a 3D scene; [x, y] needs \"dimensions\": 2)"),
              std::string::npos);
    EXPECT_NE(sceneProblems(planarScene(R"({"type": "sphere", "center": [0.3, 0.1], "radius": 0.05})"))
                  .find("obstacles[0].type: \"sphere\" is a 3D shape"),
              std::string::npos);
    EXPECT_NE(sceneProblems(planarScene(R"({"type": "mesh", "file": "x.obj"})")).find("obstacles[0].type: \"mesh\" is a 3D shape"),
              std::string::npos);
    EXPECT_NE(sceneProblems(planarScene(R"({"type": "cylinder", "center": [0.3, 0.1], "axis": "y", "radius": 0.05, "length": 0.1})"))
                  .find("obstacles[0].type: \"cylinder\" is a 3D shape"),
              std::string::npos);
    EXPECT_NE(sceneProblems(planarScene(R"({"type": "box", "min": [0.3, 0, 0], "max": [0.4, 0.1, 0.1]})"))
                  .find("obstacles[0].min: must be an array of 2 numbers"),
              std::string::npos);
    EXPECT_NE(sceneProblems(planarScene(R"({"type": "polygon", "points": [[0.3, 0], [0.4, 0]]})"))
                  .find("obstacles[0].points: a polygon needs at least 3 points, got 2"),
              std::string::npos);
    EXPECT_NE(sceneProblems(planarScene(R"({"type": "polygon", "points": [[0.3, 0], [0.4, 0, 0], [0.4, 0.1]]})"))
                  .find("obstacles[0].points[1]: must be an array of 2 numbers"),
              std::string::npos);
    const std::string circle3D = R"({"domain": {"min": [0, 0, 0], "max": [1, 1, 1]}, "particle_spacing": 0.05,
        "end_time": 0.1, "materials": [{"name": "water", "density": 1000}], "obstacles": [{"type": "circle", "center": [0.5, 0.5], "radius": 0.1}]})";
    EXPECT_NE(sceneProblems(circle3D).find("obstacles[0].type: \"circle\" is a 2D shape"), std::string::npos);
    // Floating bodies in 2D: a box or circle turning about z; a polygon is not one.
    const io::Scene floating = io::parseScene(
        planarScene(R"({"type": "circle", "center": [0.35, 0.2], "radius": 0.03, "dynamic": true, "density": 1200, "angular_velocity": 0.5})"),
        "scene.json", ".");
    ASSERT_TRUE(floating.obstacles.at(0).dynamics.has_value());
    EXPECT_EQ(floating.obstacles[0].dynamics->angularVelocity, glm::vec3(0.0f, 0.0f, 0.5f));
    EXPECT_NE(sceneProblems(planarScene(R"({"type": "circle", "center": [0.35, 0.2], "radius": 0.03, "dynamic": true, "density": 1200,
        "constraint": {"free": ["y", "rx"]}})"))
                  .find("obstacles[0].constraint.free[1]: a 2D body moves in x, y and rz only, got \"rx\""),
              std::string::npos);
    EXPECT_NE(sceneProblems(planarScene(R"({"type": "box", "min": [0.3, 0.2], "max": [0.35, 0.25], "dynamic": true, "density": 500,
        "angular_velocity": [1, 2]})"))
                  .find("obstacles[0].angular_velocity: must be a number"),
              std::string::npos);
    EXPECT_NE(sceneProblems(planarScene(R"({"type": "polygon", "points": [[0.4, 0.2], [0.5, 0.2], [0.5, 0.3]], "dynamic": true, "density": 500})"))
                  .find("obstacles[0].dynamic: a polygon cannot be a floating body"),
              std::string::npos);
    std::string gaugeZ = planarScene("");
    gaugeZ.replace(gaugeZ.find("\"x\": 0.3"), 8, "\"x\": 0.3, \"z\": 0.1");
    EXPECT_NE(sceneProblems(gaugeZ).find("gauges[0].z: a 2D scene has no z"), std::string::npos);
}

// The shipped 2D scenes parse and build.
TEST(Scene2D, ShippedScenesBuild) {
    for (const char* name : {"dam_break_2d.json", "wave_tank_2d.json"}) {
        const std::string path = std::string(TIDE_SCENES_DIR) + "/" + name;
        const io::Scene scene = io::loadScene(path);
        EXPECT_EQ(scene.world.dimensions, 2) << name;
        World world = io::buildWorld(scene);
        EXPECT_GT(world.particles().size(), 1000u) << name;
        EXPECT_TRUE(allInPlane(world)) << name;
    }
}

}  // namespace
