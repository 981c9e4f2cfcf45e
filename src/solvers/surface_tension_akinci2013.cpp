#include "solvers/surface_tension_akinci2013.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "core/kernels.hpp"
#include "core/parallel.hpp"
#include "solvers/solver.hpp"

namespace tide {

namespace {

bool anyAdhesion(const StepContext& ctx) {
    for (const MaterialDef& m : ctx.materials)
        if (m.adhesion > 0.0f) return true;
    return false;
}

bool anyTension(const StepContext& ctx) { return ctx.pairs != nullptr && ctx.pairs->anyTension(); }

/// n_i = c Σ_{j of i's material} (m_j/ρ_j) ∇W_ij (Akinci et al. 2013, eq. 4), for particles
/// whose material has a tension pair (zero for the others).
void computeNormals(const StepContext& ctx, std::vector<glm::vec3>& normals) {
    const ParticleStore& p = ctx.particles;
    const MaterialPairs& pairs = *ctx.pairs;
    const kernels::SmoothingKernel w = ctx.kernel();
    normals.assign(p.size(), glm::vec3(0.0f));
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        const MaterialIndex a = p.material[i];
        if (!pairs.hasTension(a)) return;
        const glm::vec3 xi = p.position[i];
        glm::vec3 n(0.0f);
        for (const std::uint32_t j : ctx.neighbors.of(i)) {
            if (p.material[j] != a) continue;
            const glm::vec3 rij = ctx.delta(xi, p.position[j]);
            n += (p.mass[j] / p.density[j]) * w.gradient(rij, glm::length(rij));
        }
        normals[i] = ctx.supportRadius * n;
    });
}

}  // namespace

bool surfaceTensionActive(const StepContext& ctx) { return anyTension(ctx) || anyAdhesion(ctx); }

float addSurfaceTension(const StepContext& ctx, std::span<glm::vec3> accel) {
    const bool tension = anyTension(ctx), adhesion = anyAdhesion(ctx);
    if (!tension && !adhesion) return 0.0f;
    const ParticleStore& p = ctx.particles;
    std::vector<glm::vec3> normals;
    if (tension) computeNormals(ctx, normals);
    const kernels::Cohesion cohesion(ctx.supportRadius, ctx.dimensions);
    const kernels::Adhesion adhesionKernel(ctx.supportRadius, ctx.dimensions);
    return std::sqrt(parallelMax(p.size(), ctx.threads, [&](std::uint32_t i) {
        const MaterialIndex a = p.material[i];
        const MaterialDef& mat = ctx.materials[a];
        const glm::vec3 xi = p.position[i];
        glm::vec3 sum(0.0f);
        if (tension && ctx.pairs->hasTension(a)) {
            const float mi = p.mass[i], rhoi = p.density[i];
            const glm::vec3 ni = normals[i];
            for (const std::uint32_t j : ctx.neighbors.of(i)) {
                const MaterialIndex b = p.material[j];
                const float gamma = ctx.pairs->tension(a, b);
                if (gamma <= 0.0f) continue;
                const glm::vec3 rij = ctx.delta(xi, p.position[j]);
                const float r = glm::length(rij);
                const float mj = p.mass[j];
                // K_ij = 2ρ0/(ρ_i + ρ_j) with ρ0 the pair's mean rest density (eq. 5).
                const float k = (mat.restDensity + ctx.materials[b].restDensity) / (rhoi + p.density[j]);
                // Cohesion (eq. 1), as an acceleration: −γ m_j C(r) x̂_ij; repelling between materials.
                const float sign = a == b ? 1.0f : -1.0f;
                glm::vec3 term(0.0f);
                if (r > 1e-6f * ctx.supportRadius) term = (-sign * gamma * mj * cohesion.value(r) / r) * rij;
                // Curvature (eq. 3): −γ m̄_ij (n_i − n_j)/m_i, m̄_ij the harmonic mean of the masses.
                const float mbar = mi == mj ? mi : 2.0f * mi * mj / (mi + mj);
                term -= (gamma * mbar / mi) * (ni - normals[j]);
                sum += k * term;
            }
        }
        if (mat.adhesion > 0.0f) {
            // Adhesion (eq. 6) as an acceleration: −β Ψ_b A(r) x̂_ib, Ψ_b = ρ0_a V_b.
            glm::vec3 wall(0.0f);
            const auto walls = ctx.boundaryNeighbors.of(i);
            glm::vec3* loads = ctx.loads ? ctx.loads->viscousForce.data() + ctx.boundaryNeighbors.offset(i) : nullptr;
            for (std::size_t k = 0; k < walls.size(); ++k) {
                const glm::vec3 rib = ctx.delta(xi, ctx.boundary.position[walls[k]]);
                const float r = glm::length(rib);
                if (!(r > 0.0f)) continue;
                const glm::vec3 term = (ctx.boundary.volume * adhesionKernel.value(r) / r) * rib;
                wall += term;
                if (loads) loads[k] -= (p.mass[i] * mat.adhesion * mat.restDensity) * term;  // the force b puts on i
            }
            sum -= (mat.adhesion * mat.restDensity) * wall;
        }
        accel[i] += sum;
        return glm::dot(sum, sum);
    }, 0.0f));
}

double surfaceTensionTimeStep(const StepContext& ctx, float maxTensionAccel) {
    if (!(maxTensionAccel > 0.0f)) return std::numeric_limits<double>::infinity();
    return ctx.solver.forceNumber * std::sqrt(static_cast<double>(ctx.particleSpacing) / maxTensionAccel);
}

}  // namespace tide
