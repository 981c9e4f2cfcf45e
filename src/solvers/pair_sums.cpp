// The pair sums of pair_sums.hpp, compiled once per instruction set by Highway's
// foreach_target (this file includes itself once per target) and dispatched at run time.
#include "solvers/pair_sums.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "solvers/pair_kernels.hpp"

#ifndef TIDE_PAIR_SUMS_SEQUENTIAL
#define TIDE_PAIR_SUMS_SEQUENTIAL
// One pair at a time in list order, from `initial`: compiled once, for Order::Sequential and
// for CPUs without lanes.
namespace tide::pair_sums::sequential {

template <bool Periodic>
glm::vec3 delta(const glm::vec3& xi, const glm::vec4& xj, const PeriodicBox& box) {
    const glm::vec3 d = xi - glm::vec3(xj);
    if constexpr (Periodic) return box.nearestImage(d);
    return d;
}

template <bool Periodic>
float kernelSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                const kernels::SmoothingKernel& w, const PeriodicBox& box, float initial) {
    float sum = initial;
    for (std::size_t k = 0; k < neighbors.count; ++k) {
        const glm::vec4 xj = points[neighbors.at(k)];
        const glm::vec3 r = delta<Periodic>(xi, xj, box);
        sum += xj.w * w.value(std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z));
    }
    return sum;
}

template <bool Periodic>
glm::vec4 gradientAndSquaresSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                                const PeriodicBox& box);

template <bool Periodic>
float kernelSumAndCodes(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                        const kernels::SmoothingKernel& w, const PeriodicBox& box, float initial, const PairKernels& factors,
                        std::uint16_t* codes, glm::vec4* gradients) {
    float sum = initial;
    for (std::size_t k = 0; k < neighbors.count; ++k) {
        const glm::vec4 xj = points[neighbors.at(k)];
        const glm::vec3 d = delta<Periodic>(xi, xj, box);
        const float r = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        sum += xj.w * w.value(r);
        codes[k] = factors.encode(w, r);
    }
    if (gradients != nullptr) {  // over the codes just written
        Neighbors coded = neighbors;
        coded.code = codes;
        *gradients = gradientAndSquaresSum<Periodic>(coded, points, xi, box);
    }
    return sum;
}

// Accumulating in separate floats rather than a glm::vec3: GCC keeps a vec3's third lane on
// the stack, a store-load chain through every iteration.
template <bool Periodic>
glm::vec3 gradientSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi, const PeriodicBox& box) {
    float x = 0.0f, y = 0.0f, z = 0.0f;
    for (std::size_t k = 0; k < neighbors.count; ++k) {
        const glm::vec4 xj = points[neighbors.at(k)];
        const glm::vec3 r = delta<Periodic>(xi, xj, box);
        const float s = xj.w * PairKernels::magnitude(neighbors.code[k]);
        x += s * r.x;
        y += s * r.y;
        z += s * r.z;
    }
    return {x, y, z};
}

template <bool Periodic>
glm::vec4 gradientAndSquaresSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                                const PeriodicBox& box) {
    float x = 0.0f, y = 0.0f, z = 0.0f, squares = 0.0f;
    for (std::size_t k = 0; k < neighbors.count; ++k) {
        const glm::vec4 xj = points[neighbors.at(k)];
        const glm::vec3 g = (xj.w * PairKernels::magnitude(neighbors.code[k])) * delta<Periodic>(xi, xj, box);
        x += g.x;
        y += g.y;
        z += g.z;
        squares += g.x * g.x + g.y * g.y + g.z * g.z;
    }
    return {x, y, z, squares};
}

template <bool Periodic>
glm::vec4 cappedGradientSquares(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi, float mi,
                                const PeriodicBox& box) {
    glm::vec4 sums(0.0f);
    for (std::size_t k = 0; k < neighbors.count; ++k) {
        const glm::vec4 xj = points[neighbors.at(k)];
        const glm::vec3 g = PairKernels::magnitude(neighbors.code[k]) * delta<Periodic>(xi, xj, box);
        sums += glm::vec4(g, std::max(mi / xj.w, 1.0f) * glm::dot(g, g));
    }
    return sums;
}

template <bool Periodic>
float divergenceSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                    const glm::vec3& xi, const glm::vec3& vi, const PeriodicBox& box) {
    float sum = 0.0f;
    for (std::size_t k = 0; k < neighbors.count; ++k) {
        const std::uint32_t j = neighbors.at(k);
        const glm::vec4 xj = points[j];
        sum += (xj.w * PairKernels::magnitude(neighbors.code[k])) * glm::dot(vi - glm::vec3(velocities[j]), delta<Periodic>(xi, xj, box));
    }
    return sum;
}

/// The viscous sums' pair weight: w_j u_j, or with Harmonic (w_j = μ_j) 4 μ_i μ_j/(μ_i + μ_j) u_j.
template <bool Harmonic>
float viscousWeight(float wj, float uj, float mui) {
    if constexpr (Harmonic) {
        const float sum = mui + wj;
        return sum > 0.0f ? 4.0f * mui * wj / sum * uj : 0.0f;
    }
    return wj * uj;
}

template <bool Periodic, bool Harmonic = false>
glm::vec3 viscousSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                     const glm::vec3& xi, const glm::vec3& vi, const kernels::SmoothingKernel& w, float epsilon,
                     const PeriodicBox& box, float mui = 0.0f) {
    glm::vec3 sum(0.0f);
    for (std::size_t k = 0; k < neighbors.count; ++k) {
        const std::uint32_t j = neighbors.at(k);
        const glm::vec3 d = delta<Periodic>(xi, points[j], box);
        const float r = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        sum += (viscousWeight<Harmonic>(points[j].w, velocities[j].w, mui) * r * w.derivative(r) / (r * r + epsilon)) *
               (vi - glm::vec3(velocities[j]));
    }
    return sum;
}

template <bool Periodic>
glm::vec3 xsphSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities, const glm::vec3& xi,
                  const glm::vec4& vi, const kernels::Poly6& w, const PeriodicBox& box) {
    glm::vec3 sum(0.0f);
    for (std::size_t k = 0; k < neighbors.count; ++k) {
        const std::uint32_t j = neighbors.at(k);
        const glm::vec3 d = delta<Periodic>(xi, points[j], box);
        const float reach = std::max(w.h2 - (d.x * d.x + d.y * d.y + d.z * d.z), 0.0f);
        sum += (2.0f * points[j].w / (vi.w + velocities[j].w) * reach * reach * reach) *
               (glm::vec3(velocities[j]) - glm::vec3(vi));
    }
    return sum;
}

template <bool Periodic>
GradientSums kernelGradientSums(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                                const kernels::SmoothingKernel& w, const PeriodicBox& box) {
    GradientSums sums;
    for (std::size_t k = 0; k < neighbors.count; ++k) {
        const glm::vec4 xj = points[neighbors.at(k)];
        const glm::vec3 r = delta<Periodic>(xi, xj, box);
        const glm::vec3 g = w.gradient(r, std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z));
        sums.plain += g;
        sums.weighted += xj.w * g;
    }
    return sums;
}

}  // namespace tide::pair_sums::sequential
#endif  // TIDE_PAIR_SUMS_SEQUENTIAL

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "solvers/pair_sums.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "solvers/pair_rows-inl.h"  // D, V, Columns, LoadRows, the kernel shapes

HWY_BEFORE_NAMESPACE();
namespace tide::pair_sums {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#if HWY_TARGET == HWY_SCALAR
// No lanes (GCC before 12.3 compiles Highway's fallback as HWY_SCALAR): the plain loops.

template <bool Periodic, bool Offsets, bool Wendland>
float KernelSumT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                 const kernels::SmoothingKernel& w, const PeriodicBox& box, float initial) {
    return sequential::kernelSum<Periodic>(neighbors, points, xi, w, box, initial);
}
template <bool Periodic, bool Offsets, bool Wendland>
float KernelSumAndCodesT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                         const kernels::SmoothingKernel& w, const PeriodicBox& box, float initial, const PairKernels& factors,
                         std::uint16_t* codes, glm::vec4* gradients) {
    return sequential::kernelSumAndCodes<Periodic>(neighbors, points, xi, w, box, initial, factors, codes, gradients);
}
template <bool Periodic, bool Offsets>
glm::vec3 GradientSumT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi, const PeriodicBox& box) {
    return sequential::gradientSum<Periodic>(neighbors, points, xi, box);
}
template <bool Periodic, bool Offsets, bool Wendland, bool Harmonic>
glm::vec3 ViscousSumT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                      const glm::vec3& xi, const glm::vec3& vi, const kernels::SmoothingKernel& w, float epsilon,
                      const PeriodicBox& box, float mui) {
    return sequential::viscousSum<Periodic, Harmonic>(neighbors, points, velocities, xi, vi, w, epsilon, box, mui);
}
template <bool Periodic, bool Offsets>
float DivergenceSumT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                     const glm::vec3& xi, const glm::vec3& vi, const PeriodicBox& box) {
    return sequential::divergenceSum<Periodic>(neighbors, points, velocities, xi, vi, box);
}
template <bool Periodic, bool Offsets>
glm::vec4 CappedGradientSquaresT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi, float mi,
                                 const PeriodicBox& box) {
    return sequential::cappedGradientSquares<Periodic>(neighbors, points, xi, mi, box);
}
template <bool Periodic, bool Offsets>
glm::vec3 XsphSumT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities, const glm::vec3& xi,
                   const glm::vec4& vi, const kernels::Poly6& w, const PeriodicBox& box) {
    return sequential::xsphSum<Periodic>(neighbors, points, velocities, xi, vi, w, box);
}
template <bool Periodic, bool Offsets, bool Wendland>
GradientSums KernelGradientSumsT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                                 const kernels::SmoothingKernel& w, const PeriodicBox& box) {
    return sequential::kernelGradientSums<Periodic>(neighbors, points, xi, w, box);
}

#else

template <bool Periodic, bool Offsets, bool Wendland>
float KernelSumT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                 const kernels::SmoothingKernel& w, const PeriodicBox& box, float initial) {
    const D d;
    const V xx = hn::Set(d, xi.x), xy = hn::Set(d, xi.y), xz = hn::Set(d, xi.z), invH = hn::Set(d, w.invH);
    V sum = hn::Zero(d);
    for (std::size_t k = 0; k < neighbors.count; k += hn::Lanes(d)) {
        const Columns j = LoadRows<Offsets>(points, neighbors, k);
        const PairVectors r = Delta<Periodic>(xx, xy, xz, j, box);
        const V q = hn::Mul(hn::Sqrt(hn::MulAdd(r.x, r.x, hn::MulAdd(r.y, r.y, hn::Mul(r.z, r.z)))), invH);
        sum = hn::MulAdd(hn::IfThenElseZero(hn::FirstN(d, neighbors.count - k), j.w), ValueOverSigma<Wendland>(q), sum);
    }
    return initial + w.sigma * hn::GetLane(hn::SumOfLanes(d, sum));
}

/// The lanes' PairKernels::encode(w, r), operation for operation (this file is built with
/// -ffp-contract=off, so the codes are the scalar ones bit for bit).
template <bool Wendland>
HWY_INLINE hn::Vec<DU16> EncodeFactors(V r, const kernels::SmoothingKernel& w, float invUnit) {
    const D d;
    const hn::RebindToSigned<D> di;
    const DU16 du16;
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    // W'(r) as SmoothingKernel::derivative: σ/h (24(½ − q)₊² − 6(1 − q)₊²), or σ/h (−20 q (1 − q)₊³)
    const V q = hn::Mul(r, hn::Set(d, w.invH));
    const V outer = hn::Max(hn::Sub(one, q), zero);
    V shape;
    if constexpr (Wendland) {
        shape = hn::Mul(hn::Mul(hn::Mul(hn::Mul(hn::Set(d, -20.0f), q), outer), outer), outer);
    } else {
        const V inner = hn::Max(hn::Sub(hn::Set(d, 0.5f), q), zero);
        shape = hn::Sub(hn::Mul(hn::Mul(hn::Set(d, 24.0f), inner), inner), hn::Mul(hn::Mul(hn::Set(d, 6.0f), outer), outer));
    }
    const V derivative = hn::Mul(hn::Set(d, w.sigma * w.invH), shape);
    const V f = hn::IfThenElseZero(hn::Gt(r, zero), hn::Div(derivative, r));
    const V scaled = hn::Mul(f, hn::Set(d, invUnit));
    const V x = hn::IfThenElse(hn::Lt(one, scaled), one, scaled);  // std::min: NaN stays NaN, and codes as 0
    const auto bits = hn::Add(hn::BitCast(di, x), hn::Set(di, 1 << (PairKernels::kDropped - 1)));
    const auto code = hn::Sub(hn::ShiftRight<PairKernels::kDropped>(bits),
                              hn::Set(di, static_cast<std::int32_t>(PairKernels::kLowestExponent << PairKernels::kMantissaBits)));
    return hn::DemoteTo(du16, hn::IfThenElseZero(hn::RebindMask(di, hn::Ge(x, hn::Set(d, PairKernels::kSmallest))), code));
}

template <bool Periodic, bool Offsets, bool Wendland>
float KernelSumAndCodesT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                         const kernels::SmoothingKernel& w, const PeriodicBox& box, float initial, const PairKernels& factors,
                         std::uint16_t* codes, glm::vec4* gradients) {
    const D d;
    const DU16 du16;
    const V xx = hn::Set(d, xi.x), xy = hn::Set(d, xi.y), xz = hn::Set(d, xi.z), invH = hn::Set(d, w.invH);
    V sum = hn::Zero(d);
    V gx = hn::Zero(d), gy = hn::Zero(d), gz = hn::Zero(d), squares = hn::Zero(d);
    for (std::size_t k = 0; k < neighbors.count; k += hn::Lanes(d)) {
        const Columns j = LoadRows<Offsets>(points, neighbors, k);
        const PairVectors d3 = Delta<Periodic>(xx, xy, xz, j, box);
        // Unfused, as the scalar density pass: the codes below are its codes.
        const V r = hn::Sqrt(hn::Add(hn::Add(hn::Mul(d3.x, d3.x), hn::Mul(d3.y, d3.y)), hn::Mul(d3.z, d3.z)));
        sum = hn::MulAdd(hn::IfThenElseZero(hn::FirstN(d, neighbors.count - k), j.w), ValueOverSigma<Wendland>(hn::Mul(r, invH)), sum);
        const auto code = EncodeFactors<Wendland>(r, w, factors.invUnit());
        if (gradients != nullptr) {  // α's sums over the codes just made
            const V s = hn::Mul(j.w, MagnitudesOf(code, neighbors.count - k));
            const V x = hn::Mul(s, d3.x), y = hn::Mul(s, d3.y), z = hn::Mul(s, d3.z);
            gx = hn::Add(gx, x);
            gy = hn::Add(gy, y);
            gz = hn::Add(gz, z);
            squares = hn::MulAdd(x, x, hn::MulAdd(y, y, hn::MulAdd(z, z, squares)));
        }
        if (neighbors.count - k >= hn::Lanes(d)) {
            hn::StoreU(code, du16, codes + k);
        } else {  // not past the list: the next one's codes may be another thread's
            HWY_ALIGN std::uint16_t tail[hn::MaxLanes(D())];
            hn::Store(code, du16, tail);
            for (std::size_t l = 0; k + l < neighbors.count; ++l) codes[k + l] = tail[l];
        }
    }
    if (gradients != nullptr)
        *gradients = {hn::GetLane(hn::SumOfLanes(d, gx)), hn::GetLane(hn::SumOfLanes(d, gy)),
                      hn::GetLane(hn::SumOfLanes(d, gz)), hn::GetLane(hn::SumOfLanes(d, squares))};
    return initial + w.sigma * hn::GetLane(hn::SumOfLanes(d, sum));
}

template <bool Periodic, bool Offsets>
glm::vec3 GradientSumT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi, const PeriodicBox& box) {
    const D d;
    const V xx = hn::Set(d, xi.x), xy = hn::Set(d, xi.y), xz = hn::Set(d, xi.z);
    V sx = hn::Zero(d), sy = hn::Zero(d), sz = hn::Zero(d);
    for (std::size_t k = 0; k < neighbors.count; k += hn::Lanes(d)) {
        const Columns j = LoadRows<Offsets>(points, neighbors, k);
        const V s = hn::Mul(j.w, LoadMagnitudes(neighbors, k));
        const PairVectors r = Delta<Periodic>(xx, xy, xz, j, box);
        sx = hn::MulAdd(s, r.x, sx);
        sy = hn::MulAdd(s, r.y, sy);
        sz = hn::MulAdd(s, r.z, sz);
    }
    return {hn::GetLane(hn::SumOfLanes(d, sx)), hn::GetLane(hn::SumOfLanes(d, sy)), hn::GetLane(hn::SumOfLanes(d, sz))};
}

template <bool Periodic, bool Offsets>
float DivergenceSumT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                     const glm::vec3& xi, const glm::vec3& vi, const PeriodicBox& box) {
    const D d;
    const V xx = hn::Set(d, xi.x), xy = hn::Set(d, xi.y), xz = hn::Set(d, xi.z);
    const V vx = hn::Set(d, vi.x), vy = hn::Set(d, vi.y), vz = hn::Set(d, vi.z);
    V sum = hn::Zero(d);
    for (std::size_t k = 0; k < neighbors.count; k += hn::Lanes(d)) {
        const Columns j = LoadRows<Offsets>(points, neighbors, k);
        const Columns v = LoadRows<Offsets>(velocities, neighbors, k);
        const PairVectors r = Delta<Periodic>(xx, xy, xz, j, box);
        const V dot = hn::MulAdd(hn::Sub(vx, v.x), r.x, hn::MulAdd(hn::Sub(vy, v.y), r.y, hn::Mul(hn::Sub(vz, v.z), r.z)));
        sum = hn::MulAdd(hn::Mul(j.w, LoadMagnitudes(neighbors, k)), dot, sum);
    }
    return hn::GetLane(hn::SumOfLanes(d, sum));
}

template <bool Periodic, bool Offsets>
glm::vec4 CappedGradientSquaresT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi, float mi,
                                 const PeriodicBox& box) {
    const D d;
    const V xx = hn::Set(d, xi.x), xy = hn::Set(d, xi.y), xz = hn::Set(d, xi.z);
    const V massI = hn::Set(d, mi), one = hn::Set(d, 1.0f);
    V sx = hn::Zero(d), sy = hn::Zero(d), sz = hn::Zero(d), squares = hn::Zero(d);
    for (std::size_t k = 0; k < neighbors.count; k += hn::Lanes(d)) {
        const Columns j = LoadRows<Offsets>(points, neighbors, k);
        const V m = LoadMagnitudes(neighbors, k);  // 0 past the list's end
        const PairVectors r = Delta<Periodic>(xx, xy, xz, j, box);
        const V gx = hn::Mul(m, r.x), gy = hn::Mul(m, r.y), gz = hn::Mul(m, r.z);
        sx = hn::Add(sx, gx);
        sy = hn::Add(sy, gy);
        sz = hn::Add(sz, gz);
        const V g2 = hn::MulAdd(gx, gx, hn::MulAdd(gy, gy, hn::Mul(gz, gz)));
        squares = hn::MulAdd(hn::Max(hn::Div(massI, j.w), one), g2, squares);
    }
    return {hn::GetLane(hn::SumOfLanes(d, sx)), hn::GetLane(hn::SumOfLanes(d, sy)), hn::GetLane(hn::SumOfLanes(d, sz)),
            hn::GetLane(hn::SumOfLanes(d, squares))};
}

template <bool Periodic, bool Offsets, bool Wendland, bool Harmonic>
glm::vec3 ViscousSumT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                      const glm::vec3& xi, const glm::vec3& vi, const kernels::SmoothingKernel& w, float epsilon,
                      const PeriodicBox& box, float mui) {
    const D d;
    const V xx = hn::Set(d, xi.x), xy = hn::Set(d, xi.y), xz = hn::Set(d, xi.z);
    const V vx = hn::Set(d, vi.x), vy = hn::Set(d, vi.y), vz = hn::Set(d, vi.z);
    const V invH = hn::Set(d, w.invH), zero = hn::Zero(d);
    const V eps = hn::Set(d, epsilon), muI = hn::Set(d, mui), fourMuI = hn::Set(d, 4.0f * mui);
    V sx = zero, sy = zero, sz = zero;
    for (std::size_t k = 0; k < neighbors.count; k += hn::Lanes(d)) {
        const Columns j = LoadRows<Offsets>(points, neighbors, k);
        const Columns v = LoadRows<Offsets>(velocities, neighbors, k);
        const PairVectors r = Delta<Periodic>(xx, xy, xz, j, box);
        const V r2 = hn::Add(hn::Add(hn::Mul(r.x, r.x), hn::Mul(r.y, r.y)), hn::Mul(r.z, r.z));
        const V q = hn::Mul(hn::Sqrt(r2), invH);
        // r W'(r)/σ = q (W'(r) h/σ), the σ outside the sum
        const V rDerivative = hn::Mul(q, DerivativeOverSigma<Wendland>(q));
        V weight;
        if constexpr (Harmonic) {  // 4 μ_i μ_j/(μ_i + μ_j) u_j, masked after the division (0/0 where both are 0)
            const V sum = hn::Add(muI, j.w);
            weight = hn::IfThenElseZero(hn::And(hn::FirstN(d, neighbors.count - k), hn::Gt(sum, zero)),
                                        hn::Mul(hn::Div(hn::Mul(fourMuI, j.w), sum), v.w));
        } else {
            weight = hn::IfThenElseZero(hn::FirstN(d, neighbors.count - k), hn::Mul(j.w, v.w));
        }
        const V s = hn::Div(hn::Mul(weight, rDerivative), hn::Add(r2, eps));
        sx = hn::MulAdd(s, hn::Sub(vx, v.x), sx);
        sy = hn::MulAdd(s, hn::Sub(vy, v.y), sy);
        sz = hn::MulAdd(s, hn::Sub(vz, v.z), sz);
    }
    const float scale = w.sigma;  // r W'(r) = σ/h · r · (W'h/σ) = σ q (W'h/σ) with q = r/h
    return scale * glm::vec3(hn::GetLane(hn::SumOfLanes(d, sx)), hn::GetLane(hn::SumOfLanes(d, sy)),
                             hn::GetLane(hn::SumOfLanes(d, sz)));
}

template <bool Periodic, bool Offsets>
glm::vec3 XsphSumT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities, const glm::vec3& xi,
                   const glm::vec4& vi, const kernels::Poly6& w, const PeriodicBox& box) {
    const D d;
    const V xx = hn::Set(d, xi.x), xy = hn::Set(d, xi.y), xz = hn::Set(d, xi.z);
    const V vx = hn::Set(d, vi.x), vy = hn::Set(d, vi.y), vz = hn::Set(d, vi.z), ui = hn::Set(d, vi.w);
    const V h2 = hn::Set(d, w.h2), two = hn::Set(d, 2.0f), zero = hn::Zero(d);
    V sx = zero, sy = zero, sz = zero;
    for (std::size_t k = 0; k < neighbors.count; k += hn::Lanes(d)) {
        const Columns j = LoadRows<Offsets>(points, neighbors, k);
        const Columns v = LoadRows<Offsets>(velocities, neighbors, k);
        const PairVectors r = Delta<Periodic>(xx, xy, xz, j, box);
        const V reach = hn::Max(hn::Sub(h2, hn::MulAdd(r.x, r.x, hn::MulAdd(r.y, r.y, hn::Mul(r.z, r.z)))), zero);
        // masked last: the lanes past the list's end may divide by anything
        const V s = hn::IfThenElseZero(hn::FirstN(d, neighbors.count - k),
                                       hn::Mul(hn::Div(hn::Mul(two, j.w), hn::Add(ui, v.w)), hn::Mul(reach, hn::Mul(reach, reach))));
        sx = hn::MulAdd(s, hn::Sub(v.x, vx), sx);
        sy = hn::MulAdd(s, hn::Sub(v.y, vy), sy);
        sz = hn::MulAdd(s, hn::Sub(v.z, vz), sz);
    }
    return {hn::GetLane(hn::SumOfLanes(d, sx)), hn::GetLane(hn::SumOfLanes(d, sy)), hn::GetLane(hn::SumOfLanes(d, sz))};
}

template <bool Periodic, bool Offsets, bool Wendland>
GradientSums KernelGradientSumsT(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                                 const kernels::SmoothingKernel& w, const PeriodicBox& box) {
    const D d;
    const V xx = hn::Set(d, xi.x), xy = hn::Set(d, xi.y), xz = hn::Set(d, xi.z), invH = hn::Set(d, w.invH);
    const V zero = hn::Zero(d);
    V px = zero, py = zero, pz = zero, wx = zero, wy = zero, wz = zero;
    for (std::size_t k = 0; k < neighbors.count; k += hn::Lanes(d)) {
        const Columns j = LoadRows<Offsets>(points, neighbors, k);
        const PairVectors r = Delta<Periodic>(xx, xy, xz, j, box);
        const V length = hn::Sqrt(hn::MulAdd(r.x, r.x, hn::MulAdd(r.y, r.y, hn::Mul(r.z, r.z))));
        // W'(r)/r h/σ, the σ/h outside the sums; 0 at r = 0 and past the list
        const V derivative = DerivativeOverSigma<Wendland>(hn::Mul(length, invH));
        const auto counted = hn::And(hn::FirstN(d, neighbors.count - k), hn::Gt(length, zero));
        const V f = hn::IfThenElseZero(counted, hn::Div(derivative, length));
        px = hn::MulAdd(f, r.x, px);
        py = hn::MulAdd(f, r.y, py);
        pz = hn::MulAdd(f, r.z, pz);
        const V fw = hn::Mul(f, j.w);
        wx = hn::MulAdd(fw, r.x, wx);
        wy = hn::MulAdd(fw, r.y, wy);
        wz = hn::MulAdd(fw, r.z, wz);
    }
    const float scale = w.sigma * w.invH;
    auto total = [&](V v) HWY_ATTR { return scale * hn::GetLane(hn::SumOfLanes(d, v)); };
    return {{total(px), total(py), total(pz)}, {total(wx), total(wy), total(wz)}};
}

#endif  // HWY_TARGET == HWY_SCALAR

/// Calls f(periodic, offsets) with the box's and the list's form as compile-time constants.
template <class F>
HWY_INLINE auto Choose(const PeriodicBox& box, const Neighbors& neighbors, F&& f) {
    using Yes = std::true_type;
    using No = std::false_type;
    if (neighbors.offset != nullptr) return box.any ? f(Yes{}, Yes{}) : f(No{}, Yes{});
    return box.any ? f(Yes{}, No{}) : f(No{}, No{});
}
/// Calls f(periodic, offsets, wendland): the kernel's shape a compile-time constant too.
template <class F>
HWY_INLINE auto Choose(const PeriodicBox& box, const Neighbors& neighbors, const kernels::SmoothingKernel& w, F&& f) {
    return Choose(box, neighbors, [&](auto periodic, auto offsets) HWY_ATTR {
        if (w.shape == KernelShape::WendlandC2) return f(periodic, offsets, std::true_type{});
        return f(periodic, offsets, std::false_type{});
    });
}

float KernelSumImpl(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                    const kernels::SmoothingKernel& w, const PeriodicBox& box, float initial) {
    return Choose(box, neighbors, w, [&](auto periodic, auto offsets, auto wendland) HWY_ATTR {
        return KernelSumT<periodic(), offsets(), wendland()>(neighbors, points, xi, w, box, initial);
    });
}
float KernelSumAndCodesImpl(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                            const kernels::SmoothingKernel& w, const PeriodicBox& box, float initial,
                            const PairKernels& factors, std::uint16_t* codes, glm::vec4* gradients) {
    return Choose(box, neighbors, w, [&](auto periodic, auto offsets, auto wendland) HWY_ATTR {
        return KernelSumAndCodesT<periodic(), offsets(), wendland()>(neighbors, points, xi, w, box, initial, factors, codes, gradients);
    });
}
glm::vec3 GradientSumImpl(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                          const PeriodicBox& box) {
    return Choose(box, neighbors, [&](auto periodic, auto offsets) HWY_ATTR {
        return GradientSumT<periodic(), offsets()>(neighbors, points, xi, box);
    });
}
float DivergenceSumImpl(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                        const glm::vec3& xi, const glm::vec3& vi, const PeriodicBox& box) {
    return Choose(box, neighbors, [&](auto periodic, auto offsets) HWY_ATTR {
        return DivergenceSumT<periodic(), offsets()>(neighbors, points, velocities, xi, vi, box);
    });
}
glm::vec4 CappedGradientSquaresImpl(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi, float mi,
                                    const PeriodicBox& box) {
    return Choose(box, neighbors, [&](auto periodic, auto offsets) HWY_ATTR {
        return CappedGradientSquaresT<periodic(), offsets()>(neighbors, points, xi, mi, box);
    });
}
glm::vec3 ViscousSumImpl(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                         const glm::vec3& xi, const glm::vec3& vi, const kernels::SmoothingKernel& w, float epsilon,
                         const PeriodicBox& box) {
    return Choose(box, neighbors, w, [&](auto periodic, auto offsets, auto wendland) HWY_ATTR {
        return ViscousSumT<periodic(), offsets(), wendland(), false>(neighbors, points, velocities, xi, vi, w, epsilon, box, 0.0f);
    });
}
glm::vec3 ViscousSumHarmonicImpl(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                                 const glm::vec3& xi, const glm::vec3& vi, float mui, const kernels::SmoothingKernel& w,
                                 float epsilon, const PeriodicBox& box) {
    return Choose(box, neighbors, w, [&](auto periodic, auto offsets, auto wendland) HWY_ATTR {
        return ViscousSumT<periodic(), offsets(), wendland(), true>(neighbors, points, velocities, xi, vi, w, epsilon, box, mui);
    });
}
glm::vec3 XsphSumImpl(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                      const glm::vec3& xi, const glm::vec4& vi, const kernels::Poly6& w, const PeriodicBox& box) {
    return Choose(box, neighbors, [&](auto periodic, auto offsets) HWY_ATTR {
        return XsphSumT<periodic(), offsets()>(neighbors, points, velocities, xi, vi, w, box);
    });
}
GradientSums KernelGradientSumsImpl(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                                    const kernels::SmoothingKernel& w, const PeriodicBox& box) {
    return Choose(box, neighbors, w, [&](auto periodic, auto offsets, auto wendland) HWY_ATTR {
        return KernelGradientSumsT<periodic(), offsets(), wendland()>(neighbors, points, xi, w, box);
    });
}
const char* InstructionSetImpl() { return hwy::TargetName(HWY_TARGET); }

}  // namespace HWY_NAMESPACE
}  // namespace tide::pair_sums
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace tide::pair_sums {

HWY_EXPORT(KernelSumImpl);
HWY_EXPORT(KernelSumAndCodesImpl);
HWY_EXPORT(GradientSumImpl);
HWY_EXPORT(DivergenceSumImpl);
HWY_EXPORT(CappedGradientSquaresImpl);
HWY_EXPORT(ViscousSumImpl);
HWY_EXPORT(ViscousSumHarmonicImpl);
HWY_EXPORT(XsphSumImpl);
HWY_EXPORT(KernelGradientSumsImpl);
HWY_EXPORT(InstructionSetImpl);

namespace {
/// The chosen target's sums, looked up once: HWY_DYNAMIC_DISPATCH asks libhwy for the target
/// at every call (through the PLT), and the sums are called once per particle and pass: that
/// call and the wrappers took ~2 % of the 50k dam break's run (perf, one thread); results are
/// bit for bit the same.
struct Targets {
    decltype(&HWY_STATIC_DISPATCH(KernelSumImpl)) kernelSum;
    decltype(&HWY_STATIC_DISPATCH(KernelSumAndCodesImpl)) kernelSumAndCodes;
    decltype(&HWY_STATIC_DISPATCH(GradientSumImpl)) gradientSum;
    decltype(&HWY_STATIC_DISPATCH(DivergenceSumImpl)) divergenceSum;
    decltype(&HWY_STATIC_DISPATCH(CappedGradientSquaresImpl)) cappedGradientSquares;
    decltype(&HWY_STATIC_DISPATCH(ViscousSumImpl)) viscousSum;
    decltype(&HWY_STATIC_DISPATCH(ViscousSumHarmonicImpl)) viscousSumHarmonic;
    decltype(&HWY_STATIC_DISPATCH(XsphSumImpl)) xsphSum;
    decltype(&HWY_STATIC_DISPATCH(KernelGradientSumsImpl)) kernelGradientSums;
};
Targets chooseTargets() {
    (void)HWY_DYNAMIC_DISPATCH(InstructionSetImpl)();  // a first dispatch chooses the target
    return Targets{&HWY_DYNAMIC_DISPATCH(KernelSumImpl),   &HWY_DYNAMIC_DISPATCH(KernelSumAndCodesImpl),
                   &HWY_DYNAMIC_DISPATCH(GradientSumImpl), &HWY_DYNAMIC_DISPATCH(DivergenceSumImpl),
                   &HWY_DYNAMIC_DISPATCH(CappedGradientSquaresImpl),
                   &HWY_DYNAMIC_DISPATCH(ViscousSumImpl),  &HWY_DYNAMIC_DISPATCH(ViscousSumHarmonicImpl),
                   &HWY_DYNAMIC_DISPATCH(XsphSumImpl),     &HWY_DYNAMIC_DISPATCH(KernelGradientSumsImpl)};
}
// Chosen when the program loads (no sums run before main), so a call reads a plain global.
const Targets kTargets = chooseTargets();
const Targets& targets() { return kTargets; }
}  // namespace

float kernelSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                const kernels::SmoothingKernel& w, const PeriodicBox& box, float initial, Order order) {
    if (order == Order::Sequential)
        return box.any ? sequential::kernelSum<true>(neighbors, points, xi, w, box, initial)
                       : sequential::kernelSum<false>(neighbors, points, xi, w, box, initial);
    return targets().kernelSum(neighbors, points, xi, w, box, initial);
}
float kernelSumAndCodes(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                        const kernels::SmoothingKernel& w, const PeriodicBox& box, float initial, const PairKernels& factors,
                        std::uint16_t* codes, Order order, glm::vec4* gradients) {
    if (order == Order::Sequential)
        return box.any ? sequential::kernelSumAndCodes<true>(neighbors, points, xi, w, box, initial, factors, codes, gradients)
                       : sequential::kernelSumAndCodes<false>(neighbors, points, xi, w, box, initial, factors, codes, gradients);
    return targets().kernelSumAndCodes(neighbors, points, xi, w, box, initial, factors, codes, gradients);
}
glm::vec3 gradientSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                      const PeriodicBox& box, Order order) {
    if (order == Order::Sequential)
        return box.any ? sequential::gradientSum<true>(neighbors, points, xi, box)
                       : sequential::gradientSum<false>(neighbors, points, xi, box);
    return targets().gradientSum(neighbors, points, xi, box);
}
float divergenceSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                    const glm::vec3& xi, const glm::vec3& vi, const PeriodicBox& box, Order order) {
    if (order == Order::Sequential)
        return box.any ? sequential::divergenceSum<true>(neighbors, points, velocities, xi, vi, box)
                       : sequential::divergenceSum<false>(neighbors, points, velocities, xi, vi, box);
    return targets().divergenceSum(neighbors, points, velocities, xi, vi, box);
}
glm::vec4 cappedGradientSquares(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi, float mi,
                                const PeriodicBox& box) {
    return targets().cappedGradientSquares(neighbors, points, xi, mi, box);
}
glm::vec3 viscousSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                     const glm::vec3& xi, const glm::vec3& vi, const kernels::SmoothingKernel& w, float epsilon,
                     const PeriodicBox& box) {
    return targets().viscousSum(neighbors, points, velocities, xi, vi, w, epsilon, box);
}
glm::vec3 viscousSumHarmonic(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                             const glm::vec3& xi, const glm::vec3& vi, float mui, const kernels::SmoothingKernel& w,
                             float epsilon, const PeriodicBox& box) {
    return targets().viscousSumHarmonic(neighbors, points, velocities, xi, vi, mui, w, epsilon, box);
}
glm::vec3 xsphSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities, const glm::vec3& xi,
                  const glm::vec4& vi, const kernels::Poly6& w, const PeriodicBox& box) {
    return targets().xsphSum(neighbors, points, velocities, xi, vi, w, box);
}
GradientSums kernelGradientSums(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                                const kernels::SmoothingKernel& w, const PeriodicBox& box) {
    return targets().kernelGradientSums(neighbors, points, xi, w, box);
}
const char* instructionSet() { return HWY_DYNAMIC_DISPATCH(InstructionSetImpl)(); }

}  // namespace tide::pair_sums
#endif  // HWY_ONCE
