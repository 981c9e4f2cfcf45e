#pragma once
/// \file
/// Kernel terms of every pair of a neighbour list, computed once per step for the pressure
/// solves: positions do not move while they iterate, so each iteration reads a factor
/// instead of taking a square root and a piecewise kernel per pair (4 bytes per pair traded
/// for about half the cost of an iteration, measured on the benchmark dam break).

#include <cstdint>
#include <span>
#include <vector>

#include "core/kernels.hpp"
#include "core/scratch_resize.hpp"
#include "neighbors/neighbor_list.hpp"

namespace tide {

/// A float per pair (i, j) of a neighbour list, in its pair order (NeighborList::offset):
/// here the gradient factor F_ij = W'(r_ij)/r_ij, so that ∇W_ij = F_ij (x_i − x_j).
class PairKernels {
public:
    /// Room for one value per pair of `list` (the values of the last list are lost).
    void resize(const NeighborList& list) { resizeScratch(values_, list.pairCount()); }

    /// The values of i's pairs, aligned with list.of(i).
    [[nodiscard]] std::span<const float> of(const NeighborList& list, std::uint32_t i) const {
        return {values_.data() + list.offset(i), list.of(i).size()};
    }
    [[nodiscard]] std::span<float> of(const NeighborList& list, std::uint32_t i) {
        return {values_.data() + list.offset(i), list.of(i).size()};
    }

    /// W'(r)/r, 0 at r = 0.
    [[nodiscard]] static float gradientFactor(const kernels::CubicSpline& w, float r) {
        return r > 0.0f ? w.derivative(r) / r : 0.0f;
    }

private:
    std::vector<float> values_;
};

}  // namespace tide
