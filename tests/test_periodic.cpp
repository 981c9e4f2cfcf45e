// Periodic axes: the nearest image, neighbour search across the seam against brute force,
// the wall shell, wrapping, and flows that cross the seam without feeling it.
#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <tide/world.hpp>

#include "boundary/boundary_particles.hpp"
#include "core/periodic_box.hpp"
#include "neighbors/neighbor_list.hpp"
#include "neighbors/uniform_grid.hpp"

namespace {

using namespace tide;

TEST(PeriodicBox, NearestImageAndWrap) {
    const PeriodicBox box = PeriodicBox::make({0, 0, 0}, {1, 2, 4}, {true, false, true});
    const glm::vec3 d = box.delta({0.95f, 1.9f, 0.1f}, {0.05f, 0.1f, 3.9f});
    EXPECT_NEAR(d.x, -0.1f, 1e-6f);  // across the x seam
    EXPECT_NEAR(d.y, 1.8f, 1e-6f);   // y is not periodic
    EXPECT_NEAR(d.z, 0.2f, 1e-6f);   // across the z seam
    EXPECT_EQ(box.wrap({1.0f, 5.0f, 4.0f}), glm::vec3(0.0f, 5.0f, 0.0f));  // max re-enters at min
    EXPECT_NEAR(box.wrap({-0.25f, 0, 9.5f}).x, 0.75f, 1e-6f);
    EXPECT_NEAR(box.wrap({-0.25f, 0, 9.5f}).z, 1.5f, 1e-6f);
    const float tiny = box.wrap({-1e-9f, 0, 0}).x;  // rounds onto max: must land on min
    EXPECT_TRUE(tiny >= 0.0f && tiny < 1.0f) << tiny;
    EXPECT_TRUE(std::isnan(box.wrap({std::nanf(""), 0, 0}).x));  // divergence stays visible
    const PeriodicBox none;
    EXPECT_EQ(none.delta({0.9f, 0, 0}, {0.1f, 0, 0}), glm::vec3(0.9f, 0, 0) - glm::vec3(0.1f, 0, 0));
}

/// Brute-force neighbours of x[i] among `others` within h, by the nearest image.
std::vector<std::uint32_t> bruteForce(const PeriodicBox& box, const glm::vec3& q, const std::vector<glm::vec3>& others,
                                      float h, std::uint32_t skip) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t j = 0; j < others.size(); ++j) {
        const glm::vec3 d = box.delta(q, others[j]);
        if (j != skip && glm::dot(d, d) <= h * h) out.push_back(j);
    }
    return out;
}

/// Points in [0, L) × [−0.5, 1.5] × [0, L): random, on the seams, and on a lattice with pairs
/// exactly h apart across the seam.
std::vector<glm::vec3> periodicPoints(float L, float h, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<glm::vec3> x;
    for (int i = 0; i < 1500; ++i) x.emplace_back(L * u(rng), -0.5f + 2.0f * u(rng), L * u(rng));
    for (int i = 0; i < 100; ++i) {
        x.emplace_back(0.0f, u(rng), L * u(rng));                               // on the min face
        x.emplace_back(std::nextafter(L, 0.0f), u(rng), L * u(rng));             // just below max
        x.emplace_back(L * u(rng), u(rng), 0.5f * h * u(rng));                  // near the z seam
    }
    for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 8; ++k) x.emplace_back(0.5f * h * static_cast<float>(i), 0.25f, 0.5f * h * static_cast<float>(k));
    for (glm::vec3& p : x) p = glm::vec3(std::min(p.x, std::nextafter(L, 0.0f)), p.y, std::min(p.z, std::nextafter(L, 0.0f)));
    return x;
}

// Periods of 2 h (the least allowed: two cells), 2.3 h (two cells, the last wider) and 5.5 h.
TEST(PeriodicNeighbors, MatchBruteForceWithTheNearestImage) {
    const float h = 0.25f;
    for (const float L : {2.0f * h, 2.3f * h, 5.5f * h}) {
        const PeriodicBox box = PeriodicBox::make({0, -0.5f, 0}, {L, 1.5f, L}, {true, false, true});
        const auto x = periodicPoints(L, h, 11);
        for (const int threads : {1, 2}) {
            UniformGrid grid;
            grid.build(x, h, threads, box);
            NeighborList list;
            list.build(grid, x, h, threads);
            std::uint64_t acrossSeam = 0;
            for (std::uint32_t i = 0; i < x.size(); ++i) {
                auto found = std::vector<std::uint32_t>(list.of(i).begin(), list.of(i).end());
                std::sort(found.begin(), found.end());
                ASSERT_EQ(found, bruteForce(box, x[i], x, h, i)) << "period " << L << ", particle " << i;
                for (auto j : found) acrossSeam += glm::length(x[i] - x[j]) > h;
            }
            EXPECT_GT(acrossSeam, 1000u) << "the test must have many pairs across the seam";
        }
    }
}

TEST(PeriodicNeighbors, CrossSetQueryMatchesBruteForce) {
    const float h = 0.3f, L = 1.0f;
    const PeriodicBox box = PeriodicBox::make({0, 0, 0}, {L, 1, L}, {true, false, true});
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 0.999f);
    std::vector<glm::vec3> sources, queries;
    for (int i = 0; i < 800; ++i) sources.emplace_back(u(rng), u(rng), u(rng));
    for (int i = 0; i < 300; ++i) queries.emplace_back(u(rng), 1.6f * u(rng) - 0.3f, u(rng));  // some beyond the y faces
    UniformGrid grid;
    grid.build(sources, h, 2, box);
    tide::CrossNeighborList list;
    list.build(grid, sources, queries, h, 2);
    for (std::uint32_t i = 0; i < queries.size(); ++i) {
        auto found = std::vector<std::uint32_t>(list.of(i).begin(), list.of(i).end());
        std::sort(found.begin(), found.end());
        ASSERT_EQ(found, bruteForce(box, queries[i], sources, h, 0xffffffffu)) << "query " << i;
    }
}

TEST(PeriodicWalls, ShellLeavesOutPeriodicFacesAndContinuesAcrossTheSeam) {
    const float s = 0.02f;
    BoundaryParticles walls;
    walls.periodic = PeriodicBox::make({0, 0, 0}, {0.2f, 0.1f, 0.1f}, {true, false, true});
    walls.sampleBoxShell({0, 0, 0}, {0.2f, 0.1f, 0.1f}, s, 2, 1.0f, 2.0f * s, 1);
    // Only the two y walls: 10 × 5 columns, 2 layers each.
    ASSERT_EQ(walls.size(), 2u * 2u * 10u * 5u);
    std::map<float, int> xs;
    for (const glm::vec3& p : walls.position) {
        EXPECT_TRUE(p.x > 0.0f && p.x < 0.2f && p.z > 0.0f && p.z < 0.1f) << p.x << " " << p.z;
        EXPECT_TRUE(p.y < 0.0f || p.y > 0.1f) << p.y;
        ++xs[p.x];
    }
    // The lattice runs on across the seam: first and last columns half a spacing from the faces.
    EXPECT_NEAR(xs.begin()->first, 0.5f * s, 1e-6f);
    EXPECT_NEAR(xs.rbegin()->first, 0.2f - 0.5f * s, 1e-6f);
}

WorldDef channel(const std::string& solver) {
    WorldDef def;
    def.domainMin = {0.0f, 0.0f, 0.0f};
    def.domainMax = {0.1f, 0.1f, 0.1f};
    def.periodic = {true, false, true};
    def.particleSpacing = 0.01f;
    def.threads = 1;
    def.solver.method = solver;
    return def;
}

TEST(PeriodicWorld, RejectsAPeriodTooShortAndPlacesBlocksWithinIt) {
    WorldDef def = channel("dfsph");
    def.domainMax.x = 0.035f;  // < 2 × 0.02 m
    try {
        World world(def);
        FAIL() << "accepted a periodic axis shorter than 2 supports";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("domain.periodic"), std::string::npos) << e.what();
    }
    def.domainMax.x = 0.04f;  // exactly 2 supports
    World ok(def);
    def.walls = false;
    World open(def);
    EXPECT_TRUE(open.insideDomain({0, 5, 0}, {0.04f, 6, 0.1f}));   // y is open
    EXPECT_FALSE(open.insideDomain({0, 0, 0}, {0.06f, 0.1f, 0.1f}));  // beyond the x period
}

/// A channel full of fluid, at rest under gravity −y: the lattice is invariant along the
/// periodic axes, so every particle of a layer must have the same density as its layer,
/// those beside the seam included (a missing or doubled neighbour there would show).
TEST(PeriodicWorld, SeamIsInvisibleToTheDensity) {
    for (const std::string solver : {"classic", "wcsph", "dfsph"}) {
        World world(channel(solver));
        world.addMaterial({});
        ASSERT_EQ(world.addBlock({{0, 0, 0}, {0.1f, 0.05f, 0.1f}, {0, 0, 0}, 0}), AddStatus::Added);
        world.step(1e-4);
        const ParticleStore& p = world.particles();
        std::map<int, std::pair<float, float>> layers;  // y layer → min, max density
        for (std::uint32_t i = 0; i < p.size(); ++i) {
            const int layer = static_cast<int>(std::floor(p.position[i].y / 0.01f));
            auto [it, added] = layers.try_emplace(layer, p.density[i], p.density[i]);
            it->second.first = std::min(it->second.first, p.density[i]);
            it->second.second = std::max(it->second.second, p.density[i]);
        }
        for (const auto& [layer, range] : layers)
            EXPECT_LT(range.second - range.first, 1e-3f * 1000.0f) << solver << ", layer " << layer;
    }
}

/// The channel's fluid moves as a whole along x and z: every particle must cross the seams
/// and come back in at min, keep its velocity (the seam exerts no force), and none is lost.
TEST(PeriodicWorld, FlowCrossesTheSeamsAndConservesParticles) {
    for (const std::string solver : {"classic", "wcsph", "dfsph"}) {
        WorldDef def = channel(solver);
        def.gravity = {0, 0, 0};
        def.solver.viscosity = "xsph";  // no wall friction: the whole fluid keeps its speed
        World world(def);
        world.addMaterial({});
        const glm::vec3 v0(0.5f, 0.0f, 0.2f);
        ASSERT_EQ(world.addBlock({{0, 0, 0}, {0.1f, 0.1f, 0.1f}, v0, 0}), AddStatus::Added);
        const ParticleStore& p = world.particles();
        const std::uint32_t n = p.size();
        std::vector<glm::vec3> start(n);
        for (std::uint32_t i = 0; i < n; ++i) start[p.id[i]] = p.position[i];
        const float t = 0.3f;  // 0.15 m along x (1.5 periods), 0.06 m along z
        world.advance(t);
        ASSERT_EQ(p.size(), n) << solver;
        EXPECT_EQ(world.countEscapedParticles(), 0u) << solver;
        const PeriodicBox box = PeriodicBox::make(def.domainMin, def.domainMax, def.periodic);
        float worstShift = 0.0f, worstSpeed = 0.0f;
        for (std::uint32_t i = 0; i < n; ++i) {
            ASSERT_TRUE(p.position[i].x >= 0.0f && p.position[i].x < 0.1f && p.position[i].z >= 0.0f && p.position[i].z < 0.1f)
                << solver << ": particle " << p.id[i] << " outside the period";
            // Where it should be: start + v0 t, wrapped; compared by the nearest image.
            const glm::vec3 expected = box.wrap(start[p.id[i]] + t * v0);
            worstShift = std::max(worstShift, glm::length(box.delta(p.position[i], expected)));
            worstSpeed = std::max(worstSpeed, glm::length(p.velocity[i] - v0));
        }
        std::printf("%s: worst position error %.2e m, worst velocity error %.2e m/s, mean density error %.2e\n",
                    solver.c_str(), worstShift, worstSpeed, world.stats().meanDensityError);
        EXPECT_LT(worstShift, 0.1f * def.particleSpacing) << solver;
        // classic's acoustic noise from the walls reaches 2 % of the speed (beside the y walls, not the seams).
        EXPECT_LT(worstSpeed, 0.05f * glm::length(v0)) << solver;
    }
}

}  // namespace
