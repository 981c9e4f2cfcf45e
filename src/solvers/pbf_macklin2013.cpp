#include "solvers/pbf_macklin2013.hpp"

#include <algorithm>
#include <span>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/parallel.hpp"
#include "core/scratch_resize.hpp"
#include "solvers/pair_sums.hpp"
#include "solvers/pbf_pair_sums.hpp"

namespace tide {

namespace {
/// eq. 13's artificial pressure: k (in units of h²), n and Δq/h as the paper recommends.
constexpr float kTensileK = 0.1f;
constexpr float kTensileDq = 0.2f;
/// ε of eq. 11 as a fraction of a full neighbourhood's denominator: it softens the
/// constraints of particles with few neighbours (splashes), where the denominator is small
/// and λ would otherwise throw them apart, and damps the Jacobi iteration's particle-scale
/// jitter. Measured in a 0.2 m tank at rest at 2 cm, 4 iterations, max speed over 1.5–2 s:
/// 0.01: 0.04–0.10 m/s, 0.1: 0.026–0.048, 0.3: 0.021–0.047 (mean compression 0.6, 0.7, 0.8 %).
constexpr float kRelaxation = 0.1f;
/// XSPH's c when SolverDef::xsph is negative: more than the paper's 0.01, which leaves the
/// particle-scale jitter of 4 iterations. A 0.2 m tank at rest at 2 cm, max speed over its
/// 1.5–2 s: 0.03–0.056 m/s with 0.05, 0.035–0.061 with 0.1, 0.013–0.034 with 0.2.
constexpr float kDefaultXsph = 0.2f;
/// Longest correction a particle takes in one iteration, in supports h. Jacobi corrections
/// beyond it are the linearisation failing (a spray particle driven onto a wall, a light
/// particle squeezed between heavy ones, which ~30 neighbours' constraints each move as if
/// alone), and taken whole they flung particles out faster than they came: the seed's tank
/// (16,000 particles at 2.5 cm, 8.3 ms steps) ran away to 30 m/s within 0.7 s without a cap,
/// 7 m/s spray with 0.2 h, 3–4 m/s (the dam break's own speeds) with 0.1 h.
constexpr float kMaxCorrection = 0.1f;
/// Particles a pass hands the pair loops at a time (pbf_pair_sums.hpp).
constexpr std::uint32_t kBlock = 64;
}  // namespace

float PbfMacklin2013::relaxation(const StepContext& ctx) {
    if (latticeKey_[0] != ctx.supportRadius || latticeKey_[1] != ctx.particleSpacing) {
        // V = 1/Σ W over the rest lattice; Σ_j |∇_j C_i|² = V² Σ_j |∇W_ij|² there (Σ_j ∇W_ij = 0).
        const kernels::SmoothingKernel w = ctx.kernel();
        const kernels::Spiky spiky(ctx.supportRadius, ctx.dimensions);
        const float s = ctx.particleSpacing;
        const int reach = static_cast<int>(std::ceil(ctx.supportRadius / s));
        double sumW = 0.0, sumSquares = 0.0;
        for (int z = -reach; z <= reach; ++z)
            for (int y = -reach; y <= reach; ++y)
                for (int x = -reach; x <= reach; ++x) {
                    const float r = s * std::sqrt(static_cast<float>(x * x + y * y + z * z));
                    sumW += w.value(r);
                    const double g = spiky.gradientScale(r);
                    sumSquares += g * g;
                }
        latticeDenominator_ = static_cast<float>(sumSquares / (sumW * sumW));
        latticeKey_[0] = ctx.supportRadius;
        latticeKey_[1] = ctx.particleSpacing;
    }
    return kRelaxation * latticeDenominator_;
}

void PbfMacklin2013::solveLambda(StepContext& ctx, float epsilon, bool lastIteration) {
    ParticleStore& p = ctx.particles;
    const kernels::SmoothingKernel w = ctx.kernel();
    const kernels::Spiky spiky(ctx.supportRadius, ctx.dimensions);
    const float h = ctx.supportRadius, h2 = h * h;
    const float self = w.value(0.0f);
    const float tensileScale = -kTensileK * h2;
    const float invWdq = 1.0f / w.value(kTensileDq * h);
    // eq. 13 less its value at the rest spacing: pairs at or beyond it feel none (the paper's
    // 1 % of k there pushed a coasting jet's layers apart by ~0.1 mm in 1 s, unevenly).
    const float restRatio = w.value(ctx.particleSpacing) * invWdq;
    const float restTensile = restRatio * restRatio * restRatio * restRatio;
    const float vb = ctx.boundary.volume;
    pbf_sums::LambdaKernel kernel{w};
    kernel.h = h;
    kernel.h2 = h2;
    kernel.spikyGradient = spiky.gradNorm;
    kernel.invWdq = invWdq;
    kernel.restTensile = restTensile;
    kernel.tensileScale = tensileScale;
    parallelForBlocks(p.size(), kBlock, ctx.threads, [&](std::uint32_t first, std::uint32_t last) {
        pbf_sums::LambdaSums fluid[kBlock];
        glm::vec4 walls[kBlock];
        pbf_sums::lambdaSumsOfRange(ctx.neighbors, first, last, rows_.data(), weightedVolume2_.data(), kernel, ctx.periodic,
                                    pairFactor_.data(), pairCorrection_.data(), fluid);
        pbf_sums::wallSumsOfRange(ctx.boundaryNeighbors, first, last, wallRows_.data(), rows_.data(), kernel, ctx.periodic,
                                  walls);
        for (std::uint32_t i = first; i < last; ++i) {
            const pbf_sums::LambdaSums& sums = fluid[i - first];
            const glm::vec3 xi = p.position[i];
            const float vi = volume_[i];
            const float sumW = self + sums.kernelSum;
            wallGradient_[i] = vb * glm::vec3(walls[i - first]);
            const float c = vi * sumW + vb * walls[i - first].w - 1.0f;  // eq. 1 over ρ0_i
            // ∇_i C_i = V_i Σ_j ∇W_ij + Σ_b V_b ∇W_ib; ∇_j C_i = −V_i ∇W_ij (here V_j: the pair's
            // correction moves j by its own volume's share, eq. 14).
            const glm::vec3 own = vi * sums.gradient + wallGradient_[i];
            const float denominator = weight_[i] * glm::dot(own, own) + sums.weightedSquares + epsilon;
            // eq. 11, unilateral: −c where c > 0, else +0 (also for NaN), without a branch (about
            // half the particles are compressed, and a branch on it mispredicts)
            lambda_[i] = std::min(0.0f, -c) / denominator;
            if (lastIteration) p.density[i] = ctx.materials[p.material[i]].restDensity * (c + 1.0f);
            correctionRows_[i] = glm::vec4(xi, lambda_[i] * vi);
        }
    });
}

void PbfMacklin2013::refreshGhostLambdas(StepContext& ctx) {
    if (!ctx.sharing) return;
    // A ghost's λ misses neighbours its owner has: the correction pass reads its owner's.
    ctx.refreshGhosts(std::span<float>(lambda_));
    const ParticleStore& p = ctx.particles;
    const std::span<const std::uint8_t> ghosts = ctx.sharing->ghosts();
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        if (ghosts[i]) correctionRows_[i] = glm::vec4(p.position[i], lambda_[i] * volume_[i]);
    });
}

void PbfMacklin2013::refreshGhostPositions(StepContext& ctx) {
    if (!ctx.sharing) return;
    // The next λ pass reads the neighbours' corrected positions.
    ParticleStore& p = ctx.particles;
    ctx.refreshGhosts(std::span<glm::vec3>(p.position));
    const std::span<const std::uint8_t> ghosts = ctx.sharing->ghosts();
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        if (ghosts[i]) rows_[i] = glm::vec4(p.position[i], volume_[i]);
    });
}

void PbfMacklin2013::applyCorrection(StepContext& ctx, float share) {
    ParticleStore& p = ctx.particles;
    const float cap = kMaxCorrection * ctx.supportRadius;
    // Reads the rows (x_j, λ_j V_j) the λ pass left; moves only i itself.
    parallelForBlocks(p.size(), kBlock, ctx.threads, [&](std::uint32_t first, std::uint32_t last) {
        glm::vec3 sums[kBlock];
        pbf_sums::correctionSumsOfRange(ctx.neighbors, first, last, correctionRows_.data(), pairFactor_.data(),
                                        pairCorrection_.data(), ctx.periodic, sums);  // eq. 14
        for (std::uint32_t i = first; i < last; ++i) {
            glm::vec3 correction = weight_[i] * (sums[i - first] + lambda_[i] * wallGradient_[i]);
            const float length = glm::length(correction);
            if (length > cap) correction *= cap / length;
            p.position[i] += share * correction;
            moved_[i] += share * correction;
            rows_[i] = glm::vec4(p.position[i], volume_[i]);  // for the next λ pass
        }
    });
}

void PbfMacklin2013::confineVorticity(StepContext& ctx, float dt, float epsilon) {
    ParticleStore& p = ctx.particles;
    const auto n = p.size();
    vorticity_.resize(n);
    // ω_i = ∇ × v = Σ_j V_j ∇W_ij × (v_j − v_i)  (eq. 15, with SPH volumes)
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i], vi = p.velocity[i];
        const auto list = ctx.neighbors.of(i);
        const std::uint64_t slot = ctx.neighbors.offset(i);
        glm::vec3 omega(0.0f);
        for (std::size_t k = 0; k < list.size(); ++k) {
            const float f = pairFactor_[slot + k];
            if (f == 0.0f) continue;
            const std::uint32_t j = list[k];
            omega += glm::cross((volume_[j] * f) * ctx.delta(xi, p.position[j]), p.velocity[j] - vi);
        }
        vorticity_[i] = omega;
    });
    // η = ∇|ω|, N = η/|η|, f = ε (N × ω)  (eq. 16)
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i];
        const float own = glm::length(vorticity_[i]);
        const auto list = ctx.neighbors.of(i);
        const std::uint64_t slot = ctx.neighbors.offset(i);
        glm::vec3 eta(0.0f);
        for (std::size_t k = 0; k < list.size(); ++k) {
            const float f = pairFactor_[slot + k];
            if (f == 0.0f) continue;
            const std::uint32_t j = list[k];
            eta += (volume_[j] * (glm::length(vorticity_[j]) - own) * f) * ctx.delta(xi, p.position[j]);
        }
        const float length = glm::length(eta);
        if (length > 1e-12f) p.velocity[i] += (dt * epsilon / length) * glm::cross(eta, vorticity_[i]);
    });
}

void PbfMacklin2013::predict(ParticleStore& p, const SolverDef& def, const glm::vec3& gravity, double maxDt, int threads) {
    // Algorithm 1, lines 1–4, with step()'s Δt
    const auto dt = static_cast<float>(std::min<double>(maxDt, def.maxDt));
    parallelFor(p.size(), threads, [&](std::uint32_t i) {
        p.velocity[i] += dt * gravity;
        p.position[i] += dt * p.velocity[i];
    });
    predicted_ = true;
}

void PbfMacklin2013::reserve(std::size_t particles, std::uint64_t slots) {
    // The headroom resizeScratch would give, and a quarter more pair slots: a live demo's lists
    // grow by ~12 % as its blocks fall and settle (light water: 480k slots at the start, 540k
    // later), and a per-pair array that outgrows its block is re-allocated and touched anew
    // (8.6 MB at once, a frame of ~1.9 times the median).
    const std::size_t n = particles + particles / 8;
    reserveTouched(moved_, n);
    reserveTouched(volume_, n);
    reserveTouched(weight_, n);
    reserveTouched(lambda_, n);
    reserveTouched(wallGradient_, n);
    reserveTouched(correctionRows_, n);
    reserveTouched(rows_, n);
    reserveTouched(weightedVolume2_, n);
    reserveTouched(massRows_, n);
    const std::size_t pairs = static_cast<std::size_t>(slots + slots / 4) + pair_sums::kPadding;
    reserveTouched(pairFactor_, pairs);
    reserveTouched(pairCorrection_, pairs);
}

double PbfMacklin2013::step(StepContext& ctx) {
    ParticleStore& p = ctx.particles;
    const auto n = p.size();
    const double dtStep = std::min<double>(ctx.maxDt, ctx.solver.maxDt);
    const auto dt = static_cast<float>(dtStep);
    resizeScratch(moved_, n);
    resizeScratch(volume_, n);
    resizeScratch(weight_, n);
    resizeScratch(lambda_, n);
    resizeScratch(wallGradient_, n);
    resizeScratch(correctionRows_, n);
    resizeScratch(rows_, n);
    resizeScratch(weightedVolume2_, n);
    // and pair_sums::kPadding zeros after the last list, which the correction pass reads past
    for (std::vector<float>* pairs : {&pairFactor_, &pairCorrection_}) {
        resizeScratch(*pairs, ctx.neighbors.slotCount() + pair_sums::kPadding);
        std::fill(pairs->end() - pair_sums::kPadding, pairs->end(), 0.0f);
    }
    const float referenceDensity = ctx.materials.empty() ? 1000.0f : ctx.materials[0].restDensity;
    // Algorithm 1, lines 1–4: external forces and the predicted positions (unless predict() did).
    const bool predicted = predicted_;
    predicted_ = false;
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        const float rho0 = ctx.materials[p.material[i]].restDensity;
        volume_[i] = p.mass[i] / rho0;
        weight_[i] = referenceDensity / rho0;
        moved_[i] = glm::vec3(0.0f);
        p.acceleration[i] = ctx.gravity;
        if (!predicted) {
            p.velocity[i] += dt * ctx.gravity;
            p.position[i] += dt * p.velocity[i];
        }
        // (x_j, V_j) and w_j V_j² for the λ pass, packed: one load per neighbour for each
        rows_[i] = glm::vec4(p.position[i], volume_[i]);
        weightedVolume2_[i] = weight_[i] * volume_[i] * volume_[i];
    });
    // (x_b, 0), moved to the step's end where boundaries move
    const auto nb = static_cast<std::uint32_t>(ctx.boundary.position.size());
    resizeScratch(wallRows_, nb);
    const bool moving = ctx.boundary.moving;
    parallelFor(nb, ctx.threads, [&](std::uint32_t b) {
        wallRows_[b] = glm::vec4(moving ? ctx.boundary.position[b] + dt * ctx.boundary.velocity[b] : ctx.boundary.position[b], 0.0f);
    });
    ctx.lap(Phase::Integration);
    // Lines 8–19: Jacobi iterations on the density constraints.
    const float epsilon = relaxation(ctx);
    const int iterations = ctx.solver.constraintIterations;
    // A step cut short to land on a frame (World::advance's last, down to a few ns) applies
    // (Δt/Δt_last)² of the corrections: they hold the fluid up against gravity (and remove the
    // compression the iterations left), Δx ∝ a Δt², and whole within a tiny Δt they become
    // velocities ∝ 1/Δt (measured: 1000 m/s after a 2 ns step in a tank at rest; with a
    // linear share still 2.7 m/s).
    const float lastDt = static_cast<float>(std::max(lastDt_, dtStep));
    const float share = (dt / lastDt) * (dt / lastDt);
    lastDt_ = dtStep;
    for (int it = 0; it < iterations; ++it) {
        solveLambda(ctx, epsilon, it == iterations - 1);
        refreshGhostLambdas(ctx);
        applyCorrection(ctx, share);
        refreshGhostPositions(ctx);
    }
    ctx.lap(Phase::PressureSolve);
    // Lines 21–24: velocities from the positions, then vorticity confinement and XSPH.
    const float invDt = 1.0f / dt;
    const float toPressure = -referenceDensity / (lastDt * lastDt);  // share/Δt² = 1/Δt_last²
    parallelFor(n, ctx.threads, [&](std::uint32_t i) {
        // (x* − x)/Δt as v + Σ Δx/Δt: exact where nothing corrected (a coasting jet keeps its
        // layers; the difference of positions rounds at ~1e-7 of |x|, which split them).
        p.velocity[i] += invDt * moved_[i];
        // p = −ρ0_ref λ/Δt²: the SPH pressure whose acceleration moves i by Δx (the equivalent, for output).
        p.pressure[i] = toPressure * lambda_[i];
    });
    if (ctx.sharing) {  // vorticity and XSPH read the neighbours' velocities and densities
        ctx.refreshGhosts(std::span<glm::vec3>(p.velocity));
        ctx.refreshGhosts(std::span<float>(p.density));
    }
    if (ctx.solver.vorticity > 0.0f) confineVorticity(ctx, dt, ctx.solver.vorticity);
    // XSPH in SIMD lanes over rows (x_j, m_j), with rows_ (free now) for (v_j, ρ_j)
    resizeScratch(massRows_, n);
    parallelFor(n, ctx.threads, [&](std::uint32_t i) { massRows_[i] = glm::vec4(p.position[i], p.mass[i]); });
    xsph_.apply(p, ctx.neighbors, ctx.periodic, ctx.poly6(), ctx.solver.xsph >= 0.0f ? ctx.solver.xsph : kDefaultXsph,
                ctx.threads, rows_, massRows_.data());
    ctx.lap(Phase::NonPressureForces);
    ctx.pressureIterations = iterations;
    ctx.divergenceIterations = 0;
    ctx.pressureConverged = true;
    return dtStep;
}

}  // namespace tide
