#pragma once
/// \file
/// Viscosity models, chosen by name (SolverDef::viscosity, scene key `solver.viscosity`).
///
/// Two kinds of viscosity act in tide:
///  - a physical one, driven by the materials' dynamic viscosity μ (Pa·s), which converges
///    to ν∇²v as the spacing shrinks: `morris` (the default), `monaghan` or `muller`;
///  - an artificial one, XSPH velocity smoothing (SolverDef::xsph, ε ≥ 0, see
///    xsph_monaghan1989.hpp), which damps particle-scale noise but whose effect depends on
///    the time step and spacing, not on μ. It runs after every model (ε = 0 switches it off).
/// The model `xsph` switches the physical term off: XSPH is then the only viscosity.
///
/// Walls (boundary particles) take part in the physical sums with the mirrored properties of
/// the fluid particle (μ_b = μ_i, ρ_b = ρ_i; Akinci et al. 2012) and its velocity mirrored
/// through the wall (v_b = −v_i, after Morris et al. 1997), so the fluid sticks to the wall
/// surface (no slip): a channel flow has the parabolic profile (tests/test_poiseuille.cpp).
/// Moving walls (BoundaryParticles::moving) mirror it in the wall's frame: 2 v_b − v_i.
///
/// Between two materials every model takes the interface viscosity μ_ij = 2μ_iμ_j/(μ_i + μ_j),
/// the harmonic mean (Hu & Adams 2006), in place of the (μ_i + μ_j)/2 written below; equal
/// viscosities give the formulas as written.

#include <span>
#include <string_view>

#include <glm/vec3.hpp>

namespace tide {

struct StepContext;

enum class ViscosityModel {
    /// Morris, Fox & Zhu 1997, "Modeling low Reynolds number incompressible flows using SPH",
    /// J. Comput. Phys. 136, eq. (8):
    ///   a_i = Σ_j m_j (μ_i + μ_j)/(ρ_i ρ_j) (r_ij · ∇W_ij)/(r² + 0.01ĥ²) v_ij,
    /// ĥ the smoothing length (support / 2), cubic spline. Each velocity component gets the
    /// SPH Laplacian of a scalar, which depends only on the kernel's second moment: isotropic
    /// on a cubic lattice and within 1.3 % of ν∇²v there at support ratio 2. The default of
    /// wcsph and dfsph; does not conserve angular momentum exactly (the force is along v_ij).
    Morris1997,
    /// The Laplacian form of Monaghan 2005, "Smoothed particle hydrodynamics", Rep. Prog. Phys., eq. 6.11/6.12:
    ///   a_i = 2(d + 2) Σ_j (m_j/ρ_j) ν_ij (v_ij · r_ij)/(r² + 0.01ĥ²) ∇W_ij,  d = 3,
    /// ν_ij = (μ_i + μ_j)/(ρ_i + ρ_j), cubic spline. The force acts along r_ij, so it conserves
    /// angular momentum, but its 2(d + 2) assumes the kernel's fourth moment is isotropic,
    /// which the 26 neighbours of a cubic lattice at support ratio 2 are not: there it gives
    /// 0.71 ν∂²u/∂y² for a shear flow and 3 ν/s² for the harmonic (x² − y², −2xy, 0), whose
    /// Laplacian is 0 (tests/test_viscosity.cpp); plane Poiseuille flow runs 22 % fast. It
    /// is within 4 % from support ratio 3.
    Monaghan2005,
    /// Müller, Charypar & Gross 2003, eq. (14): a_i = (1/ρ_i) Σ_j m_j μ_ij (v_j − v_i)/ρ_j ∇²W_visc(r_ij),
    /// μ_ij = (μ_i + μ_j)/2, with their viscosity kernel: the seed's model.
    Muller2003,
    /// No physical viscosity: the materials' μ is unused, XSPH smoothing alone damps the flow.
    Xsph,
};

/// The model called `name`; throws std::invalid_argument naming solver.viscosity for an
/// unknown one. An empty name means `solverDefault`.
ViscosityModel viscosityModel(std::string_view name, ViscosityModel solverDefault);

/// accel[i] += the physical viscous acceleration of particle i (nothing for Xsph).
void addViscosity(const StepContext& ctx, std::span<glm::vec3> accel);

/// Largest kinematic viscosity μ/ρ0 of the materials that the model uses (0 for Xsph), or
/// dye diffusivity D of a material pair if larger, m²/s: the explicit time-step limit.
float maxKinematicViscosity(const StepContext& ctx);

}  // namespace tide
