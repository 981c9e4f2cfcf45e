#pragma once
/// \file
/// Fickian particle shifting (Lind, Xu, Stansby & Rogers 2012, "Incompressible smoothed
/// particle hydrodynamics for free-surface flows: a generalised diffusion-based algorithm
/// for stability and validations for impulsive flows and propagating waves", JCP 231):
/// after a step, a particle moves down the gradient of the particle concentration,
/// δr_i = −D ∇C_i with ∇C_i = Σ_j V_j ∇W_ij and D = A s² (s the particle spacing), so that
/// the packing stays even. The pressure's own regularisation (the symmetric form's
/// p_i Σ_j V_j ∇W_ij) does that too, but stores the energy elastically: a wave's strain of
/// the packing turns into particle-scale motion and is lost (docs/waves.md § Particle
/// shifting).
///
/// Only particles with a full neighbourhood shift. The top layer keeps its place; the one
/// below it shifts, up along the surface's ∇C (Lind et al. shift only tangentially near the
/// surface), and that is where the waves' gain comes from (measured: shifting only where
/// |∇C| s < 0.05 kept the decay). A particle with a wall within reach keeps its place too
/// (its ∇C without the wall's share points into the wall; with it, still water stirred three
/// times as much, measured), so no shift can carry a particle to a wall.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace tide {

struct FickianShifting {
    float coefficient;            ///< A of D = A s² (SolverDef::shifting)
    float spacing;                ///< s, m
    std::uint32_t minNeighbors;   ///< fewer fluid neighbours: at the free surface, no shift

    /// A neighbourhood counts as full from 3/4 of a sphere (in 2D a disc) of the support's
    /// radius filled at the lattice's number density (25 of 33.5 at 2 spacings; 9 of 12.6 in 2D).
    static constexpr float kFullNeighborhood = 0.75f;
    /// A shift moves at most this many spacings a step.
    static constexpr float kMaxShift = 0.05f;

    FickianShifting(float coefficientIn, float spacingIn, float supportRadius, int dimensions = 3)
        : coefficient(coefficientIn), spacing(spacingIn),
          minNeighbors(static_cast<std::uint32_t>(
              dimensions == 2 ? kFullNeighborhood * std::numbers::pi_v<float> * std::pow(supportRadius / spacingIn, 2.0f)
                              : kFullNeighborhood * (4.0f / 3.0f) * std::numbers::pi_v<float> *
                                    std::pow(supportRadius / spacingIn, 3.0f))) {}

    [[nodiscard]] bool enabled() const { return coefficient > 0.0f; }
    /// Whether particle i shifts: a full neighbourhood and no wall particle within reach.
    [[nodiscard]] bool shifts(std::size_t fluidNeighbors, std::size_t wallNeighbors) const {
        return enabled() && fluidNeighbors >= minNeighbors && wallNeighbors == 0;
    }
    /// δr from ∇C_i = Σ_j V_j ∇W_ij, capped at kMaxShift spacings.
    [[nodiscard]] glm::vec3 displacement(const glm::vec3& concentrationGradient) const {
        glm::vec3 d = -(coefficient * spacing * spacing) * concentrationGradient;
        const float length = glm::length(d), cap = kMaxShift * spacing;
        if (length > cap) d *= cap / length;
        return d;
    }
};

}  // namespace tide
