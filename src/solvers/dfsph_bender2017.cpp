#include "solvers/dfsph_bender2017.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/kernels.hpp"
#include "core/parallel.hpp"
#include "solvers/owned_sums.hpp"
#include "solvers/shifting_lind2012.hpp"
#include "solvers/sph_sums.hpp"
#include "solvers/time_step.hpp"

namespace tide {

namespace {
/// Particles with fewer neighbours sit at the free surface: their density deficit is
/// geometric, not compression, so the divergence solve leaves them alone (as SPlisHSPlasH
/// does: 20 in 3D, 7 in 2D). Counting the particle itself, a lattice site at the default
/// support has 27 neighbours in 3D and 9 in 2D, one on the top layer 18 and 6: both limits
/// leave out the top layer and keep the one below. With 3D's 20 in 2D no particle took part
/// and the divergence solve never acted (docs/notes/waves.md § The 2D divergence solve).
constexpr std::uint32_t minNeighborsForDivergence(int dimensions) { return dimensions == 2 ? 7 : 20; }
/// Jacobi weight of the density solve. Its pressure may fall as well as rise, and full
/// Jacobi steps on this system overshoot and diverge; IISPH (Ihmsen et al. 2014) uses 0.5.
/// Both solves' weights are for the default support; wider ones scale them (jacobi_weight.hpp).
constexpr float kRelaxation = 0.5f;
/// The density solve stops at this fraction of SolverDef::maxDensityError: what it checks is
/// the density predicted over this step's neighbour lists; the density reached also counts
/// pairs that come into range during the step (measured: up to 2 % more in a dam break).
constexpr double kDensityTarget = 0.9;
/// Fraction of the last step's κ the density solve starts from; SPlisHSPlasH halves it too.
/// The divergence solve's is SolverDef::divergenceWarmStart (the same half by default).
constexpr float kWarmStart = 0.5f;
/// Heavy-ball momentum of the density solve (Polyak 1964, "Some methods of speeding up the
/// convergence of iteration methods"): each Jacobi update adds this fraction of the last
/// one. Jacobi alone is slowest on smooth pressure fields (the half of a hydrostatic profile
/// the warm start leaves to rebuild); with 0.7 the 50k benchmark dam break takes 8.9
/// iterations per step instead of 15.5 at the same compression (0.045 %), and the 0.3 m
/// tank at rest 14 instead of 35 (0.8: 9.1 on the dam break; 0.5: 11.0). The price: a probe
/// in that tank reads a pressure that wanders 62 Pa (3 %) in time instead of 38 Pa; the
/// per-particle pressure noise (12 % RMS) and the speeds at rest are the same.
/// Off with a density contrast: there the Jacobi converges slowly at the stiff interfaces
/// and the momentum overshoots them (5000/1000/200 columns at 1 cm: a light particle's κ
/// ran away within 0.04 s; without it the drop settles).
constexpr float kMomentum = 0.7f;  // the default of SolverDef::momentum
}  // namespace

void DfsphBender2017::prepare(StepContext& ctx) {
    ParticleStore& p = ctx.particles;
    const auto n = p.size();
    const kernels::SmoothingKernel w = ctx.kernel();
    // Densities (Solenthaler & Pajarola 2008 with Akinci et al. 2012 walls, as
    // sph::computeDensities) and the gradient factors from one square root per pair.
    contrast_.prepare(p, ctx.materials, ctx.threads);
    // (x_j, m_j) for one rest density, (x_j, 1) with a density contrast, where i's own mass
    // multiplies the sums instead.
    const bool uniform = contrast_.uniform();
    positionMass_.resize(n);
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        positionMass_[i] = glm::vec4(p.position[i], uniform ? p.mass[i] : 1.0f);
    });
    // With a density contrast, (x_j, m_j) rows for α (computeAlpha) as well.
    if (!uniform) {
        mixedRows_.resize(n);
        parallelFor(n, ctx.threads, [&](std::uint32_t i) { mixedRows_[i] = glm::vec4(p.position[i], p.mass[i]); });
    }
    fluidF_.resize(ctx.neighbors, w);
    wallF_.resize(ctx.boundaryNeighbors, w);
    alpha_.resize(n);
    fluidGradient_.resize(n);
    const bool smooth = ctx.solver.smoothDensityError.value_or(false);
    if (smooth) fluidKernelSum_.resize(n);
    const float self = w.value(0.0f);
    withPairVector(ctx.periodic, [&](auto delta) {
        parallelFor(n, ctx.threads, [&](std::uint32_t i) {
            const glm::vec3 xi = p.position[i];
            // m_i δ_i: Σ_j m_j W_ij, or δ_i = Σ_j W_ij times m_i below
            // One rest density: α's fluid sums from the same pass (computeAlpha), kept meanwhile
            // in fluidGradient_ and alpha_.
            glm::vec4 sums(0.0f);
            float rho = pair_sums::kernelSumAndCodes(fluidPairs(ctx, i), positionMass_.data(), xi, w, ctx.periodic,
                                                     positionMass_[i].w * self, fluidF_, fluidF_.of(ctx.neighbors, i).data(),
                                                     pair_sums::Order::Lanes, uniform ? &sums : nullptr);
            if (uniform) {
                fluidGradient_[i] = fluidF_.unit() * glm::vec3(sums);
                alpha_[i] = fluidF_.unit() * fluidF_.unit() * sums.w;
            }
            float volume = 0.0f;
            PairKernels::Code* f = wallF_.of(ctx.boundaryNeighbors, i).data();
            for (const std::uint32_t b : ctx.boundaryNeighbors.of(i)) {
                const glm::vec3 d = delta(xi, ctx.boundary.position[b]);
                const float r = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
                volume += ctx.boundary.volume * w.value(r);
                *f++ = wallF_.encode(w, r);
            }
            if (smooth) fluidKernelSum_[i] = uniform ? rho / positionMass_[i].w : rho;
            if (!uniform) rho *= p.mass[i];  // ρ_i = m_i δ_i
            p.density[i] = rho + ctx.materials[p.material[i]].restDensity * volume;
        });
    });
}

void DfsphBender2017::computeAlpha(StepContext& ctx) {
    ParticleStore& p = ctx.particles;
    const auto n = p.size();
    wallGradient_.resize(n);  // alpha_ and fluidGradient_: sized in prepare
    if (ctx.boundary.moving) wallVelocityRate_.resize(n);
    const bool uniform = contrast_.uniform();
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i];
        // Density contrast: ρ_i = m_i Σ_j W_ij, and j answers i's κ_i with Δv_j = Δt κ_i (m_i/m_j) (m_i/ρ_i) ∇W_ij,
        // so the own term takes m_i Σ_j ∇W_ij and the neighbours' Σ_j (m_i³/m_j) |∇W_ij|²
        // (with one mass: Σ_j m_j ∇W_ij and Σ_j |m_j ∇W_ij|², eq. 11).
        const float mi = p.mass[i];
        glm::vec3 fluidGrad(0.0f), wallGrad(0.0f);
        float sumSquares = 0.0f;
        if (uniform) {  // summed in prepare's pass, in SIMD lanes over the (x_j, m_j) rows (m_j = m_i)
            fluidGrad = fluidGradient_[i];
            sumSquares = alpha_[i];
        } else {
            // The exact factor is m_i/m_j; for a light i among heavy j it makes i's diagonal
            // tiny next to the terms through its light neighbours, and the Jacobi iteration
            // diverges (a 25:1 column drop went to NaN within 0.1 s, measured). Capping it
            // below at 1 under-relaxes exactly those rows; one mass gives 1 either way.
            // In SIMD lanes over the (x_j, m_j) rows prepare() packed.
            const glm::vec4 sums = pair_sums::cappedGradientSquares(fluidPairs(ctx, i), mixedRows_.data(), xi, mi, ctx.periodic);
            const float unit = mi * fluidF_.unit();
            fluidGrad = unit * glm::vec3(sums);
            sumSquares = unit * unit * sums.w;
        }
        const PairKernels::Code* f = wallF_.of(ctx.boundaryNeighbors, i).data();
        float wallRate = 0.0f;
        for (const std::uint32_t b : ctx.boundaryNeighbors.of(i)) {
            const glm::vec3 g = (ctx.boundary.volume * wallF_.factor(*f++)) * ctx.delta(xi, ctx.boundary.position[b]);
            wallGrad += g;
            if (ctx.boundary.moving) wallRate += glm::dot(ctx.boundary.velocity[b], g);
        }
        if (ctx.boundary.moving) wallVelocityRate_[i] = wallRate;
        fluidGradient_[i] = fluidGrad;
        wallGradient_[i] = wallGrad;
        const glm::vec3 boundaryGrad = ctx.materials[p.material[i]].restDensity * wallGrad;
        // ρ_i's response to its own κ_i: the boundary pushes with the mirrored pressure. The
        // product can dip below 0 where fluid and wall pull opposite ways; it is never a gain.
        const float ownTerm = glm::dot(fluidGrad + boundaryGrad, fluidGrad + sph::kBoundaryPressureMirror * boundaryGrad);
        const float denominator = std::max(ownTerm, 0.0f) + sumSquares;
        alpha_[i] = denominator > 1e-12f ? p.density[i] / denominator : 0.0f;
    });
}

// The iterations' fluid pair sums run in SIMD lanes (solvers/pair_sums.hpp); the wall
// loops, which only particles near walls take, stay scalar.

float DfsphBender2017::densityRate(const StepContext& ctx, std::uint32_t i) const {
    const ParticleStore& p = ctx.particles;
    const glm::vec3 xi = p.position[i];
    const glm::vec3 vi = p.velocity[i];
    // Σ_j m_j (v_i − v_j)·∇W_ij, in units of PairKernels::unit()
    float rate = fluidF_.unit() * pair_sums::divergenceSum(fluidPairs(ctx, i), positionMass_.data(), positionK_.data(),
                                                          xi, vi, ctx.periodic);
    if (!contrast_.uniform()) rate *= p.mass[i];  // m_i Σ_j v_ij·∇W_ij: Dρ_i/Dt of ρ_i = m_i δ_i
    // Walls: Σ_b Ψ_b (v_i − v_b)·∇W_ib, the v_b part kept from computeAlpha.
    const float wall = ctx.boundary.moving ? glm::dot(vi, wallGradient_[i]) - wallVelocityRate_[i]
                                           : glm::dot(vi, wallGradient_[i]);
    return rate + ctx.materials[p.material[i]].restDensity * wall;
}

template <class PairVector>
float DfsphBender2017::predictedDensity(const StepContext& ctx, PairVector delta, const kernels::SmoothingKernel& w,
                                        std::uint32_t i) const {
    const glm::vec3 xi(positionK_[i]);
    float rho = pair_sums::kernelSum(fluidPairs(ctx, i), positionK_.data(), xi, w, ctx.periodic,
                                     positionK_[i].w * w.value(0.0f));
    if (!contrast_.uniform()) rho *= ctx.particles.mass[i];  // m_i δ*_i
    float volume = 0.0f;
    const glm::vec3* wallX = ctx.boundary.moving ? wallMoved_.data() : ctx.boundary.position.data();
    for (const std::uint32_t b : ctx.boundaryNeighbors.of(i)) {
        const glm::vec3 r = delta(xi, wallX[b]);
        volume += ctx.boundary.volume * w.value(std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z));
    }
    return rho + ctx.materials[ctx.particles.material[i]].restDensity * volume;
}

void DfsphBender2017::applyPressure(StepContext& ctx, std::span<const float> boundaryK) {
    ParticleStore& p = ctx.particles;
    const auto n = p.size();
    // j's part of every pair term, m_j² k_j/ρ_j (÷ m_i below: density contrast), packed with
    // x_j: one load per neighbour.
    const bool uniform = contrast_.uniform();
    parallelFor(n, ctx.threads, [&](std::uint32_t j) {
        const float part = p.mass[j] * k_[j] / p.density[j];
        positionK_[j] = glm::vec4(p.position[j], uniform ? part : p.mass[j] * part);
    });
    withPairVector(ctx.periodic, [&](auto delta) {
        parallelFor(n, ctx.threads, [&](std::uint32_t i) {
            const glm::vec3 xi = p.position[i];
            // Σ_j (k_i m_i/ρ_i + k_j (m_j/m_i) m_j/ρ_j) ∇W_ij = (k_i/ρ_i) m_i Σ_j ∇W_ij + (1/m_i) Σ_j (m_j² k_j/ρ_j) ∇W_ij
            const float unit = uniform ? fluidF_.unit() : fluidF_.unit() / p.mass[i];
            const glm::vec3 sum = unit * pair_sums::gradientSum(fluidPairs(ctx, i), positionK_.data(), xi, ctx.periodic);
            const glm::vec3 dv = (k_[i] / p.density[i]) * fluidGradient_[i] + sum;
            // Σ_b Ψ_b (κ_i/ρ_i + κ_b/ρ_b) ∇W_ib with Ψ_b = ρ0 V_b, ρ_b = ρ_i; κ_b = κ_i when mirrored.
            const float psi = ctx.materials[p.material[i]].restDensity / p.density[i];
            glm::vec3 wall = k_[i] * wallGradient_[i];
            if (boundaryK.empty()) {
                wall *= 2.0f;
            } else {
                const auto walls = ctx.boundaryNeighbors.of(i);
                const PairKernels::Code* fb = wallF_.of(ctx.boundaryNeighbors, i).data();
                glm::vec3 pushed = uniform ? wall : glm::vec3(0.0f);
                // x_b and V_b k_b read from the boundary's arrays, not packed per step: only
                // particles near walls take this loop, and a packed copy cost 16 bytes a
                // boundary particle (~25 a fluid particle at 205k).
                for (std::size_t k = 0; k < walls.size(); ++k) {
                    const std::uint32_t b = walls[k];
                    const float volumeK = ctx.boundary.volume * boundaryK[b];
                    pushed += (volumeK * wallF_.factor(fb[k])) * delta(xi, ctx.boundary.position[b]);
                }
                // k̃_b is p_b/ρ0_ref (density contrast): fluid i reads k_b = k̃_b ρ0_ref/ρ0_i.
                wall = uniform ? pushed : wall + pushed / contrast_.scale(i);
            }
            p.velocity[i] -= dv + psi * wall;
            if (ctx.loads) loadK_[i] += k_[i];
        });
    });
    if (ctx.loads && !boundaryK.empty())
        parallelFor(static_cast<std::uint32_t>(boundaryK.size()), ctx.threads,
                    [&](std::uint32_t b) { loadBoundaryK_[b] += boundaryK[b]; });
}

void DfsphBender2017::startWallImpulses(const StepContext& ctx, bool walls) {
    if (!ctx.loads) return;
    loadK_.assign(ctx.particles.size(), 0.0f);
    if (walls) loadBoundaryK_.assign(ctx.boundary.position.size(), 0.0f);
}

void DfsphBender2017::recordWallImpulses(StepContext& ctx, bool mirrored) const {
    if (!ctx.loads) return;
    // Pair b's share of the solve's wall terms, psi (k_i + k_b) g_ib with g_ib = V_b ∇W_ib
    // (k_b = k_i mirrored; read through the density contrast's scale), as the impulse on i.
    // Positions, densities and so g_ib and psi hold over a solve, so its pushes' k sum first.
    const ParticleStore& p = ctx.particles;
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        const auto walls = ctx.boundaryNeighbors.of(i);
        if (walls.empty()) return;
        const glm::vec3 xi = p.position[i];
        const PairKernels::Code* f = wallF_.of(ctx.boundaryNeighbors, i).data();
        glm::vec3* impulse = ctx.loads->pressureImpulse.data() + ctx.boundaryNeighbors.offset(i);
        const float toImpulse = -p.mass[i] * ctx.materials[p.material[i]].restDensity / p.density[i];
        const float scale = contrast_.uniform() ? 1.0f : 1.0f / contrast_.scale(i);
        for (std::size_t k = 0; k < walls.size(); ++k) {
            const std::uint32_t b = walls[k];
            const glm::vec3 g = (ctx.boundary.volume * wallF_.factor(f[k])) * ctx.delta(xi, ctx.boundary.position[b]);
            const float kb = mirrored ? loadK_[i] : scale * loadBoundaryK_[b];
            impulse[k] += (toImpulse * (loadK_[i] + kb)) * g;
        }
    });
}

double DfsphBender2017::meanRelativeError(const StepContext& ctx, Solve solve) const {
    const ParticleStore& p = ctx.particles;
    if (!contrast_.uniform()) return owned_sums::worstMaterialMean(ctx, [&](std::uint32_t i) { return errorLeft(i, solve); });
    return owned_sums::mean(ctx, [&](std::uint32_t i) { return errorLeft(i, solve) / ctx.materials[p.material[i]].restDensity; });
}

int DfsphBender2017::solveDivergence(StepContext& ctx) {
    ParticleStore& p = ctx.particles;
    const auto n = p.size();
    error_.resize(n);
    k_.resize(n);
    // p.warmDivergence sums κᵛ·Δt over this solve from here on (the pressure output and the
    // next warm start): no array of its own.
    const float warmStart = ctx.solver.divergenceWarmStart;
    startWallImpulses(ctx, false);
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        k_[i] = warmStart * p.warmDivergence[i];
        p.warmDivergence[i] = k_[i];
    });
    // Applies k_, then packs the velocities as (v_j, 1/ρ_j) rows, (v_j, m_j/ρ_j) with several rest
    // densities, into positionK_ (free until the next applyPressure) for densityRate's SIMD
    // loads, and the viscosity's after the solve. Without a warm start there is nothing to
    // apply first: a pair pass less a step (SolverDef::divergenceWarmStart).
    const bool uniform = contrast_.uniform();
    auto push = [&](bool apply) {
        if (apply) {
            applyPressure(ctx, {});
            ctx.refreshGhosts(std::span<glm::vec3>(p.velocity));
        }
        parallelFor(n, ctx.threads, [&](std::uint32_t i) {
            positionK_[i] = glm::vec4(p.velocity[i], (uniform ? 1.0f : p.mass[i]) / p.density[i]);
        });
    };
    push(warmStart > 0.0f);
    const int minimum = ctx.solver.minDivergenceIterations >= 0 ? ctx.solver.minDivergenceIterations : ctx.solver.minIterations;
    const double tolerance = ctx.solver.maxDivergenceError >= 0.0f ? ctx.solver.maxDivergenceError : ctx.solver.maxDensityError;
    const std::uint32_t minNeighbors = minNeighborsForDivergence(ctx.dimensions);
    int iteration = 0;
    for (; iteration < ctx.solver.maxIterations; ++iteration) {
        parallelFor(n, ctx.threads, [&](std::uint32_t i) {
            const bool interior = ctx.neighbors.of(i).size() + ctx.boundaryNeighbors.of(i).size() >= minNeighbors;
            error_[i] = interior ? std::max(densityRate(ctx, i), 0.0f) : 0.0f;  // only compression
        });
        // Mean relative compression rate, over the last step's length.
        if (iteration >= minimum &&
            meanRelativeError(ctx, Solve::Divergence) * lastDt_ <= tolerance)
            break;
        // Full Jacobi steps, as the paper takes, for one rest density; with a density contrast
        // the light particles' rows are far from diagonally dominant and full steps diverge.
        const float weight = (contrast_.uniform() ? 1.0f : kRelaxation) * weightScale_(ctx.supportRadius / ctx.particleSpacing, ctx.solver.kernel, ctx.dimensions);
        parallelFor(n, ctx.threads, [&](std::uint32_t i) {
            k_[i] = weight * error_[i] * alpha_[i];  // κᵛ·Δt (eq. 15)
            p.warmDivergence[i] += k_[i];
        });
        ctx.refreshGhosts(k_);  // a ghost's error and α miss neighbours
        push(true);
    }
    recordWallImpulses(ctx, true);
    return iteration;
}

int DfsphBender2017::solveDensity(StepContext& ctx, float dt, float driftTime) {
    ParticleStore& p = ctx.particles;
    const auto n = p.size();
    const auto nb = static_cast<std::uint32_t>(ctx.boundary.position.size());
    const kernels::SmoothingKernel w = ctx.kernel();
    const float invDt2 = 1.0f / (dt * dt);
    std::vector<float>& kappa = kappa_;
    kappa.resize(n);
    error_.resize(n);
    k_.resize(n);
    boundaryK_.resize(nb);
    wall_.prepare(ctx.boundary, ctx.boundaryFluidNeighbors, ctx.boundaryNearFluid, p.position, ctx.periodic, ctx.gravity,
                  ctx.kernel(), ctx.threads, contrast_.scale());
    // Moving walls are where they will be at the end of the step when the predicted densities are.
    if (ctx.boundary.moving) {
        wallMoved_.resize(nb);
        parallelFor(nb, ctx.threads, [&](std::uint32_t b) {
            wallMoved_[b] = ctx.boundary.position[b] + dt * ctx.boundary.velocity[b];
        });
    }
    startWallImpulses(ctx, true);  // recorded by step(), once the step is kept
    // Applies the change of κ (fluid, then walls from it) as a velocity change.
    auto push = [&] {
        wall_.update(ctx.boundaryFluidNeighbors, contrast_.wallKappa(kappa, scaledKappa_, ctx.threads), ctx.threads, dt,
                     boundaryK_);
        applyPressure(ctx, boundaryK_);
        ctx.refreshGhosts(std::span<glm::vec3>(p.velocity));  // a ghost misses part of the wall's κ
    };
    // Warm start (§4.3) with half of the last step's κ: the full κ drifts within the
    // tolerance band (the mean-error test accepts an over-pressured, slightly expanded tank)
    // to 1.1 × ρgd and agitates a tank at rest (max speed 0.37 m/s, tests/
    // test_incompressible_solvers.cpp); half keeps it within 1.5 % of ρgd and takes 15
    // iterations per step on the benchmark dam break instead of 38 cold.
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        kappa[i] = kWarmStart * p.warmKappa[i];
        k_[i] = kappa[i] * dt;
    });
    push();
    const float heavyBall = ctx.solver.momentum >= 0.0f ? ctx.solver.momentum : kMomentum;
    const float relaxation = kRelaxation * weightScale_(ctx.supportRadius / ctx.particleSpacing, ctx.solver.kernel, ctx.dimensions);
    // A step the free-fall limit or a short max_dt shortened removes the compression the
    // particles already have (ρ_i − ρ0, what earlier solves left within their tolerance) over
    // the step it would otherwise have taken, not within dt (Baumgarte 1972, "Stabilization of constraints and
    // integrals of motion in dynamical systems", time constant driftTime): removing it within
    // a shorter step takes a velocity ∝ 1/dt that the next step keeps. Measured in a thin box
    // of still water at 1 cm (0.1 m deep, 2 s): 5 ms steps keep an RMS speed of 0.03 m/s,
    // 3.6 ms steps without this 0.07. The target is lowered by the same factor so that the
    // compression kept still ends within the tolerance. Unshortened steps keep nothing.
    const float keep = dt < driftTime ? 1.0f - dt / driftTime : 0.0f;
    const double target = kDensityTarget * ctx.solver.maxDensityError * (1.0 - keep);
    int iteration = 0;
    bool converged = false;
    densityDiverged_ = false;
    double initialError = 0.0;
    bool linearised = false;  // ρ*_i = ρ_i + Δt Dρ_i/Dt instead of the density at x + Δt v
    const bool smoothResidual = ctx.solver.smoothDensityError.value_or(false);
    for (; iteration < ctx.solver.maxIterations; ++iteration) {
        if (linearised) {
            // positionK_ holds the (v_j, 1/ρ_j) rows densityRate reads until push() packs the next κ change.
            parallelFor(n, ctx.threads, [&](std::uint32_t i) { positionK_[i] = glm::vec4(p.velocity[i], 1.0f / p.density[i]); });
            parallelFor(n, ctx.threads, [&](std::uint32_t i) {
                const float rho0 = ctx.materials[p.material[i]].restDensity;
                error_[i] = p.density[i] + dt * densityRate(ctx, i) - rho0 - keep * std::max(p.density[i] - rho0, 0.0f);
            });
        } else {
            parallelFor(n, ctx.threads, [&](std::uint32_t i) {
                // positionK_ holds the predicted positions until push() packs the next κ change.
                positionK_[i] = glm::vec4(p.position[i] + dt * p.velocity[i], positionMass_[i].w);
            });
            withPairVector(ctx.periodic, [&](auto delta) {
                parallelFor(n, ctx.threads, [&](std::uint32_t i) {
                    const float rho0 = ctx.materials[p.material[i]].restDensity;
                    // ρ* − ρ0, less the compression left to later steps
                    error_[i] = predictedDensity(ctx, delta, w, i) - rho0 - keep * std::max(p.density[i] - rho0, 0.0f);
                });
            });
        }
        if (smoothResidual) smoothDensityError(ctx);
        const double error = meanRelativeError(ctx, Solve::Density);
        converged = error <= target;
        if (converged && iteration >= ctx.solver.minIterations) break;
        // Diverging (retaken shorter): the error doubled from where it started or from the
        // target, whichever is larger (min_iterations may stir a solve that started converged).
        if (iteration == 0) initialError = std::max(error, target);
        else if (!converged && error > 2.0 * initialError && !contrast_.uniform()) {
            densityDiverged_ = true;
            break;
        } else if (!converged && error > 2.0 * initialError && !linearised) {
            // The Jacobi iteration on the densities at the predicted positions has an unstable
            // particle-scale mode in deep water at a loose tolerance (0.6 m at 2 cm and 0.3 %:
            // the mean error grew from 0.38 % to 6 % within 75 iterations, worst particles
            // through the bulk, and the tank blew up at 0.075 s; docs/robustness.md). The
            // paper's prediction, linear in v (Bender & Koschier 2017, eq. 9), holds it: the
            // rest of such a solve takes that. No solve in the shipped scenes' first second gets here.
            linearised = true;
        }
        // Projected Jacobi with momentum: κ stays ≥ 0 (no tension at the free surface) but may
        // fall back where the warm start pushed too hard; k_ still holds the last change (× Δt).
        // None in the iterations min_iterations adds to a solve already within its target: there
        // it overshoots the residual's noise, and step after step the overshoot grew (water at
        // rest in a closed box without gravity went from round-off to 0.1 m/s within 1 s).
        const float momentum = iteration > 0 && contrast_.uniform() && !converged ? heavyBall / dt : 0.0f;
        parallelFor(n, ctx.threads, [&](std::uint32_t i) {
            const float updated =
                std::max(kappa[i] + relaxation * error_[i] * alpha_[i] * invDt2 + momentum * k_[i], 0.0f);  // eq. 12
            k_[i] = (updated - kappa[i]) * dt;
            kappa[i] = updated;
        });
        ctx.refreshGhosts(k_);  // a ghost's error and α miss neighbours
        ctx.refreshGhosts(kappa);
        push();
    }
    densityConverged_ = converged;
    return iteration;
}

// A Shepard (1968) filter of the residual: the solve then corrects the compression's smooth
// part and leaves the particle-scale part a wave's strain makes in the packing to shifting
// (SolverDef::smoothDensityError; docs/notes/waves.md § Smoothing the density solve's residual).
void DfsphBender2017::smoothDensityError(StepContext& ctx) {
    const ParticleStore& p = ctx.particles;
    const auto n = p.size();
    const kernels::SmoothingKernel w = ctx.kernel();
    const float self = w.value(0.0f);
    ctx.refreshGhosts(error_);  // a ghost's error misses neighbours
    smoothedError_.resize(n);
    // (x_j, e_j) rows at the step's positions, where fluidKernelSum_ was summed.
    parallelFor(n, ctx.threads, [&](std::uint32_t j) { positionK_[j] = glm::vec4(p.position[j], error_[j]); });
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        const float sum = pair_sums::kernelSum(fluidPairs(ctx, i), positionK_.data(), p.position[i], w, ctx.periodic,
                                               error_[i] * self);
        smoothedError_[i] = sum / fluidKernelSum_[i];
    });
    error_.swap(smoothedError_);
}

void DfsphBender2017::smoothKappa(StepContext& ctx) {
    const ParticleStore& p = ctx.particles;
    const auto n = p.size();
    const kernels::SmoothingKernel w = ctx.kernel();
    const float self = w.value(0.0f);
    error_.resize(n);
    // Weights m_j W_ij (W_ij with several rest densities, as positionMass_ holds): the SIMD
    // kernel sums over (x_j, m_j κ_j) rows, packed into positionK_ (free after the solve), and
    // over positionMass_.
    parallelFor(n, ctx.threads, [&](std::uint32_t j) { positionK_[j] = glm::vec4(p.position[j], positionMass_[j].w * kappa_[j]); });
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i];
        const float sum = pair_sums::kernelSum(fluidPairs(ctx, i), positionK_.data(), xi, w, ctx.periodic, positionK_[i].w * self);
        const float weights = pair_sums::kernelSum(fluidPairs(ctx, i), positionMass_.data(), xi, w, ctx.periodic,
                                                   positionMass_[i].w * self);
        error_[i] = sum / weights;
    });
}

double DfsphBender2017::step(StepContext& ctx) {
    ParticleStore& p = ctx.particles;
    const auto n = p.size();
    prepare(ctx);  // sets contrast_
    ctx.refreshGhosts(std::span<float>(p.density));  // α, the forces and the solves read neighbours' densities
    const bool uniform = contrast_.uniform();
    positionK_.resize(n);
    computeAlpha(ctx);
    ctx.lap(Phase::Density);
    const int divergenceIterations = solveDivergence(ctx);
    ctx.lap(Phase::PressureSolve);

    // Straight into the particles' acceleration, which the step reports: no copy of it kept.
    // The divergence solve left (v_j, 1/ρ_j) in positionK_ for one rest density, next to the
    // (x_j, m_j) rows; with several, (v_j, m_j/ρ_j), next to (x_j, μ_j) rows packed here.
    if (uniform) {
        ctx.positionMassRows = positionMass_.data();
    } else {
        parallelFor(n, ctx.threads, [&](std::uint32_t i) { mixedRows_[i].w = ctx.materials[p.material[i]].viscosity; });
        ctx.viscosityRows = mixedRows_.data();
    }
    ctx.velocityRows = positionK_.data();
    const float tensionAccel = sph::addNonPressureForces(ctx, p.acceleration);
    ctx.positionMassRows = ctx.velocityRows = ctx.viscosityRows = nullptr;
    // XSPH's (x_j, m_j) rows with several rest densities (positionMass_ holds (x_j, 1) then).
    if (!uniform) parallelFor(n, ctx.threads, [&](std::uint32_t i) { mixedRows_[i].w = p.mass[i]; });
    ctx.lap(Phase::NonPressureForces);
    // The step limits from a given max_dt: explicit forces, a density contrast, pressure speed.
    const float pressureSpeed = sph::pressureSpeedStep(ctx);
    auto limitsFrom = [&](SolverDef base) {
        SolverDef limits = sph::explicitForceLimits(ctx, base, tensionAccel);
        if (!uniform)
            limits.maxDt = std::min(limits.maxDt, DensityContrast::timeStepLimit(ctx.materials, glm::length(ctx.gravity),
                                                                                  ctx.particleSpacing, ctx.solver.forceNumber));
        limits.maxDt = std::max(limits.minDt, std::min(limits.maxDt, pressureSpeed));
        return limits;
    };
    SolverDef limits = limitsFrom(ctx.solver);
    sph::limitFreeFall(ctx, limits);
    // The drift time (solveDensity) is the step the solver would take without the free-fall
    // limit and with a max_dt of at least the default: a user's shorter max_dt must not
    // remove the compression earlier solves left within 1/Δt either. Measured in the 0.3 m
    // tank at 2 cm, settled: max_dt 1 ms kept a max speed of 0.44–0.51 m/s (RMS 0.13; 5 ms
    // steps: 0.05–0.09, RMS 0.015), with this 0.05–0.07 (RMS 0.014) at 6 iterations a step.
    SolverDef driftBase = ctx.solver;
    driftBase.maxDt = std::max(driftBase.maxDt, SolverDef{}.maxDt);
    const SolverDef driftLimits = limitsFrom(driftBase);
    const float speed = sph::maxSpeed(ctx);
    // With a density contrast a density solve that diverges (its error doubles) is taken
    // again at half the step, as pcisph does (Ihmsen et al. 2010); the cap grows back by a
    // quarter per good step. (One that only runs out of iterations is kept: at a shorter
    // step it needs as many, measured in a Rayleigh–Taylor box.) Measured: a 5:1 column drop in a thin box (two layers
    // between walls) ran into a diverging solve at 0.1 s without it. One rest density: one try.
    // The retaken step keeps the drift time of the uncapped one: shortened with it, the
    // compression already there had to go within the shorter step, with velocities ∝ 1/Δt,
    // and retakes down to min_dt made 70 m/s out of still layers in one step (alternating
    // 1 cm layers of 1000 and 200 kg/m³ diverged at 5 ms; Multifluid.DfsphThinAlternatingLayersHold).
    if (!uniform) savedVelocity_ = p.velocity;
    double dt = 0.0, driftTime = 0.0;
    int densityIterations = 0;
    for (;;) {
        SolverDef capped = limits;
        if (!uniform) capped.maxDt = std::max(limits.minDt, std::min(static_cast<float>(dtCap_), limits.maxDt));
        dt = cflTimeStep(capped, ctx.particleSpacing, speed, ctx.maxDt);
        // Not landed on the frame: a frame's last step would otherwise remove all the compression
        // kept (at 1 ms max_dt the pressure written at frame ends read 1.22 ρgd, 1.0 between).
        driftTime = std::max(dt, cflTimeStep(driftLimits, ctx.particleSpacing, speed, std::numeric_limits<double>::infinity()));
        const auto dtTry = static_cast<float>(dt);
        parallelFor(n, ctx.threads, [&](std::uint32_t i) {
            p.velocity[i] += dtTry * p.acceleration[i];
        });
        // XSPH is a non-pressure force too: smoothing after the density solve would undo part of it.
        ctx.lap(Phase::Integration);
        // positionK_ is free until the density solve predicts positions into it.
        // In SIMD lanes over the (x_j, m_j) rows.
        xsph_.apply(p, ctx.neighbors, ctx.periodic, ctx.poly6(),
                    ctx.solver.xsph >= 0.0f ? ctx.solver.xsph : 0.01f, ctx.threads, positionK_,
                    uniform ? positionMass_.data() : mixedRows_.data());
        ctx.refreshGhosts(std::span<glm::vec3>(p.velocity));
        ctx.lap(Phase::NonPressureForces);
        densityIterations += solveDensity(ctx, dtTry, static_cast<float>(driftTime));
        ctx.lap(Phase::PressureSolve);
        if (uniform || !densityDiverged_ || dt <= limits.minDt) break;
        dtCap_ = 0.5 * dt;
        p.velocity = savedVelocity_;
    }
    recordWallImpulses(ctx, false);  // the density solve kept, not one taken again shorter
    if (!uniform && !densityDiverged_) dtCap_ = std::min(1.25 * dtCap_, static_cast<double>(limits.maxDt));
    const auto dtf = static_cast<float>(dt);
    // The pressure reported is κ averaged over this step and the last, weighted by their
    // lengths: the momentum of the density solve leaves κ zigzagging from step to step (±15 %
    // at the bottom of the 0.3 m tank at rest at 2 cm) about an average that holds the water
    // up, and output written every few steps sampled the zigzag's same side (a probe read
    // 1.25 ρgd with 4.4 ms steps and 25 ms frames; the two-step average 0.97–1.05).
    // Steps shorter than the drift time (a short max_dt, the free-fall limit) share out the
    // compression they remove over several steps, and κ then cycles over as many: in the
    // 0.24 m tank at rest with 1 ms steps (drift time 5 ms) the pressure written every 25th
    // step read 0.91 ρgd at every depth while its mean over all steps was 1.00. There the
    // pressure reported is a running mean over the drift time (weight Δt/drift time: 0.2), so
    // frames read it wherever they fall in the cycle; steps of the drift time report their own
    // (a step shortened to land on a frame mixes in the last report by the same weight).
    const float lastWeight = static_cast<float>(lastDt_ / (lastDt_ + dt)), weight = 1.0f - lastWeight;
    const float smoothing = static_cast<float>(std::min(1.0, dt / driftTime));
    // ∇C_i = Σ_j V_j ∇W_ij from this step's gradient sums (Σ_j m_j ∇W_ij, or m_i Σ_j ∇W_ij
    // with several rest densities: every particle fills one lattice volume) over ρ_i.
    const FickianShifting shifting(ctx.solver.shifting, ctx.particleSpacing, ctx.supportRadius, ctx.dimensions);
    const float differenceShare = ctx.solver.differenceForm;
    if (differenceShare > 0.0f) smoothKappa(ctx);  // into error_, free after the solve
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        if (differenceShare > 0.0f) {
            // i's own term is −(κ_i/ρ_i)(G_f + ρ0 G_b) in the symmetric form and +(κ_i/ρ_i)(…) in
            // the difference form: the share of their difference, on κ̄.
            const glm::vec3 ownGradient = fluidGradient_[i] + ctx.materials[p.material[i]].restDensity * wallGradient_[i];
            p.velocity[i] += (differenceShare * dtf * 2.0f * error_[i] / p.density[i]) * ownGradient;
        }
        p.position[i] += dtf * p.velocity[i];
        if (shifting.shifts(ctx.neighbors.of(i).size(), ctx.boundaryNeighbors.of(i).size()))
            p.position[i] += shifting.displacement(fluidGradient_[i] / p.density[i]);
        const float meanKappa = weight * kappa_[i] + lastWeight * p.warmKappa[i];
        p.warmKappa[i] = kappa_[i];
        // The divergence solve's velocity change (its κᵛ·Δt summed in warmDivergence) acts over this step.
        const float pressure = p.density[i] * (meanKappa + p.warmDivergence[i] / dtf);  // p = ρκ: the equivalent SPH pressure
        p.pressure[i] = smoothing < 1.0f ? p.pressure[i] + smoothing * (pressure - p.pressure[i]) : pressure;
    });
    ctx.pressureIterations = divergenceIterations + densityIterations;
    ctx.divergenceIterations = divergenceIterations;
    ctx.pressureConverged = densityConverged_;
    lastDt_ = dt;
    return dt;
}

}  // namespace tide
