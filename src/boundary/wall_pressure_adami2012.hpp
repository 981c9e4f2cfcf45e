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
    /// Kernel sums of the boundary particles near fluid, `near` (in the order `fluidNear` was
    /// built for: its query a is boundary particle near[a]), over the fluid near them, at the
    /// current positions (the kernel values are kept: the solves call update() every
    /// iteration). κ_b is kept for the boundary particles near fluid only: the fluid reads no
    /// other, and the shell has several times more (memory: issue 8).
    void prepare(const BoundaryParticles& boundary, const CrossNeighborList& fluidNear, std::span<const std::uint32_t> near,
                 std::span<const glm::vec3> fluid, const PeriodicBox& box, const glm::vec3& gravity, const kernels::SmoothingKernel& w,
                 int threads, std::span<const float> fluidScale = {}) {
        const auto n = static_cast<std::uint32_t>(near.size());
        near_ = near;
        boundaryCount_ = boundary.position.size();
        weightSum_.resize(n);
        gravityTerm_.resize(n);
        kappa_.resize(n);
        resizeScratch(weights_, fluidNear.slotCount());
        parallelFor(n, threads, [&](std::uint32_t a) {
            const std::uint32_t b = near[a];
            const glm::vec3 xb = boundary.position[b];
            const glm::vec3 g = boundary.moving ? gravity - boundary.acceleration[b] : gravity;
            float* weight = weights_.data() + fluidNear.offset(a);
            float weights = 0.0f, lift = 0.0f;
            for (const std::uint32_t f : fluidNear.of(a)) {
                const glm::vec3 xbf = box.delta(xb, fluid[f]);
                const float wbf = w.value(glm::length(xbf));
                *weight++ = wbf;
                weights += wbf;
                lift += fluidScale.empty() ? glm::dot(g, xbf) * wbf : fluidScale[f] * glm::dot(g, xbf) * wbf;
            }
            weightSum_[a] = weights;
            gravityTerm_[a] = lift;
            kappa_[a] = 0.0f;
        });
    }

    /// κ_b from the fluid's κ_f over the lists and positions prepare() saw; read by boundary
    /// particle with kappa().
    void update(const CrossNeighborList& fluidNear, std::span<const float> fluidKappa, int threads) {
        byBoundary_.resize(boundaryCount_);
        update(fluidNear, fluidKappa, threads, [&](std::uint32_t b, float updated, float) { byBoundary_[b] = updated; });
    }
    /// As above, but what a solve that pushes with the change of κ needs instead of κ_b:
    /// change[b] = (new κ_b − last κ_b)·scale for each b near fluid (the others are left as
    /// they are), with no array of κ_b over the whole shell.
    void update(const CrossNeighborList& fluidNear, std::span<const float> fluidKappa, int threads, float scale,
                std::span<float> change) {
        update(fluidNear, fluidKappa, threads,
               [&](std::uint32_t b, float updated, float last) { change[b] = (updated - last) * scale; });
    }

    /// κ_b by boundary particle, from the last update() without a change; set for those near
    /// fluid (prepare).
    [[nodiscard]] std::span<const float> kappa() const { return byBoundary_; }

private:
    template <class OnUpdate>
    void update(const CrossNeighborList& fluidNear, std::span<const float> fluidKappa, int threads, OnUpdate&& onUpdate) {
        parallelFor(static_cast<std::uint32_t>(near_.size()), threads, [&](std::uint32_t a) {
            float updated = kappa_[a];  // 0 (prepare) where the kernel sum is 0
            if (weightSum_[a] > 0.0f) {
                const float* weight = weights_.data() + fluidNear.offset(a);
                float sum = gravityTerm_[a];
                for (const std::uint32_t f : fluidNear.of(a)) sum += fluidKappa[f] * *weight++;
                updated = std::max(sum / weightSum_[a], 0.0f);
            }
            onUpdate(near_[a], updated, kappa_[a]);
            kappa_[a] = updated;
        });
    }

    std::span<const std::uint32_t> near_;  ///< the boundary particles near fluid, as prepare() saw them
    std::vector<float> weightSum_;    ///< Σ_f W_bf, per boundary particle near fluid
    std::vector<float> gravityTerm_;  ///< (g − a_b)·Σ_f (x_b − x_f) W_bf, m²/s², likewise
    std::size_t boundaryCount_ = 0;   ///< boundary particles, near fluid or not
    std::vector<float> kappa_;        ///< κ_b = p_b/ρ, m²/s², per boundary particle near fluid
    std::vector<float> byBoundary_;   ///< κ_b by boundary particle (update() without a change only)
    std::vector<float> weights_;      ///< W_bf per pair of the fluid-near list
};

}  // namespace tide
