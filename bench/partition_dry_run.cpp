// A dry run of the domain decomposition (src/comm/partition_rcb.hpp) on an ocean far too
// large for this machine to step: the near field of scenes/ocean_pile.json scaled to 10^8
// particles (by default), split among 16-1024 ranks. Owned and ghost particles, neighbour
// ranks and messages are exact counts of the lattice the scene would fill; the bytes follow
// from what a ghost costs a step as measured on this machine (--bytes-per-ghost). docs/performance.md § Past one
// machine quotes its output.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

#include "comm/partition_rcb.hpp"

namespace {

/// Lattice points (i + 1/2) s, 0 <= i < n, per cell of width h along one axis.
std::vector<std::uint64_t> pointsPerCell(std::int64_t n, double s, double h, int cells) {
    std::vector<std::uint64_t> count(static_cast<std::size_t>(cells), 0);
    for (std::int64_t i = 0; i < n; ++i) {
        const auto c = static_cast<int>(std::floor((static_cast<double>(i) + 0.5) * s / h));
        ++count[static_cast<std::size_t>(std::min(c, cells - 1))];
    }
    return count;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Partition an ocean near field of N particles among ranks (no simulation)"};
    double particles = 1e8, lengthX = 2.4, lengthZ = 2.4, height = 0.6, depth = 0.32, supportRatio = 2.0;
    // What a ghost costs a step, as measured (bench/mpi_scaling.sh: the 200k dam break with
    // dfsph on 2 ranks sends 5.8 MB a step for 13.7 k ghosts: the record, migration and the
    // pressure solve's refreshes).
    double bytesPerGhost = 425;
    // As the split run (src/core/world_distributed.cpp): walls' pressure reaches 2 supports.
    constexpr int kGhostCells = 2;
    std::vector<int> rankCounts{16, 32, 64, 128, 256, 512, 1024};
    app.add_option("--particles", particles, "water particles (the spacing follows)")->check(CLI::PositiveNumber);
    app.add_option("--length-x", lengthX, "near field length in x, m (ocean_pile: 2.4)")->check(CLI::PositiveNumber);
    app.add_option("--length-z", lengthZ, "near field length in z, m (ocean_pile: 2.4)")->check(CLI::PositiveNumber);
    app.add_option("--height", height, "domain height, m (ocean_pile: 0.6)")->check(CLI::PositiveNumber);
    app.add_option("--depth", depth, "still-water depth, m (ocean_pile: 0.32)")->check(CLI::PositiveNumber);
    app.add_option("--support-ratio", supportRatio, "kernel support / spacing = cell width / spacing")
        ->check(CLI::PositiveNumber);
    app.add_option("--bytes-per-ghost", bytesPerGhost, "bytes a ghost costs a step (default: measured with dfsph)")
        ->check(CLI::PositiveNumber);
    app.add_option("--ranks", rankCounts, "rank counts")->check(CLI::PositiveNumber);
    CLI11_PARSE(app, argc, argv);
    if (depth > height) {
        std::fprintf(stderr, "--depth %g is above --height %g\n", depth, height);
        return 2;
    }

    const double spacing = std::cbrt(lengthX * lengthZ * depth / particles);
    const double h = supportRatio * spacing;
    tide::comm::CellGrid grid;
    grid.cells = {static_cast<int>(std::ceil(lengthX / h)), static_cast<int>(std::ceil(height / h)),
                  static_cast<int>(std::ceil(lengthZ / h))};
    const auto nx = static_cast<std::int64_t>(std::floor(lengthX / spacing));
    const auto ny = static_cast<std::int64_t>(std::floor(depth / spacing));
    const auto nz = static_cast<std::int64_t>(std::floor(lengthZ / spacing));
    const auto px = pointsPerCell(nx, spacing, h, grid.cells[0]);
    const auto py = pointsPerCell(ny, spacing, h, grid.cells[1]);
    const auto pz = pointsPerCell(nz, spacing, h, grid.cells[2]);
    std::vector<std::uint64_t> cost(static_cast<std::size_t>(grid.cellCount()));
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x)
                cost[static_cast<std::size_t>(grid.index(x, y, z))] = px[x] * py[y] * pz[z];
    const std::uint64_t total = std::accumulate(cost.begin(), cost.end(), std::uint64_t{0});
    std::printf("near field %.2f x %.2f m, depth %.2f m: spacing %.3g mm, %llu particles, %d x %d x %d cells\n",
                lengthX, lengthZ, depth, spacing * 1e3, static_cast<unsigned long long>(total), grid.cells[0],
                grid.cells[1], grid.cells[2]);
    std::printf("ghost rings %d cells deep; %g B a ghost a step (measured on 200k particles)\n\n", kGhostCells, bytesPerGhost);
    std::printf("%6s %12s %10s %12s %12s %10s %10s %12s %14s %8s\n", "ranks", "owned/rank", "imbalance",
                "ghosts/owned", "max ghosts", "nbrs mean", "nbrs max", "msgs/exch", "MB/step max", "time s");
    for (const int ranks : rankCounts) {
        const auto start = std::chrono::steady_clock::now();
        const auto boxes = tide::comm::partitionRcb(grid, cost, ranks);
        const auto loads = tide::comm::rankLoads(grid, cost, boxes, kGhostCells);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::uint64_t ghosts = 0, maxGhosts = 0, messages = 0;
        std::size_t maxNeighbours = 0;
        for (const auto& l : loads) {
            ghosts += l.ghosts;
            maxGhosts = std::max(maxGhosts, l.ghosts);
            messages += l.neighbours.size();
            maxNeighbours = std::max(maxNeighbours, l.neighbours.size());
        }
        const double bytesPerStep = static_cast<double>(maxGhosts) * bytesPerGhost;
        std::printf("%6d %12.0f %10.4f %12.4f %12llu %10.2f %10zu %12llu %14.2f %8.1f\n", ranks,
                    static_cast<double>(total) / ranks, tide::comm::loadImbalance(loads),
                    static_cast<double>(ghosts) / static_cast<double>(total),
                    static_cast<unsigned long long>(maxGhosts), static_cast<double>(messages) / ranks, maxNeighbours,
                    static_cast<unsigned long long>(messages), bytesPerStep / 1e6, seconds);
    }
}
