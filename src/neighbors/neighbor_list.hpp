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
///
/// The lists `build` makes hold each neighbour j of i as the 16-bit offset j − i where all of
/// i's fit (particles stored in cell order are near their neighbours in storage), each list
/// padded with offset 0 to a whole SIMD block: ~2.2 bytes a pair instead of 4 (~60 bytes a
/// fluid particle). A list with a neighbour farther in storage (across a slab of cells
/// holding more than 32k particles: a few dozen of the 205k dam break's lists late in its
/// second) keeps 32-bit indices, as every CrossNeighborList does.
/// NeighborSpan reads either.

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "neighbors/uniform_grid.hpp"

namespace tide {

/// One particle's neighbours: 32-bit indices, or 16-bit offsets from a base index (the
/// particle's own), read as indices either way.
class NeighborSpan {
public:
    NeighborSpan() = default;
    NeighborSpan(const std::uint32_t* index, std::uint32_t count) : index_(index), count_(count) {}
    NeighborSpan(const std::int16_t* offset, std::uint32_t base, std::uint32_t count)
        : offset_(offset), base_(base), count_(count) {}

    [[nodiscard]] std::size_t size() const { return count_; }
    [[nodiscard]] bool empty() const { return count_ == 0; }
    [[nodiscard]] std::uint32_t operator[](std::size_t k) const { return at(index_, offset_, base_, k); }
    /// Neighbour k of a list of indices (offset null) or of offsets from base.
    [[nodiscard]] static std::uint32_t at(const std::uint32_t* index, const std::int16_t* offset, std::uint32_t base,
                                          std::size_t k) {
        return offset != nullptr ? base + static_cast<std::uint32_t>(static_cast<std::int32_t>(offset[k])) : index[k];
    }
    /// The indices (nullptr when offsets), or the offsets and their base (nullptr when indices).
    [[nodiscard]] const std::uint32_t* indices() const { return index_; }
    [[nodiscard]] const std::int16_t* offsets() const { return offset_; }
    [[nodiscard]] std::uint32_t base() const { return base_; }

    class iterator {
    public:
        using iterator_category = std::input_iterator_tag;
        using iterator_concept = std::forward_iterator_tag;
        using value_type = std::uint32_t;
        using difference_type = std::ptrdiff_t;
        iterator() = default;
        iterator(const NeighborSpan& span, std::size_t k)
            : index_(span.index_), offset_(span.offset_), base_(span.base_), k_(k) {}
        std::uint32_t operator*() const { return at(index_, offset_, base_, k_); }
        iterator& operator++() {
            ++k_;
            return *this;
        }
        iterator operator++(int) {
            iterator before = *this;
            ++k_;
            return before;
        }
        bool operator==(const iterator& other) const { return k_ == other.k_; }

    private:
        const std::uint32_t* index_ = nullptr;
        const std::int16_t* offset_ = nullptr;
        std::uint32_t base_ = 0;
        std::size_t k_ = 0;
    };
    [[nodiscard]] iterator begin() const { return {*this, 0}; }
    [[nodiscard]] iterator end() const { return {*this, count_}; }

private:
    const std::uint32_t* index_ = nullptr;
    const std::int16_t* offset_ = nullptr;
    std::uint32_t base_ = 0;
    std::uint32_t count_ = 0;
};

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
    /// Every list may be read this many entries past its end (SIMD loops read whole blocks):
    /// indices of the same set (the next lists' or 0 after a chunk's last).
    static constexpr std::size_t kReadPast = 8;
    /// Lists of offsets are padded with offset 0 (the particle itself) to a multiple of this:
    /// the next list's offsets are from another particle, and SIMD loops read whole blocks.
    static constexpr std::size_t kOffsetBlock = 8;

    [[nodiscard]] NeighborSpan of(std::uint32_t i) const {
        const std::uint32_t chunk = count_[i] >> kChunkShift, count = count_[i] & kCountMask;
        if (count_[i] & kWide) return {chunkData_[chunk] + start_[i], count};
        return {chunkOffsets_[chunk] + start_[i], i, count};
    }
    /// Position of i's first neighbour in the list's pair slots: per-pair data computed
    /// alongside the list (e.g. kernel factors) is indexed by offset(i) + k, in an array of
    /// slotCount() (lists of offsets keep their padding there too).
    [[nodiscard]] std::uint64_t offset(std::uint32_t i) const {
        const std::uint32_t chunk = count_[i] >> kChunkShift;
        return chunkBase_[chunk] + start_[i] + ((count_[i] & kWide) ? chunkOffsetSlots_[chunk] : 0);
    }
    [[nodiscard]] std::uint32_t particleCount() const { return static_cast<std::uint32_t>(count_.size()); }
    [[nodiscard]] std::uint64_t pairCount() const { return pairs_; }
    [[nodiscard]] std::uint64_t slotCount() const { return slots_; }

private:
    friend class CrossNeighborList;
    /// CrossNeighborList::build's lists, as indices.
    void buildCross(const UniformGrid& grid, std::span<const glm::vec3> gridPositions,
                    std::span<const glm::vec3> queries, float radius, int threads,
                    std::span<const std::uint32_t> queryIndices);
    [[nodiscard]] std::span<const std::uint32_t> indicesOf(std::uint32_t i) const {
        return {chunkData_[count_[i] >> kChunkShift] + start_[i], count_[i] & kCountMask};
    }

    /// count_ holds a particle's neighbour count in its low kCountBits bits, kWide if its list
    /// holds indices, and the index of the chunk that found it from kChunkShift up; start_ its
    /// first neighbour's place in that chunk's buffer of offsets or of indices. A particle's
    /// list and pair offset come from these and a per-chunk table, with 8 bytes a particle per
    /// list instead of 20 for a pointer and a 64-bit offset (~40 bytes a fluid particle at
    /// 205k across the fluid and wall lists).
    static constexpr unsigned kCountBits = 19;
    static constexpr std::uint32_t kCountMask = (1u << kCountBits) - 1u;
    static constexpr std::uint32_t kWide = 1u << kCountBits;
    static constexpr unsigned kChunkShift = kCountBits + 1;
    static constexpr int kMaxChunks = 1 << (32 - kChunkShift);

    /// Once every chunk's buffers are final: sets each particle's start_ in its chunk's buffer
    /// (its slots follow those of the particles before it in the chunk: a list of offsets
    /// takes its count rounded up to kOffsetBlock), tags its count with the chunk and records
    /// each chunk's first slot (its offsets', then its indices'); `forEachParticleOfChunk(c, f)`
    /// calls f(i) for chunk c's particles in the order they were found.
    template <class ForEachParticleOfChunk>
    void linkChunks(int chunks, int threads, ForEachParticleOfChunk&& forEachParticleOfChunk);

    std::vector<std::uint32_t> start_;         ///< i's first neighbour's place in its chunk's buffer
    std::vector<std::uint32_t> count_;         ///< neighbours, kWide, and the chunk (from kChunkShift)
    std::vector<std::uint64_t> chunkBase_;     ///< slot of each chunk's first pair
    std::vector<std::uint64_t> chunkOffsetSlots_;  ///< slots of each chunk's lists of offsets
    std::vector<const std::uint32_t*> chunkData_;  ///< each chunk's buffer of indices
    std::vector<const std::int16_t*> chunkOffsets_;  ///< each chunk's buffer of offsets
    std::uint64_t pairs_ = 0, slots_ = 0;
    std::vector<std::vector<std::uint32_t>> chunkBuffers_;  ///< per-chunk lists of indices, capacity kept between builds
    std::vector<std::vector<std::int16_t>> offsetBuffers_;  ///< per-chunk lists of offsets, the same
};

/// Neighbours in another set (fluid particles' boundary particles, and back), as 32-bit
/// indices: the same lists in the same form as NeighborList's, with plain spans for the loops.
class CrossNeighborList {
public:
    /// Find, for every query point i, the points j of another set (the one `grid` was built
    /// from, at `gridPositions`) with |q_i − x_j|² ≤ radius². With `queryIndices`, the queries
    /// are queries[queryIndices[a]] and the lists are indexed by a.
    void build(const UniformGrid& grid, std::span<const glm::vec3> gridPositions, std::span<const glm::vec3> queries,
               float radius, int threads, std::span<const std::uint32_t> queryIndices = {}) {
        list_.buildCross(grid, gridPositions, queries, radius, threads, queryIndices);
    }

    [[nodiscard]] std::span<const std::uint32_t> of(std::uint32_t i) const { return list_.indicesOf(i); }
    [[nodiscard]] std::uint64_t offset(std::uint32_t i) const { return list_.offset(i); }
    [[nodiscard]] std::uint32_t particleCount() const { return list_.particleCount(); }
    [[nodiscard]] std::uint64_t pairCount() const { return list_.pairCount(); }
    [[nodiscard]] std::uint64_t slotCount() const { return list_.slotCount(); }

private:
    NeighborList list_;
};

}  // namespace tide
