#pragma once
/// \file
/// Domain decomposition over the global cell grid by recursive coordinate bisection (Berger &
/// Bokhari 1987, "A partitioning strategy for nonuniform problems on multiprocessors", IEEE
/// Trans. Computers C-36(5)): the box of cells is cut across its longest axis at the plane
/// that splits the cells' cost in the ratio of the ranks on either side, and each half is cut
/// again until every rank has a box. Boxes of whole cells, with the grid's cells one kernel
/// support wide, make a rank's ghost layer exactly the ring of cells around its box.
///
/// A pure function of the grid and the costs: every rank computes the same partition.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace tide::comm {

/// A box of cells, half-open: cells lo[a] <= c < hi[a] on each axis a.
struct CellBox {
    std::array<int, 3> lo{0, 0, 0};
    std::array<int, 3> hi{0, 0, 0};

    [[nodiscard]] std::int64_t cellCount() const {
        return std::int64_t{hi[0] - lo[0]} * (hi[1] - lo[1]) * (hi[2] - lo[2]);
    }
};

/// The global cell grid: cells per axis and which axes wrap (periodic domains).
struct CellGrid {
    std::array<int, 3> cells{1, 1, 1};
    std::array<bool, 3> periodic{false, false, false};

    [[nodiscard]] std::int64_t cellCount() const { return std::int64_t{cells[0]} * cells[1] * cells[2]; }
    /// Index of cell (x, y, z), x fastest.
    [[nodiscard]] std::int64_t index(int x, int y, int z) const {
        return (std::int64_t{z} * cells[1] + y) * cells[0] + x;
    }
};

/// One box per rank (rank r owns boxes[r]), covering the grid without overlap. `cost` holds
/// one non-negative cost per cell (particles, or measured work), x fastest. Throws
/// std::invalid_argument when a rank would get no cells or no cost (more ranks than the
/// grid can split, or than cells with particles), naming the counts.
std::vector<CellBox> partitionRcb(const CellGrid& grid, std::span<const std::uint64_t> cost, int ranks);

/// What a partition costs each rank: its own particles, the ghosts it receives (the cost of
/// the cells within `ghostCells` of its box, periodic images included), and the ranks it
/// exchanges with.
struct RankLoad {
    std::uint64_t owned = 0;
    std::uint64_t ghosts = 0;
    std::vector<int> neighbours;  ///< ranks owning a ghost cell of this rank, ascending
};

std::vector<RankLoad> rankLoads(const CellGrid& grid, std::span<const std::uint64_t> cost,
                                std::span<const CellBox> boxes, int ghostCells = 1);

/// max over ranks / mean over ranks of the owned cost (1 = perfectly balanced).
double loadImbalance(std::span<const RankLoad> loads);

}  // namespace tide::comm
