// Domain decomposition by recursive coordinate bisection (src/comm/partition_rcb.hpp): boxes
// that tile the grid, balanced cost, and ghost counts checked against a brute-force count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "comm/partition_rcb.hpp"

namespace {

using namespace tide::comm;

/// A tank of water: full cells (8 particles: cells are two spacings wide) below `fill` of the
/// height, none above: the cost of a flume or an ocean's near field.
std::vector<std::uint64_t> tankCost(const CellGrid& g, double fill) {
    std::vector<std::uint64_t> cost(static_cast<std::size_t>(g.cellCount()), 0);
    const int wet = static_cast<int>(fill * g.cells[1]);
    for (int z = 0; z < g.cells[2]; ++z)
        for (int y = 0; y < wet; ++y)
            for (int x = 0; x < g.cells[0]; ++x) cost[static_cast<std::size_t>(g.index(x, y, z))] = 8;
    return cost;
}

bool inside(const CellBox& b, int x, int y, int z) {
    return x >= b.lo[0] && x < b.hi[0] && y >= b.lo[1] && y < b.hi[1] && z >= b.lo[2] && z < b.hi[2];
}

/// Distance in cells from coordinate c to the interval [lo, hi) on an axis of n cells.
int axisGap(int c, int lo, int hi, int n, bool periodic) {
    auto gap = [&](int v) { return v < lo ? lo - v : (v >= hi ? v - hi + 1 : 0); };
    int best = gap(c);
    if (periodic) best = std::min({best, gap(c - n), gap(c + n)});
    return best;
}

TEST(PartitionRcb, BoxesTileTheGridAndBalanceTheWater) {
    const CellGrid grid{{64, 24, 16}, {false, false, false}};
    const std::vector<std::uint64_t> cost = tankCost(grid, 0.5);
    for (int ranks : {1, 2, 3, 4, 7, 16}) {
        const std::vector<CellBox> boxes = partitionRcb(grid, cost, ranks);
        ASSERT_EQ(boxes.size(), static_cast<std::size_t>(ranks));
        std::vector<int> owners(static_cast<std::size_t>(grid.cellCount()), 0);
        for (const CellBox& b : boxes)
            for (int z = b.lo[2]; z < b.hi[2]; ++z)
                for (int y = b.lo[1]; y < b.hi[1]; ++y)
                    for (int x = b.lo[0]; x < b.hi[0]; ++x) ++owners[static_cast<std::size_t>(grid.index(x, y, z))];
        EXPECT_TRUE(std::all_of(owners.begin(), owners.end(), [](int n) { return n == 1; })) << ranks << " ranks";
        const std::vector<RankLoad> loads = rankLoads(grid, cost, boxes);
        // Cuts fall between whole cell slabs, each within half a slab of its target: at these
        // sizes (slabs of 1/64 to 1/12 of a box) the worst rank stays within 10 % of its share.
        EXPECT_LT(loadImbalance(loads), 1.1) << ranks << " ranks";
        std::uint64_t owned = 0;
        for (const RankLoad& l : loads) owned += l.owned;
        EXPECT_EQ(owned, 64u * 12u * 16u * 8u);
        // The same partition every time (every rank computes it for itself).
        const std::vector<CellBox> again = partitionRcb(grid, cost, ranks);
        for (int r = 0; r < ranks; ++r) {
            EXPECT_EQ(again[r].lo, boxes[r].lo);
            EXPECT_EQ(again[r].hi, boxes[r].hi);
        }
    }
}

TEST(PartitionRcb, GhostsAndNeighboursMatchABruteForceCount) {
    for (const bool periodicX : {false, true}) {
        const CellGrid grid{{20, 10, 9}, {periodicX, false, false}};
        std::vector<std::uint64_t> cost(static_cast<std::size_t>(grid.cellCount()));
        for (std::size_t c = 0; c < cost.size(); ++c) cost[c] = (c * 7919u) % 5u;  // uneven, some empty
        const std::vector<CellBox> boxes = partitionRcb(grid, cost, 5);
        const std::vector<RankLoad> loads = rankLoads(grid, cost, boxes);
        for (std::size_t r = 0; r < boxes.size(); ++r) {
            std::uint64_t ghosts = 0;
            std::set<int> neighbours;
            for (int z = 0; z < grid.cells[2]; ++z)
                for (int y = 0; y < grid.cells[1]; ++y)
                    for (int x = 0; x < grid.cells[0]; ++x) {
                        const CellBox& b = boxes[r];
                        if (inside(b, x, y, z)) continue;
                        const int gap = std::max({axisGap(x, b.lo[0], b.hi[0], grid.cells[0], periodicX),
                                                  axisGap(y, b.lo[1], b.hi[1], grid.cells[1], false),
                                                  axisGap(z, b.lo[2], b.hi[2], grid.cells[2], false)});
                        if (gap > 1) continue;
                        const std::uint64_t c = cost[static_cast<std::size_t>(grid.index(x, y, z))];
                        ghosts += c;
                        for (std::size_t o = 0; o < boxes.size(); ++o)
                            if (c > 0 && inside(boxes[o], x, y, z)) neighbours.insert(static_cast<int>(o));
                    }
            EXPECT_EQ(loads[r].ghosts, ghosts) << "rank " << r << (periodicX ? " periodic" : "");
            EXPECT_EQ(loads[r].neighbours, std::vector<int>(neighbours.begin(), neighbours.end())) << "rank " << r;
        }
    }
}

TEST(PartitionRcb, RefusesRankCountsThatLeaveARankEmpty) {
    const CellGrid grid{{4, 1, 1}, {false, false, false}};
    const std::vector<std::uint64_t> cost{1, 1, 1, 1};
    try {
        partitionRcb(grid, cost, 5);
        FAIL() << "5 ranks on 4 cells";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("more ranks (5) than cells (4)"), std::string::npos) << e.what();
    }
    const std::vector<std::uint64_t> oneWetCell{0, 0, 9, 0};
    try {
        partitionRcb(grid, oneWetCell, 2);
        FAIL() << "2 ranks, particles in one cell";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("without particles"), std::string::npos) << e.what();
    }
    EXPECT_THROW(partitionRcb(grid, cost, 0), std::invalid_argument);
    EXPECT_THROW(partitionRcb(grid, std::vector<std::uint64_t>{1, 1}, 1), std::invalid_argument);
}

}  // namespace
