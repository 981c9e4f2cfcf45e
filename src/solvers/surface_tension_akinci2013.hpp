#pragma once
/// \file
/// Surface tension, interface tension and wall adhesion after Akinci, Akinci & Teschner 2013,
/// "Versatile surface tension and adhesion for SPH fluids", ACM TOG 32(6), 182.
///
/// A non-pressure force, added where the solvers add viscosity (sph::addNonPressureForces;
/// classic adds it after its own pass). For particle i of material a and neighbour j of
/// material b, with γ = MaterialPairDef::surfaceTension of the pair (a, b) and c the support:
///   normals (eq. 4):   n_i = c Σ_{j of a} (m_j/ρ_j) ∇W_ij   (cubic spline; own material only,
///                      so a particle at an interface with another fluid has a normal too)
///   cohesion (eq. 1):  F_ij^coh  = −γ m_i m_j C(|x_ij|) x̂_ij      (C: kernels::Cohesion)
///   curvature (eq. 3): F_ij^curv = −γ m̄_ij (n_i − n_j)
///   total (eq. 5):     F_ij = K_ij (s F_ij^coh + F_ij^curv),  K_ij = (ρ0_a + ρ0_b)/(ρ_i + ρ_j)
/// with s = +1 for a == b (the paper's surface tension: a's particles attract each other) and
/// s = −1 for a ≠ b (interface tension: a and b particles repel at the distances where
/// C > 0, so every a–b contact costs energy and the interface shrinks; their normals point
/// out of their own fluid, n_i − n_j ≈ 2n_i, so the curvature term pushes them apart too).
///
/// Several materials: each particle keeps its own mass and rest density. K_ij is the paper's
/// 2ρ0/(ρ_i + ρ_j) with ρ0 replaced by the mean of the two rest densities (≈ 1 under density
/// contrast, ρ_i ≈ ρ0_a); the paper's m_i in the curvature term becomes the harmonic mean
/// m̄_ij = 2m_i m_j/(m_i + m_j) (m_i for one material), so that F_ji = −F_ij and momentum is
/// conserved, while a light particle beside heavy ones is accelerated by at most 2γ|n_i − n_j|.
///
/// Adhesion (eq. 6): F_ib = −β m_i Ψ_b A(|x_ib|) x̂_ib, Ψ_b = ρ0_a V_b (Akinci et al. 2012),
/// A the adhesion spline (kernels::Adhesion), β = MaterialDef::adhesion of i's material.
///
/// γ and β are model parameters, not physical coefficients: for one fluid the cohesion
/// acceleration scales as γ ρ0 (m_j C ~ ρ0 s³/c³), independent of the spacing, the curvature
/// one as γ. Nothing here runs when every γ and β is 0.

#include <span>

#include <glm/vec3.hpp>

namespace tide {

struct StepContext;

/// Whether any material pair has γ > 0 or any material β > 0.
[[nodiscard]] bool surfaceTensionActive(const StepContext& ctx);

/// accel[i] += the tension and adhesion acceleration of particle i (module comment). Returns
/// the largest magnitude it added, m/s² (0 when surfaceTensionActive() is false: no pass runs),
/// for the time-step limit surfaceTensionTimeStep().
float addSurfaceTension(const StepContext& ctx, std::span<glm::vec3> accel);

/// The explicit force's step limit, s: the force criterion of Monaghan 1992,
/// dt ≤ forceNumber · √(spacing / a_max), a_max the largest tension acceleration of the step
/// (infinity for a_max = 0). Applied by the incompressible solvers, whose CFL step does not
/// see forces; wcsph and classic apply the same criterion to the total acceleration.
[[nodiscard]] double surfaceTensionTimeStep(const StepContext& ctx, float maxTensionAccel);

}  // namespace tide
