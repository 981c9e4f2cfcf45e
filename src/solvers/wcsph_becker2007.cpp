#include "solvers/wcsph_becker2007.hpp"

#include <glm/geometric.hpp>

#include "core/kernels.hpp"
#include "core/parallel.hpp"
#include "solvers/equation_of_state.hpp"
#include "solvers/pair_sums.hpp"
#include "solvers/sph_sums.hpp"
#include "solvers/time_step.hpp"

namespace tide {

double WcsphBecker2007::step(StepContext& ctx) {
    ParticleStore& p = ctx.particles;
    const auto n = p.size();
    // One rest density: rows (x_j, m_j) for the SIMD pair sums of the densities, then
    // (v_j, 1/ρ_j) for the viscosity's and (x_j, m_j p_j/ρ_j²) for the pressure force's, as
    // dfsph packs them.
    contrast_.prepare(p, ctx.materials, ctx.threads);
    const bool lanes = contrast_.uniform();
    if (lanes) {
        positionMass_.resize(n);
        rows_.resize(n);
        parallelFor(n, ctx.threads, [&](std::uint32_t i) { positionMass_[i] = glm::vec4(p.position[i], p.mass[i]); });
    }
    sph::computeDensities(ctx, lanes ? positionMass_.data() : nullptr);
    ctx.refreshGhosts(std::span<float>(p.density));  // pressure, κ and the forces read neighbours' densities
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        p.pressure[i] = pressureFromDensity(EquationOfState::Tait, p.density[i], ctx.materials[p.material[i]].restDensity,
                                            ctx.soundSpeed, true);
        if (lanes) rows_[i] = glm::vec4(p.velocity[i], 1.0f / p.density[i]);
    });
    if (lanes) {
        ctx.positionMassRows = positionMass_.data();
        ctx.velocityRows = rows_.data();
    }
    ctx.lap(Phase::Density);
    // Tension's force limit is in stableTimeStep's criterion on the total acceleration.
    sph::addNonPressureForces(ctx, accel_);
    ctx.positionMassRows = ctx.velocityRows = nullptr;
    ctx.lap(Phase::NonPressureForces);
    // Walls take the pressure of the fluid around them, extrapolated hydrostatically.
    kappa_.resize(n);
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        kappa_[i] = p.pressure[i] / p.density[i];
        if (lanes) rows_[i] = glm::vec4(p.position[i], p.mass[i] * kappa_[i] / p.density[i]);
    });
    wall_.prepare(ctx.boundary, ctx.boundaryFluidNeighbors, ctx.boundaryNearFluid, p.position, ctx.periodic, ctx.gravity,
                  ctx.kernel(), ctx.threads, contrast_.scale());
    wall_.update(ctx.boundaryFluidNeighbors, contrast_.wallKappa(kappa_, scaledKappa_, ctx.threads), ctx.threads);
    const auto wallKappa = wall_.kappa();
    const kernels::SmoothingKernel w = ctx.kernel();
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i];
        // Density contrast (Solenthaler & Pajarola 2008, eq. 6): F_i = −Σ_j (p_i V_i² + p_j V_j²) ∇W_ij,
        // V = m/ρ, a_i = F_i/m_i (Becker & Teschner's Σ_j m_j (p_i/ρ_i² + p_j/ρ_j²) ∇W_ij for one mass).
        const float mi = p.mass[i];
        const float pi = mi * p.pressure[i] / (p.density[i] * p.density[i]);
        glm::vec3 sum(0.0f);
        const auto neighbors = ctx.neighbors.of(i);
        if (lanes) {  // pi Σ_j ∇W_ij + Σ_j (m p_j/ρ_j²) ∇W_ij
            const pair_sums::GradientSums sums =
                pair_sums::kernelGradientSums(pair_sums::Neighbors(neighbors), rows_.data(), xi, w, ctx.periodic);
            sum = pi * sums.plain + sums.weighted;
        } else {
            for (const std::uint32_t j : neighbors) {
                const glm::vec3 rij = ctx.delta(xi, p.position[j]);
                const float vj = p.mass[j] / p.density[j];
                sum += (pi + p.pressure[j] * vj * vj / mi) * w.gradient(rij, glm::length(rij));
            }
        }
        // Ψ_b (p_i/ρ_i² + p_b/ρ_b²) with ρ_b = ρ_i (Akinci et al. 2012, Adami et al. 2012); the
        // wall's κ̃_b is p_b/ρ0_ref, read as κ_b = κ̃_b ρ0_ref/ρ0_i for fluid i.
        const float psi = ctx.materials[p.material[i]].restDensity / p.density[i];
        const float wallScale = 1.0f / contrast_.scale(i);
        const auto walls = ctx.boundaryNeighbors.of(i);
        glm::vec3* loads = ctx.loads ? ctx.loads->pressureForce.data() + ctx.boundaryNeighbors.offset(i) : nullptr;
        for (std::size_t k = 0; k < walls.size(); ++k) {
            const std::uint32_t b = walls[k];
            const glm::vec3 rib = ctx.delta(xi, ctx.boundary.position[b]);
            const glm::vec3 term = (ctx.boundary.volume * psi * (kappa_[i] + wallScale * wallKappa[b])) * w.gradient(rib, glm::length(rib));
            sum += term;
            if (loads) loads[k] = -mi * term;  // the force b puts on i
        }
        p.acceleration[i] = accel_[i] - sum;
    });
    ctx.lap(Phase::PressureSolve);
    // Ghosts then move as their owners do, so XSPH reads the neighbours' true new velocities.
    ctx.refreshGhosts(std::span<glm::vec3>(p.acceleration));
    const float maxAccel = ctx.maxOverRanks(std::sqrt(parallelMax(n, ctx.threads, [&](std::uint32_t i) {
        return glm::dot(p.acceleration[i], p.acceleration[i]);
    }, 0.0f)));
    const double dt = stableTimeStep(ctx.solver, ctx.particleSpacing, ctx.soundSpeed, sph::maxSpeed(ctx), maxAccel,
                                     sph::maxKinematicViscosity(ctx),
                                     ctx.maxDt);
    const auto dtf = static_cast<float>(dt);
    parallelFor(n, ctx.threads, [&](std::uint32_t i) { p.velocity[i] += dtf * p.acceleration[i]; });
    ctx.lap(Phase::Integration);
    // rows_ is free now: XSPH packs its (v_j, ρ_j) rows there.
    xsph_.apply(p, ctx.neighbors, ctx.periodic, ctx.poly6(), ctx.solver.xsph >= 0.0f ? ctx.solver.xsph : 0.01f,
                ctx.threads, rows_, lanes ? positionMass_.data() : nullptr);
    ctx.lap(Phase::NonPressureForces);
    parallelFor(n, ctx.threads, [&](std::uint32_t i) { p.position[i] += dtf * p.velocity[i]; });
    return dt;
}

}  // namespace tide
