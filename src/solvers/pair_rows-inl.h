// The row loads and kernel shapes of the SIMD pair sums (solvers/pair_sums.cpp,
// solvers/pbf_pair_sums.cpp): compiled once per target of the file that includes it (Highway's
// per-target include guard), in that target's namespace. Not for HWY_SCALAR (no lanes).
#if defined(TIDE_SOLVERS_PAIR_ROWS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef TIDE_SOLVERS_PAIR_ROWS_INL_H_
#undef TIDE_SOLVERS_PAIR_ROWS_INL_H_
#else
#define TIDE_SOLVERS_PAIR_ROWS_INL_H_
#endif

#include <cstddef>
#include <cstdint>

#include <hwy/highway.h>

#include "core/nearest_image-inl.h"
#include "core/periodic_box.hpp"
#include "neighbors/neighbor_list.hpp"
#include "solvers/pair_kernels.hpp"
#include "solvers/pair_sums.hpp"

#if HWY_TARGET != HWY_SCALAR
HWY_BEFORE_NAMESPACE();
namespace tide::pair_sums {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Eight lanes at most: a fluid particle has ~30 neighbours, so wider vectors would run
// half empty, and AVX2 and AVX-512 machines then add in the same order.
using D = hn::CappedTag<float, 8>;
using DU = hn::RebindToUnsigned<D>;
using DU16 = hn::Rebind<std::uint16_t, D>;
using V = hn::Vec<D>;

static_assert(hn::MaxLanes(D()) == 4 || hn::MaxLanes(D()) == 8, "rows of four floats fill 4 or 8 lanes");

/// PairKernels::magnitude of the codes of neighbours k …; 0 past the list's end (the codes
/// are read kPadding past it, and masked).
HWY_INLINE V MagnitudesOf(hn::Vec<DU16> codes, std::size_t left) {
    const D d;
    const DU du;
    const auto code = hn::PromoteTo(du, codes);
    const auto bits = hn::ShiftLeft<PairKernels::kDropped>(
        hn::Add(code, hn::Set(du, PairKernels::kLowestExponent << PairKernels::kMantissaBits)));
    const auto zero = hn::Or(hn::RebindMask(d, hn::Eq(code, hn::Zero(du))), hn::Not(hn::FirstN(d, left)));
    return hn::IfThenZeroElse(zero, hn::BitCast(d, bits));
}
HWY_INLINE V LoadMagnitudes(const Neighbors& neighbors, std::size_t k) {
    return MagnitudesOf(hn::LoadU(DU16(), neighbors.code + k), neighbors.count - k);
}

/// Four floats from each of `lanes` rows, transposed into one vector per column.
struct Columns {
    V x, y, z, w;
};

/// x_i − x_j of a block of pairs, to the nearest periodic image.
struct PairVectors {
    V x, y, z;
};
template <bool Periodic>
HWY_INLINE PairVectors Delta(V xx, V xy, V xz, const Columns& j, const PeriodicBox& box) {
    return {tide::HWY_NAMESPACE::NearestImageDelta<Periodic>(xx, j.x, box.period.x, box.half.x),
            tide::HWY_NAMESPACE::NearestImageDelta<Periodic>(xy, j.y, box.period.y, box.half.y),
            tide::HWY_NAMESPACE::NearestImageDelta<Periodic>(xz, j.z, box.period.z, box.half.z)};
}

/// W/σ of the smoothing kernel at q = r/h, as SmoothingKernel::value: the cubic spline's
/// 2(1 − q)₊³ − 8(½ − q)₊³, or Wendland C2's (1 − q)₊⁴(1 + 4q).
template <bool Wendland>
HWY_INLINE V ValueOverSigma(V q) {
    const D d;
    const V zero = hn::Zero(d);
    const V outer = hn::Max(hn::Sub(hn::Set(d, 1.0f), q), zero);
    if constexpr (Wendland) {
        const V outer2 = hn::Mul(outer, outer);
        return hn::Mul(hn::Mul(outer2, outer2), hn::MulAdd(hn::Set(d, 4.0f), q, hn::Set(d, 1.0f)));
    }
    const V inner = hn::Max(hn::Sub(hn::Set(d, 0.5f), q), zero);
    return hn::Sub(hn::Mul(hn::Set(d, 2.0f), hn::Mul(outer, hn::Mul(outer, outer))),
                   hn::Mul(hn::Set(d, 8.0f), hn::Mul(inner, hn::Mul(inner, inner))));
}

/// W'(r) h/σ, the derivative less its factor σ/h, at q = r/h, as SmoothingKernel::derivative:
/// the cubic spline's 24(½ − q)₊² − 6(1 − q)₊², or Wendland C2's −20 q (1 − q)₊³.
template <bool Wendland>
HWY_INLINE V DerivativeOverSigma(V q) {
    const D d;
    const V zero = hn::Zero(d);
    const V outer = hn::Max(hn::Sub(hn::Set(d, 1.0f), q), zero);
    if constexpr (Wendland) return hn::Mul(hn::Mul(hn::Mul(hn::Mul(hn::Set(d, -20.0f), q), outer), outer), outer);
    const V inner = hn::Max(hn::Sub(hn::Set(d, 0.5f), q), zero);
    return hn::Sub(hn::Mul(hn::Set(d, 24.0f), hn::Mul(inner, inner)), hn::Mul(hn::Set(d, 6.0f), hn::Mul(outer, outer)));
}

/// Rows r_l = row(l) (four floats each) to columns: loads, then the 4 × 4 transposes of SSE
/// within each 128-bit block. Loading whole rows and shuffling beats gathering each column:
/// on the AMD EPYC (Zen 4) four gathers of 8 lanes cost more than the scalar loop they
/// replaced (the 50k dam break's pressure solve, one thread: 3.2 µs a particle-step with
/// gathers, 2.6 scalar, 1.7 with these loads).
template <class Row>
HWY_INLINE Columns Transpose(Row row) {
    const D d;
    const hn::Repartition<double, D> dd;
    V a0, a1, a2, a3;
    if constexpr (hn::MaxLanes(D()) == 8) {
        const hn::Half<D> dh;  // rows l and l + 4 share a vector, one per 128-bit block
        a0 = hn::Combine(d, hn::LoadU(dh, row(4)), hn::LoadU(dh, row(0)));
        a1 = hn::Combine(d, hn::LoadU(dh, row(5)), hn::LoadU(dh, row(1)));
        a2 = hn::Combine(d, hn::LoadU(dh, row(6)), hn::LoadU(dh, row(2)));
        a3 = hn::Combine(d, hn::LoadU(dh, row(7)), hn::LoadU(dh, row(3)));
    } else {
        a0 = hn::LoadU(d, row(0));
        a1 = hn::LoadU(d, row(1));
        a2 = hn::LoadU(d, row(2));
        a3 = hn::LoadU(d, row(3));
    }
    const V xy01 = hn::InterleaveLower(d, a0, a1), xy23 = hn::InterleaveLower(d, a2, a3);  // x0 x1 y0 y1 | …
    const V zw01 = hn::InterleaveUpper(d, a0, a1), zw23 = hn::InterleaveUpper(d, a2, a3);
    return {hn::BitCast(d, hn::InterleaveLower(dd, hn::BitCast(dd, xy01), hn::BitCast(dd, xy23))),
            hn::BitCast(d, hn::InterleaveUpper(dd, hn::BitCast(dd, xy01), hn::BitCast(dd, xy23))),
            hn::BitCast(d, hn::InterleaveLower(dd, hn::BitCast(dd, zw01), hn::BitCast(dd, zw23))),
            hn::BitCast(d, hn::InterleaveUpper(dd, hn::BitCast(dd, zw01), hn::BitCast(dd, zw23)))};
}

// A block's lanes past the list's end read the indices that follow it (NeighborList::kReadPast)
// and the sums zero their terms: no branch on where a list ends but the loop's own, which the
// scalar loop had too. A branch to a separate tail block mispredicted for most particles
// (lists end anywhere in a block): 30 % of the pressure solve's time on the dam break; and
// clamping each lane's index to the list cost as much as the lanes saved.
static_assert(NeighborList::kReadPast >= kPadding);

/// (x_j, w_j) of neighbours k … as columns. Offsets come padded to whole blocks with 0 (the
/// base's own row), indices followed by others of the same set.
template <bool Offsets>
HWY_INLINE Columns LoadRows(const glm::vec4* rows, const Neighbors& neighbors, std::size_t k) {
    if constexpr (Offsets) {
        const std::int16_t* offset = neighbors.offset + k;
        const glm::vec4* base = rows + neighbors.base;
        return Transpose([&](std::size_t l) HWY_ATTR { return &base[offset[l]].x; });
    } else {
        const std::uint32_t* index = neighbors.index + k;
        return Transpose([&](std::size_t l) HWY_ATTR { return &rows[index[l]].x; });
    }
}
static_assert(NeighborList::kOffsetBlock % hn::MaxLanes(D()) == 0);

}  // namespace HWY_NAMESPACE
}  // namespace tide::pair_sums
HWY_AFTER_NAMESPACE();
#endif  // HWY_TARGET != HWY_SCALAR

#endif  // TIDE_SOLVERS_PAIR_ROWS_INL_H_
