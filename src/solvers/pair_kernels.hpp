#pragma once
/// \file
/// Kernel terms of every pair of a neighbour list, computed once per step for the pressure
/// solves: positions do not move while they iterate, so each iteration reads a factor
/// instead of taking a square root and a piecewise kernel per pair (the "precomputed kernel
/// gradients" of Ihmsen et al. 2014, "SPH fluids in computer graphics", §7).

#include <cstdint>
#include <span>
#include <vector>

#include <glm/geometric.hpp>

#include "core/kernels.hpp"
#include "core/parallel.hpp"
#include "core/periodic_box.hpp"
#include "neighbors/neighbor_list.hpp"

namespace tide {

/// Per pair (i, j) of a list, in its pair order (NeighborList::offset): either the gradient
/// factor F_ij = W'(r_ij)/r_ij, so ∇W_ij = F_ij (x_i − x_j), or the value W(r_ij).
class PairKernels {
public:
    enum class Term { GradientFactor, Value };

    /// `queries` are the list's particles i, `points` the set its neighbours j index.
    void compute(const NeighborList& list, std::span<const glm::vec3> queries, std::span<const glm::vec3> points,
                 const PeriodicBox& box, const kernels::CubicSpline& w, Term term, int threads) {
        values_.resize(list.pairCount());
        parallelFor(list.particleCount(), threads, [&](std::uint32_t i) {
            float* out = values_.data() + list.offset(i);
            const glm::vec3 xi = queries[i];
            for (const std::uint32_t j : list.of(i)) {
                const float r = glm::length(box.delta(xi, points[j]));
                *out++ = term == Term::Value ? w.value(r) : (r > 0.0f ? w.derivative(r) / r : 0.0f);
            }
        });
    }

    /// The factors of i's pairs, aligned with list.of(i).
    [[nodiscard]] std::span<const float> of(const NeighborList& list, std::uint32_t i) const {
        return {values_.data() + list.offset(i), list.of(i).size()};
    }

private:
    std::vector<float> values_;
};

}  // namespace tide
