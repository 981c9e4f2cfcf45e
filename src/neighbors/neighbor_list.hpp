#pragma once
/// \file
/// Neighbours within a radius, in compressed-row form: the seed's `NeighborTable`.
/// Built once per step from a UniformGrid and reused by every pass of that step.
/// A particle's neighbours come in a fixed order (grid cell order, then index), never
/// including the particle itself, and never capped. Each particle's list is a contiguous
/// slice of one index array (begin + count per particle, so lists may be laid out in cell
/// order for speed while being looked up by particle index).
/// On the periodic axes of the grid's PeriodicBox, distances are to the nearest image.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "neighbors/uniform_grid.hpp"

namespace tide {

class NeighborList {
public:
    /// Find, for every particle, all others with |x_i − x_j|² ≤ radius² (nearest image on the
    /// grid's periodic axes). The grid must have been built from the same positions with a
    /// cell size ≥ radius.
    void build(const UniformGrid& grid, std::span<const glm::vec3> positions, float radius, int threads);
    /// Find, for every query point i, the points j of another set (the one `grid` was built
    /// from, at `gridPositions`) with |q_i − x_j|² ≤ radius².
    void buildCross(const UniformGrid& grid, std::span<const glm::vec3> gridPositions,
                    std::span<const glm::vec3> queries, float radius, int threads);

    [[nodiscard]] std::span<const std::uint32_t> of(std::uint32_t i) const {
        return {indices_.data() + begin_[i], count_[i]};
    }
    /// Position of i's first neighbour in the list's pair order: per-pair data computed
    /// alongside the list (e.g. kernel factors) is indexed by offset(i) + k.
    [[nodiscard]] std::uint64_t offset(std::uint32_t i) const { return begin_[i]; }
    [[nodiscard]] std::uint32_t particleCount() const { return static_cast<std::uint32_t>(count_.size()); }
    [[nodiscard]] std::uint64_t pairCount() const { return indices_.size(); }

private:
    /// Concatenate the per-chunk buffers into indices_ and shift each particle's begin_ by
    /// its chunk's base; `forEachParticleOfChunk(c, f)` calls f(i) for chunk c's particles.
    template <class ForEachParticleOfChunk>
    void concatenateChunks(int chunks, ForEachParticleOfChunk&& forEachParticleOfChunk);

    std::vector<std::uint64_t> begin_;
    std::vector<std::uint32_t> count_;
    std::vector<std::uint32_t> indices_;
    std::vector<std::vector<std::uint32_t>> chunkBuffers_;  ///< per-thread scratch, kept between builds
};

}  // namespace tide
