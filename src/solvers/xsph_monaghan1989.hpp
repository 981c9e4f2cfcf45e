#pragma once
/// \file
/// XSPH velocity smoothing (Monaghan 1989, "On the problem of penetration in particle
/// methods", eq. 2.4): v_i ← v_i + ε Σ_j m_j/ρ̄_ij (v_j − v_i) W_poly6(r_ij), ρ̄_ij = (ρ_i + ρ_j)/2.
/// Pairwise antisymmetric, so momentum is conserved; it damps the particle-scale noise
/// that explicit weakly compressible SPH (and Müller's Poly6/Spiky kernel mix, which is not
/// energy-conserving) feeds, without slowing bulk flow.

#include <span>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <tide/particles.hpp>

#include "core/kernels.hpp"
#include "core/periodic_box.hpp"
#include "core/parallel.hpp"
#include "neighbors/neighbor_list.hpp"
#include "solvers/pair_sums.hpp"

namespace tide {

class XsphFilter {
public:
    /// Smooths p.velocity. `scratch`, if it has room for every particle, holds the smoothed
    /// velocities meanwhile instead of the filter's own array (a solver lends one it has free
    /// at this point of its step: 12 bytes a particle fewer).
    /// With `positionMass`, the rows (x_j, m_j) of every particle, the sums run in SIMD lanes
    /// (pair_sums::xsphSum) over rows (v_j, ρ_j) packed into `scratch`, and the smoothed
    /// velocities go straight to p.velocity.
    /// `poly6` is the smoothing kernel, normalised for the world's dimension.
    void apply(ParticleStore& p, const NeighborList& neighbors, const PeriodicBox& box, const kernels::Poly6& poly6,
               float epsilon, int threads, std::span<glm::vec4> scratch = {}, const glm::vec4* positionMass = nullptr) {
        if (epsilon <= 0.0f) return;
        if (positionMass != nullptr && scratch.size() >= p.size()) {
            parallelFor(p.size(), threads, [&](std::uint32_t i) { scratch[i] = glm::vec4(p.velocity[i], p.density[i]); });
            const float scale = epsilon * poly6.norm;
            parallelFor(p.size(), threads, [&](std::uint32_t i) {
                const auto list = neighbors.of(i);
                const glm::vec3 sum = pair_sums::xsphSum(pair_sums::Neighbors(list), positionMass, scratch.data(),
                                                         p.position[i], scratch[i], poly6, box);
                p.velocity[i] = glm::vec3(scratch[i]) + scale * sum;
            });
            return;
        }
        if (scratch.size() >= p.size()) {
            smooth(p, neighbors, box, poly6, epsilon, threads, [&](std::uint32_t i, const glm::vec3& v) {
                scratch[i] = glm::vec4(v, 0.0f);
            });
            parallelFor(p.size(), threads, [&](std::uint32_t i) { p.velocity[i] = glm::vec3(scratch[i]); });
            return;
        }
        filtered_.resize(p.size());
        smooth(p, neighbors, box, poly6, epsilon, threads, [&](std::uint32_t i, const glm::vec3& v) { filtered_[i] = v; });
        // Copied back, not swapped: the velocity array stays where it is between steps (views
        // of it, the Python module's numpy arrays, keep pointing at the current velocities).
        parallelFor(p.size(), threads, [&](std::uint32_t i) { p.velocity[i] = filtered_[i]; });
    }

private:
    template <class Store>
    static void smooth(const ParticleStore& p, const NeighborList& neighbors, const PeriodicBox& box,
                       const kernels::Poly6& poly6, float epsilon, int threads, Store&& store) {
        parallelFor(p.size(), threads, [&](std::uint32_t i) {
            const glm::vec3 xi = p.position[i];
            const glm::vec3 vi = p.velocity[i];
            glm::vec3 sum(0.0f);
            for (const std::uint32_t j : neighbors.of(i)) {
                const glm::vec3 d = box.delta(xi, p.position[j]);
                const float weight = p.mass[j] / (0.5f * (p.density[i] + p.density[j])) * poly6.valueSq(glm::dot(d, d));
                sum += weight * (p.velocity[j] - vi);
            }
            store(i, vi + epsilon * sum);
        });
    }

    std::vector<glm::vec3> filtered_;
};

}  // namespace tide
