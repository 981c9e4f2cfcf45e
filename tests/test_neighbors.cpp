// Grid + CSR neighbour lists against brute force, including cell borders and r == h.
#include <algorithm>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "neighbors/neighbor_list.hpp"
#include "neighbors/uniform_grid.hpp"

namespace {

using tide::NeighborList;
using tide::UniformGrid;

std::vector<glm::vec3> testPoints(float h) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 2.0f);
    std::vector<glm::vec3> points;
    for (int i = 0; i < 3000; ++i) points.emplace_back(u(rng), u(rng), 0.5f * u(rng));
    // Exactly representable points on cell borders, and pairs exactly h apart (h = 0.25).
    for (int i = -4; i <= 8; ++i)
        for (int j = -4; j <= 8; ++j)
            for (int k = 0; k < 3; ++k) points.emplace_back(h * i, h * j, h * k);
    points.emplace_back(0.5f, 0.5f, 0.5f);
    points.emplace_back(0.5f, 0.5f, 0.5f);  // a duplicate: distance 0
    return points;
}

std::vector<std::uint32_t> bruteForce(const std::vector<glm::vec3>& x, std::uint32_t i, float h) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t j = 0; j < x.size(); ++j) {
        const glm::vec3 d = x[i] - x[j];
        if (j != i && d.x * d.x + d.y * d.y + d.z * d.z <= h * h) out.push_back(j);
    }
    return out;
}

TEST(Neighbors, MatchBruteForceIncludingBordersAndExactDistance) {
    const float h = 0.25f;
    const auto x = testPoints(h);
    UniformGrid grid;
    grid.build(x, h, 2);
    NeighborList list;
    list.build(grid, x, h, 2);
    std::uint64_t exactlyH = 0;
    for (std::uint32_t i = 0; i < x.size(); ++i) {
        auto found = std::vector<std::uint32_t>(list.of(i).begin(), list.of(i).end());
        std::sort(found.begin(), found.end());
        ASSERT_EQ(found, bruteForce(x, i, h)) << "particle " << i;
        for (auto j : found) exactlyH += glm::length(x[i] - x[j]) == h;
    }
    EXPECT_GT(exactlyH, 100u) << "the test set must contain pairs exactly h apart";
}

TEST(Neighbors, SameListsForOneAndTwoThreads) {
    const float h = 0.25f;
    const auto x = testPoints(h);
    UniformGrid g1, g2;
    g1.build(x, h, 1);
    g2.build(x, h, 2);
    NeighborList l1, l2;
    l1.build(g1, x, h, 1);
    l2.build(g2, x, h, 2);
    ASSERT_EQ(l1.pairCount(), l2.pairCount());
    for (std::uint32_t i = 0; i < x.size(); ++i)
        ASSERT_TRUE(std::ranges::equal(l1.of(i), l2.of(i))) << "particle " << i;
}

// Per-pair data (kernel factors, wall weights) is indexed by offset(i) + k: the particles'
// ranges must tile [0, pairCount) without gaps or overlaps, in the same pair order for any
// thread count (the offsets are recovered from the chunk kept in each count's top bits).
TEST(Neighbors, PairOffsetsTileThePairRangeForAnyThreadCount) {
    const float h = 0.25f;
    const auto x = testPoints(h);
    UniformGrid grid;
    grid.build(x, h, 1);
    std::vector<std::uint64_t> reference;
    for (int threads : {1, 2, 3}) {
        NeighborList list;
        list.build(grid, x, h, threads);
        std::vector<int> covered(list.slotCount(), 0);
        std::vector<std::uint64_t> offsets;
        std::uint64_t pairs = 0;
        for (std::uint32_t i = 0; i < x.size(); ++i) {
            offsets.push_back(list.offset(i));
            pairs += list.of(i).size();
            for (std::uint64_t k = 0; k < list.of(i).size(); ++k) {
                ASSERT_LT(list.offset(i) + k, list.slotCount()) << "particle " << i;
                ++covered[list.offset(i) + k];
            }
        }
        EXPECT_EQ(pairs, list.pairCount());
        // Each pair has a slot of its own; lists of offsets leave at most a block's padding each.
        EXPECT_TRUE(std::ranges::all_of(covered, [](int c) { return c <= 1; })) << threads << " threads";
        EXPECT_LT(list.slotCount(), list.pairCount() + x.size() * NeighborList::kOffsetBlock);
        if (reference.empty()) reference = offsets;
        EXPECT_EQ(offsets, reference) << threads << " threads";
    }
}

TEST(Neighbors, CrossSetQueryMatchesBruteForce) {
    const float h = 0.3f;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<glm::vec3> sources, queries;
    for (int i = 0; i < 800; ++i) sources.emplace_back(u(rng), u(rng), u(rng));
    for (int i = 0; i < 300; ++i) queries.emplace_back(u(rng), u(rng), u(rng));
    UniformGrid grid;
    grid.build(sources, h, 2);
    tide::CrossNeighborList list;
    list.build(grid, sources, queries, h, 2);
    for (std::uint32_t i = 0; i < queries.size(); ++i) {
        std::vector<std::uint32_t> expected;
        for (std::uint32_t j = 0; j < sources.size(); ++j)
            if (glm::dot(queries[i] - sources[j], queries[i] - sources[j]) <= h * h) expected.push_back(j);
        auto found = std::vector<std::uint32_t>(list.of(i).begin(), list.of(i).end());
        std::sort(found.begin(), found.end());
        ASSERT_EQ(found, expected);
    }
}

// Queries in cell order go in groups that share their candidates (buildCross): each list must
// still hold exactly the points within reach, in the grid's order, as the scalar test of a
// query's 27 cells lists them; some queries lie out of the grid's reach.
TEST(Neighbors, CrossListsOfQueriesInCellOrderKeepTheGridsOrder) {
    const float h = 0.1f;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<glm::vec3> sources, queries;
    for (int i = 0; i < 3000; ++i) sources.emplace_back(u(rng), 0.3f * u(rng), u(rng));  // a slab, like a floor
    for (float z = -0.12f; z < 1.1f; z += 0.037f)
        for (float y = -0.05f; y < 0.6f; y += 0.041f)
            for (float x = -0.13f; x < 1.12f; x += 0.029f) queries.emplace_back(x, y, z);
    UniformGrid queryGrid;  // queries in cell order, as a re-sorted fluid is
    queryGrid.build(queries, h, 1);
    std::vector<glm::vec3> ordered;
    for (const std::uint32_t q : queryGrid.sortedParticles()) ordered.push_back(queries[q]);
    UniformGrid grid;
    grid.build(sources, h, 2);
    std::vector<std::uint32_t> rank(sources.size());
    for (std::uint32_t k = 0; k < sources.size(); ++k) rank[grid.sortedParticles()[k]] = k;
    for (const int threads : {1, 2}) {
        tide::CrossNeighborList list;
        list.build(grid, sources, ordered, h, threads);
        std::size_t pairs = 0;
        for (std::uint32_t i = 0; i < ordered.size(); ++i) {
            std::vector<std::uint32_t> expected;
            for (std::uint32_t j = 0; j < sources.size(); ++j) {
                const glm::vec3 d = ordered[i] - sources[j];
                if (d.x * d.x + d.y * d.y + d.z * d.z <= h * h) expected.push_back(j);
            }
            std::sort(expected.begin(), expected.end(), [&](auto a, auto b) { return rank[a] < rank[b]; });
            ASSERT_EQ(std::vector<std::uint32_t>(list.of(i).begin(), list.of(i).end()), expected) << "query " << i;
            pairs += expected.size();
        }
        EXPECT_GT(pairs, 100000u);  // the test has lists to compare
    }
}

// Lists of neighbours near in storage hold 16-bit offsets; a list with a neighbour farther
// than an offset reaches keeps 32-bit indices, the others still offsets.
TEST(Neighbors, ListsKeepIndicesWhereOffsetsDoNotReach) {
    const float h = 0.25f;
    const auto near = testPoints(h);
    UniformGrid grid;
    grid.build(near, h, 2);
    NeighborList list;
    list.build(grid, near, h, 2);
    for (std::uint32_t i = 0; i < near.size(); ++i) ASSERT_NE(list.of(i).offsets(), nullptr) << "particle " << i;
    // 40,000 points a metre apart, but the first and the last 0.1 m apart: 39,999 indices.
    std::vector<glm::vec3> far;
    for (int i = 0; i < 40000; ++i) far.emplace_back(2.0f + static_cast<float>(i % 34), static_cast<float>(i / 34 % 34), static_cast<float>(i / 1156));
    far.front() = {0.0f, 0.0f, 0.0f};
    far.back() = {0.1f, 0.0f, 0.0f};
    far[1] = {0.0f, 0.2f, 0.0f};
    grid.build(far, h, 2);
    for (int threads : {1, 2}) {
        list.build(grid, far, h, threads);
        EXPECT_EQ(list.pairCount(), 6u);
        for (const std::uint32_t i : {0u, 1u, 39999u, 2u, 20000u}) {
            auto found = std::vector<std::uint32_t>(list.of(i).begin(), list.of(i).end());
            std::sort(found.begin(), found.end());
            ASSERT_EQ(found, bruteForce(far, i, h)) << "particle " << i;
            const bool reachesFar = i == 0 || i == 1 || i == 39999;
            EXPECT_EQ(list.of(i).indices() != nullptr, reachesFar) << "particle " << i;
        }
        std::vector<int> covered(list.slotCount(), 0);  // the indices' slots follow the offsets'
        for (const std::uint32_t i : {0u, 1u, 39999u})
            for (std::uint64_t k = 0; k < list.of(i).size(); ++k) ASSERT_EQ(++covered.at(list.offset(i) + k), 1);
    }
    // And the set that fits, with the same list after the misfit: the same lists as a fresh one.
    grid.build(near, h, 2);
    list.build(grid, near, h, 2);
    NeighborList fresh;
    fresh.build(grid, near, h, 2);
    for (std::uint32_t i = 0; i < near.size(); ++i) ASSERT_TRUE(std::ranges::equal(list.of(i), fresh.of(i))) << "particle " << i;
}

TEST(Neighbors, FarStrayParticleDoesNotBlowUpTheGrid) {
    std::vector<glm::vec3> x = {{0, 0, 0}, {0.01f, 0, 0}, {1e6f, 1e6f, 1e6f}};
    UniformGrid grid;
    grid.build(x, 0.02f, 1);
    EXPECT_LE(grid.cellCount(), 8u * 3u + 4096u);
    NeighborList list;
    list.build(grid, x, 0.02f, 1);
    EXPECT_EQ(list.of(0).size(), 1u);
    EXPECT_EQ(list.of(2).size(), 0u);
}

}  // namespace
