#include "solvers/viscosity.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include <tide/world.hpp>

#include "core/kernels.hpp"
#include "core/parallel.hpp"
#include "solvers/pair_sums.hpp"
#include "solvers/solver.hpp"

namespace tide {

namespace {

struct Entry {
    std::string_view name;
    ViscosityModel model;
};
constexpr Entry kModels[] = {
    {"morris", ViscosityModel::Morris1997},
    {"monaghan", ViscosityModel::Monaghan2005},
    {"muller", ViscosityModel::Muller2003},
    {"xsph", ViscosityModel::Xsph},
};

/// Velocity a boundary particle takes in the viscous sum with fluid particle i: no slip on
/// walls at rest, v_b = 2 v_wall − v_i = −v_i, the fluid velocity mirrored through the wall.
/// Morris et al. 1997 extrapolate v_b = −(d_b/d_i) v_i from the distances to the wall (for
/// their Couette and Poiseuille flows); in the lattice shell, the only pairs within a support
/// of 2 spacings are the first layers either side of the wall surface, d_b = d_i = s/2. With
/// v_b = 0 the fluid slips instead: it sticks to the first boundary layer, half a spacing
/// inside the wall (10 % of the centre-line speed in the Poiseuille test).
inline glm::vec3 wallVelocity(const glm::vec3& vi) { return -vi; }
/// The same for a moving wall (a wave paddle) of velocity v_b: v_i mirrored in the wall's
/// frame, 2 v_b − v_i. (Walls at rest keep the form above, so their sums stay bit-identical.)
inline glm::vec3 wallVelocity(const glm::vec3& vi, const glm::vec3& vb) { return 2.0f * vb - vi; }

/// μ_i + μ_j of a pair in the models' sums, with the interface viscosity between two
/// materials: twice their harmonic mean, μ_ij = 2μ_iμ_j/(μ_i + μ_j) (Hu & Adams 2006, "A
/// multi-phase SPH method for macroscopic and mesoscopic flows", J. Comput. Phys. 213, the
/// inter-particle viscosity of their momentum equation; Cleary 1998 takes the same mean for
/// conductivities). It keeps the shear stress continuous across an interface: the flux
/// through two layers in series is set by the harmonic mean, and a 30× oil does not drag
/// water along as if the water were 15× thicker (the arithmetic mean would). Equal viscosities
/// give μ_i + μ_j exactly.
inline float pairViscositySum(float mui, float muj) {
    if (mui == muj) return mui + muj;
    const float sum = mui + muj;
    return sum > 0.0f ? 4.0f * mui * muj / sum : 0.0f;
}

void addMonaghan2005(const StepContext& ctx, std::span<glm::vec3> accel) {
    const ParticleStore& p = ctx.particles;
    const kernels::SmoothingKernel w = ctx.kernel();
    const float h2 = ctx.supportRadius * ctx.supportRadius * 0.25f;  // smoothing length = support / 2
    const float factor = 2.0f * static_cast<float>(ctx.dimensions + 2);  // 2(d + 2): 10 in 3D, 8 in 2D
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i];
        const glm::vec3 vi = p.velocity[i];
        const float mui = ctx.materials[p.material[i]].viscosity;
        glm::vec3 sum(0.0f);
        for (const std::uint32_t j : ctx.neighbors.of(i)) {
            const glm::vec3 rij = ctx.delta(xi, p.position[j]);
            const float r = glm::length(rij);
            const float nu = pairViscositySum(mui, ctx.materials[p.material[j]].viscosity) / (p.density[i] + p.density[j]);
            const float vr = glm::dot(vi - p.velocity[j], rij);
            sum += (p.mass[j] / p.density[j] * nu * vr / (r * r + 0.01f * h2)) * w.gradient(rij, r);
        }
        // Walls, mirrored: m_b/ρ_b = Ψ_b/ρ_i = ρ0_i V_b/ρ_i and ν_ib = 2μ_i/(2ρ_i); v_b no-slip.
        if (mui > 0.0f) {
            glm::vec3 wallSum(0.0f);
            const float scale = ctx.materials[p.material[i]].restDensity / p.density[i] * mui / p.density[i];
            const auto walls = ctx.boundaryNeighbors.of(i);
            glm::vec3* loads = ctx.loads ? ctx.loads->viscousForce.data() + ctx.boundaryNeighbors.offset(i) : nullptr;
            for (std::size_t k = 0; k < walls.size(); ++k) {
                const std::uint32_t b = walls[k];
                const glm::vec3 rib = ctx.delta(xi, ctx.boundary.position[b]);
                const float r = glm::length(rib);
                const glm::vec3 vb = ctx.boundary.moving ? wallVelocity(vi, ctx.boundary.velocity[b]) : wallVelocity(vi);
                const float vr = glm::dot(vi - vb, rib);
                const glm::vec3 term = (ctx.boundary.volume * vr / (r * r + 0.01f * h2)) * w.gradient(rib, r);
                wallSum += term;
                if (loads) loads[k] += (p.mass[i] * factor * scale) * term;  // the force b puts on i
            }
            sum += scale * wallSum;
        }
        accel[i] += factor * sum;
    });
}

void addMorris1997(const StepContext& ctx, std::span<glm::vec3> accel) {
    const ParticleStore& p = ctx.particles;
    const kernels::SmoothingKernel w = ctx.kernel();
    const float h2 = ctx.supportRadius * ctx.supportRadius * 0.25f;  // smoothing length = support / 2
    // One viscosity and the solver's packed rows: the fluid sum in SIMD lanes, 2μ Σ_j (m_j/ρ_j) f (v_i − v_j);
    // with viscosityRows, Σ_j (m_j/ρ_j) μ̄_ij f (v_i − v_j) (μ̄_ij = 2μ within rounding where they are equal).
    const bool lanes = ctx.positionMassRows && ctx.velocityRows &&
                       std::all_of(ctx.materials.begin(), ctx.materials.end(),
                                   [&](const MaterialDef& m) { return m.viscosity == ctx.materials.front().viscosity; });
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i];
        const glm::vec3 vi = p.velocity[i];
        const float mui = ctx.materials[p.material[i]].viscosity;
        glm::vec3 sum(0.0f);
        if (lanes) {
            const auto neighbors = ctx.neighbors.of(i);
            sum = (2.0f * mui) * pair_sums::viscousSum(pair_sums::Neighbors(neighbors), ctx.positionMassRows,
                                                       ctx.velocityRows, xi, vi, w, 0.01f * h2, ctx.periodic);
        } else if (ctx.viscosityRows && ctx.velocityRows) {
            sum = pair_sums::viscousSumHarmonic(pair_sums::Neighbors(ctx.neighbors.of(i)), ctx.viscosityRows, ctx.velocityRows,
                                                xi, vi, mui, w, 0.01f * h2, ctx.periodic);
        } else {
            for (const std::uint32_t j : ctx.neighbors.of(i)) {
                const glm::vec3 rij = ctx.delta(xi, p.position[j]);
                const float r = glm::length(rij);
                // r_ij · ∇W_ij / (r² + 0.01ĥ²) = r W'(r) / (r² + 0.01ĥ²) ≤ 0
                const float f = r * w.derivative(r) / (r * r + 0.01f * h2);
                sum += (p.mass[j] * pairViscositySum(mui, ctx.materials[p.material[j]].viscosity) / p.density[j] * f) *
                       (vi - p.velocity[j]);
            }
        }
        // Walls, mirrored: m_b = Ψ_b = ρ0_i V_b, ρ_b = ρ_i, μ_b = μ_i; v_b no-slip.
        if (mui > 0.0f) {
            const float scale = ctx.materials[p.material[i]].restDensity * 2.0f * mui / p.density[i];
            if (ctx.loads) {  // the force b puts on i: m_i/ρ_i times its term of the sums below
                const auto walls = ctx.boundaryNeighbors.of(i);
                glm::vec3* loads = ctx.loads->viscousForce.data() + ctx.boundaryNeighbors.offset(i);
                for (std::size_t k = 0; k < walls.size(); ++k) {
                    const std::uint32_t b = walls[k];
                    const float r = glm::length(ctx.delta(xi, ctx.boundary.position[b]));
                    const glm::vec3 vb = ctx.boundary.moving ? wallVelocity(vi, ctx.boundary.velocity[b]) : wallVelocity(vi);
                    loads[k] += (p.mass[i] / p.density[i] * scale * ctx.boundary.volume * r * w.derivative(r) /
                                 (r * r + 0.01f * h2)) * (vi - vb);
                }
            }
            if (!ctx.boundary.moving) {
                float wallWeight = 0.0f;
                for (const std::uint32_t b : ctx.boundaryNeighbors.of(i)) {
                    const float r = glm::length(ctx.delta(xi, ctx.boundary.position[b]));
                    wallWeight += ctx.boundary.volume * r * w.derivative(r) / (r * r + 0.01f * h2);
                }
                sum += (scale * wallWeight) * (vi - wallVelocity(vi));
            } else {
                glm::vec3 wallSum(0.0f);
                for (const std::uint32_t b : ctx.boundaryNeighbors.of(i)) {
                    const float r = glm::length(ctx.delta(xi, ctx.boundary.position[b]));
                    wallSum += (ctx.boundary.volume * r * w.derivative(r) / (r * r + 0.01f * h2)) *
                               (vi - wallVelocity(vi, ctx.boundary.velocity[b]));
                }
                sum += scale * wallSum;
            }
        }
        accel[i] += sum / p.density[i];
    });
}

void addMuller2003(const StepContext& ctx, std::span<glm::vec3> accel) {
    const ParticleStore& p = ctx.particles;
    const kernels::Viscosity viscosity(ctx.supportRadius, ctx.dimensions);
    parallelFor(p.size(), ctx.threads, [&](std::uint32_t i) {
        const glm::vec3 xi = p.position[i];
        const glm::vec3 vi = p.velocity[i];
        const float mui = ctx.materials[p.material[i]].viscosity;
        glm::vec3 sum(0.0f);
        for (const std::uint32_t j : ctx.neighbors.of(i)) {
            const float r = glm::length(ctx.delta(xi, p.position[j]));
            // A symmetric μ_ij keeps the force antisymmetric: momentum is conserved between materials.
            const float muij = 0.5f * pairViscositySum(mui, ctx.materials[p.material[j]].viscosity);
            sum += (p.mass[j] / p.density[j] * muij * viscosity.laplacian(r)) * (p.velocity[j] - vi);
        }
        // Walls, mirrored as in the classic pressure sum: m_b/ρ_b = V_b, μ_b = μ_i; v_b no-slip.
        if (mui > 0.0f) {
            if (ctx.loads) {  // the force b puts on i: m_i/ρ_i times its term of the sums below
                const auto walls = ctx.boundaryNeighbors.of(i);
                glm::vec3* loads = ctx.loads->viscousForce.data() + ctx.boundaryNeighbors.offset(i);
                for (std::size_t k = 0; k < walls.size(); ++k) {
                    const std::uint32_t b = walls[k];
                    const glm::vec3 vb = ctx.boundary.moving ? wallVelocity(vi, ctx.boundary.velocity[b]) : wallVelocity(vi);
                    loads[k] += (p.mass[i] / p.density[i] * mui * ctx.boundary.volume *
                                 viscosity.laplacian(glm::length(ctx.delta(xi, ctx.boundary.position[b])))) * (vb - vi);
                }
            }
            if (!ctx.boundary.moving) {
                float wallWeight = 0.0f;
                for (const std::uint32_t b : ctx.boundaryNeighbors.of(i))
                    wallWeight += ctx.boundary.volume * viscosity.laplacian(glm::length(ctx.delta(xi, ctx.boundary.position[b])));
                sum += (mui * wallWeight) * (wallVelocity(vi) - vi);
            } else {
                for (const std::uint32_t b : ctx.boundaryNeighbors.of(i))
                    sum += (mui * ctx.boundary.volume * viscosity.laplacian(glm::length(ctx.delta(xi, ctx.boundary.position[b])))) *
                           (wallVelocity(vi, ctx.boundary.velocity[b]) - vi);
            }
        }
        accel[i] += sum / p.density[i];
    });
}

}  // namespace

std::vector<std::string> viscosityNames() {
    std::vector<std::string> names;
    for (const Entry& entry : kModels) names.emplace_back(entry.name);
    return names;
}

ViscosityModel viscosityModel(std::string_view name, ViscosityModel solverDefault) {
    if (name.empty()) return solverDefault;
    for (const Entry& entry : kModels)
        if (entry.name == name) return entry.model;
    std::string known;
    for (const Entry& entry : kModels) known += (known.empty() ? "" : ", ") + std::string(entry.name);
    throw std::invalid_argument("solver.viscosity: unknown viscosity model \"" + std::string(name) + "\" (known: " +
                                known + ")");
}

void addViscosity(const StepContext& ctx, std::span<glm::vec3> accel) {
    switch (ctx.viscosity) {
        case ViscosityModel::Morris1997: addMorris1997(ctx, accel); break;
        case ViscosityModel::Monaghan2005: addMonaghan2005(ctx, accel); break;
        case ViscosityModel::Muller2003: addMuller2003(ctx, accel); break;
        case ViscosityModel::Xsph: break;
    }
}

float maxKinematicViscosity(const StepContext& ctx) {
    // Dye diffusion (diffusion_cleary1999.hpp) is explicit too, with the same limit on D.
    const float diffusivity = ctx.pairs ? ctx.pairs->maxDiffusivity() : 0.0f;
    if (ctx.viscosity == ViscosityModel::Xsph) return diffusivity;
    float nu = diffusivity;
    for (const MaterialDef& m : ctx.materials) nu = std::max(nu, m.viscosity / m.restDensity);
    return nu;
}

}  // namespace tide
