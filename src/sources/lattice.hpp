#pragma once
/// \file
/// Cubic-lattice sampling of a box: the particles a block or an emitter layer holds.

#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>
#include <glm/ext/vector_uint3.hpp>

namespace tide {

/// Points min + offset + k·spacing, k in [0, count), centred in [min, max] per axis.
/// An axis thinner than one spacing (a flat outlet) holds one point at its middle.
struct Lattice {
    glm::vec3 first;
    glm::uvec3 count;
    float spacing;

    Lattice(const glm::vec3& min, const glm::vec3& max, float spacingIn) : spacing(spacingIn) {
        for (int axis = 0; axis < 3; ++axis) {
            const float extent = max[axis] - min[axis];
            // The small slack absorbs round-off in extents that are whole multiples of the spacing.
            const float cells = std::floor(extent / spacing + 1e-3f);
            // Saturate: beyond 2^32 the cast is undefined (a tiny spacing in a fuzzed scene); NaN gives 1.
            const std::uint32_t n = cells >= 4.0e9f ? 4000000000u : cells >= 1.0f ? static_cast<std::uint32_t>(cells) : 1u;
            count[axis] = n;
            first[axis] = min[axis] + 0.5f * (extent - static_cast<float>(count[axis] - 1) * spacing);
        }
    }
    /// The points of the domain's lattice origin + (k + ½)·spacing whose cells (the cube of
    /// one spacing around each) lie inside [min, max]: a block of water. Walls and obstacles
    /// are sampled on that lattice, so a block put against them continues it, at rest
    /// density; on its own centred lattice it could sit up to half a spacing off theirs,
    /// pressed against their particles or hanging a gap above them (it then falls into it).
    /// Adjacent blocks keep a spacing apart. An axis with no whole cell inside keeps the
    /// centred lattice's point at the middle; so does an axis where the centred lattice
    /// already is the domain's, to the last bit.
    static Lattice onDomainLattice(const glm::vec3& min, const glm::vec3& max, float spacing, const glm::vec3& origin) {
        Lattice lattice(min, max, spacing);
        for (int axis = 0; axis < 3; ++axis) {
            // In double: the indices of far-off blocks at fine spacings exceed float's 24 bits.
            const double s = spacing, slack = 1e-3;
            const double lo = std::ceil((double{min[axis]} - origin[axis]) / s - slack);
            const double hi = std::floor((double{max[axis]} - origin[axis]) / s + slack) - 1.0;
            if (!(hi >= lo) || hi - lo >= 4.0e9) continue;
            const auto n = static_cast<std::uint32_t>(hi - lo + 1.0);
            const auto first = static_cast<float>(origin[axis] + (lo + 0.5) * s);
            if (n == lattice.count[axis] && std::abs(first - lattice.first[axis]) <= 1e-3f * spacing) continue;
            lattice.count[axis] = n;
            lattice.first[axis] = first;
        }
        return lattice;
    }
    /// Number of points, saturating at 2^64 − 1.
    [[nodiscard]] std::uint64_t size() const {
        const std::uint64_t xy = std::uint64_t{count.x} * count.y;  // < 2^64: each count < 2^32
        return count.z != 0 && xy > UINT64_MAX / count.z ? UINT64_MAX : xy * count.z;
    }
    /// Calls f(point) for every lattice point, x fastest.
    template <class F>
    void forEach(F&& f) const {
        for (std::uint32_t k = 0; k < count.z; ++k)
            for (std::uint32_t j = 0; j < count.y; ++j)
                for (std::uint32_t i = 0; i < count.x; ++i)
                    f(first + spacing * glm::vec3(static_cast<float>(i), static_cast<float>(j), static_cast<float>(k)));
    }
};

}  // namespace tide
