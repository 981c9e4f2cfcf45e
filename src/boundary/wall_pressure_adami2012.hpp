#pragma once
/// \file
/// Pressure of boundary particles extrapolated from the fluid around them (Adami, Hu &
/// Adams 2012, "A generalized wall boundary condition for smoothed particle hydrodynamics",
/// J. Comput. Phys. 231, eq. 27):
///   p_b = (Σ_f p_f W_bf + ρ_f (g − a_b)·Σ_f (x_b − x_f) W_bf) / Σ_f W_bf,
/// a_b the wall's acceleration (zero at rest; a wave paddle's otherwise),
/// kept here as κ_b = p_b/ρ (the solvers' unit). Mirroring p_b = p_i (Akinci et al. 2012)
/// gives a particle beside a vertical wall only the fluid half of the pressure gradient that
/// carries its weight, so particles slide down walls and stir the whole tank; with the
/// hydrostatic term the wall carries its share and a tank at rest stays at rest.
/// Walls never pull: κ_b ≥ 0.
/// Several rest densities (solvers/density_contrast_solenthaler2008.hpp): the sums run over
/// κ̃_f = κ_f ρ0_f/ρ0_ref, the gravity term weighs each fluid particle by ρ0_f/ρ0_ref, so κ_b
/// is p_b/ρ0_ref, the pressure of the layered fluid at the wall.

#include <span>
#include <vector>

#include <glm/geometric.hpp>

#include "boundary/boundary_particles.hpp"
#include "core/kernels.hpp"
#include "core/periodic_box.hpp"
#include "core/scratch_resize.hpp"
#include "core/parallel.hpp"
#include "neighbors/neighbor_list.hpp"

namespace tide {

class WallPressure {
public:
    /// Kernel sums of each boundary particle over the fluid near it, at the current positions
    /// (the kernel values are kept: the solves call update() every iteration).
    void prepare(const BoundaryParticles& boundary, const NeighborList& fluidNear, std::span<const glm::vec3> fluid,
                 const PeriodicBox& box, const glm::vec3& gravity, float supportRadius, int threads,
                 std::span<const float> fluidScale = {}) {
        const kernels::CubicSpline w(supportRadius);
        const auto n = static_cast<std::uint32_t>(boundary.position.size());
        weightSum_.assign(n, 0.0f);
        gravityTerm_.assign(n, 0.0f);
        kappa_.assign(n, 0.0f);
        resizeScratch(weights_, fluidNear.pairCount());
        parallelFor(n, threads, [&](std::uint32_t b) {
            const glm::vec3 xb = boundary.position[b];
            const glm::vec3 g = boundary.moving ? gravity - boundary.acceleration[b] : gravity;
            float* weight = weights_.data() + fluidNear.offset(b);
            float weights = 0.0f, lift = 0.0f;
            for (const std::uint32_t f : fluidNear.of(b)) {
                const glm::vec3 xbf = box.delta(xb, fluid[f]);
                const float wbf = w.value(glm::length(xbf));
                *weight++ = wbf;
                weights += wbf;
                lift += fluidScale.empty() ? glm::dot(g, xbf) * wbf : fluidScale[f] * glm::dot(g, xbf) * wbf;
            }
            weightSum_[b] = weights;
            gravityTerm_[b] = lift;
        });
    }

    /// κ_b from the fluid's κ_f over the lists and positions prepare() saw; read with kappa().
    void update(const NeighborList& fluidNear, std::span<const float> fluidKappa, int threads) {
        update(fluidNear, fluidKappa, threads, [](std::uint32_t, float) {});
    }
    /// As above, and change[b] = (new κ_b − last κ_b)·scale for every b: what a solve that
    /// pushes with the change of κ needs, without keeping the last κ_b in an array of its own.
    void update(const NeighborList& fluidNear, std::span<const float> fluidKappa, int threads, float scale,
                std::span<float> change) {
        update(fluidNear, fluidKappa, threads, [&](std::uint32_t b, float updated) { change[b] = (updated - kappa_[b]) * scale; });
    }

    [[nodiscard]] std::span<const float> kappa() const { return kappa_; }
    [[nodiscard]] std::span<float> kappa() { return kappa_; }

private:
    template <class OnUpdate>
    void update(const NeighborList& fluidNear, std::span<const float> fluidKappa, int threads, OnUpdate&& onUpdate) {
        parallelFor(static_cast<std::uint32_t>(kappa_.size()), threads, [&](std::uint32_t b) {
            float updated = kappa_[b];  // 0 (prepare) where no fluid is near
            if (weightSum_[b] > 0.0f) {
                const float* weight = weights_.data() + fluidNear.offset(b);
                float sum = gravityTerm_[b];
                for (const std::uint32_t f : fluidNear.of(b)) sum += fluidKappa[f] * *weight++;
                updated = std::max(sum / weightSum_[b], 0.0f);
            }
            onUpdate(b, updated);
            kappa_[b] = updated;
        });
    }

    std::vector<float> weightSum_;    ///< Σ_f W_bf
    std::vector<float> gravityTerm_;  ///< (g − a_b)·Σ_f (x_b − x_f) W_bf, m²/s²
    std::vector<float> kappa_;        ///< κ_b = p_b/ρ, m²/s²
    std::vector<float> weights_;      ///< W_bf per pair of the fluid-near list
};

}  // namespace tide
