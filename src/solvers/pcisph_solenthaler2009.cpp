#include "solvers/pcisph_solenthaler2009.hpp"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>

#include "core/kernels.hpp"
#include "core/parallel.hpp"
#include "solvers/owned_sums.hpp"
#include "solvers/sph_sums.hpp"
#include "solvers/time_step.hpp"

namespace tide {

namespace {
/// Jacobi weight: pressure may fall as well as rise, and full steps overshoot (as in IISPH,
/// Ihmsen et al. 2014); for the default support, wider ones scale it (jacobi_weight.hpp).
constexpr float kRelaxation = 0.5f;
/// The solve stops at this fraction of the tolerance: the density reached also counts pairs
/// that come into range during the step, which the prediction over x(t)'s neighbours misses.
constexpr double kDensityTarget = 0.9;
/// A retake at half the step whose predicted error (before pressure) is still above this
/// fraction of the longer try's was not failing for the step's length: it is not halved again.
constexpr double kUselessHalving = 0.9;
}  // namespace

// δ per particle rather than the paper's one prototype δ (§3.3). The paper's derivation,
// repeated for particle i's own neighbourhood: with one pressure p̃ around i,
//   Δx_i = −Δt² p̃/ρ0² (2 Σ_j m_j ∇W_ij + Σ_b Ψ_b ∇W_ib),   Δx_j = Δt² p̃/ρ0² 2 m_i ∇W_ij,
//   Δρ_i = Σ_j m_j (Δx_i − Δx_j)·∇W_ij + Σ_b Ψ_b Δx_i·∇W_ib
//        = −Δt² p̃/ρ0² ((2G_f + G_b)·(G_f + G_b) + 2 Σ_j m_i m_j |∇W_ij|²),
// G_f = Σ_j m_j ∇W_ij, G_b = Σ_b Ψ_b ∇W_ib, so δ_i = ρ0² / (Δt² (…)) (with the walls'
// mirrored pressure, 2G_f + G_b becomes 2(G_f + G_b)). Without boundaries and
// with equal masses this is the paper's δ = 1/(β(|Σ∇W|² + Σ|∇W|²)), β = 2(Δt m/ρ0)². Why per
// particle: the prototype (a filled fluid neighbourhood) is too soft for particles at a wall,
// which have half the fluid neighbours, so those converge slowly. Measured on the 0.3 m
// hydrostatic tank (tests/test_incompressible_solvers.cpp): both give the same pressure
// (RMS 0.10 vs 0.11 off ρgd, averaged over all steps), but δ_i takes 38 iterations per step
// at rest instead of 53, and 8 instead of 13 on the dam break.
void PcisphSolenthaler2009::computeDelta(StepContext& ctx, float dt) {
    ParticleStore& p = ctx.particles;
    const kernels::SmoothingKernel w = ctx.kernel();
    delta_.resize(p.size());
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i];
        // Density contrast (Solenthaler & Pajarola 2008): ρ_i = m_i Σ_j W_ij and the pressure
        // force (1/m_i) Σ_j (p_i V_i² + p_j V_j²) ∇W_ij turn G_f into m_i Σ_j ∇W_ij and the
        // neighbours' term into Σ_j (m_i³/m_j) |∇W_ij|² (the above for one mass).
        const float mi = p.mass[i];
        glm::vec3 fluidGrad(0.0f);
        float squares = 0.0f;
        for (const std::uint32_t j : ctx.neighbors.of(i)) {
            const glm::vec3 rij = ctx.delta(xi, p.position[j]);
            const glm::vec3 g = w.gradient(rij, glm::length(rij));
            fluidGrad += mi * g;
            squares += mi * mi * (mi / p.mass[j]) * glm::dot(g, g);
        }
        const float rho0 = ctx.materials[p.material[i]].restDensity;
        glm::vec3 boundaryGrad(0.0f);
        for (const std::uint32_t b : ctx.boundaryNeighbors.of(i)) {
            const glm::vec3 rib = ctx.delta(xi, ctx.boundary.position[b]);
            boundaryGrad += (rho0 * ctx.boundary.volume) * w.gradient(rib, glm::length(rib));
        }
        // Walls push with the mirrored pressure (Ψ_b (p_i + p_b)/ρ0², p_b ≈ p_i), so i's own
        // displacement is −Δt² p̃/ρ0² 2(G_f + G_b).
        const float own = 2.0f * glm::dot(fluidGrad + boundaryGrad, fluidGrad + boundaryGrad);
        const float denominator = dt * dt * (own + 2.0f * squares);
        delta_[i] = denominator > 0.0f ? rho0 * rho0 / denominator : 0.0f;
    });
}

void PcisphSolenthaler2009::predictPositions(StepContext& ctx, float dt) {
    ParticleStore& p = ctx.particles;
    predicted_.resize(p.size());
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        predicted_[i] = p.position[i] + dt * (p.velocity[i] + dt * (accel_[i] + pressureAccel_[i]));
    });
}

void PcisphSolenthaler2009::predictCompression(StepContext& ctx, float dt) {
    ParticleStore& p = ctx.particles;
    const kernels::SmoothingKernel w = ctx.kernel();
    const float self = w.value(0.0f);
    error_.resize(p.size());
    residual_.resize(p.size());
    // The neighbours of x(t), as the paper does: x* is less than a spacing away. Moving walls
    // are where they will be at the end of the step, x_b + Δt v_b (as in dfsph).
    const bool moving = ctx.boundary.moving;
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = predicted_[i];
        float number = self;  // ρ*_i = m_i Σ_j W_ij (Solenthaler & Pajarola 2008)
        for (const std::uint32_t j : ctx.neighbors.of(i)) number += w.value(glm::length(ctx.delta(xi, predicted_[j])));
        const float rho = p.mass[i] * number;
        float boundaryVolume = 0.0f;
        for (const std::uint32_t b : ctx.boundaryNeighbors.of(i)) {
            const glm::vec3 xb = moving ? ctx.boundary.position[b] + dt * ctx.boundary.velocity[b] : ctx.boundary.position[b];
            boundaryVolume += ctx.boundary.volume * w.value(glm::length(ctx.delta(xi, xb)));
        }
        const float rho0 = ctx.materials[p.material[i]].restDensity;
        residual_[i] = rho + rho0 * boundaryVolume - rho0;
        // Expansion is an error only where pressure could still relax: free-surface particles
        // lack neighbours, not pressure.
        error_[i] = pressure_[i] > 0.0f ? std::abs(residual_[i]) : std::max(residual_[i], 0.0f);
    });
}

double PcisphSolenthaler2009::meanRelativeCompression(const StepContext& ctx) const {
    const ParticleStore& p = ctx.particles;
    if (!contrast_.uniform()) return owned_sums::worstMaterialMean(ctx, [&](std::uint32_t i) { return error_[i]; });
    return owned_sums::mean(ctx, [&](std::uint32_t i) { return error_[i] / ctx.materials[p.material[i]].restDensity; });
}

void PcisphSolenthaler2009::computePressureAccel(StepContext& ctx) {
    ParticleStore& p = ctx.particles;
    const kernels::SmoothingKernel w = ctx.kernel();
    pressureAccel_.resize(p.size());
    // ρ0 rather than ρ in p/ρ², as δ assumes: free-surface particles (ρ < ρ0) would otherwise
    // be pushed harder than the correction predicted.
    kappa_.resize(p.size());
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        kappa_[i] = pressure_[i] / ctx.materials[p.material[i]].restDensity;
    });
    wall_.update(ctx.boundaryFluidNeighbors, contrast_.wallKappa(kappa_, scaledKappa_, ctx.threads), ctx.threads);
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i];
        const float rho0 = ctx.materials[p.material[i]].restDensity;
        const float mi = p.mass[i];
        const float pi = pressure_[i] / (rho0 * rho0);
        // (1/m_i) Σ_j (p_i V_i² + p_j V_j²) ∇W_ij with V = m/ρ0 (density contrast, Solenthaler &
        // Pajarola 2008): Σ_j (m_i p_i/ρ0_i² + (m_j/m_i) m_j p_j/ρ0_j²) ∇W_ij.
        glm::vec3 sum(0.0f);
        for (const std::uint32_t j : ctx.neighbors.of(i)) {
            const glm::vec3 rij = ctx.delta(xi, p.position[j]);
            const float rho0j = ctx.materials[p.material[j]].restDensity;
            const float mj = p.mass[j];
            sum += (mi * pi + (mj / mi) * mj * pressure_[j] / (rho0j * rho0j)) * w.gradient(rij, glm::length(rij));
        }
        // Ψ_b (p_i + p_b)/ρ0², p_b the wall pressure (Akinci et al. 2012, Adami et al. 2012),
        // κ̃_b = p_b/ρ0_ref read as p_b/ρ0_i.
        const auto wallKappa = wall_.kappa();
        const float wallScale = 1.0f / contrast_.scale(i);
        // Every call overwrites the loads: the last one's accelerations are the step's.
        const auto walls = ctx.boundaryNeighbors.of(i);
        glm::vec3* loads = ctx.loads ? ctx.loads->pressureForce.data() + ctx.boundaryNeighbors.offset(i) : nullptr;
        for (std::size_t k = 0; k < walls.size(); ++k) {
            const std::uint32_t b = walls[k];
            const glm::vec3 rib = ctx.delta(xi, ctx.boundary.position[b]);
            const glm::vec3 term = (ctx.boundary.volume * (rho0 * pi + wallScale * wallKappa[b])) * w.gradient(rib, glm::length(rib));
            sum += term;
            if (loads) loads[k] = -mi * term;  // the force b puts on i
        }
        pressureAccel_[i] = -sum;
    });
    // Split among processes: a ghost near a wall misses part of the wall's pressure sum.
    ctx.refreshGhosts(std::span<glm::vec3>(pressureAccel_));
}

PcisphSolenthaler2009::Solve PcisphSolenthaler2009::solvePressure(StepContext& ctx, float dt) {
    const auto n = ctx.particles.size();
    // δ depends on Δt², and Δt is adaptive: once per try, not once per simulation.
    computeDelta(ctx, dt);
    pressure_.assign(n, 0.0f);
    // The walls' hydrostatic part acts from the start, before any fluid pressure.
    computePressureAccel(ctx);
    Solve solve;
    const float relaxation = kRelaxation * weightScale_(ctx.supportRadius / ctx.particleSpacing, ctx.solver.kernel, ctx.dimensions);
    for (; solve.iterations < ctx.solver.maxIterations; ++solve.iterations) {
        predictPositions(ctx, dt);
        predictCompression(ctx, dt);
        const double compression = meanRelativeCompression(ctx);
        if (solve.iterations == 0) solve.uncorrected = compression;
        if (compression <= kDensityTarget * ctx.solver.maxDensityError) {
            if (solve.iterations >= ctx.solver.minIterations) {
                solve.converged = true;
                return solve;
            }
        } else if (compression > 2.0 * solve.uncorrected) {
            return solve;  // the corrections feed the compression: this Δt is too long
        }
        // Projected relaxed Jacobi (as in dfsph): p ≥ 0, and it may fall back after overshooting.
        parallelFor(n, ctx.threads, [&](std::uint32_t i) {
            pressure_[i] = std::max(pressure_[i] + relaxation * delta_[i] * residual_[i], 0.0f);
        });
        ctx.refreshGhosts(std::span<float>(pressure_));  // a ghost's δ and residual miss neighbours
        computePressureAccel(ctx);
    }
    return solve;
}

double PcisphSolenthaler2009::step(StepContext& ctx) {
    ParticleStore& p = ctx.particles;
    const auto n = p.size();
    sph::computeDensities(ctx);
    ctx.refreshGhosts(std::span<float>(p.density));  // the forces read neighbours' densities
    contrast_.prepare(p, ctx.materials, ctx.threads);
    wall_.prepare(ctx.boundary, ctx.boundaryFluidNeighbors, ctx.boundaryNearFluid, p.position, ctx.periodic, ctx.gravity, ctx.kernel(),
                  ctx.threads, contrast_.scale());
    ctx.lap(Phase::Density);
    const float tensionAccel = sph::addNonPressureForces(ctx, accel_);
    ctx.lap(Phase::NonPressureForces);
    SolverDef limits = sph::explicitForceLimits(ctx, tensionAccel);
    if (!contrast_.uniform())
        limits.maxDt = std::max(limits.minDt, std::min(limits.maxDt, DensityContrast::timeStepLimit(
                                    ctx.materials, glm::length(ctx.gravity), ctx.particleSpacing, ctx.solver.forceNumber)));
    const float speed = sph::maxSpeed(ctx);

    // A failed solve (no convergence in maxIterations, or corrections that feed the
    // compression) takes the step again at half the length, after the adaptive PCISPH step of
    // Ihmsen et al. 2010 ("Boundary handling and adaptive time-stepping for PCISPH"). The CFL
    // step alone misses impacts: a column falling onto the floor compresses only its bottom
    // layer, which the mean compression hides until that layer is squeezed by more than one
    // step's corrections can undo, and the pressure then runs away (the 50k-particle dam break
    // of bench_core blew up at 5 ms steps). The cap grows back by a quarter per good step.
    double dt = 0.0;
    Solve solve;
    int iterations = 0;  // failed tries included: they cost as much
    double longerTryError = std::numeric_limits<double>::infinity();
    for (;;) {
        SolverDef capped = limits;
        capped.maxDt = std::max(limits.minDt, std::min(static_cast<float>(dtCap_), limits.maxDt));
        dt = cflTimeStep(capped, ctx.particleSpacing, speed, ctx.maxDt);
        solve = solvePressure(ctx, static_cast<float>(dt));
        iterations += solve.iterations;
        if (solve.converged || dt <= limits.minDt) break;
        // Halving helps where this step's motion makes the error. Where the error was there
        // before the step (a density contrast, whose stiff interface the Jacobi corrects slowly:
        // 5000/1000/200 columns at 1 cm), a shorter step only corrects the same error in less
        // time, i.e. faster: halved down to the minimum step it flung particles at 10⁴–10⁵ m/s.
        if (solve.uncorrected > kUselessHalving * longerTryError) break;
        longerTryError = solve.uncorrected;
        dtCap_ = 0.5 * dt;
    }
    dtCap_ = solve.converged ? std::min(1.25 * dtCap_, static_cast<double>(limits.maxDt)) : dtCap_;
    ctx.lap(Phase::PressureSolve);
    const auto dtf = static_cast<float>(dt);

    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        p.acceleration[i] = accel_[i] + pressureAccel_[i];
        p.velocity[i] += dtf * p.acceleration[i];
        p.pressure[i] = pressure_[i];
    });
    ctx.lap(Phase::Integration);
    xsph_.apply(p, ctx.neighbors, ctx.periodic, ctx.poly6(), ctx.solver.xsph >= 0.0f ? ctx.solver.xsph : 0.01f,
                ctx.threads);
    ctx.lap(Phase::NonPressureForces);
    parallelFor(n, ctx.threads, [&](std::uint32_t i) { p.position[i] += dtf * p.velocity[i]; });
    ctx.pressureIterations = iterations;
    ctx.pressureConverged = solve.converged;
    return dt;
}

}  // namespace tide
