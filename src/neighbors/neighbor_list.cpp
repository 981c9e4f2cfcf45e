#include "neighbors/neighbor_list.hpp"

#include <algorithm>

#include "core/parallel.hpp"

namespace tide {

namespace {
/// Appends to `out` every grid point j within the radius of xi, in the grid's fixed order,
/// skipping j == skip. Branch-free: every candidate is written and the end advances only
/// for hits, since about 15 % of candidates are hits and a branch on them mispredicts.
void appendNeighbors(const UniformGrid& grid, std::span<const glm::vec3> positions, float radius2,
                     const glm::vec3& xi, std::uint32_t skip, std::vector<std::uint32_t>& out) {
    const auto sorted = grid.sortedParticles();
    grid.forEachNeighborRun(grid.cellOf(xi), [&](std::uint32_t begin, std::uint32_t end) {
        std::size_t size = out.size();
        out.resize(size + (end - begin));
        std::uint32_t* dst = out.data();
        for (std::uint32_t k = begin; k < end; ++k) {
            const std::uint32_t j = sorted[k];
            const glm::vec3 d = xi - positions[j];
            dst[size] = j;
            size += static_cast<std::size_t>((d.x * d.x + d.y * d.y + d.z * d.z <= radius2) & (j != skip));
        }
        out.resize(size);
    });
}
}  // namespace

void NeighborList::build(const UniformGrid& grid, std::span<const glm::vec3> gridPositions,
                         std::span<const glm::vec3> queries, float radius, int threads, bool excludeSelf) {
    const auto n = static_cast<std::uint32_t>(queries.size());
    constexpr std::uint32_t kNone = 0xffffffffu;
    const float radius2 = radius * radius;
    // One pass: each thread lists a contiguous range of particles into its own buffer, then
    // the buffers are copied behind each other. Per-particle lists do not depend on the
    // thread count, so the result is identical for any number of threads.
    const int chunks = n >= kParallelGrain ? threads : 1;
    chunkBuffers_.resize(static_cast<std::size_t>(chunks));
    offsets_.resize(static_cast<std::size_t>(n) + 1);
    auto chunkBegin = [&](int c) { return static_cast<std::uint32_t>(std::uint64_t{n} * c / chunks); };
#pragma omp parallel for schedule(static, 1) num_threads(chunks)
    for (int c = 0; c < chunks; ++c) {
        std::vector<std::uint32_t>& buffer = chunkBuffers_[static_cast<std::size_t>(c)];
        buffer.clear();
        for (std::uint32_t i = chunkBegin(c); i < chunkBegin(c + 1); ++i) {
            const auto before = buffer.size();
            appendNeighbors(grid, gridPositions, radius2, queries[i], excludeSelf ? i : kNone, buffer);
            offsets_[i + 1] = buffer.size() - before;  // a count for now
        }
    }
    offsets_[0] = 0;
    for (std::uint32_t i = 0; i < n; ++i) offsets_[i + 1] += offsets_[i];
    indices_.resize(offsets_[n]);
#pragma omp parallel for schedule(static, 1) num_threads(chunks)
    for (int c = 0; c < chunks; ++c) {
        const auto& buffer = chunkBuffers_[static_cast<std::size_t>(c)];
        std::copy(buffer.begin(), buffer.end(), indices_.begin() + static_cast<std::ptrdiff_t>(offsets_[chunkBegin(c)]));
    }
}

}  // namespace tide
