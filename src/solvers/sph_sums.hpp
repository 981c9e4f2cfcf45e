#pragma once
/// \file
/// Sums shared by the solvers built on the cubic spline kernel (wcsph, pcisph, dfsph): density
/// with Akinci et al. 2012 boundary contributions, and the non-pressure forces (gravity,
/// viscosity, surface tension) with their time-step limits.

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/kernels.hpp"
#include "core/parallel.hpp"
#include "solvers/pair_sums.hpp"
#include "solvers/solver.hpp"
#include "solvers/surface_tension_akinci2013.hpp"
#include "solvers/viscosity.hpp"

namespace tide::sph {

/// Pressure mirroring onto boundary particles (Akinci et al. 2012; written out in Ihmsen et
/// al. 2014, "Implicit incompressible SPH", eq. 13): a boundary particle b takes p_b = p_i
/// and ρ_b = ρ_i, so it pushes with Ψ_b (p_i/ρ_i² + p_b/ρ_b²) = 2 Ψ_b p_i/ρ_i². With a
/// factor 1 the wall holds only half of what the fluid beside a particle pushes it with:
/// particles at walls are driven into them, most at edges and corners. (The density solves
/// replace p_b by the wall pressure of Adami et al. 2012; this factor is their estimate of
/// how κ_b follows κ_i.)
inline constexpr float kBoundaryPressureMirror = 2.0f;

/// ρ_i = m_i Σ_j W_ij + ρ0_i Σ_b V_b W_ib, cubic spline: the number density of Solenthaler &
/// Pajarola 2008 (eq. 4–5; plain Σ_j m_j W_ij for one rest density, see
/// density_contrast_solenthaler2008.hpp) with the walls of Akinci et al. 2012 (eq. 4).
/// With `positionMass`, rows (x_j, m_j) of one rest density, the fluid sum Σ_j m_j W_ij runs in
/// SIMD lanes (pair_sums::kernelSum).
inline void computeDensities(StepContext& ctx, const glm::vec4* positionMass = nullptr) {
    ParticleStore& p = ctx.particles;
    const kernels::SmoothingKernel w = ctx.kernel();
    const float self = w.value(0.0f);
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i];
        float rho = 0.0f;
        const auto neighbors = ctx.neighbors.of(i);
        if (positionMass != nullptr) {
            rho = pair_sums::kernelSum(pair_sums::Neighbors(neighbors), positionMass, xi, w, ctx.periodic,
                                       p.mass[i] * self);
        } else {
            float number = self;
            for (const std::uint32_t j : neighbors) number += w.value(glm::length(ctx.delta(xi, p.position[j])));
            rho = p.mass[i] * number;
        }
        float boundaryVolume = 0.0f;
        for (const std::uint32_t b : ctx.boundaryNeighbors.of(i))
            boundaryVolume += ctx.boundary.volume * w.value(glm::length(ctx.delta(xi, ctx.boundary.position[b])));
        p.density[i] = rho + ctx.materials[p.material[i]].restDensity * boundaryVolume;
    });
}

/// `accel` = gravity + the physical viscosity of the model SolverDef::viscosity names
/// (Morris et al. 1997 by default; see viscosity.hpp) + surface tension and adhesion (Akinci
/// et al. 2013, off unless a material pair or material sets them). Returns the largest
/// tension acceleration, m/s² (0 when off), for explicitForceLimits().
inline float addNonPressureForces(StepContext& ctx, std::vector<glm::vec3>& accel) {
    accel.assign(ctx.particles.size(), ctx.gravity);
    addViscosity(ctx, accel);
    const float tension = addSurfaceTension(ctx, accel);
    // Split among processes: the ghosts' copies are summed from their owners' neighbourhoods.
    ctx.refreshGhosts(std::span<glm::vec3>(accel));
    return ctx.maxOverRanks(tension);
}

/// Largest kinematic viscosity μ/ρ0 the model uses, m²/s (for the viscous dt limit).
inline float maxKinematicViscosity(const StepContext& ctx) { return tide::maxKinematicViscosity(ctx); }

/// The solver's settings with maxDt lowered to the explicit non-pressure forces' limits, never
/// below the user's floor minDt: viscosity and dye diffusion 0.125 s²/ν, surface tension
/// forceNumber √(s/a) (surfaceTensionTimeStep). For the incompressible solvers, whose CFL
/// step does not see forces.
inline SolverDef explicitForceLimits(const StepContext& ctx, SolverDef limits, float maxTensionAccel) {
    const float nu = tide::maxKinematicViscosity(ctx);
    if (nu > 0.0f)
        limits.maxDt = std::max(limits.minDt, std::min(limits.maxDt, 0.125f * ctx.particleSpacing * ctx.particleSpacing / nu));
    if (maxTensionAccel > 0.0f)
        limits.maxDt = std::max(limits.minDt, std::min(limits.maxDt, static_cast<float>(surfaceTensionTimeStep(ctx, maxTensionAccel))));
    return limits;
}
inline SolverDef explicitForceLimits(const StepContext& ctx, float maxTensionAccel) {
    return explicitForceLimits(ctx, ctx.solver, maxTensionAccel);
}

/// Gravity may move a particle at rest by g Δt² ≤ this fraction of the spacing in one step.
inline constexpr float kFreeFallShare = 1.0f / 80.0f;

/// Lowers limits.maxDt (never below minDt) to the free-fall step √(s/(80 g)) of spacing s.
/// What a step's pressure solve must cancel grows with Δt² (g Δt² over the spacing), and a
/// relaxed Jacobi solve needs ~the square of the water's depth in particle layers to build
/// the hydrostatic pressure it takes, so a fixed max_dt fails as the spacing shrinks: dfsph
/// in the 0.3 m tank at rest (30 layers at 1 cm) ran its solves to the iteration limit at
/// 5 ms steps and blew up within 0.03 s; at 3.6 ms it takes 25–33 iterations a step and
/// lasts (the 0.24 m tank 2 s; a 0.12 m one blows up at ~2 s all the same: Jacobi is the
/// weak part). The limit is above the default 5 ms from 2 cm up: coarser scenes do not change.
inline void limitFreeFall(const StepContext& ctx, SolverDef& limits) {
    const float g = glm::length(ctx.gravity);
    if (g > 0.0f)
        limits.maxDt = std::max(limits.minDt, std::min(limits.maxDt, std::sqrt(kFreeFallShare * ctx.particleSpacing / g)));
}

/// Courant number of the pressure-speed step limit (pressureSpeedStep).
inline constexpr float kPressureCourant = 0.45f;

/// The pressure-speed step limit kPressureCourant · s / √(g D), infinite without gravity; D
/// the depth of the water: its height along gravity, or the largest pressure head κ/g of the
/// last density solve if that is less (spray above the water makes the height alone too large). A
/// relaxed Jacobi solve with momentum builds a hydrostatic pressure over ~(D/s)² sweeps and
/// keeps up with g Δt² per step only while Δt √(g D) stays within about half a spacing: the
/// 0.3 m tank at rest at 1 cm blew up at 5 ms steps within 0.03 s, with the free-fall limit
/// alone (3.6 ms) at ~2 s, and at 0.5 s/√(gD) (2.9 ms) at 0.1 s; at 0.45 (2.6 ms) it holds,
/// its pressure within 1.3 % RMS of ρgd (1.1 % in a 0.24 m square tank). The margin is the
/// momentum's (docs/robustness.md). At 2 cm this gives 5.2 ms for 0.3 m of water: scenes at
/// 2 cm and up to 0.3 m deep keep their 5 ms steps.
inline float pressureSpeedStep(const StepContext& ctx) {
    const ParticleStore& p = ctx.particles;
    const float g = glm::length(ctx.gravity);
    constexpr float none = std::numeric_limits<float>::infinity();
    // A process may hold no particles: it still takes part in the maxima over processes.
    if (!(g > 0.0f)) return none;
    const glm::vec3 down = ctx.gravity / g;
    const float deepest = parallelMax(p.size(), ctx.threads, [&](std::uint32_t i) { return glm::dot(p.position[i], down); },
                                      -std::numeric_limits<float>::max());
    const float highest = parallelMax(p.size(), ctx.threads, [&](std::uint32_t i) { return -glm::dot(p.position[i], down); },
                                      -std::numeric_limits<float>::max());
    // The density solve's κ: the divergence solve's impulses (impacts) are left out.
    const float head = parallelMax(p.size(), ctx.threads, [&](std::uint32_t i) { return p.warmKappa[i]; }, 0.0f);
    const float depth = ctx.maxOverRanks(deepest) + ctx.maxOverRanks(highest) + ctx.particleSpacing;  // particle centres lie half a spacing inside
    const float speed2 = std::min(g * depth, ctx.maxOverRanks(head));
    return speed2 > 0.0f ? kPressureCourant * ctx.particleSpacing / std::sqrt(speed2) : none;
}

/// Largest speed of a fluid particle or a moving boundary particle, m/s: the CFL step must
/// not let a fast paddle or obstacle pass a particle spacing in one step.
inline float maxSpeed(const StepContext& ctx) {
    const ParticleStore& p = ctx.particles;
    return std::max(ctx.maxOverRanks(std::sqrt(parallelMax(p.size(), ctx.threads, [&](std::uint32_t i) {
        return glm::dot(p.velocity[i], p.velocity[i]);
    }, 0.0f))), ctx.boundary.maxSpeed);
}

}  // namespace tide::sph
