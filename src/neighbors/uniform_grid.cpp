#include "neighbors/uniform_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.hpp"

namespace tide {

namespace {
/// The bounding box of the finite coordinates (non-finite ones count as 0), in one pass
/// over the points per thread; min and max do not depend on the order, so neither on the
/// thread count.
void finiteBounds(std::span<const glm::vec3> positions, int threads, glm::vec3& lo, glm::vec3& hi) {
    const auto n = static_cast<std::int64_t>(positions.size());
    constexpr float inf = std::numeric_limits<float>::infinity();
    float lx = inf, ly = inf, lz = inf, hx = -inf, hy = -inf, hz = -inf;
    auto finiteOr0 = [](float v) { return std::isfinite(v) ? v : 0.0f; };
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1 && n >= kParallelGrain) \
    reduction(min : lx, ly, lz) reduction(max : hx, hy, hz)
    for (std::int64_t i = 0; i < n; ++i) {
        const glm::vec3& x = positions[static_cast<std::size_t>(i)];
        const float px = finiteOr0(x.x), py = finiteOr0(x.y), pz = finiteOr0(x.z);
        lx = std::min(lx, px);
        ly = std::min(ly, py);
        lz = std::min(lz, pz);
        hx = std::max(hx, px);
        hy = std::max(hy, py);
        hz = std::max(hz, pz);
    }
    lo = {lx, ly, lz};
    hi = {hx, hy, hz};
}
}  // namespace

void UniformGrid::build(std::span<const glm::vec3> positions, float minCellSize, int threads,
                        const PeriodicBox& periodic, const glm::vec3* anchor) {
    const auto n = static_cast<std::uint32_t>(positions.size());
    periodic_ = periodic;
    glm::vec3 lo(0.0f), hi(0.0f);
    if (n > 0) finiteBounds(positions, threads, lo, hi);
    for (int axis = 0; axis < 3; ++axis)
        if (periodic.periodic(axis)) {
            lo[axis] = periodic.min[axis];
            hi[axis] = periodic.max[axis];
        }
    glm::vec3 extent = hi - lo;
    const double maxCells = 8.0 * n + 4096.0;
    double cell = minCellSize;
    // Cells along an axis: enough to hold the extent's far end, or exactly tiling a period.
    auto cellsAlong = [&](int axis, double edge) {
        const double cells = std::floor(extent[axis] / edge);
        return periodic.periodic(axis) ? std::max(1.0, cells) : cells + 1.0;
    };
    auto cellsFor = [&](double edge) { return cellsAlong(0, edge) * cellsAlong(1, edge) * cellsAlong(2, edge); };
    if (!anchor)
        while (cellsFor(cell) > maxCells) cell *= 1.5;
    cellSize_ = static_cast<float>(cell);
    invCellSize_ = 1.0f / cellSize_;
    anchor_ = lo;
    anchorCells_ = glm::vec3(0.0f);
    if (anchor)
        for (int axis = 0; axis < 3; ++axis) {
            if (periodic.periodic(axis)) continue;  // the period is the same on every process
            // The origin moves down to the anchor's lattice; hi stays covered (one cell more).
            anchorCells_[axis] = std::floor((lo[axis] - (*anchor)[axis]) * invCellSize_);
            anchor_[axis] = (*anchor)[axis];
            lo[axis] = anchor_[axis] + anchorCells_[axis] * cellSize_;
        }
    origin_ = lo;
    extent = hi - lo;
    dims_ = glm::ivec3(static_cast<int>(cellsAlong(0, cell)), static_cast<int>(cellsAlong(1, cell)),
                       static_cast<int>(cellsAlong(2, cell)));
    if (anchor)  // the far end's cell by cellOf's own arithmetic: no point is clamped into a neighbour
        for (int axis = 0; axis < 3; ++axis)
            if (!periodic.periodic(axis))
                dims_[axis] = static_cast<int>(std::floor((hi[axis] - anchor_[axis]) * invCellSize_ - anchorCells_[axis])) + 1;
    const auto cells = static_cast<std::uint32_t>(dims_.x) * static_cast<std::uint32_t>(dims_.y) *
                       static_cast<std::uint32_t>(dims_.z);

    // Stable counting sort with no per-particle scratch (memory: issue 8): the cells are
    // computed into sorted_ to be counted, then again while scattering, last index first,
    // each into the slot below its cell's end; that leaves the starts one entry up.
    sorted_.resize(n);
    parallelFor(n, threads, [&](std::uint32_t i) { sorted_[i] = cellIndex(cellOf(positions[i])); });
    cellStart_.assign(static_cast<std::size_t>(cells) + 1, 0);
    for (std::uint32_t i = 0; i < n; ++i) ++cellStart_[sorted_[i] + 1];
    for (std::uint32_t c = 0; c < cells; ++c) cellStart_[c + 1] += cellStart_[c];
    for (std::uint32_t i = n; i-- > 0;) sorted_[--cellStart_[cellIndex(cellOf(positions[i])) + 1]] = i;
    std::copy(cellStart_.begin() + 1, cellStart_.end(), cellStart_.begin());
    cellStart_[cells] = n;
}

}  // namespace tide
