#include "neighbors/neighbor_list.hpp"

#include "core/parallel.hpp"

namespace tide {

namespace {
/// Calls visit(j) for every grid point j within the radius of xi, in the grid's fixed order,
/// skipping j == skip.
template <class Visit>
void forEachNeighbor(const UniformGrid& grid, std::span<const glm::vec3> positions, float radius2,
                     const glm::vec3& xi, std::uint32_t skip, Visit&& visit) {
    const auto sorted = grid.sortedParticles();
    grid.forEachNeighborRun(grid.cellOf(xi), [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t k = begin; k < end; ++k) {
            const std::uint32_t j = sorted[k];
            const glm::vec3 d = xi - positions[j];
            if (j != skip && d.x * d.x + d.y * d.y + d.z * d.z <= radius2) visit(j);
        }
    });
}
}  // namespace

void NeighborList::build(const UniformGrid& grid, std::span<const glm::vec3> gridPositions,
                         std::span<const glm::vec3> queries, float radius, int threads, bool excludeSelf) {
    const auto n = static_cast<std::uint32_t>(queries.size());
    constexpr std::uint32_t kNone = 0xffffffffu;
    const float radius2 = radius * radius;
    counts_.resize(n);
    parallelFor(n, threads, [&](std::uint32_t i) {
        std::uint32_t count = 0;
        forEachNeighbor(grid, gridPositions, radius2, queries[i], excludeSelf ? i : kNone,
                        [&](std::uint32_t) { ++count; });
        counts_[i] = count;
    });
    offsets_.resize(static_cast<std::size_t>(n) + 1);
    offsets_[0] = 0;
    for (std::uint32_t i = 0; i < n; ++i) offsets_[i + 1] = offsets_[i] + counts_[i];
    indices_.resize(offsets_[n]);
    parallelFor(n, threads, [&](std::uint32_t i) {
        std::uint64_t at = offsets_[i];
        forEachNeighbor(grid, gridPositions, radius2, queries[i], excludeSelf ? i : kNone,
                        [&](std::uint32_t j) { indices_[at++] = j; });
    });
}

}  // namespace tide
