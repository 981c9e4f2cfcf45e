#pragma once
/// \file
/// Neighbours within a radius, in compressed-row form: the seed's `NeighborTable`.
/// Built once per step from a UniformGrid and reused by every pass of that step.
/// A particle's neighbours come in a fixed order (grid cell order, then index), never
/// including the particle itself, and never capped. Each particle's list is a contiguous
/// slice of the index buffer of the thread that found it (a pointer + count per particle,
/// so lists may be laid out in cell order for speed while being looked up by particle
/// index); the buffers are the storage, not concatenated into one array, which would hold
/// every pair twice at the peak (4 bytes a pair, ~140 bytes a fluid particle).
/// On the periodic axes of the grid's PeriodicBox, distances are to the nearest image.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "neighbors/uniform_grid.hpp"

namespace tide {

class NeighborList {
public:
    NeighborList() = default;
    // chunkData_ points into chunkBuffers_: a copy would point into the original's buffers.
    NeighborList(const NeighborList&) = delete;
    NeighborList& operator=(const NeighborList&) = delete;
    NeighborList(NeighborList&&) noexcept = default;
    NeighborList& operator=(NeighborList&&) noexcept = default;

    /// Find, for every particle, all others with |x_i − x_j|² ≤ radius² (nearest image on the
    /// grid's periodic axes). The grid must have been built from the same positions with a
    /// cell size ≥ radius.
    void build(const UniformGrid& grid, std::span<const glm::vec3> positions, float radius, int threads);
    /// Find, for every query point i, the points j of another set (the one `grid` was built
    /// from, at `gridPositions`) with |q_i − x_j|² ≤ radius². With `queryIndices`, the queries
    /// are queries[queryIndices[a]] and the lists are indexed by a.
    void buildCross(const UniformGrid& grid, std::span<const glm::vec3> gridPositions,
                    std::span<const glm::vec3> queries, float radius, int threads,
                    std::span<const std::uint32_t> queryIndices = {});

    /// Every list may be read this many indices past its end (SIMD loops read whole blocks):
    /// they are indices of the same set, the next lists' or 0 after a chunk's last.
    static constexpr std::size_t kReadPast = 8;

    [[nodiscard]] std::span<const std::uint32_t> of(std::uint32_t i) const {
        return {chunkData_[count_[i] >> kCountBits] + start_[i], count_[i] & kCountMask};
    }
    /// Position of i's first neighbour in the list's pair order: per-pair data computed
    /// alongside the list (e.g. kernel factors) is indexed by offset(i) + k.
    [[nodiscard]] std::uint64_t offset(std::uint32_t i) const {
        return chunkBase_[count_[i] >> kCountBits] + start_[i];
    }
    [[nodiscard]] std::uint32_t particleCount() const { return static_cast<std::uint32_t>(count_.size()); }
    [[nodiscard]] std::uint64_t pairCount() const { return pairs_; }

private:
    /// count_ holds a particle's neighbour count in its low kCountBits bits and the index of
    /// the chunk that found it above; start_ its first neighbour's place in that chunk's
    /// buffer. A particle's list and pair offset come from these and a per-chunk table, with
    /// 8 bytes a particle per list instead of 20 for a pointer and a 64-bit offset (~40 bytes
    /// a fluid particle at 205k across the fluid and wall lists).
    static constexpr unsigned kCountBits = 20;
    static constexpr std::uint32_t kCountMask = (1u << kCountBits) - 1u;
    static constexpr int kMaxChunks = 1 << (32 - kCountBits);

    /// Once every chunk's buffer is final: sets each particle's start_ in its chunk's buffer
    /// (its pairs follow those of the particles before it in the chunk), tags its
    /// count with the chunk and records each chunk's first pair offset;
    /// `forEachParticleOfChunk(c, f)` calls f(i) for chunk c's particles in the order they
    /// were found.
    template <class ForEachParticleOfChunk>
    void linkChunks(int chunks, int threads, ForEachParticleOfChunk&& forEachParticleOfChunk);

    std::vector<std::uint32_t> start_;         ///< i's first neighbour's place in its chunk's buffer
    std::vector<std::uint32_t> count_;         ///< neighbours, and the chunk (above kCountBits)
    std::vector<std::uint64_t> chunkBase_;     ///< pair offset of each chunk's first pair
    std::vector<const std::uint32_t*> chunkData_;  ///< each chunk's buffer
    std::uint64_t pairs_ = 0;
    std::vector<std::vector<std::uint32_t>> chunkBuffers_;  ///< per-chunk lists, capacity kept between builds
};

}  // namespace tide
