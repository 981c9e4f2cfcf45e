#pragma once
/// \file
/// The seed's solver: weakly compressible SPH after Müller, Charypar & Gross 2003,
/// "Particle-based fluid simulation for interactive applications" (SCA 2003).
///   density    ρ_i = Σ_j m_j W_poly6(r_ij)                                  (eq. 3)
///   pressure   p = κ(ρ − ρ0), κ = c²; or Tait's (Becker & Teschner 2007)    (eq. 12)
///   a_p,i = −1/ρ_i Σ_j m_j (p_i + p_j)/(2ρ_j) ∇W_spiky(r_ij)                 (eq. 10)
///   a_v,i = μ_ij/ρ_i Σ_j m_j (v_j − v_i)/ρ_j ∇²W_viscosity(r_ij)            (eq. 14)
/// (eq. 14 is the default viscosity model `muller`; SolverDef::viscosity may name another,
/// see viscosity.hpp).
/// Each sum carries the neighbour's own mass (seed eq. 10), so materials of different
/// rest density and viscosity share one simulation; μ_ij = (μ_i + μ_j)/2 keeps the viscous
/// force antisymmetric, so momentum is conserved between materials.
/// Walls are boundary particles that mirror the fluid particle (p_b = p_i, ρ_b = ρ0_i), so
/// in the pressure sum m_b (p_i + p_b)/(2ρ_b) becomes V_b p_i (Akinci et al. 2012).
/// Known flaw kept for fidelity: the (p_i + p_j)/2 symmetrisation is half the true pressure
/// gradient in the bulk (Σ_j V_j (p_j − p_i)/2 ∇W ≈ ∇p/2), so at rest the pressure is
/// 2ρg·depth and the compression twice that of a consistent scheme (the `wcsph` solver).
/// Integration is symplectic Euler followed by XSPH smoothing (SolverDef::xsph): the
/// Poly6-density/Spiky-gradient pair is not the gradient of an energy and, undamped, feeds
/// noise that grows in confined flows (tests/test_classic_solver.cpp measures it).

#include "solvers/solver.hpp"
#include "solvers/xsph_monaghan1989.hpp"

namespace tide {

class ClassicMuller2003 final : public Solver {
public:
    [[nodiscard]] std::string_view name() const override { return "classic"; }
    [[nodiscard]] DensityKernel densityKernel() const override { return DensityKernel::Poly6; }
    /// Müller's mirrored boundary pressure (V_b p_i) is too soft to hold particles at the
    /// lattice position half a spacing from a wall; the projection does it.
    [[nodiscard]] float wallMargin() const override { return 0.5f; }
    /// Points nearer the surface than the margin would be pushed out onto their neighbours.
    [[nodiscard]] float fillClearance() const override { return 0.499f; }
    [[nodiscard]] bool usesWallPressure() const override { return false; }
    [[nodiscard]] ViscosityModel defaultViscosity() const override { return ViscosityModel::Muller2003; }
    double step(StepContext& ctx) override;

private:
    void computeDensityAndPressure(StepContext& ctx) const;
    void computeAccelerations(StepContext& ctx) const;

    XsphFilter xsph_;
};

}  // namespace tide
