#pragma once
/// \file
/// Neighbours within a radius, in compressed-row (CSR) form: the seed's `NeighborTable`.
/// Built once per step from a UniformGrid and reused by every pass of that step.
/// A particle's neighbours come in a fixed order (grid cell order, then index), never
/// including the particle itself, and never capped.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "neighbors/uniform_grid.hpp"

namespace tide {

class NeighborList {
public:
    /// Find, for every particle, all others with |x_i − x_j|² ≤ radius². The grid must have
    /// been built from the same positions with a cell size ≥ radius.
    void build(const UniformGrid& grid, std::span<const glm::vec3> positions, float radius, int threads) {
        build(grid, positions, positions, radius, threads, true);
    }
    /// Find, for every query point i, the points j of another set (the one `grid` was built
    /// from, at `gridPositions`) with |q_i − x_j|² ≤ radius²; `excludeSelf` skips j == i.
    void build(const UniformGrid& grid, std::span<const glm::vec3> gridPositions,
               std::span<const glm::vec3> queries, float radius, int threads, bool excludeSelf);

    [[nodiscard]] std::span<const std::uint32_t> of(std::uint32_t i) const {
        return {indices_.data() + offsets_[i], static_cast<std::size_t>(offsets_[i + 1] - offsets_[i])};
    }
    [[nodiscard]] std::uint32_t particleCount() const { return static_cast<std::uint32_t>(offsets_.size() - 1); }
    [[nodiscard]] std::uint64_t pairCount() const { return offsets_.back(); }

private:
    std::vector<std::uint64_t> offsets_{0};
    std::vector<std::uint32_t> indices_;
    std::vector<std::vector<std::uint32_t>> chunkBuffers_;  ///< per-thread scratch, kept between builds
};

}  // namespace tide
