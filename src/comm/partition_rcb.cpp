#include "comm/partition_rcb.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace tide::comm {
namespace {

std::uint64_t costIn(const CellGrid& grid, std::span<const std::uint64_t> cost, const CellBox& box) {
    std::uint64_t total = 0;
    for (int z = box.lo[2]; z < box.hi[2]; ++z)
        for (int y = box.lo[1]; y < box.hi[1]; ++y)
            for (int x = box.lo[0]; x < box.hi[0]; ++x) total += cost[static_cast<std::size_t>(grid.index(x, y, z))];
    return total;
}

/// Cost of each slab of `box` across `axis` (slab k = cells with coordinate lo + k).
std::vector<std::uint64_t> slabCosts(const CellGrid& grid, std::span<const std::uint64_t> cost, const CellBox& box,
                                     int axis) {
    std::vector<std::uint64_t> slab(static_cast<std::size_t>(box.hi[axis] - box.lo[axis]), 0);
    for (int z = box.lo[2]; z < box.hi[2]; ++z)
        for (int y = box.lo[1]; y < box.hi[1]; ++y)
            for (int x = box.lo[0]; x < box.hi[0]; ++x) {
                const int c[3] = {x, y, z};
                slab[static_cast<std::size_t>(c[axis] - box.lo[axis])] += cost[static_cast<std::size_t>(grid.index(x, y, z))];
            }
    return slab;
}

struct Bisection {
    const CellGrid& grid;
    std::span<const std::uint64_t> cost;
    int ranks;
    std::vector<CellBox> boxes;

    void split(const CellBox& box, int firstRank, int count) {
        if (count == 1) {
            if (costIn(grid, cost, box) == 0)
                throw std::invalid_argument("partition: " + std::to_string(ranks) + " ranks leave rank " +
                                            std::to_string(firstRank) +
                                            " without particles; run on fewer ranks");
            boxes[static_cast<std::size_t>(firstRank)] = box;
            return;
        }
        const int lowRanks = count / 2;
        // Longest axis first (ties: x, y, z), so boxes stay compact and ghost rings small.
        std::array<int, 3> axes{0, 1, 2};
        std::stable_sort(axes.begin(), axes.end(), [&](int a, int b) {
            return box.hi[a] - box.lo[a] > box.hi[b] - box.lo[b];
        });
        const int axis = axes[0];
        const int extent = box.hi[axis] - box.lo[axis];
        if (extent < 2)
            throw std::invalid_argument("partition: more ranks (" + std::to_string(ranks) + ") than cells (" +
                                        std::to_string(grid.cellCount()) + ") to split among them");
        const std::vector<std::uint64_t> slab = slabCosts(grid, cost, box, axis);
        const std::uint64_t total = std::accumulate(slab.begin(), slab.end(), std::uint64_t{0});
        if (total > std::numeric_limits<std::uint64_t>::max() / static_cast<unsigned>(count))
            throw std::invalid_argument("partition: a total cost of " + std::to_string(total) + " is too large");
        // The plane p (cells lo..lo+p-1 below it) whose cost below is nearest to
        // total * lowRanks / count, compared exactly in integers (cost * count against
        // total * lowRanks); ties go to the lower plane.
        const std::uint64_t target = total * static_cast<unsigned>(lowRanks);
        std::uint64_t below = 0;
        int bestPlane = 1;
        std::uint64_t bestMiss = std::numeric_limits<std::uint64_t>::max();
        for (int p = 1; p < extent; ++p) {
            below += slab[static_cast<std::size_t>(p - 1)];
            const std::uint64_t scaled = below * static_cast<unsigned>(count);
            const std::uint64_t miss = scaled > target ? scaled - target : target - scaled;
            if (miss < bestMiss) {
                bestMiss = miss;
                bestPlane = p;
            }
        }
        CellBox low = box, high = box;
        low.hi[axis] = box.lo[axis] + bestPlane;
        high.lo[axis] = low.hi[axis];
        split(low, firstRank, lowRanks);
        split(high, firstRank + lowRanks, count - lowRanks);
    }
};

}  // namespace

std::vector<CellBox> partitionRcb(const CellGrid& grid, std::span<const std::uint64_t> cost, int ranks) {
    if (ranks < 1) throw std::invalid_argument("partition: ranks must be at least 1, got " + std::to_string(ranks));
    for (int a = 0; a < 3; ++a)
        if (grid.cells[a] < 1)
            throw std::invalid_argument("partition: the grid needs at least one cell on each axis, axis " +
                                        std::to_string(a) + " has " + std::to_string(grid.cells[a]));
    if (static_cast<std::int64_t>(cost.size()) != grid.cellCount())
        throw std::invalid_argument("partition: " + std::to_string(cost.size()) + " cell costs for " +
                                    std::to_string(grid.cellCount()) + " cells");
    Bisection bisection{grid, cost, ranks, std::vector<CellBox>(static_cast<std::size_t>(ranks))};
    bisection.split(CellBox{{0, 0, 0}, grid.cells}, 0, ranks);
    return std::move(bisection.boxes);
}

std::vector<RankLoad> rankLoads(const CellGrid& grid, std::span<const std::uint64_t> cost,
                                std::span<const CellBox> boxes, int ghostCells) {
    std::vector<int> owner(static_cast<std::size_t>(grid.cellCount()), -1);
    for (std::size_t r = 0; r < boxes.size(); ++r) {
        const CellBox& b = boxes[r];
        for (int z = b.lo[2]; z < b.hi[2]; ++z)
            for (int y = b.lo[1]; y < b.hi[1]; ++y)
                for (int x = b.lo[0]; x < b.hi[0]; ++x) owner[static_cast<std::size_t>(grid.index(x, y, z))] = static_cast<int>(r);
    }
    std::vector<RankLoad> loads(boxes.size());
    for (std::size_t r = 0; r < boxes.size(); ++r) {
        const CellBox& b = boxes[r];
        RankLoad& load = loads[r];
        load.owned = costIn(grid, cost, b);
        std::array<int, 3> lo{}, hi{};
        for (int a = 0; a < 3; ++a) {
            lo[a] = b.lo[a] - ghostCells;
            hi[a] = b.hi[a] + ghostCells;
        }
        for (int z = lo[2]; z < hi[2]; ++z)
            for (int y = lo[1]; y < hi[1]; ++y)
                for (int x = lo[0]; x < hi[0]; ++x) {
                    std::array<int, 3> c{x, y, z};
                    const bool inside = x >= b.lo[0] && x < b.hi[0] && y >= b.lo[1] && y < b.hi[1] &&
                                        z >= b.lo[2] && z < b.hi[2];
                    if (inside) continue;
                    bool exists = true;
                    for (int a = 0; a < 3 && exists; ++a) {
                        if (c[a] >= 0 && c[a] < grid.cells[a]) continue;
                        if (!grid.periodic[a]) exists = false;
                        else c[a] = (c[a] % grid.cells[a] + grid.cells[a]) % grid.cells[a];
                    }
                    if (!exists) continue;
                    const auto cell = static_cast<std::size_t>(grid.index(c[0], c[1], c[2]));
                    load.ghosts += cost[cell];
                    // A cell without particles sends nothing: no message for it alone.
                    if (owner[cell] != static_cast<int>(r) && cost[cell] > 0) load.neighbours.push_back(owner[cell]);
                }
        std::sort(load.neighbours.begin(), load.neighbours.end());
        load.neighbours.erase(std::unique(load.neighbours.begin(), load.neighbours.end()), load.neighbours.end());
    }
    return loads;
}

double loadImbalance(std::span<const RankLoad> loads) {
    if (loads.empty()) return 1.0;
    std::uint64_t most = 0, total = 0;
    for (const RankLoad& l : loads) {
        most = std::max(most, l.owned);
        total += l.owned;
    }
    return total == 0 ? 1.0 : static_cast<double>(most) * static_cast<double>(loads.size()) / static_cast<double>(total);
}

}  // namespace tide::comm
