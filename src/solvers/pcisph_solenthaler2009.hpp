#pragma once
/// \file
/// Predictive-corrective incompressible SPH after Solenthaler & Pajarola 2009,
/// "Predictive-Corrective Incompressible SPH" (ACM TOG 28(3), SIGGRAPH 2009), Algorithm 1.
/// From p_i = 0 each step, iterate
///   predict  v*_i = v_i + Δt (a^{v,g}_i + a^p_i),  x*_i = x_i + Δt v*_i,
///   density  ρ*_i = Σ_j m_j W(x*_i − x*_j) + ρ0 Σ_b V_b W(x*_i − x_b)  (the neighbours of x(t)),
///   correct  p_i ← max(p_i + ½ δ_i (ρ*_i − ρ0), 0)   (projected, relaxed: see dfsph),
///   force    a^p_i = −Σ_j m_j (p_i/ρ0² + p_j/ρ0²) ∇W_ij − Σ_b Ψ_b ((p_i + p_b)/ρ0²) ∇W_ib,
/// until the mean density error (compression, and expansion where p > 0) is below
/// SolverDef::maxDensityError after at least SolverDef::minIterations corrections. Boundaries
/// are Akinci et al. 2012 particles (Ψ_b = ρ0_i V_b) with the wall pressure p_b of Adami et al.
/// 2012 (boundary/wall_pressure_adami2012.hpp). δ is computed per particle
/// and per step (the .cpp says why). Cubic spline kernel, SolverDef::viscosity (Morris 1997), CFL time
/// step (no sound speed: the iteration, not the time step, keeps the fluid incompressible),
/// halved and retaken when the solve fails (Ihmsen et al. 2010).
/// No warm start of p (the paper starts from zero each step too; see dfsph for why).
/// Several rest densities: density and pressure force in the density-contrast forms of
/// Solenthaler & Pajarola 2008 (density_contrast_solenthaler2008.hpp), the above for one.

#include <vector>

#include "boundary/wall_pressure_adami2012.hpp"
#include "solvers/density_contrast_solenthaler2008.hpp"
#include "solvers/jacobi_weight.hpp"
#include "solvers/solver.hpp"
#include "solvers/xsph_monaghan1989.hpp"

namespace tide {

class PcisphSolenthaler2009 final : public Solver {
public:
    [[nodiscard]] std::string_view name() const override { return "pcisph"; }
    [[nodiscard]] DensityKernel densityKernel() const override { return DensityKernel::Smoothing; }
    double step(StepContext& ctx) override;
    [[nodiscard]] std::vector<double> carriedState() const override { return {dtCap_}; }
    bool restoreCarriedState(std::span<const double> state) override {
        if (state.size() != 1) return false;
        dtCap_ = state[0];
        return true;
    }

private:
    JacobiWeightScale weightScale_;  ///< the Jacobi weight's factor for supports beyond 2 spacings
    struct Solve {
        int iterations = 0;
        bool converged = false;
        double uncorrected = 0.0;  ///< the compression predicted without pressure
    };
    /// The prediction-correction loop for a step of length dt: pressure_ and pressureAccel_.
    Solve solvePressure(StepContext& ctx, float dt);
    /// δ_i for a step of length dt.
    void computeDelta(StepContext& ctx, float dt);
    /// x*_i = x_i + Δt (v_i + Δt (a^{v,g}_i + a^p_i)).
    void predictPositions(StepContext& ctx, float dt);
    /// residual_ and error_ at the predicted positions.
    void predictCompression(StepContext& ctx, float dt);
    /// Mean over particles of error_[i] / ρ0_i (serial, so it does not depend on the thread count).
    [[nodiscard]] double meanRelativeCompression(const StepContext& ctx) const;
    /// pressureAccel_ from pressure_ (and the walls' pressure from it) at the current positions.
    void computePressureAccel(StepContext& ctx);

    std::vector<float> delta_;              ///< δ_i, Pa per kg/m³ of compression
    std::vector<float> pressure_;           ///< p_i, Pa
    std::vector<float> residual_;           ///< ρ*_i − ρ0, kg/m³
    std::vector<float> error_;              ///< the part of it that counts as error, kg/m³
    std::vector<float> kappa_;              ///< p_i/ρ0, m²/s², for the wall pressure
    WallPressure wall_;
    DensityContrast contrast_;        ///< several rest densities: Solenthaler & Pajarola 2008
    std::vector<float> scaledKappa_;  ///< κ ρ0_i/ρ0_ref for the wall pressure (several rest densities)
    std::vector<glm::vec3> predicted_;      ///< x*_i, m
    std::vector<glm::vec3> accel_;          ///< gravity + viscosity, m/s²
    std::vector<glm::vec3> pressureAccel_;  ///< m/s²
    XsphFilter xsph_;
    double dtCap_ = 1e30;                   ///< s; halved when a solve fails, grows back after
};

}  // namespace tide
