#pragma once
/// \file
/// XSPH velocity smoothing (Monaghan 1989, "On the problem of penetration in particle
/// methods", eq. 2.4): v_i ← v_i + ε Σ_j m_j/ρ̄_ij (v_j − v_i) W_poly6(r_ij), ρ̄_ij = (ρ_i + ρ_j)/2.
/// Pairwise antisymmetric, so momentum is conserved; it damps the particle-scale noise
/// that explicit weakly compressible SPH (and Müller's Poly6/Spiky kernel mix, which is not
/// energy-conserving) feeds, without slowing bulk flow.

#include <vector>

#include <glm/geometric.hpp>

#include <tide/particles.hpp>

#include "core/kernels.hpp"
#include "core/periodic_box.hpp"
#include "core/parallel.hpp"
#include "neighbors/neighbor_list.hpp"

namespace tide {

class XsphFilter {
public:
    void apply(ParticleStore& p, const NeighborList& neighbors, const PeriodicBox& box, float supportRadius, float epsilon,
               int threads) {
        if (epsilon <= 0.0f) return;
        const kernels::Poly6 poly6(supportRadius);
        filtered_.resize(p.size());
        parallelFor(p.size(), threads, [&](std::uint32_t i) {
            const glm::vec3 xi = p.position[i];
            const glm::vec3 vi = p.velocity[i];
            glm::vec3 sum(0.0f);
            for (const std::uint32_t j : neighbors.of(i)) {
                const glm::vec3 d = box.delta(xi, p.position[j]);
                const float weight = p.mass[j] / (0.5f * (p.density[i] + p.density[j])) * poly6.valueSq(glm::dot(d, d));
                sum += weight * (p.velocity[j] - vi);
            }
            filtered_[i] = vi + epsilon * sum;
        });
        p.velocity.swap(filtered_);
    }

private:
    std::vector<glm::vec3> filtered_;
};

}  // namespace tide
