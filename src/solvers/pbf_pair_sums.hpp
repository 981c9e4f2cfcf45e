#pragma once
/// \file
/// The pair loops of position based fluids' constraint iterations (Macklin & Müller 2013,
/// solvers/pbf_macklin2013.cpp), eight neighbours at a time in SIMD lanes with the row loads
/// of the pressure solves' pair sums (pair_sums.hpp, Highway, chosen at run time). Lanes add in
/// a fixed order for a given CPU: the same results for any thread count.
///
/// The positions move between iterations, so each λ pass evaluates the kernels anew (a square
/// root, the cubic spline and the spiky gradient per pair); it leaves each pair's gradient
/// factor and artificial pressure for the correction pass of the same iteration, which then
/// streams them with the neighbours' rows.

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/kernels.hpp"
#include "core/periodic_box.hpp"
#include "neighbors/neighbor_list.hpp"
#include "solvers/pair_sums.hpp"

namespace tide::pbf_sums {

/// The kernels and constants of one λ pass (eq. 1, 11 and 13 of Macklin & Müller 2013).
struct LambdaKernel {
    kernels::SmoothingKernel density;  ///< W of the density (the solver's kernel)
    float h = 0.0f, h2 = 0.0f;         ///< support, and its square
    float spikyGradient = 0.0f;        ///< the spiky kernel's gradient factor: ∇W = g (h − r)² r̂
    float invWdq = 0.0f;               ///< 1/W(Δq)
    float restTensile = 0.0f;          ///< (W(s)/W(Δq))⁴ at the rest spacing s
    float tensileScale = 0.0f;         ///< −k h² of eq. 13
};

/// One particle's sums of the λ pass.
struct LambdaSums {
    float kernelSum = 0.0f;         ///< Σ_j W_ij over neighbours closer than h
    glm::vec3 gradient{0.0f};       ///< Σ_j ∇W_ij (spiky)
    float weightedSquares = 0.0f;   ///< Σ_j w_j V_j² |∇W_ij|²
};

/// The λ pass's pair sums of particle i at xi with volume vi over `neighbors`, with
/// (x_j, V_j) = rows[j] and w_j V_j² = weightedVolume2[j]; writes each pair's F_ij = W'(r)/r of
/// the spiky kernel (0 at r = 0 and beyond h) to factor[k] and its s_corr (V_i + V_j)/2 (eq. 13,
/// n = 4, less its value at the rest spacing, 0 where negative) to tensile[k], for k < count
/// (lists of offsets: to their padded length, which is theirs).
LambdaSums lambdaSums(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const float* weightedVolume2,
                      const glm::vec3& xi, float vi, const LambdaKernel& kernel, const PeriodicBox& box, float* factor,
                      float* tensile);

/// (Σ_b ∇W_ib, Σ_b W_ib) over boundary particles closer than h, the spiky gradient and the density
/// kernel as lambdaSums, with x_b = rows[b] (a CrossNeighborList's indices, read past the end).
glm::vec4 wallSums(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const glm::vec3& xi,
                   const LambdaKernel& kernel, const PeriodicBox& box);

/// Σ_j (li + l_j + s_ij) F_ij (x_i − x_j) of eq. 14 with (x_j, l_j) = rows[j] (l = λV) and the
/// factors and s_corr of lambdaSums, read kPadding past the list (ignored).
glm::vec3 correctionSum(const pair_sums::Neighbors& neighbors, const glm::vec4* rows, const glm::vec3& xi, float li,
                        const float* factor, const float* tensile, const PeriodicBox& box);

// The passes call the loops a block of consecutive particles at a time: one dispatch and one
// set of broadcast constants a block instead of a particle (a particle's sums are ~4 blocks of
// lanes, and the call around them cost about as much as one). The sums are the same, bit for bit.

/// lambdaSums of particles first … last − 1 of `list` to out[i − first], with (x_i, V_i) = rows[i]
/// and the pair arrays factor and tensile indexed by list.offset(i) + k.
void lambdaSumsOfRange(const NeighborList& list, std::uint32_t first, std::uint32_t last, const glm::vec4* rows,
                       const float* weightedVolume2, const LambdaKernel& kernel, const PeriodicBox& box, float* factor,
                       float* tensile, LambdaSums* out);

/// wallSums of particles first … last − 1 over their lists in `walls` to out[i − first], with x_i
/// from rows[i]; zero, without a call, where a particle has no boundary neighbour (most do not).
void wallSumsOfRange(const CrossNeighborList& walls, std::uint32_t first, std::uint32_t last, const glm::vec4* wallRows,
                     const glm::vec4* rows, const LambdaKernel& kernel, const PeriodicBox& box, glm::vec4* out);

/// correctionSum of particles first … last − 1 of `list` to out[i − first], with (x_i, l_i) = rows[i].
void correctionSumsOfRange(const NeighborList& list, std::uint32_t first, std::uint32_t last, const glm::vec4* rows,
                           const float* factor, const float* tensile, const PeriodicBox& box, glm::vec3* out);

}  // namespace tide::pbf_sums
