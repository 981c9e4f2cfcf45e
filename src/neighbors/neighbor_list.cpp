#include "neighbors/neighbor_list.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <glm/common.hpp>

#include "core/parallel.hpp"
#include "core/scratch_resize.hpp"
#include "neighbors/within_radius.hpp"

namespace tide {

namespace {

/// Candidates of one cell's 3×3×3 neighbourhood, copied into contiguous SoA arrays so the
/// distance test over them runs in SIMD lanes (within_radius.hpp) and is shared by every
/// particle of the cell.
struct CandidateSet {
    std::vector<float> x, y, z;
    std::vector<std::uint32_t> index;

    void gather(const UniformGrid& grid, std::span<const glm::vec3> positions, const glm::ivec3& cell) {
        gatherRuns(grid, positions, [&](auto&& f) { grid.forEachNeighborRun(cell, f); });
    }
    /// The candidates of every cell holding points of [lo, hi] (not periodic).
    void gatherBox(const UniformGrid& grid, std::span<const glm::vec3> positions, const glm::vec3& lo,
                   const glm::vec3& hi) {
        gatherRuns(grid, positions, [&](auto&& f) { grid.forEachRunInBox(lo, hi, f); });
    }

    [[nodiscard]] std::size_t size() const { return count_; }

    /// Writes to `out` the offsets j − i of the candidates j within the radius of q = x_i,
    /// skipping i (within_radius::selectOffsets); returns how many. `out` is scratch: grown to
    /// the room the test needs, never shrunk or cleared.
    std::size_t offsetsWithin(const glm::vec3& q, float radius2, std::uint32_t i, const PeriodicBox& box,
                              std::vector<std::int16_t>& out, bool& misfit) const {
        if (out.size() < count_ + within_radius::kBlock) out.resize(count_ + within_radius::kBlock);
        return within_radius::selectOffsets({x.data(), y.data(), z.data(), index.data(), count_}, q, radius2, i, box,
                                            out.data(), misfit);
    }
    /// Appends to `out` the candidates within the radius of q, skipping `skip` (distances to
    /// the nearest periodic image), in candidate order.
    void appendWithin(const glm::vec3& q, float radius2, std::uint32_t skip, const PeriodicBox& box,
                      std::vector<std::uint32_t>& out) const {
        const std::size_t size = out.size();
        reserveGrowing(out, size + count_ + within_radius::kBlock);
        out.resize(size + count_ + within_radius::kBlock);
        const std::size_t hits =
            within_radius::select({x.data(), y.data(), z.data(), index.data(), count_}, q, radius2, skip, box, out.data() + size);
        out.resize(size + hits);
    }

private:
    /// Sized once per gather and filled through pointers: four push_backs a candidate, each
    /// checking its capacity, were most of the list build's own time.
    template <class ForEachRun>
    void gatherRuns(const UniformGrid& grid, std::span<const glm::vec3> positions, ForEachRun&& forEachRun) {
        std::size_t total = 0;
        forEachRun([&](std::uint32_t begin, std::uint32_t end) { total += end - begin; });
        if (x.size() < total + within_radius::kBlock) {  // grown, never shrunk
            x.resize(total + within_radius::kBlock);
            y.resize(total + within_radius::kBlock);
            z.resize(total + within_radius::kBlock);
            index.resize(total + within_radius::kBlock);
        }
        float* px = x.data();
        float* py = y.data();
        float* pz = z.data();
        std::uint32_t* pi = index.data();
        std::size_t m = 0;
        const auto sorted = grid.sortedParticles();
        forEachRun([&](std::uint32_t begin, std::uint32_t end) {
            for (std::uint32_t k = begin; k < end; ++k, ++m) {
                const std::uint32_t j = sorted[k];
                px[m] = positions[j].x;
                py[m] = positions[j].y;
                pz[m] = positions[j].z;
                pi[m] = j;
            }
        });
        count_ = total;
        // A whole last block: candidates at +∞, never within reach.
        constexpr float far = std::numeric_limits<float>::infinity();
        std::fill_n(px + total, within_radius::kBlock, far);
        std::fill_n(py + total, within_radius::kBlock, far);
        std::fill_n(pz + total, within_radius::kBlock, far);
        std::fill_n(pi + total, within_radius::kBlock, 0u);
    }

    std::size_t count_ = 0;
};

/// Empties a chunk's buffer with room for a sixteenth more than it last held: growing while
/// filling copies it, the old block and the new resident together (the run's peak memory on
/// the 50k dam break, when a splash adds pairs), while an empty buffer is re-allocated
/// without a copy.
template <class Entry>
void clearWithRoom(std::vector<Entry>& buffer) {
    const std::size_t last = buffer.size();
    buffer.clear();
    if (buffer.capacity() < last + last / 16) {
        std::vector<Entry>().swap(buffer);
        buffer.reserve(last + last / 8);
    }
}

/// Chunks of a list build per thread, taken dynamically: the work per query is uneven (the wall
/// shell lists its floor first, and most of the rest is far from the fluid), and one static
/// chunk per thread left one thread idle. Measured on the 50k dam break, 2 threads, 0.5 s
/// (median of 3): boundary-to-fluid lists 2.29 → 1.91 s, fluid lists 5.56 → 5.11 s. The lists
/// do not depend on the chunking: chunks are concatenated in order.
constexpr int kChunksPerThread = 8;

/// Pair slots a particle a first build reserves (NeighborList::build).
constexpr std::size_t kFirstSlotsPerParticle = 40;

}  // namespace

template <class ForEachParticleOfChunk>
void NeighborList::linkChunks(int chunks, int threads, ForEachParticleOfChunk&& forEachParticleOfChunk) {
    chunkBase_.assign(static_cast<std::size_t>(chunks) + 1, 0);
    chunkOffsetSlots_.resize(static_cast<std::size_t>(chunks));
    chunkData_.resize(static_cast<std::size_t>(chunks));
    chunkOffsets_.resize(static_cast<std::size_t>(chunks));
    for (int c = 0; c < chunks; ++c) {
        std::vector<std::int16_t>& offsets = offsetBuffers_[static_cast<std::size_t>(c)];
        std::vector<std::uint32_t>& indices = chunkBuffers_[static_cast<std::size_t>(c)];
        // start_ is 32-bit: a chunk of 2^32 pairs (8–16 GiB of lists) would need more.
        if (offsets.size() > std::numeric_limits<std::uint32_t>::max() || indices.size() > std::numeric_limits<std::uint32_t>::max())
            throw std::length_error("NeighborList: more than 2^32 pairs in one chunk");
        chunkOffsetSlots_[c] = offsets.size();
        chunkBase_[c + 1] = chunkBase_[c] + offsets.size() + indices.size();
        // not pairs: room to read past the last list
        reserveGrowing(offsets, offsets.size() + kReadPast);
        offsets.resize(offsets.size() + kReadPast, std::int16_t{0});
        reserveGrowing(indices, indices.size() + kReadPast);
        indices.resize(indices.size() + kReadPast, 0u);
        chunkOffsets_[static_cast<std::size_t>(c)] = offsets.data();
        chunkData_[static_cast<std::size_t>(c)] = indices.data();
    }
    slots_ = chunkBase_[chunks];
    std::uint64_t pairs = 0;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) reduction(+ : pairs)
    for (int c = 0; c < chunks; ++c) {
        std::uint32_t nextOffset = 0, nextIndex = 0;
        const std::uint32_t tag = static_cast<std::uint32_t>(c) << kChunkShift;
        forEachParticleOfChunk(c, [&](std::uint32_t i) {
            const std::uint32_t count = count_[i] & kCountMask;
            if (count_[i] & kWide) {
                start_[i] = nextIndex;
                nextIndex += count;
            } else {
                start_[i] = nextOffset;
                nextOffset += static_cast<std::uint32_t>((count + kOffsetBlock - 1) / kOffsetBlock * kOffsetBlock);
            }
            pairs += count;
            count_[i] |= tag;
        });
    }
    pairs_ = pairs;
}

namespace {
/// Throws if a particle had more neighbours than count_ keeps (flagged by the chunks that
/// found them: an exception must not leave an OpenMP region).
void throwIfTooMany(const std::atomic<bool>& tooMany, std::uint32_t limit) {
    if (tooMany.load())
        throw std::length_error("NeighborList: a particle has more than " + std::to_string(limit) + " neighbours");
}
}  // namespace

void NeighborList::build(const UniformGrid& grid, std::span<const glm::vec3> positions, float radius, int threads) {
    const auto n = static_cast<std::uint32_t>(positions.size());
    const float radius2 = radius * radius;
    start_.resize(n);
    count_.resize(n);
    // Offsets are found in 32-bit lanes.
    const bool offsets = n <= static_cast<std::uint32_t>(std::numeric_limits<std::int32_t>::max());
    // Cells are split into contiguous ranges, balanced by particle count.
    const int chunks = n >= kParallelGrain ? std::min(threads * kChunksPerThread, kMaxChunks) : 1;
    const std::uint32_t cells = grid.cellCount();
    std::vector<std::uint32_t> firstCell(static_cast<std::size_t>(chunks) + 1, cells);
    for (int c = 0; c < chunks; ++c) {
        std::uint32_t lo = 0, hi = cells;  // first cell whose start ≥ the chunk's share
        const auto share = static_cast<std::uint32_t>(std::uint64_t{n} * c / chunks);
        while (lo < hi) {
            const std::uint32_t mid = lo + (hi - lo) / 2;
            if (grid.cellStart(mid) < share) lo = mid + 1; else hi = mid;
        }
        firstCell[c] = c == 0 ? 0 : lo;
    }
    offsetBuffers_.resize(static_cast<std::size_t>(chunks));
    chunkBuffers_.resize(static_cast<std::size_t>(chunks));
    const auto sorted = grid.sortedParticles();
    const glm::ivec3 dims = grid.dims();
    auto forEachCell = [&](int c, auto&& f) {
        for (std::uint32_t cell = firstCell[c]; cell < firstCell[c + 1]; ++cell)
            if (grid.cellStart(cell) < grid.cellStart(cell + 1)) f(cell);
    };
    std::atomic<bool> tooMany{false};
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int c = 0; c < chunks; ++c) {
        // Filled through locals, as the vectors' headers share cache lines in the members.
        std::vector<std::int16_t> offsetBuffer = std::move(offsetBuffers_[static_cast<std::size_t>(c)]);
        std::vector<std::uint32_t> indexBuffer = std::move(chunkBuffers_[static_cast<std::size_t>(c)]);
        clearWithRoom(offsetBuffer);
        clearWithRoom(indexBuffer);
        // A first build takes room for a 3D fluid's ~33 neighbours a particle, padded to whole
        // blocks, at once: grown from empty by an eighth at a time the buffer was copied ~90
        // times (a sixth of the seed's tank's first step, its costliest frame).
        if (offsetBuffer.capacity() == 0)
            offsetBuffer.reserve(kFirstSlotsPerParticle * (grid.cellStart(firstCell[c + 1]) - grid.cellStart(firstCell[c])));
        CandidateSet candidates;
        std::vector<std::int16_t> hits;  // one query's offsets, before they join the buffer
        forEachCell(c, [&](std::uint32_t cell) {
            const auto cx = static_cast<int>(cell % static_cast<std::uint32_t>(dims.x));
            const auto cy = static_cast<int>((cell / static_cast<std::uint32_t>(dims.x)) % static_cast<std::uint32_t>(dims.y));
            const auto cz = static_cast<int>(cell / (static_cast<std::uint32_t>(dims.x) * static_cast<std::uint32_t>(dims.y)));
            candidates.gather(grid, positions, {cx, cy, cz});
            for (std::uint32_t k = grid.cellStart(cell); k < grid.cellStart(cell + 1); ++k) {
                const std::uint32_t i = sorted[k];
                bool wide = !offsets;
                std::size_t count = 0;
                if (offsets) {
                    count = candidates.offsetsWithin(positions[i], radius2, i, grid.periodic(), hits, wide);
                    if (!wide) {
                        const std::size_t padded = (count + kOffsetBlock - 1) / kOffsetBlock * kOffsetBlock;
                        std::fill(hits.begin() + static_cast<std::ptrdiff_t>(count),
                                  hits.begin() + static_cast<std::ptrdiff_t>(padded), std::int16_t{0});
                        reserveGrowing(offsetBuffer, offsetBuffer.size() + padded);
                        offsetBuffer.insert(offsetBuffer.end(), hits.begin(), hits.begin() + static_cast<std::ptrdiff_t>(padded));
                    }
                }
                if (wide) {  // a neighbour beyond an offset's reach: the same list as indices
                    const std::size_t begin = indexBuffer.size();
                    candidates.appendWithin(positions[i], radius2, i, grid.periodic(), indexBuffer);
                    count = indexBuffer.size() - begin;
                }
                if (count > kCountMask) tooMany.store(true);
                count_[i] = (static_cast<std::uint32_t>(count) & kCountMask) | (wide ? kWide : 0u);
            }
        });
        offsetBuffers_[static_cast<std::size_t>(c)] = std::move(offsetBuffer);
        chunkBuffers_[static_cast<std::size_t>(c)] = std::move(indexBuffer);
    }
    throwIfTooMany(tooMany, kCountMask);
    linkChunks(chunks, threads, [&](int c, auto&& f) {
        forEachCell(c, [&](std::uint32_t cell) {
            for (std::uint32_t k = grid.cellStart(cell); k < grid.cellStart(cell + 1); ++k) f(sorted[k]);
        });
    });
}

void NeighborList::buildCross(const UniformGrid& grid, std::span<const glm::vec3> gridPositions,
                              std::span<const glm::vec3> queries, float radius, int threads,
                              std::span<const std::uint32_t> queryIndices) {
    const bool indexed = !queryIndices.empty();
    const auto n = static_cast<std::uint32_t>(indexed ? queryIndices.size() : queries.size());
    const float radius2 = radius * radius;
    start_.resize(n);
    count_.resize(n);
    const int chunks = n >= kParallelGrain ? std::min(threads * kChunksPerThread, kMaxChunks) : 1;
    chunkBuffers_.resize(static_cast<std::size_t>(chunks));
    offsetBuffers_.resize(static_cast<std::size_t>(chunks));
    for (auto& unused : offsetBuffers_) unused.clear();
    auto chunkBegin = [&](int c) { return static_cast<std::uint32_t>(std::uint64_t{n} * c / chunks); };
    const auto sorted = grid.sortedParticles();
    // Queries farther than the radius from the grid's box have no neighbours (and would
    // otherwise scan the clamped border cells): most of a container's wall shell. A periodic
    // axis has no far side.
    const PeriodicBox& box = grid.periodic();
    glm::vec3 lo = grid.origin() - glm::vec3(radius);
    glm::vec3 hi = grid.origin() + grid.cellSize() * glm::vec3(grid.dims()) + glm::vec3(radius);
    for (int axis = 0; axis < 3; ++axis)
        if (box.periodic(axis)) {
            lo[axis] = -std::numeric_limits<float>::infinity();
            hi[axis] = std::numeric_limits<float>::infinity();
        }
    auto query = [&](std::uint32_t i) { return queries[indexed ? queryIndices[i] : i]; };
    auto outside = [&](const glm::vec3& a, const glm::vec3& b) {  // the box [a, b] lies out of reach
        return grid.empty() || b.x < lo.x || b.y < lo.y || b.z < lo.z || a.x > hi.x || a.y > hi.y || a.z > hi.z;
    };
    // Without periodic axes, queries go in groups of consecutive ones spanning at most a cell
    // along each axis (a fluid in cell order gives ~8 to a group): the candidates in reach of
    // the group are gathered once and each query tests them in SIMD lanes (within_radius.hpp).
    // The lists are what the scalar test over each query's 27 cells writes: the same hits, in
    // the same order (by cell row z, y, then grid order). The 50k dam break, one thread, 0.3 s:
    // the neighbour phase 336 → 252 ns a particle-step (the wall lists were 10 % of the run).
    const float span = grid.cellSize();
    constexpr std::uint32_t kMaxGroup = 64;
    constexpr std::uint32_t kSkipNone = std::numeric_limits<std::uint32_t>::max();
    std::atomic<bool> tooMany{false};
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int c = 0; c < chunks; ++c) {
        std::vector<std::uint32_t> buffer = std::move(chunkBuffers_[static_cast<std::size_t>(c)]);  // a local, as in build
        clearWithRoom(buffer);
        auto finish = [&](std::uint32_t i, std::size_t begin) {
            const std::size_t count = buffer.size() - begin;
            if (count > kCountMask) tooMany.store(true);
            count_[i] = (static_cast<std::uint32_t>(count) & kCountMask) | kWide;
        };
        if (box.any) {
            for (std::uint32_t i = chunkBegin(c); i < chunkBegin(c + 1); ++i) {
                const std::size_t begin = buffer.size();
                const glm::vec3 q = query(i);
                if (!outside(q, q))
                    grid.forEachNeighborRun(grid.cellOf(q), [&](std::uint32_t first, std::uint32_t last) {
                        for (std::uint32_t k = first; k < last; ++k) {
                            const glm::vec3 d = box.delta(q, gridPositions[sorted[k]]);
                            if (d.x * d.x + d.y * d.y + d.z * d.z <= radius2) {
                                reserveGrowing(buffer, buffer.size() + 1);
                                buffer.push_back(sorted[k]);
                            }
                        }
                    });
                finish(i, begin);
            }
            chunkBuffers_[static_cast<std::size_t>(c)] = std::move(buffer);
            continue;
        }
        CandidateSet candidates;
        const std::uint32_t end = chunkBegin(c + 1);
        for (std::uint32_t first = chunkBegin(c); first < end;) {
            // The group: queries first … last − 1 and their bounding box.
            glm::vec3 a = query(first), b = a;
            std::uint32_t last = first + 1;
            const bool finite = std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
            if (finite)
                for (; last < end && last - first < kMaxGroup; ++last) {
                    const glm::vec3 q = query(last);
                    if (!(std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z))) break;  // a group of its own, no hits
                    const glm::vec3 a2 = glm::min(a, q), b2 = glm::max(b, q);
                    if (!(b2.x - a2.x <= span && b2.y - a2.y <= span && b2.z - a2.z <= span)) break;
                    a = a2;
                    b = b2;
                }
            const glm::vec3 reach(radius);
            const bool none = !finite || outside(a - reach, b + reach);
            if (!none) candidates.gatherBox(grid, gridPositions, a - reach, b + reach);
            for (std::uint32_t i = first; i < last; ++i) {
                const std::size_t begin = buffer.size();
                if (!none && candidates.size() > 0) candidates.appendWithin(query(i), radius2, kSkipNone, box, buffer);
                finish(i, begin);
            }
            first = last;
        }
        chunkBuffers_[static_cast<std::size_t>(c)] = std::move(buffer);
    }
    throwIfTooMany(tooMany, kCountMask);
    linkChunks(chunks, threads, [&](int c, auto&& f) {
        for (std::uint32_t i = chunkBegin(c); i < chunkBegin(c + 1); ++i) f(i);
    });
}

}  // namespace tide
