#pragma once
/// \file
/// Periodic domain axes (WorldDef::periodic): the pair vector between two particles and
/// the wrap of positions back into [min, max).
///
/// On a periodic axis a particle leaving through max re-enters at min, and every pair
/// vector x_i − x_j is that to the nearest image of j, the minimum-image convention
/// (Allen & Tildesley, "Computer simulation of liquids", §1.5.2). Positions are kept in
/// [min, max) (World wraps them after each step), so two particles are less than one period
/// apart and a single shift by the period finds the nearest image; with periods of at
/// least 2 h (checked by World) no other image lies within the kernel support.
///
/// On a non-periodic axis the period is 0 and half of it +∞, so the shift is always 0;
/// a world without periodic axes skips it altogether (`any` is false): delta() is then
/// the plain difference plus one well-predicted branch.

#include <cmath>
#include <limits>

#include <glm/vec3.hpp>

namespace tide {

struct PeriodicBox {
    glm::vec3 min{0.0f};                                     ///< domain corner, m
    glm::vec3 max{0.0f};                                     ///< domain corner, m
    glm::vec3 period{0.0f};                                  ///< max − min on periodic axes, 0 on the others
    glm::vec3 half{std::numeric_limits<float>::infinity()};  ///< period / 2; +∞ on non-periodic axes
    bool any = false;                                        ///< whether any axis is periodic

    /// The box [min, max) with the axes flagged in `periodic` wrapping.
    static PeriodicBox make(const glm::vec3& min, const glm::vec3& max, const glm::bvec3& periodic) {
        PeriodicBox box;
        box.min = min;
        box.max = max;
        for (int axis = 0; axis < 3; ++axis)
            if (periodic[axis]) {
                box.period[axis] = max[axis] - min[axis];
                box.half[axis] = 0.5f * box.period[axis];
                box.any = true;
            }
        return box;
    }

    [[nodiscard]] bool periodic(int axis) const { return period[axis] > 0.0f; }

    /// x_a − x_b to the nearest image of b.
    [[nodiscard]] glm::vec3 delta(const glm::vec3& a, const glm::vec3& b) const {
        const glm::vec3 d = a - b;
        return any ? nearestImage(d) : d;
    }

    /// A difference of two positions in the box, shifted by a period where that makes it shorter.
    [[nodiscard]] glm::vec3 nearestImage(glm::vec3 d) const {
        for (int axis = 0; axis < 3; ++axis)
            d[axis] -= period[axis] * (static_cast<float>(d[axis] > half[axis]) - static_cast<float>(d[axis] < -half[axis]));
        return d;
    }

    /// x moved by whole periods into [min, max) on every periodic axis (non-finite values stay).
    [[nodiscard]] glm::vec3 wrap(glm::vec3 x) const {
        for (int axis = 0; axis < 3; ++axis) {
            if (!periodic(axis) || (x[axis] >= min[axis] && x[axis] < max[axis]) || !std::isfinite(x[axis])) continue;
            const float offset = x[axis] - min[axis];
            x[axis] = min[axis] + (offset - period[axis] * std::floor(offset / period[axis]));
            // Round-off can land a point just below min on max itself.
            if (!(x[axis] >= min[axis] && x[axis] < max[axis])) x[axis] = min[axis];
        }
        return x;
    }
};

/// The pair vector x_a − x_b as a function object, with the periodic shift compiled in or
/// out: pair loops written once as `withPairVector(box, [&](auto delta) { … })` get a plain
/// subtraction when no axis is periodic, with nothing in the loop to keep them from being
/// optimised as such.
template <bool Periodic>
struct PairVector {
    const PeriodicBox* box;
    [[nodiscard]] glm::vec3 operator()(const glm::vec3& a, const glm::vec3& b) const {
        if constexpr (Periodic) return box->nearestImage(a - b);
        else return a - b;
    }
};

template <class F>
decltype(auto) withPairVector(const PeriodicBox& box, F&& f) {
    if (box.any) return f(PairVector<true>{&box});
    return f(PairVector<false>{&box});
}

}  // namespace tide

