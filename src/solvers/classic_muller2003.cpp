#include "solvers/classic_muller2003.hpp"

#include <algorithm>
#include <span>

#include <glm/geometric.hpp>

#include "core/kernels.hpp"
#include "core/parallel.hpp"
#include "solvers/equation_of_state.hpp"
#include "solvers/surface_tension_akinci2013.hpp"
#include "solvers/time_step.hpp"
#include "solvers/viscosity.hpp"

namespace tide {

void ClassicMuller2003::computeDensityAndPressure(StepContext& ctx) const {
    ParticleStore& p = ctx.particles;
    const kernels::Poly6 poly6 = ctx.poly6();
    const float selfWeight = poly6.valueSq(0.0f);
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i];
        float rho = p.mass[i] * selfWeight;
        for (const std::uint32_t j : ctx.neighbors.of(i)) {
            const glm::vec3 d = ctx.delta(xi, p.position[j]);
            rho += p.mass[j] * poly6.valueSq(glm::dot(d, d));
        }
        float boundaryVolume = 0.0f;
        for (const std::uint32_t b : ctx.boundaryNeighbors.of(i)) {
            const glm::vec3 d = ctx.delta(xi, ctx.boundary.position[b]);
            boundaryVolume += ctx.boundary.volume * poly6.valueSq(glm::dot(d, d));
        }
        const MaterialDef& mat = ctx.materials[p.material[i]];
        rho += mat.restDensity * boundaryVolume;  // Akinci et al. 2012, eq. (4), Ψ_b = ρ0_i V_b
        p.density[i] = rho;
        p.pressure[i] = pressureFromDensity(ctx.solver.equationOfState, rho, mat.restDensity, ctx.soundSpeed,
                                            ctx.solver.clampNegativePressure);
    });
}

void ClassicMuller2003::computeAccelerations(StepContext& ctx) const {
    ParticleStore& p = ctx.particles;
    const kernels::Spiky spiky(ctx.supportRadius, ctx.dimensions);
    const kernels::Viscosity viscosity(ctx.supportRadius);
    // Eq. (14), the default model, shares the pressure loop's pass over the neighbours (as
    // addViscosity computes it for the other solvers); another model is added before it.
    const bool muller = ctx.viscosity == ViscosityModel::Muller2003;
    if (!muller) {
        std::fill(p.acceleration.begin(), p.acceleration.end(), glm::vec3(0.0f));
        addViscosity(ctx, p.acceleration);
    }
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i];
        const glm::vec3 vi = p.velocity[i];
        const float pi = p.pressure[i];
        const float mui = ctx.materials[p.material[i]].viscosity;
        glm::vec3 pressureSum(0.0f);
        glm::vec3 viscousSum(0.0f);
        for (const std::uint32_t j : ctx.neighbors.of(i)) {
            const glm::vec3 rij = ctx.delta(xi, p.position[j]);
            const float r = glm::length(rij);
            const float massOverRho = p.mass[j] / p.density[j];
            // −∇W_spiky = 45/(πh⁶)(h − r)² r̂: positive pressure pushes i away from j.
            if (r > 0.0f) pressureSum += (massOverRho * 0.5f * (pi + p.pressure[j]) * -spiky.gradientScale(r) / r) * rij;
            if (muller) {
                const float muij = 0.5f * (mui + ctx.materials[p.material[j]].viscosity);
                viscousSum += (massOverRho * muij * viscosity.laplacian(r)) * (p.velocity[j] - vi);
            }
        }
        float wallViscosity = 0.0f;
        glm::vec3 wallDrive(0.0f);  // Σ_b V_b ∇²W_ib v_b, moving walls only
        const auto walls = ctx.boundaryNeighbors.of(i);
        const std::uint64_t slot = ctx.loads ? ctx.boundaryNeighbors.offset(i) : 0;
        // The force b puts on i: m_i/ρ_i times each term of the sums below.
        const float toForce = p.mass[i] / p.density[i];
        for (std::size_t k = 0; k < walls.size(); ++k) {
            const std::uint32_t b = walls[k];
            const glm::vec3 rib = ctx.delta(xi, ctx.boundary.position[b]);
            const float r = glm::length(rib);
            if (r > 0.0f) {
                const glm::vec3 term = (ctx.boundary.volume * pi * -spiky.gradientScale(r) / r) * rib;
                pressureSum += term;
                if (ctx.loads) ctx.loads->pressureForce[slot + k] = toForce * term;
            }
            if (!muller) continue;
            const float weight = ctx.boundary.volume * viscosity.laplacian(r);
            wallViscosity += weight;
            if (ctx.boundary.moving) wallDrive += weight * ctx.boundary.velocity[b];
            if (ctx.loads) {
                const glm::vec3 vb = ctx.boundary.moving ? ctx.boundary.velocity[b] : glm::vec3(0.0f);
                ctx.loads->viscousForce[slot + k] = toForce * (2.0f * mui * weight) * (vb - vi);
            }
        }
        if (!muller) {
            p.acceleration[i] += ctx.gravity + pressureSum / p.density[i];
            return;
        }
        // No-slip walls: v_b = −v_i at rest, 2 v_wall − v_i moving (see viscosity.cpp).
        if (ctx.boundary.moving) viscousSum += (2.0f * mui) * wallDrive;
        viscousSum -= (2.0f * mui * wallViscosity) * vi;
        p.acceleration[i] = ctx.gravity + (pressureSum + viscousSum) / p.density[i];
    });
}

double ClassicMuller2003::step(StepContext& ctx) {
    ParticleStore& p = ctx.particles;
    computeDensityAndPressure(ctx);
    // A split run: the forces read neighbours' densities and pressures, complete only on their owners.
    ctx.refreshGhosts(std::span<float>(p.density));
    ctx.refreshGhosts(std::span<float>(p.pressure));
    ctx.lap(Phase::Density);
    computeAccelerations(ctx);  // pressure and viscosity in one pass
    // Surface tension and adhesion (Akinci et al. 2013), when set: their force limit is in
    // stableTimeStep's criterion on the total acceleration.
    addSurfaceTension(ctx, p.acceleration);
    ctx.lap(Phase::PressureSolve);
    // Ghosts then move as their owners do, so XSPH reads the neighbours' true new velocities.
    ctx.refreshGhosts(std::span<glm::vec3>(p.acceleration));

    const auto n = p.size();
    const float maxSpeed2 = std::max(parallelMax(n, ctx.threads, [&](std::uint32_t i) {
        return glm::dot(p.velocity[i], p.velocity[i]);
    }, 0.0f), ctx.boundary.maxSpeed * ctx.boundary.maxSpeed);  // moving walls too: see sph::maxSpeed
    const float maxAccel2 = parallelMax(n, ctx.threads, [&](std::uint32_t i) {
        return glm::dot(p.acceleration[i], p.acceleration[i]);
    }, 0.0f);
    const double dt = stableTimeStep(ctx.solver, ctx.particleSpacing, ctx.soundSpeed, ctx.maxOverRanks(std::sqrt(maxSpeed2)),
                                     ctx.maxOverRanks(std::sqrt(maxAccel2)), maxKinematicViscosity(ctx), ctx.maxDt);

    const auto dtf = static_cast<float>(dt);
    parallelFor(n, ctx.threads, [&](std::uint32_t i) { p.velocity[i] += dtf * p.acceleration[i]; });
    ctx.lap(Phase::Integration);
    xsph_.apply(p, ctx.neighbors, ctx.periodic, ctx.poly6(),
                ctx.solver.xsph >= 0.0f ? ctx.solver.xsph : 0.25f, ctx.threads);
    ctx.lap(Phase::NonPressureForces);
    parallelFor(n, ctx.threads, [&](std::uint32_t i) { p.position[i] += dtf * p.velocity[i]; });
    return dt;
}

}  // namespace tide
