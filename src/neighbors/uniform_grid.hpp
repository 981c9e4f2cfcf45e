#pragma once
/// \file
/// A dense uniform grid over the particles' bounding box, built each step by a stable
/// counting sort of particle indices into cells (the seed's `Grid`). Cells are at least
/// the search radius wide, so a particle's neighbours lie in its 3×3×3 block of cells.
/// Cell index = x + dims.x · (y + dims.y · z): along x, neighbouring cells are adjacent
/// in the sorted order, so a 3×3×3 search reads 9 contiguous ranges.
///
/// On a periodic axis (see core/periodic_box.hpp) the grid spans the domain's period
/// exactly, floor(period / cell) cells (the last one takes the remainder), and a cell's
/// neighbours wrap around: the first and last cells are adjacent. Each distinct cell is
/// visited once, also when an axis has fewer than 3 cells.

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/ext/vector_int3.hpp>

#include "core/periodic_box.hpp"

namespace tide {

class UniformGrid {
public:
    /// Bin `positions` into cells of edge ≥ minCellSize. The edge grows when the bounding
    /// box would need more than ~8 cells per particle, so a stray particle far away costs
    /// memory proportional to the particle count, never to the distance.
    /// On the periodic axes of `periodic` the grid covers the period instead of the points.
    /// With an `anchor` (a run split among processes), the cell edge is minCellSize exactly
    /// and cell boundaries lie at anchor + k·edge, computed from the anchor, so every process
    /// bins a point into the same global cell and visits neighbours in the same order.
    void build(std::span<const glm::vec3> positions, float minCellSize, int threads, const PeriodicBox& periodic = {},
               const glm::vec3* anchor = nullptr);

    [[nodiscard]] float cellSize() const { return cellSize_; }
    /// Whether no particle was binned.
    [[nodiscard]] bool empty() const { return sorted_.empty(); }
    [[nodiscard]] glm::ivec3 dims() const { return dims_; }
    [[nodiscard]] glm::vec3 origin() const { return origin_; }
    /// The periodic axes the grid was built with: pair vectors over its points use periodic().delta().
    [[nodiscard]] const PeriodicBox& periodic() const { return periodic_; }
    /// Cell coordinates of a point, clamped into the grid (non-finite input maps to a border cell).
    [[nodiscard]] glm::ivec3 cellOf(const glm::vec3& x) const {
        const glm::vec3 c = (x - anchor_) * invCellSize_ - anchorCells_;
        return {clampCoord(c.x, dims_.x), clampCoord(c.y, dims_.y), clampCoord(c.z, dims_.z)};
    }
    [[nodiscard]] std::uint32_t cellIndex(const glm::ivec3& c) const {
        return static_cast<std::uint32_t>(c.x + dims_.x * (c.y + dims_.y * c.z));
    }
    /// First position in sortedParticles() of cell c; cellStart(c + 1) is one past its last.
    [[nodiscard]] std::uint32_t cellStart(std::uint32_t c) const { return cellStart_[c]; }
    /// Particle indices ordered by cell, stable (by index) inside a cell.
    [[nodiscard]] std::span<const std::uint32_t> sortedParticles() const { return sorted_; }
    [[nodiscard]] std::uint32_t cellCount() const { return static_cast<std::uint32_t>(cellStart_.size() - 1); }

    /// Calls f(begin, end) for the 9 contiguous runs of sortedParticles() that make up the
    /// 3×3×3 cells around cell c, in a fixed order (z, then y); more runs where a periodic
    /// axis wraps.
    template <class F>
    void forEachNeighborRun(const glm::ivec3& c, F&& f) const {
        if (periodic_.any) {
            forEachWrappedNeighborRun(c, f);
            return;
        }
        const int x0 = c.x > 0 ? c.x - 1 : 0;
        const int x1 = c.x + 1 < dims_.x ? c.x + 1 : dims_.x - 1;
        for (int z = c.z - 1; z <= c.z + 1; ++z) {
            if (z < 0 || z >= dims_.z) continue;
            for (int y = c.y - 1; y <= c.y + 1; ++y) {
                if (y < 0 || y >= dims_.y) continue;
                const std::uint32_t first = cellIndex({x0, y, z});
                const std::uint32_t last = cellIndex({x1, y, z});
                f(cellStart_[first], cellStart_[last + 1]);
            }
        }
    }

    /// Calls f(begin, end) for the runs of sortedParticles() of every cell that holds points of
    /// the box [lo, hi] (clamped into the grid), one run per row of cells along x, in the order
    /// of forEachNeighborRun (z, then y). Not periodic.
    template <class F>
    void forEachRunInBox(const glm::vec3& lo, const glm::vec3& hi, F&& f) const {
        const glm::ivec3 a = cellOf(lo), b = cellOf(hi);
        for (int z = a.z; z <= b.z; ++z)
            for (int y = a.y; y <= b.y; ++y) f(cellStart_[cellIndex({a.x, y, z})], cellStart_[cellIndex({b.x, y, z}) + 1]);
    }

private:
    static int clampCoord(float c, int dim) {
        // `c > 0 ? c : 0` also maps NaN to 0.
        const float lo = c > 0.0f ? c : 0.0f;
        const float hi = static_cast<float>(dim - 1);
        return static_cast<int>(lo < hi ? lo : hi);
    }

    /// The distinct cell coordinates around c along one axis, ascending; returns how many (≤ 3).
    [[nodiscard]] int neighborCoordinates(int c, int axis, int out[3]) const {
        const int dim = dims_[axis];
        int n = 0;
        if (!periodic_.periodic(axis)) {
            for (int k = std::max(c - 1, 0); k <= std::min(c + 1, dim - 1); ++k) out[n++] = k;
        } else if (dim <= 3) {  // every cell of the period, once
            for (int k = 0; k < dim; ++k) out[n++] = k;
        } else {
            for (const int k : {c - 1, c, c + 1}) out[n++] = (k + dim) % dim;
            std::sort(out, out + n);
        }
        return n;
    }

    template <class F>
    void forEachWrappedNeighborRun(const glm::ivec3& c, F&& f) const {
        int xs[3], ys[3], zs[3];
        const int nx = neighborCoordinates(c.x, 0, xs);
        const int ny = neighborCoordinates(c.y, 1, ys);
        const int nz = neighborCoordinates(c.z, 2, zs);
        for (int k = 0; k < nz; ++k)
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx;) {
                    int last = i;  // merge consecutive x coordinates into one run
                    while (last + 1 < nx && xs[last + 1] == xs[last] + 1) ++last;
                    f(cellStart_[cellIndex({xs[i], ys[j], zs[k]})], cellStart_[cellIndex({xs[last], ys[j], zs[k]}) + 1]);
                    i = last + 1;
                }
    }

    PeriodicBox periodic_;
    glm::vec3 origin_{0.0f};
    float cellSize_ = 1.0f;
    glm::vec3 anchor_{0.0f};       ///< cells are counted from here (the origin, unless anchored)
    glm::vec3 anchorCells_{0.0f};  ///< whole cells from the anchor to the origin
    float invCellSize_ = 1.0f;
    glm::ivec3 dims_{1, 1, 1};
    std::vector<std::uint32_t> cellStart_{0, 0};
    std::vector<std::uint32_t> sorted_;
};

}  // namespace tide
