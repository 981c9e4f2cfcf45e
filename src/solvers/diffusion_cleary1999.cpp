#include "solvers/diffusion_cleary1999.hpp"

#include <glm/geometric.hpp>

#include "core/kernels.hpp"
#include "core/parallel.hpp"

namespace tide {

void DyeDiffusion::apply(ParticleStore& p, const NeighborList& neighbors, const PeriodicBox& box,
                         const MaterialPairs& pairs, const kernels::SmoothingKernel& w, float dt, int threads) {
    const float eta2 = 0.01f * 0.25f * w.h * w.h;
    rate_.resize(p.size());
    parallelFor(p.size(), threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i];
        const float ci = p.concentration[i];
        const float rhoi = p.density[i];
        const MaterialIndex mi = p.material[i];
        // Summed in double: the pair terms cancel between i and j only to their round-off.
        double rate = 0.0;
        for (const std::uint32_t j : neighbors.of(i)) {
            const float d = pairs.diffusivity(mi, p.material[j]);
            if (d <= 0.0f) continue;
            const float r = glm::length(box.delta(xi, p.position[j]));
            const float rj = p.density[j];
            const float k = p.mass[j] * (rhoi + rj) * d / (rhoi * rj);  // K_ij m_j
            rate += static_cast<double>(k * (ci - p.concentration[j]) * (r * w.derivative(r) / (r * r + eta2)));
        }
        rate_[i] = static_cast<float>(rate);
    });
    parallelFor(p.size(), threads, [&](std::uint32_t i) { p.concentration[i] += dt * rate_[i]; });
}

}  // namespace tide
