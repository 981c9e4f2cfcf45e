#pragma once
/// \file
/// Kernel terms of every pair of a neighbour list, computed once per step for the pressure
/// solves: positions do not move while they iterate, so each iteration reads a factor
/// instead of taking a square root and a piecewise kernel per pair (about half the cost of
/// an iteration, measured on the benchmark dam break).

#include <algorithm>
#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#include "core/kernels.hpp"
#include "core/scratch_resize.hpp"
#include "neighbors/neighbor_list.hpp"
#include "solvers/pair_sums.hpp"

namespace tide {

/// The gradient factor F_ij = W'(r_ij)/r_ij of the smoothing kernel per pair (i, j) of a
/// neighbour list, in its pair order (NeighborList::offset), so that ∇W_ij = F_ij (x_i − x_j).
/// Kept in 16 bits as a small float: F lies in [F(0), 0] (−12σ/h² for the cubic spline,
/// −20σ/h² for Wendland C2: its value as r → 0), and
/// F / (−12σ/h²) in [2⁻³¹, 1] is coded with 5 exponent and 11 mantissa bits (0 for less), so
/// every factor is within 2.4e-4 (relative) of its exact value. (A fixed-point code, finer
/// at half the support, was 1.6 % off near its edge, and the 1 cm tank at rest and a
/// two-fluid interface read worse for it.) Half the bytes of a float: ~60 bytes a fluid
/// particle.
class PairKernels {
public:
    using Code = std::uint16_t;

    /// Room for one value per pair slot of `list` (a NeighborList or CrossNeighborList; the
    /// values of the last list are lost), for
    /// the kernel `w`, and pair_sums::kPadding zeros after them for the SIMD sums (pair_sums.hpp).
    template <class List>
    void resize(const List& list, const kernels::SmoothingKernel& w) {
        resizeScratch(values_, list.slotCount() + pair_sums::kPadding);
        std::fill(values_.end() - pair_sums::kPadding, values_.end(), Code{0});
        unit_ = w.gradientFactorAtZero();
        invUnit_ = 1.0f / unit_;
    }

    /// The codes of i's pairs, aligned with list.of(i).
    template <class List>
    [[nodiscard]] std::span<const Code> of(const List& list, std::uint32_t i) const {
        return {values_.data() + list.offset(i), list.of(i).size()};
    }
    template <class List>
    [[nodiscard]] std::span<Code> of(const List& list, std::uint32_t i) {
        return {values_.data() + list.offset(i), list.of(i).size()};
    }

    /// F(r) = W'(r)/r of `w` (the kernel given to resize), coded; 0 at r = 0.
    [[nodiscard]] Code encode(const kernels::SmoothingKernel& w, float r) const {
        const float f = r > 0.0f ? w.derivative(r) / r : 0.0f;
        const float x = std::min(f * invUnit_, 1.0f);  // NaN (a diverged step) codes as 0
        if (!(x >= kSmallest)) return 0;
        // Round the 23-bit mantissa to 11 bits (a carry moves into the exponent, as it should).
        const std::uint32_t bits = std::bit_cast<std::uint32_t>(x) + (1u << (kDropped - 1));
        return static_cast<Code>((bits >> kDropped) - (kLowestExponent << kMantissaBits));
    }
    /// F / unit() of a code, in [0, 1].
    [[nodiscard]] static float magnitude(Code code) {
        const float x = std::bit_cast<float>((static_cast<std::uint32_t>(code) + (kLowestExponent << kMantissaBits)) << kDropped);
        return code == 0 ? 0.0f : x;
    }
    /// The factor of a code's magnitude 1: F(0), SmoothingKernel::gradientFactorAtZero.
    [[nodiscard]] float unit() const { return unit_; }
    [[nodiscard]] float invUnit() const { return invUnit_; }
    /// The factor F a code stands for.
    [[nodiscard]] float factor(Code code) const { return unit_ * magnitude(code); }

    /// The code's layout (public for the SIMD code in pair_sums.cpp): a code c ≠ 0 stands
    /// for the float with bits (c + (kLowestExponent << kMantissaBits)) << kDropped.
    static constexpr unsigned kMantissaBits = 11, kDropped = 23 - kMantissaBits;
    static constexpr std::uint32_t kLowestExponent = 127 - 31;  ///< biased exponent of 2⁻³¹
    static constexpr float kSmallest = 0x1p-31f;

private:
    std::vector<Code> values_;
    float unit_ = 0.0f, invUnit_ = 0.0f;  ///< −12σ/h², and its inverse
};

}  // namespace tide
