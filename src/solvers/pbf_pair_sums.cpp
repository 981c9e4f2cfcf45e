// The pair loops of pbf_pair_sums.hpp, compiled once per instruction set by Highway's
// foreach_target (this file includes itself once per target) and dispatched at run time.
#include "solvers/pbf_pair_sums.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include <glm/geometric.hpp>

#ifndef TIDE_PBF_PAIR_SUMS_SEQUENTIAL
#define TIDE_PBF_PAIR_SUMS_SEQUENTIAL
// One pair at a time in list order: for CPUs without lanes.
namespace tide::pbf_sums::sequential {

inline float tensileOf(float wij, float vi, float vj, const LambdaKernel& kernel) {
    const float ratio = wij * kernel.invWdq;
    const float ratio2 = ratio * ratio;
    return 0.5f * (vi + vj) * kernel.tensileScale * std::max(ratio2 * ratio2 - kernel.restTensile, 0.0f);
}

template <bool Periodic>
LambdaSums lambdaSums(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const float* weightedVolume2,
                      const glm::vec3& xi, float vi, const LambdaKernel& kernel, const PeriodicBox& box, float* factor,
                      float* tensile) {
    LambdaSums sums;
    for (std::size_t k = 0; k < neighbors.count; ++k) {
        const std::uint32_t j = neighbors.at(k);
        const glm::vec4 row = rows[j];
        glm::vec3 d = xi - glm::vec3(row);
        if constexpr (Periodic) d = box.nearestImage(d);
        const float r2 = glm::dot(d, d);
        float f = 0.0f, s = 0.0f;
        if (r2 < kernel.h2) {
            const float r = std::sqrt(r2);
            const float wij = kernel.density.value(r);
            sums.kernelSum += wij;
            const float reach = kernel.h - r;
            f = r > 0.0f ? kernel.spikyGradient * reach * reach / r : 0.0f;
            const glm::vec3 g = f * d;
            sums.gradient += g;
            sums.weightedSquares += weightedVolume2[j] * glm::dot(g, g);
            s = tensileOf(wij, vi, row.w, kernel);
        }
        factor[k] = f;
        tensile[k] = s;
    }
    return sums;
}

template <bool Periodic>
glm::vec4 wallSums(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const glm::vec3& xi,
                   const LambdaKernel& kernel, const PeriodicBox& box) {
    glm::vec4 sums(0.0f);
    for (std::size_t k = 0; k < neighbors.count; ++k) {
        glm::vec3 d = xi - glm::vec3(rows[neighbors.at(k)]);
        if constexpr (Periodic) d = box.nearestImage(d);
        const float r2 = glm::dot(d, d);
        if (r2 >= kernel.h2) continue;
        const float r = std::sqrt(r2);
        const float reach = kernel.h - r;
        const float f = r > 0.0f ? kernel.spikyGradient * reach * reach / r : 0.0f;
        sums += glm::vec4(f * d, kernel.density.value(r));
    }
    return sums;
}

template <bool Periodic>
glm::vec3 correctionSum(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const glm::vec3& xi, float li,
                        const float* factor, const float* tensile, const PeriodicBox& box) {
    glm::vec3 dx(0.0f);
    for (std::size_t k = 0; k < neighbors.count; ++k) {
        const glm::vec4 row = rows[neighbors.at(k)];
        glm::vec3 d = xi - glm::vec3(row);
        if constexpr (Periodic) d = box.nearestImage(d);
        dx += ((li + row.w + tensile[k]) * factor[k]) * d;
    }
    return dx;
}

}  // namespace tide::pbf_sums::sequential
#endif  // TIDE_PBF_PAIR_SUMS_SEQUENTIAL

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "solvers/pbf_pair_sums.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "solvers/pair_rows-inl.h"

HWY_BEFORE_NAMESPACE();
namespace tide::pbf_sums {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#if HWY_TARGET == HWY_SCALAR

template <bool Periodic, bool Offsets, bool Wendland>
LambdaSums LambdaSumsT(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const float* weightedVolume2,
                       const glm::vec3& xi, float vi, const LambdaKernel& kernel, const PeriodicBox& box, float* factor,
                       float* tensile) {
    return sequential::lambdaSums<Periodic>(neighbors, rows, weightedVolume2, xi, vi, kernel, box, factor, tensile);
}
template <bool Periodic, bool Offsets, bool Wendland>
glm::vec4 WallSumsT(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const glm::vec3& xi,
                    const LambdaKernel& kernel, const PeriodicBox& box) {
    return sequential::wallSums<Periodic>(neighbors, rows, xi, kernel, box);
}
template <bool Periodic, bool Offsets>
glm::vec3 CorrectionSumT(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const glm::vec3& xi, float li,
                         const float* factor, const float* tensile, const PeriodicBox& box) {
    return sequential::correctionSum<Periodic>(neighbors, rows, xi, li, factor, tensile, box);
}

#else

namespace ps = tide::pair_sums::HWY_NAMESPACE;
using ps::D;
using ps::V;

/// v[j] of neighbours k … (one float each), gathered.
template <bool Offsets>
HWY_INLINE V GatherOf(const float* v, const pair_sums::Neighbors& neighbors, std::size_t k) {
    const D d;
    const hn::RebindToSigned<D> di;
    if constexpr (Offsets) {
        const hn::Rebind<std::int16_t, D> di16;
        return hn::GatherIndex(d, v + neighbors.base, hn::PromoteTo(di, hn::LoadU(di16, neighbors.offset + k)));
    } else {
        const hn::RebindToUnsigned<D> du;
        return hn::GatherIndex(d, v, hn::BitCast(di, hn::LoadU(du, neighbors.index + k)));
    }
}

/// Lanes to out[k …], not past the list's end where it holds indices (the next list's slots
/// may be another thread's); lists of offsets own their padding to a whole block.
template <bool Offsets>
HWY_INLINE void StoreBlock(V v, float* out, std::size_t left) {
    const D d;
    if (Offsets || left >= hn::Lanes(d)) {
        hn::StoreU(v, d, out);
        return;
    }
    HWY_ALIGN float tail[hn::MaxLanes(D())];
    hn::Store(v, d, tail);
    for (std::size_t l = 0; l < left; ++l) out[l] = tail[l];
}

template <bool Periodic, bool Offsets, bool Wendland>
HWY_INLINE LambdaSums LambdaSumsT(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const float* weightedVolume2,
                       const glm::vec3& xi, float vi, const LambdaKernel& kernel, const PeriodicBox& box, float* factor,
                       float* tensile) {
    const D d;
    const V xx = hn::Set(d, xi.x), xy = hn::Set(d, xi.y), xz = hn::Set(d, xi.z);
    const V zero = hn::Zero(d), h = hn::Set(d, kernel.h), h2 = hn::Set(d, kernel.h2), invH = hn::Set(d, kernel.density.invH);
    const V sigma = hn::Set(d, kernel.density.sigma), spiky = hn::Set(d, kernel.spikyGradient);
    const V invWdq = hn::Set(d, kernel.invWdq), restTensile = hn::Set(d, kernel.restTensile);
    const V halfVi = hn::Set(d, 0.5f * vi), tensileScale = hn::Set(d, kernel.tensileScale);
    V sumW = zero, gx = zero, gy = zero, gz = zero, squares = zero;
    for (std::size_t k = 0; k < neighbors.count; k += hn::Lanes(d)) {
        const ps::Columns j = ps::LoadRows<Offsets>(rows, neighbors, k);
        const ps::PairVectors r = ps::Delta<Periodic>(xx, xy, xz, j, box);
        const V r2 = hn::MulAdd(r.x, r.x, hn::MulAdd(r.y, r.y, hn::Mul(r.z, r.z)));
        const auto near = hn::And(hn::FirstN(d, neighbors.count - k), hn::Lt(r2, h2));
        const V length = hn::Sqrt(r2);
        const V wij = hn::IfThenElseZero(near, hn::Mul(sigma, ps::ValueOverSigma<Wendland>(hn::Mul(length, invH))));
        sumW = hn::Add(sumW, wij);
        // spiky ∇W_ij = g (h − r)²/r (x_i − x_j); 0 at r = 0 (Spiky::gradient)
        const V reach = hn::Sub(h, length);
        const V f = hn::IfThenElseZero(hn::And(near, hn::Gt(length, zero)),
                                       hn::Div(hn::Mul(spiky, hn::Mul(reach, reach)), length));
        const V x = hn::Mul(f, r.x), y = hn::Mul(f, r.y), z = hn::Mul(f, r.z);
        gx = hn::Add(gx, x);
        gy = hn::Add(gy, y);
        gz = hn::Add(gz, z);
        const V g2 = hn::MulAdd(x, x, hn::MulAdd(y, y, hn::Mul(z, z)));
        squares = hn::MulAdd(GatherOf<Offsets>(weightedVolume2, neighbors, k), g2, squares);
        // eq. 13 with n = 4, less its value at the rest spacing, times the pair's mean volume
        const V ratio = hn::Mul(wij, invWdq);
        const V ratio2 = hn::Mul(ratio, ratio);
        const V s = hn::Mul(hn::Mul(hn::MulAdd(hn::Set(d, 0.5f), j.w, halfVi), tensileScale),
                            hn::Max(hn::Sub(hn::Mul(ratio2, ratio2), restTensile), zero));
        StoreBlock<Offsets>(f, factor + k, neighbors.count - k);
        StoreBlock<Offsets>(s, tensile + k, neighbors.count - k);
    }
    LambdaSums sums;
    sums.kernelSum = hn::GetLane(hn::SumOfLanes(d, sumW));
    sums.gradient = {hn::GetLane(hn::SumOfLanes(d, gx)), hn::GetLane(hn::SumOfLanes(d, gy)),
                     hn::GetLane(hn::SumOfLanes(d, gz))};
    sums.weightedSquares = hn::GetLane(hn::SumOfLanes(d, squares));
    return sums;
}

template <bool Periodic, bool Offsets, bool Wendland>
HWY_INLINE glm::vec4 WallSumsT(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const glm::vec3& xi,
                    const LambdaKernel& kernel, const PeriodicBox& box) {
    const D d;
    const V xx = hn::Set(d, xi.x), xy = hn::Set(d, xi.y), xz = hn::Set(d, xi.z);
    const V zero = hn::Zero(d), h = hn::Set(d, kernel.h), h2 = hn::Set(d, kernel.h2), invH = hn::Set(d, kernel.density.invH);
    V sumW = zero, gx = zero, gy = zero, gz = zero;
    for (std::size_t k = 0; k < neighbors.count; k += hn::Lanes(d)) {
        const ps::Columns b = ps::LoadRows<Offsets>(rows, neighbors, k);
        const ps::PairVectors r = ps::Delta<Periodic>(xx, xy, xz, b, box);
        const V r2 = hn::MulAdd(r.x, r.x, hn::MulAdd(r.y, r.y, hn::Mul(r.z, r.z)));
        const auto near = hn::And(hn::FirstN(d, neighbors.count - k), hn::Lt(r2, h2));
        const V length = hn::Sqrt(r2);
        sumW = hn::Add(sumW, hn::IfThenElseZero(near, ps::ValueOverSigma<Wendland>(hn::Mul(length, invH))));
        const V reach = hn::Sub(h, length);
        const V f = hn::IfThenElseZero(hn::And(near, hn::Gt(length, zero)), hn::Div(hn::Mul(reach, reach), length));
        gx = hn::MulAdd(f, r.x, gx);
        gy = hn::MulAdd(f, r.y, gy);
        gz = hn::MulAdd(f, r.z, gz);
    }
    const float g = kernel.spikyGradient;
    return {g * hn::GetLane(hn::SumOfLanes(d, gx)), g * hn::GetLane(hn::SumOfLanes(d, gy)),
            g * hn::GetLane(hn::SumOfLanes(d, gz)), kernel.density.sigma * hn::GetLane(hn::SumOfLanes(d, sumW))};
}

template <bool Periodic, bool Offsets>
HWY_INLINE glm::vec3 CorrectionSumT(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const glm::vec3& xi, float li,
                         const float* factor, const float* tensile, const PeriodicBox& box) {
    const D d;
    const V xx = hn::Set(d, xi.x), xy = hn::Set(d, xi.y), xz = hn::Set(d, xi.z), own = hn::Set(d, li);
    V sx = hn::Zero(d), sy = hn::Zero(d), sz = hn::Zero(d);
    for (std::size_t k = 0; k < neighbors.count; k += hn::Lanes(d)) {
        const ps::Columns j = ps::LoadRows<Offsets>(rows, neighbors, k);
        const ps::PairVectors r = ps::Delta<Periodic>(xx, xy, xz, j, box);
        // (λ_i V_i + λ_j V_j + s_corr V̄) F_ij, eq. 14; masked last: past the list, anything
        const V c = hn::IfThenElseZero(hn::FirstN(d, neighbors.count - k),
                                       hn::Mul(hn::Add(hn::Add(own, j.w), hn::LoadU(d, tensile + k)), hn::LoadU(d, factor + k)));
        sx = hn::MulAdd(c, r.x, sx);
        sy = hn::MulAdd(c, r.y, sy);
        sz = hn::MulAdd(c, r.z, sz);
    }
    return {hn::GetLane(hn::SumOfLanes(d, sx)), hn::GetLane(hn::SumOfLanes(d, sy)), hn::GetLane(hn::SumOfLanes(d, sz))};
}

#endif  // HWY_TARGET == HWY_SCALAR

LambdaSums LambdaSumsImpl(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const float* weightedVolume2,
                          const glm::vec3& xi, float vi, const LambdaKernel& kernel, const PeriodicBox& box, float* factor,
                          float* tensile) {
    const auto call = [&](auto periodic, auto offsets) HWY_ATTR {
        if (kernel.density.shape == KernelShape::WendlandC2)
            return LambdaSumsT<periodic(), offsets(), true>(neighbors, rows, weightedVolume2, xi, vi, kernel, box, factor, tensile);
        return LambdaSumsT<periodic(), offsets(), false>(neighbors, rows, weightedVolume2, xi, vi, kernel, box, factor, tensile);
    };
    using Yes = std::true_type;
    using No = std::false_type;
    if (neighbors.offset != nullptr) return box.any ? call(Yes{}, Yes{}) : call(No{}, Yes{});
    return box.any ? call(Yes{}, No{}) : call(No{}, No{});
}
glm::vec4 WallSumsImpl(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const glm::vec3& xi,
                       const LambdaKernel& kernel, const PeriodicBox& box) {
    // boundary lists hold indices (CrossNeighborList)
    if (kernel.density.shape == KernelShape::WendlandC2)
        return box.any ? WallSumsT<true, false, true>(neighbors, rows, xi, kernel, box)
                       : WallSumsT<false, false, true>(neighbors, rows, xi, kernel, box);
    return box.any ? WallSumsT<true, false, false>(neighbors, rows, xi, kernel, box)
                   : WallSumsT<false, false, false>(neighbors, rows, xi, kernel, box);
}
glm::vec3 CorrectionSumImpl(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const glm::vec3& xi, float li,
                            const float* factor, const float* tensile, const PeriodicBox& box) {
    if (neighbors.offset != nullptr)
        return box.any ? CorrectionSumT<true, true>(neighbors, rows, xi, li, factor, tensile, box)
                       : CorrectionSumT<false, true>(neighbors, rows, xi, li, factor, tensile, box);
    return box.any ? CorrectionSumT<true, false>(neighbors, rows, xi, li, factor, tensile, box)
                   : CorrectionSumT<false, false>(neighbors, rows, xi, li, factor, tensile, box);
}

// The ranges: the template variant chosen once a block; a particle's list holds offsets or
// (kWide) indices, chosen per particle.
template <bool Periodic, bool Wendland>
void LambdaSumsOfRangeT(const NeighborList& list, std::uint32_t first, std::uint32_t last, const glm::vec4* rows,
                        const float* weightedVolume2, const LambdaKernel& kernel, const PeriodicBox& box, float* factor,
                        float* tensile, LambdaSums* out) {
    for (std::uint32_t i = first; i < last; ++i) {
        const pair_sums::Neighbors neighbors(list.of(i));
        const std::uint64_t slot = list.offset(i);
        const glm::vec4 own = rows[i];
        out[i - first] =
            neighbors.offset != nullptr
                ? LambdaSumsT<Periodic, true, Wendland>(neighbors, rows, weightedVolume2, glm::vec3(own), own.w, kernel, box,
                                                        factor + slot, tensile + slot)
                : LambdaSumsT<Periodic, false, Wendland>(neighbors, rows, weightedVolume2, glm::vec3(own), own.w, kernel, box,
                                                         factor + slot, tensile + slot);
    }
}
void LambdaSumsOfRangeImpl(const NeighborList& list, std::uint32_t first, std::uint32_t last, const glm::vec4* rows,
                           const float* weightedVolume2, const LambdaKernel& kernel, const PeriodicBox& box, float* factor,
                           float* tensile, LambdaSums* out) {
    const bool wendland = kernel.density.shape == KernelShape::WendlandC2;
    if (box.any)
        wendland ? LambdaSumsOfRangeT<true, true>(list, first, last, rows, weightedVolume2, kernel, box, factor, tensile, out)
                 : LambdaSumsOfRangeT<true, false>(list, first, last, rows, weightedVolume2, kernel, box, factor, tensile, out);
    else
        wendland ? LambdaSumsOfRangeT<false, true>(list, first, last, rows, weightedVolume2, kernel, box, factor, tensile, out)
                 : LambdaSumsOfRangeT<false, false>(list, first, last, rows, weightedVolume2, kernel, box, factor, tensile, out);
}

template <bool Periodic, bool Wendland>
void WallSumsOfRangeT(const CrossNeighborList& walls, std::uint32_t first, std::uint32_t last, const glm::vec4* wallRows,
                      const glm::vec4* rows, const LambdaKernel& kernel, const PeriodicBox& box, glm::vec4* out) {
    for (std::uint32_t i = first; i < last; ++i) {
        const auto list = walls.of(i);
        out[i - first] = list.empty() ? glm::vec4(0.0f)
                                      : WallSumsT<Periodic, false, Wendland>(
                                            pair_sums::Neighbors(NeighborSpan(list.data(), static_cast<std::uint32_t>(list.size()))),
                                            wallRows, glm::vec3(rows[i]), kernel, box);
    }
}
void WallSumsOfRangeImpl(const CrossNeighborList& walls, std::uint32_t first, std::uint32_t last, const glm::vec4* wallRows,
                         const glm::vec4* rows, const LambdaKernel& kernel, const PeriodicBox& box, glm::vec4* out) {
    const bool wendland = kernel.density.shape == KernelShape::WendlandC2;
    if (box.any)
        wendland ? WallSumsOfRangeT<true, true>(walls, first, last, wallRows, rows, kernel, box, out)
                 : WallSumsOfRangeT<true, false>(walls, first, last, wallRows, rows, kernel, box, out);
    else
        wendland ? WallSumsOfRangeT<false, true>(walls, first, last, wallRows, rows, kernel, box, out)
                 : WallSumsOfRangeT<false, false>(walls, first, last, wallRows, rows, kernel, box, out);
}

template <bool Periodic>
void CorrectionSumsOfRangeT(const NeighborList& list, std::uint32_t first, std::uint32_t last, const glm::vec4* rows,
                            const float* factor, const float* tensile, const PeriodicBox& box, glm::vec3* out) {
    for (std::uint32_t i = first; i < last; ++i) {
        const pair_sums::Neighbors neighbors(list.of(i));
        const std::uint64_t slot = list.offset(i);
        const glm::vec4 own = rows[i];
        out[i - first] = neighbors.offset != nullptr
                             ? CorrectionSumT<Periodic, true>(neighbors, rows, glm::vec3(own), own.w, factor + slot, tensile + slot, box)
                             : CorrectionSumT<Periodic, false>(neighbors, rows, glm::vec3(own), own.w, factor + slot, tensile + slot, box);
    }
}
void CorrectionSumsOfRangeImpl(const NeighborList& list, std::uint32_t first, std::uint32_t last, const glm::vec4* rows,
                               const float* factor, const float* tensile, const PeriodicBox& box, glm::vec3* out) {
    box.any ? CorrectionSumsOfRangeT<true>(list, first, last, rows, factor, tensile, box, out)
            : CorrectionSumsOfRangeT<false>(list, first, last, rows, factor, tensile, box, out);
}

}  // namespace HWY_NAMESPACE
}  // namespace tide::pbf_sums
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace tide::pbf_sums {

HWY_EXPORT(LambdaSumsImpl);
HWY_EXPORT(WallSumsImpl);
HWY_EXPORT(CorrectionSumImpl);
HWY_EXPORT(LambdaSumsOfRangeImpl);
HWY_EXPORT(WallSumsOfRangeImpl);
HWY_EXPORT(CorrectionSumsOfRangeImpl);

namespace {
/// The chosen target's loops, looked up once (as pair_sums.cpp: a dispatch per call costs).
struct Targets {
    decltype(&HWY_STATIC_DISPATCH(LambdaSumsImpl)) lambdaSums;
    decltype(&HWY_STATIC_DISPATCH(WallSumsImpl)) wallSums;
    decltype(&HWY_STATIC_DISPATCH(CorrectionSumImpl)) correctionSum;
    decltype(&HWY_STATIC_DISPATCH(LambdaSumsOfRangeImpl)) lambdaSumsOfRange;
    decltype(&HWY_STATIC_DISPATCH(WallSumsOfRangeImpl)) wallSumsOfRange;
    decltype(&HWY_STATIC_DISPATCH(CorrectionSumsOfRangeImpl)) correctionSumsOfRange;
};
Targets chooseTargets() {
    hwy::GetChosenTarget().Update(hwy::SupportedTargets());
    return Targets{&HWY_DYNAMIC_DISPATCH(LambdaSumsImpl), &HWY_DYNAMIC_DISPATCH(WallSumsImpl),
                   &HWY_DYNAMIC_DISPATCH(CorrectionSumImpl), &HWY_DYNAMIC_DISPATCH(LambdaSumsOfRangeImpl),
                   &HWY_DYNAMIC_DISPATCH(WallSumsOfRangeImpl), &HWY_DYNAMIC_DISPATCH(CorrectionSumsOfRangeImpl)};
}
const Targets& targets() {
    static const Targets chosen = chooseTargets();
    return chosen;
}
}  // namespace

LambdaSums lambdaSums(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const float* weightedVolume2,
                      const glm::vec3& xi, float vi, const LambdaKernel& kernel, const PeriodicBox& box, float* factor,
                      float* tensile) {
    return targets().lambdaSums(neighbors, rows, weightedVolume2, xi, vi, kernel, box, factor, tensile);
}
glm::vec4 wallSums(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const glm::vec3& xi,
                   const LambdaKernel& kernel, const PeriodicBox& box) {
    return targets().wallSums(neighbors, rows, xi, kernel, box);
}
glm::vec3 correctionSum(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const glm::vec3& xi, float li,
                        const float* factor, const float* tensile, const PeriodicBox& box) {
    return targets().correctionSum(neighbors, rows, xi, li, factor, tensile, box);
}
void lambdaSumsOfRange(const NeighborList& list, std::uint32_t first, std::uint32_t last, const glm::vec4* rows,
                       const float* weightedVolume2, const LambdaKernel& kernel, const PeriodicBox& box, float* factor,
                       float* tensile, LambdaSums* out) {
    targets().lambdaSumsOfRange(list, first, last, rows, weightedVolume2, kernel, box, factor, tensile, out);
}
void wallSumsOfRange(const CrossNeighborList& walls, std::uint32_t first, std::uint32_t last, const glm::vec4* wallRows,
                     const glm::vec4* rows, const LambdaKernel& kernel, const PeriodicBox& box, glm::vec4* out) {
    targets().wallSumsOfRange(walls, first, last, wallRows, rows, kernel, box, out);
}
void correctionSumsOfRange(const NeighborList& list, std::uint32_t first, std::uint32_t last, const glm::vec4* rows,
                           const float* factor, const float* tensile, const PeriodicBox& box, glm::vec3* out) {
    targets().correctionSumsOfRange(list, first, last, rows, factor, tensile, box, out);
}

}  // namespace tide::pbf_sums
#endif  // HWY_ONCE
