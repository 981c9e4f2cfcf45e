#pragma once
/// \file
/// Divergence-free SPH after Bender & Koschier 2017, "Divergence-free SPH for incompressible
/// and viscous fluids" (IEEE TVCG 23(3)), Algorithm 1:
///   α_i = ρ_i / (|Σ_j m_j ∇W_ij|² + Σ_j |m_j ∇W_ij|²)                          (eq. 11)
///   divergence-free solve:  κᵛ_i = (1/Δt) (Dρ_i/Dt) α_i,                         (eq. 15)
///   constant-density solve: κ_i = (ρ*_i − ρ0)/Δt² α_i,                            (eq. 12)
///   each: v_i −= Δt Σ_j m_j (κ_i/ρ_i + κ_j/ρ_j) ∇W_ij                            (eq. 13)
/// iterated (Jacobi) until the mean compression is below SolverDef::maxDensityError.
/// Boundaries are Akinci et al. 2012 particles: Ψ_b = ρ0_i V_b joins the first sum of α and
/// pushes with Ψ_b κ_i/ρ_i ∇W_ib. Cubic spline kernel, Monaghan 2005 viscosity, CFL time
/// step (no sound speed: the solver, not the time step, keeps the fluid incompressible).
/// Not yet: warm start of κ from the previous step (it needs solver state that follows
/// particle reordering).

#include <vector>

#include "solvers/solver.hpp"
#include "solvers/xsph_monaghan1989.hpp"

namespace tide {

class DfsphBender2017 final : public Solver {
public:
    [[nodiscard]] std::string_view name() const override { return "dfsph"; }
    [[nodiscard]] DensityKernel densityKernel() const override { return DensityKernel::CubicSpline; }
    double step(StepContext& ctx) override;

private:
    void computeAlpha(StepContext& ctx);
    /// Makes the velocity field divergence-free; returns iterations.
    int solveDivergence(StepContext& ctx);
    /// Corrects the predicted velocities so the next positions have rest density; returns iterations.
    int solveDensity(StepContext& ctx, float dt);
    /// Mean over particles of source_[i] / ρ0_i: the solves' convergence measure (serial, so
    /// it does not depend on the thread count).
    [[nodiscard]] double meanRelativeSource(const StepContext& ctx) const;
    /// v_i −= Σ_j m_j (k_i/ρ_i + k_j/ρ_j) ∇W_ij + Σ_b Ψ_b (k_i/ρ_i) ∇W_ib for the current k_.
    void applyPressure(StepContext& ctx);

    std::vector<float> alpha_;
    std::vector<float> source_;        ///< Dρ/Dt (divergence) or ρ* − ρ0 (density), per particle
    std::vector<float> k_;             ///< κ·Δt (divergence) or κ·Δt² (density) of one iteration
    std::vector<float> pressureSum_;   ///< Σ over iterations, for the pressure output
    std::vector<glm::vec3> accel_;
    XsphFilter xsph_;
    double lastDt_ = 1e-3;             ///< s; the divergence solve runs before this step's dt is known
};

}  // namespace tide
