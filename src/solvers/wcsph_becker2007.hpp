#pragma once
/// \file
/// Weakly compressible SPH after Becker & Teschner 2007, "Weakly compressible SPH for free
/// surface flows" (SCA 2007): Tait's equation p = B((ρ/ρ0)^7 − 1), B = ρ0c²/7 (eq. 6;
/// negative pressures clamped), the symmetric pressure force
///   a_i = −Σ_j m_j (p_i/ρ_i² + p_j/ρ_j²) ∇W_ij − Σ_b ρ0_i V_b (p_i/ρ_i² + p_b/ρ_i²) ∇W_ib
/// (eq. 5; boundary particles after Akinci et al. 2012 with the wall pressure p_b of Adami et
/// al. 2012, see boundary/wall_pressure_adami2012.hpp), the cubic spline kernel, physical
/// viscosity (SolverDef::viscosity, Morris et al. 1997 by default), XSPH smoothing, and a
/// CFL/force time step with c = SolverDef::soundSpeed. Several rest densities: the
/// density-contrast forms of Solenthaler & Pajarola 2008 (ρ_i = m_i Σ_j W_ij, pressure force
/// −Σ_j (p_i V_i² + p_j V_j²) ∇W_ij / m_i; density_contrast_solenthaler2008.hpp), which are
/// the above for one rest density.

#include <vector>

#include <glm/vec4.hpp>

#include "boundary/wall_pressure_adami2012.hpp"
#include "solvers/density_contrast_solenthaler2008.hpp"
#include "solvers/solver.hpp"
#include "solvers/xsph_monaghan1989.hpp"

namespace tide {

class WcsphBecker2007 final : public Solver {
public:
    [[nodiscard]] std::string_view name() const override { return "wcsph"; }
    [[nodiscard]] DensityKernel densityKernel() const override { return DensityKernel::Smoothing; }
    double step(StepContext& ctx) override;

private:
    std::vector<glm::vec3> accel_;
    std::vector<float> kappa_;  ///< p/ρ per particle, m²/s²
    WallPressure wall_;
    DensityContrast contrast_;
    std::vector<float> scaledKappa_;  ///< κ ρ0_i/ρ0_ref for the wall pressure (several rest densities)
    XsphFilter xsph_;
    std::vector<glm::vec4> positionMass_;  ///< (x_j, m_j), one rest density
    /// (v_j, 1/ρ_j) for the viscosity, then (x_j, m_j p_j/ρ_j²) for the pressure force, then
    /// XSPH's (v_j, ρ_j): one array for three (one rest density)
    std::vector<glm::vec4> rows_;
};

}  // namespace tide
