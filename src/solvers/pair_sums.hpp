#pragma once
/// \file
/// The pair sums of the pressure solves' inner loops, over one particle's neighbour list,
/// eight neighbours at a time in SIMD lanes (Google Highway, chosen at run time: AVX-512,
/// AVX2, SSE4 or plain code, so one portable binary uses what the CPU has).
///
/// Each sum reads neighbour j's position and a per-neighbour weight packed as a vec4
/// (x_j, w_j), loaded by index. The lanes add in a fixed order for a given CPU, so
/// results stay the same for any thread count; AVX2 and AVX-512 machines run the same
/// eight lanes and agree bit for bit, while SSE4 and plain code round differently.

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/kernels.hpp"
#include "core/periodic_box.hpp"
#include "neighbors/neighbor_list.hpp"

namespace tide {
class PairKernels;
}

namespace tide::pair_sums {

/// How far past a list's end its indices and codes are read (and ignored): NeighborList and
/// PairKernels leave that much room after their last list.
inline constexpr std::size_t kPadding = 8;

/// One particle's neighbours: indices into the loaded arrays, readable kPadding past the end,
/// or offsets from `base` (NeighborSpan), padded with 0 to a multiple of
/// NeighborList::kOffsetBlock; and, where a sum needs them, the pairs' coded gradient factors
/// (PairKernels::Code, aligned with the indices), readable as far.
struct Neighbors {
    const std::uint32_t* index = nullptr;
    const std::uint16_t* code = nullptr;
    std::size_t count = 0;
    const std::int16_t* offset = nullptr;  ///< instead of index: neighbour k is base + offset[k]
    std::uint32_t base = 0;

    Neighbors() = default;
    explicit Neighbors(const NeighborSpan& list, const std::uint16_t* codes = nullptr)
        : index(list.indices()), code(codes), count(list.size()), offset(list.offsets()), base(list.base()) {}
    [[nodiscard]] std::uint32_t at(std::size_t k) const {
        return NeighborSpan::at(index, offset, base, k);
    }
};

/// How a sum adds its terms.
enum class Order {
    Lanes,       ///< in the SIMD lanes, then across them
    Sequential,  ///< one pair at a time in list order: the rounding of the scalar loops
};

/// initial + Σ_j w_j W(|x_i − x_j|) of the cubic spline `w`, with (x_j, w_j) = points[j].
float kernelSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                const kernels::SmoothingKernel& w, const PeriodicBox& box, float initial = 0.0f, Order order = Order::Lanes);

/// kernelSum, and each pair's coded gradient factor, factors.encode(w, r_ij), written to
/// codes[k] for k < count (and nothing past it: the next list's codes may be another thread's);
/// with `gradients`, also (Σ_j g_ij, Σ_j |g_ij|²) over those codes, g_ij = w_j m_ij (x_i − x_j)
/// with m_ij = PairKernels::magnitude(code_ij): the two sums of DFSPH's factor α_i (Bender &
/// Koschier 2017, eq. 11) in units of PairKernels::unit(), from the same pass.
float kernelSumAndCodes(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                        const kernels::SmoothingKernel& w, const PeriodicBox& box, float initial, const PairKernels& factors,
                        std::uint16_t* codes, Order order = Order::Lanes, glm::vec4* gradients = nullptr);

/// Σ_j w_j m_ij (x_i − x_j), with m_ij = PairKernels::magnitude(code_ij).
glm::vec3 gradientSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                      const PeriodicBox& box, Order order = Order::Lanes);

/// Σ_j w_j m_ij (v_i − v_j)·(x_i − x_j), with m_ij as above and (v_j, ·) = velocities[j].
float divergenceSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                    const glm::vec3& xi, const glm::vec3& vi, const PeriodicBox& box, Order order = Order::Lanes);

/// (Σ_j g_ij, Σ_j max(m_i/w_j, 1) |g_ij|²), g_ij = m_ij (x_i − x_j) with m_ij as above and
/// (x_j, w_j) = points[j]: with w_j = m_j, DFSPH's α sums over neighbours of other masses
/// (several rest densities, DfsphBender2017::computeAlpha), the factor m_i/m_j capped below
/// at 1, in units of PairKernels::unit() and without the m_i and m_i² there.
glm::vec4 cappedGradientSquares(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi, float mi,
                                const PeriodicBox& box);

/// Σ_j w_j u_j r W'(r)/(r² + ε) (v_i − v_j) of the cubic spline `w`, r = |x_i − x_j|, with
/// (x_j, w_j) = points[j] and (v_j, u_j) = velocities[j]: the fluid part of Morris et al.'s
/// 1997 viscosity (solvers/viscosity.cpp).
glm::vec3 viscousSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                     const glm::vec3& xi, const glm::vec3& vi, const kernels::SmoothingKernel& w, float epsilon,
                     const PeriodicBox& box);

/// viscousSum between materials of different viscosities: Σ_j μ̄_ij u_j r W'(r)/(r² + ε) (v_i − v_j),
/// with (x_j, μ_j) = points[j], (v_j, u_j) = velocities[j] and μ̄_ij = 4 μ_i μ_j/(μ_i + μ_j) (0 where
/// both are 0): twice the pair's harmonic mean, 2μ for equal viscosities (solvers/viscosity.cpp).
glm::vec3 viscousSumHarmonic(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities,
                             const glm::vec3& xi, const glm::vec3& vi, float mui, const kernels::SmoothingKernel& w,
                             float epsilon, const PeriodicBox& box);

/// Σ_j (2 w_j/(u_i + u_j)) (h² − r²)₊³ (v_j − v_i), r = |x_i − x_j|, with (x_j, w_j) = points[j]
/// and (v_j, u_j) = velocities[j]: XSPH's sum (Monaghan 1989) with w = m and u = ρ, over the
/// poly6 kernel `w` less its normalisation (xsph_monaghan1989.hpp).
glm::vec3 xsphSum(const Neighbors& neighbors, const glm::vec4* points, const glm::vec4* velocities, const glm::vec3& xi,
                  const glm::vec4& vi, const kernels::Poly6& w, const PeriodicBox& box);

/// Two kernel-gradient sums of one pass: Σ_j ∇W_ij and Σ_j w_j ∇W_ij of the cubic spline `w`,
/// with (x_j, w_j) = points[j] and ∇W_ij = W'(r)/r (x_i − x_j): the pressure force of
/// weakly compressible SPH, (p_i/ρ_i²) m Σ_j ∇W_ij + Σ_j (m p_j/ρ_j²) ∇W_ij for one mass m.
struct GradientSums {
    glm::vec3 plain{0.0f}, weighted{0.0f};
};
GradientSums kernelGradientSums(const Neighbors& neighbors, const glm::vec4* points, const glm::vec3& xi,
                                const kernels::SmoothingKernel& w, const PeriodicBox& box);

/// The instruction set the sums run on here (e.g. "AVX2"), for reports.
const char* instructionSet();

}  // namespace tide::pair_sums
