#include "solvers/dfsph_bender2017.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

#include "core/kernels.hpp"
#include "core/parallel.hpp"
#include "solvers/sph_sums.hpp"
#include "solvers/time_step.hpp"

namespace tide {

namespace {
/// Particles with fewer neighbours sit at the free surface: their density deficit is
/// geometric, not compression, so the divergence solve leaves them alone (as SPlisHSPlasH does).
constexpr std::uint32_t kMinNeighborsForDivergence = 20;
/// Jacobi weight of the density solve. Its pressure may fall as well as rise, and full
/// Jacobi steps on this system overshoot and diverge; IISPH (Ihmsen et al. 2014) uses 0.5.
constexpr float kRelaxation = 0.5f;
/// The density solve stops at this fraction of SolverDef::maxDensityError: what it checks is
/// the density predicted over this step's neighbour lists; the density reached also counts
/// pairs that come into range during the step (measured: up to 2 % more in a dam break).
constexpr double kDensityTarget = 0.9;

/// Σ_j m_j (v_i − v_j)·∇W_ij + Σ_b Ψ_b v_i·∇W_ib: the rate of change of ρ_i (boundaries at rest).
float densityRate(const StepContext& ctx, const kernels::CubicSpline& w, std::uint32_t i) {
    const ParticleStore& p = ctx.particles;
    const glm::vec3 xi = p.position[i];
    const glm::vec3 vi = p.velocity[i];
    float rate = 0.0f;
    for (const std::uint32_t j : ctx.neighbors.of(i)) {
        const glm::vec3 rij = ctx.delta(xi, p.position[j]);
        rate += p.mass[j] * glm::dot(vi - p.velocity[j], w.gradient(rij, glm::length(rij)));
    }
    const float rho0 = ctx.materials[p.material[i]].restDensity;
    for (const std::uint32_t b : ctx.boundaryNeighbors.of(i)) {
        const glm::vec3 rib = ctx.delta(xi, ctx.boundary.position[b]);
        rate += rho0 * ctx.boundary.volume[b] * glm::dot(vi, w.gradient(rib, glm::length(rib)));
    }
    return rate;
}
/// ρ*_i: the density at the positions the current velocities reach after dt, over this step's
/// neighbours. The paper linearises it, ρ_i + Δt Dρ_i/Dt (eq. 9); the kernel is convex where
/// neighbours close in, so the linear guess misses up to 90 % of the tolerance at CFL 0.4 in a
/// dam break (measured), and evaluating W at the new positions costs no more than ∇W·v.
float predictedDensity(const StepContext& ctx, const kernels::CubicSpline& w, std::uint32_t i, float dt) {
    const ParticleStore& p = ctx.particles;
    const glm::vec3 xi = p.position[i] + dt * p.velocity[i];
    float rho = p.mass[i] * w.value(0.0f);
    for (const std::uint32_t j : ctx.neighbors.of(i))
        rho += p.mass[j] * w.value(glm::length(ctx.delta(xi, p.position[j] + dt * p.velocity[j])));
    float volume = 0.0f;
    for (const std::uint32_t b : ctx.boundaryNeighbors.of(i))
        volume += ctx.boundary.volume[b] * w.value(glm::length(ctx.delta(xi, ctx.boundary.position[b])));
    return rho + ctx.materials[p.material[i]].restDensity * volume;
}
}  // namespace

void DfsphBender2017::computeAlpha(StepContext& ctx) {
    ParticleStore& p = ctx.particles;
    const kernels::CubicSpline w(ctx.supportRadius);
    alpha_.resize(p.size());
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i];
        glm::vec3 fluidGrad(0.0f), boundaryGrad(0.0f);
        float sumSquares = 0.0f;
        for (const std::uint32_t j : ctx.neighbors.of(i)) {
            const glm::vec3 rij = ctx.delta(xi, p.position[j]);
            const glm::vec3 g = p.mass[j] * w.gradient(rij, glm::length(rij));
            fluidGrad += g;
            sumSquares += glm::dot(g, g);
        }
        const float rho0 = ctx.materials[p.material[i]].restDensity;
        for (const std::uint32_t b : ctx.boundaryNeighbors.of(i)) {
            const glm::vec3 rib = ctx.delta(xi, ctx.boundary.position[b]);
            boundaryGrad += (rho0 * ctx.boundary.volume[b]) * w.gradient(rib, glm::length(rib));
        }
        // ρ_i's response to its own κ_i: the boundary pushes with the mirrored pressure. The
        // product can dip below 0 where fluid and wall pull opposite ways; it is never a gain.
        const float ownTerm = glm::dot(fluidGrad + boundaryGrad, fluidGrad + sph::kBoundaryPressureMirror * boundaryGrad);
        const float denominator = std::max(ownTerm, 0.0f) + sumSquares;
        alpha_[i] = denominator > 1e-12f ? p.density[i] / denominator : 0.0f;
    });
}

void DfsphBender2017::applyPressure(StepContext& ctx, std::span<const float> boundaryK) {
    ParticleStore& p = ctx.particles;
    const kernels::CubicSpline w(ctx.supportRadius);
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i];
        const float ki = k_[i] / p.density[i];
        glm::vec3 dv(0.0f);
        for (const std::uint32_t j : ctx.neighbors.of(i)) {
            const glm::vec3 rij = ctx.delta(xi, p.position[j]);
            dv += (p.mass[j] * (ki + k_[j] / p.density[j])) * w.gradient(rij, glm::length(rij));
        }
        // Ψ_b (κ_i/ρ_i + κ_b/ρ_b) ∇W_ib with ρ_b = ρ_i; κ_b = κ_i when mirrored.
        const float psi = ctx.materials[p.material[i]].restDensity / p.density[i];
        for (const std::uint32_t b : ctx.boundaryNeighbors.of(i)) {
            const glm::vec3 rib = ctx.delta(xi, ctx.boundary.position[b]);
            const float kSum = k_[i] + (boundaryK.empty() ? k_[i] : boundaryK[b]);
            dv += (ctx.boundary.volume[b] * psi * kSum) * w.gradient(rib, glm::length(rib));
        }
        p.velocity[i] -= dv;
    });
}

double DfsphBender2017::meanRelativeSource(const StepContext& ctx) const {
    const ParticleStore& p = ctx.particles;
    double sum = 0.0;
    for (std::uint32_t i = 0; i < p.size(); ++i) sum += source_[i] / ctx.materials[p.material[i]].restDensity;
    return sum / std::max<double>(1.0, p.size());
}

int DfsphBender2017::solveDivergence(StepContext& ctx) {
    ParticleStore& p = ctx.particles;
    const auto n = p.size();
    const kernels::CubicSpline w(ctx.supportRadius);
    source_.resize(n);
    k_.resize(n);
    int iteration = 0;
    for (; iteration < ctx.solver.maxIterations; ++iteration) {
        parallelFor(n, ctx.threads, [&](std::uint32_t i) {
            const bool interior = ctx.neighbors.of(i).size() + ctx.boundaryNeighbors.of(i).size() >= kMinNeighborsForDivergence;
            source_[i] = interior ? std::max(densityRate(ctx, w, i), 0.0f) : 0.0f;  // only compression
        });
        // Mean relative compression rate, over the last step's length.
        if (iteration >= ctx.solver.minIterations && meanRelativeSource(ctx) * lastDt_ <= ctx.solver.maxDensityError)
            break;
        parallelFor(n, ctx.threads, [&](std::uint32_t i) {
            k_[i] = source_[i] * alpha_[i];  // κᵛ·Δt (eq. 15)
            divergenceK_[i] += k_[i];
        });
        applyPressure(ctx, {});
    }
    return iteration;
}

int DfsphBender2017::solveDensity(StepContext& ctx, float dt) {
    ParticleStore& p = ctx.particles;
    const auto n = p.size();
    const auto nb = static_cast<std::uint32_t>(ctx.boundary.position.size());
    const kernels::CubicSpline w(ctx.supportRadius);
    const float invDt2 = 1.0f / (dt * dt);
    std::vector<float>& kappa = kappa_;
    kappa.resize(n);
    source_.resize(n);
    residual_.resize(n);
    k_.resize(n);
    boundaryK_.resize(nb);
    boundaryKappa_.assign(nb, 0.0f);
    wall_.prepare(ctx.boundary, ctx.boundaryFluidNeighbors, p.position, ctx.periodic, ctx.gravity,
                  ctx.supportRadius, ctx.threads);
    // Applies the change of κ (fluid, then walls from it) as a velocity change.
    auto push = [&] {
        wall_.update(ctx.boundaryFluidNeighbors, p.position, ctx.boundary.position, ctx.periodic,
                     kappa, ctx.supportRadius, ctx.threads);
        const auto wallKappa = wall_.kappa();
        parallelFor(nb, ctx.threads, [&](std::uint32_t b) {
            boundaryK_[b] = (wallKappa[b] - boundaryKappa_[b]) * dt;
            boundaryKappa_[b] = wallKappa[b];
        });
        applyPressure(ctx, boundaryK_);
    };
    // Cold start. Bender & Koschier warm-start κ from the last step (§4.3); measured here, the
    // warm-started κ drifts within the tolerance band to 1.5–2 × ρgd in a tank at rest (an
    // over-pressured, slightly expanded state the mean-error test accepts), so every step
    // solves afresh. The walls' hydrostatic part (κ_b with κ = 0) is applied first.
    std::fill(kappa.begin(), kappa.end(), 0.0f);
    std::fill(k_.begin(), k_.end(), 0.0f);
    push();
    int iteration = 0;
    for (; iteration < ctx.solver.maxIterations; ++iteration) {
        parallelFor(n, ctx.threads, [&](std::uint32_t i) {
            const float rho0 = ctx.materials[p.material[i]].restDensity;
            residual_[i] = predictedDensity(ctx, w, i, dt) - rho0;  // ρ* − ρ0
            // Error left: compression anywhere, expansion only where pressure could still relax.
            source_[i] = kappa[i] > 0.0f ? std::abs(residual_[i]) : std::max(residual_[i], 0.0f);
        });
        if (iteration >= ctx.solver.minIterations && meanRelativeSource(ctx) <= kDensityTarget * ctx.solver.maxDensityError)
            break;
        // Projected Jacobi: κ stays ≥ 0 (no tension at the free surface) but may fall back
        // where the warm start pushed too hard.
        parallelFor(n, ctx.threads, [&](std::uint32_t i) {
            const float updated = std::max(kappa[i] + kRelaxation * residual_[i] * alpha_[i] * invDt2, 0.0f);  // eq. 12
            k_[i] = (updated - kappa[i]) * dt;
            kappa[i] = updated;
        });
        push();
    }
    return iteration;
}

double DfsphBender2017::step(StepContext& ctx) {
    ParticleStore& p = ctx.particles;
    const auto n = p.size();
    sph::computeDensities(ctx);
    computeAlpha(ctx);
    divergenceK_.assign(n, 0.0f);
    const int divergenceIterations = solveDivergence(ctx);

    sph::addGravityAndViscosity(ctx, accel_);
    const float nu = sph::maxKinematicViscosity(ctx);
    SolverDef limits = ctx.solver;
    // Explicit viscosity's limit, but never below the user's floor min_dt.
    if (nu > 0.0f)
        limits.maxDt = std::max(limits.minDt, std::min(limits.maxDt, 0.125f * ctx.particleSpacing * ctx.particleSpacing / nu));
    const double dt = cflTimeStep(limits, ctx.particleSpacing, sph::maxSpeed(ctx), ctx.maxDt);
    const auto dtf = static_cast<float>(dt);
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        p.acceleration[i] = accel_[i];
        p.velocity[i] += dtf * accel_[i];
    });
    // XSPH is a non-pressure force too: smoothing after the density solve would undo part of it.
    xsph_.apply(p, ctx.neighbors, ctx.periodic, ctx.supportRadius,
                ctx.solver.xsph >= 0.0f ? ctx.solver.xsph : 0.01f, ctx.threads);
    const int densityIterations = solveDensity(ctx, dtf);
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        p.position[i] += dtf * p.velocity[i];
        // The divergence solve's velocity change acts over this step.
        p.pressure[i] = p.density[i] * (kappa_[i] + divergenceK_[i] / dtf);  // p = ρκ: the equivalent SPH pressure
    });
    ctx.pressureIterations = divergenceIterations + densityIterations;
    lastDt_ = dt;
    return dt;
}

}  // namespace tide
