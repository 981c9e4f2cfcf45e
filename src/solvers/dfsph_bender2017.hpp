#pragma once
/// \file
/// Divergence-free SPH after Bender & Koschier 2017, "Divergence-free SPH for incompressible
/// and viscous fluids" (IEEE TVCG 23(3)), Algorithm 1:
///   α_i = ρ_i / (|Σ_j m_j ∇W_ij|² + Σ_j |m_j ∇W_ij|²)                          (eq. 11)
/// (several rest densities: the density-contrast forms of Solenthaler & Pajarola 2008,
/// ρ_i = m_i Σ_j W_ij and the pressure in volume form, see density_contrast_solenthaler2008.hpp),
///   divergence-free solve:  κᵛ_i = (1/Δt) (Dρ_i/Dt) α_i,                         (eq. 15)
///   constant-density solve: κ_i = (ρ*_i − ρ0)/Δt² α_i,                            (eq. 12)
///     with ρ*_i evaluated at the predicted positions rather than linearised (eq. 9);
///     a solve whose error doubles goes on with the linearised ρ*_i (deep water at a loose
///     tolerance, where the former's Jacobi iteration is unstable),
///   each: v_i −= Δt Σ_j m_j (κ_i/ρ_i + κ_j/ρ_j) ∇W_ij                            (eq. 13)
/// iterated until the mean density error is below SolverDef::maxDensityError. The density
/// solve is a projected Jacobi iteration (κ ≥ 0, weight ½, may fall back after overshooting),
/// which holds the pressure of a tank at rest to a few per cent of ρgd; the paper's
/// compression-only increments stop once the mean is met and leave it at ~70 %.
/// Boundaries are Akinci et al. 2012 particles (Ψ_b = ρ0_i V_b) pushing with
/// Ψ_b (κ_i + κ_b)/ρ_i ∇W_ib: κ_b mirrors κ_i in the divergence solve and is the wall pressure
/// of Adami et al. 2012 in the density solve. Moving boundaries (wave paddles) enter the
/// density rate with (v_i − v_b) and the predicted density at x_b + Δt v_b. With
/// SolverDef::differenceForm, a share of the smoothed pressure's self-term is taken in the
/// difference form of incompressible SPH after the solve (see there). Cubic spline kernel,
/// SolverDef::viscosity (Morris 1997), CFL time step (no sound speed: the solver, not the
/// time step, keeps the fluid incompressible).

#include <vector>

#include <glm/vec4.hpp>

#include "boundary/wall_pressure_adami2012.hpp"
#include "core/kernels.hpp"
#include "solvers/density_contrast_solenthaler2008.hpp"
#include "solvers/jacobi_weight.hpp"
#include "solvers/pair_kernels.hpp"
#include "solvers/pair_sums.hpp"
#include "solvers/solver.hpp"
#include "solvers/xsph_monaghan1989.hpp"

namespace tide {

class DfsphBender2017 final : public Solver {
public:
    [[nodiscard]] std::string_view name() const override { return "dfsph"; }
    [[nodiscard]] DensityKernel densityKernel() const override { return DensityKernel::Smoothing; }
    double step(StepContext& ctx) override;
    [[nodiscard]] std::vector<double> carriedState() const override { return {lastDt_}; }
    bool restoreCarriedState(std::span<const double> state) override {
        if (state.size() != 1) return false;
        lastDt_ = state[0];
        return true;
    }

private:
    enum class Solve { Divergence, Density };
    /// Densities, kernel factors of this step's pairs and the packed positions the iterations read.
    void prepare(StepContext& ctx);
    void computeAlpha(StepContext& ctx);
    /// i's fluid neighbours with their coded gradient factors, as the SIMD pair sums read them.
    [[nodiscard]] pair_sums::Neighbors fluidPairs(const StepContext& ctx, std::uint32_t i) const {
        return pair_sums::Neighbors(ctx.neighbors.of(i), fluidF_.of(ctx.neighbors, i).data());
    }
    /// Σ_j m_j (v_i − v_j)·∇W_ij + Σ_b Ψ_b (v_i − v_b)·∇W_ib: the rate of change of ρ_i.
    [[nodiscard]] float densityRate(const StepContext& ctx, std::uint32_t i) const;
    /// ρ*_i: the density at the predicted positions positionK_ holds (x + Δt v), over this step's
    /// neighbours. The paper linearises it, ρ_i + Δt Dρ_i/Dt (eq. 9); the kernel is convex where
    /// neighbours close in, so the linear guess misses up to 90 % of the tolerance at CFL 0.4
    /// in a dam break (measured).
    template <class PairVector>
    [[nodiscard]] float predictedDensity(const StepContext& ctx, PairVector delta, const kernels::SmoothingKernel& w,
                                         std::uint32_t i) const;
    /// Makes the velocity field divergence-free; returns iterations.
    int solveDivergence(StepContext& ctx);
    /// Corrects the predicted velocities so the next positions have rest density; returns
    /// iterations. driftTime ≥ dt: the step before the free-fall limit (sph::limitFreeFall).
    int solveDensity(StepContext& ctx, float dt, float driftTime);
    /// The error a solve has left at i, from error_: the compression rate (divergence solve),
    /// or |ρ* − ρ0| where κ_i > 0 and the compression alone where κ_i = 0 (density solve:
    /// expansion only counts where pressure could still relax).
    [[nodiscard]] float errorLeft(std::uint32_t i, Solve solve) const {
        return solve == Solve::Divergence || kappa_[i] > 0.0f ? std::abs(error_[i]) : std::max(error_[i], 0.0f);
    }
    /// Mean over particles of errorLeft(i) / ρ0_i: the solves' convergence measure (a
    /// parallelSum, so it does not depend on the thread count).
    [[nodiscard]] double meanRelativeError(const StepContext& ctx, Solve solve) const;
    /// v_i −= Σ_j m_j (k_i/ρ_i + k_j/ρ_j) ∇W_ij + Σ_b Ψ_b ((k_i + k_b)/ρ_i) ∇W_ib for the
    /// current k_; boundary particles take `boundaryK`, or mirror k_i when it is empty.
    void applyPressure(StepContext& ctx, std::span<const float> boundaryK);
    /// Zeroes the k sums a solve's pushes leave for its loads (walls: the boundary's too).
    void startWallImpulses(const StepContext& ctx, bool walls);
    /// Adds each boundary pair's part of the solve's pushes to ctx.loads, from the k sums;
    /// `mirrored`: the walls took k_i (the divergence solve). Recorded once per solve, not per
    /// iteration: per iteration it cost about 5 % of a step with loads (docs/rigid-bodies.md).
    void recordWallImpulses(StepContext& ctx, bool mirrored) const;
    /// κ̄_i = Σ_j m_j W_ij κ_j / Σ_j m_j W_ij over i and its fluid neighbours
    /// (SolverDef::differenceForm), into error_.
    void smoothKappa(StepContext& ctx);
    /// error_ ← its kernel average Σ_j W_ij e_j / Σ_j W_ij over i and its fluid neighbours
    /// (SolverDef::smoothDensityError); uses positionK_, free between an iteration's error
    /// and its push.
    void smoothDensityError(StepContext& ctx);

    std::vector<float> alpha_;
    /// The divergence solve's max(Dρ/Dt, 0), or the density solve's ρ* − ρ0, signed (one
    /// array for both: 4 bytes a particle)
    std::vector<float> error_;
    std::vector<float> k_;             ///< κ·Δt (divergence) or κ·Δt² (density) of one iteration
    std::vector<float> kappa_;         ///< κ of the density solve so far, m²/s²
    std::vector<float> fluidKernelSum_;  ///< Σ_j W_ij over i and its fluid neighbours (SolverDef::smoothDensityError)
    std::vector<float> smoothedError_;   ///< smoothDensityError's output, swapped into error_
    std::vector<float> boundaryK_;     ///< k of the walls for one iteration (like k_)
    std::vector<float> loadK_;         ///< Σ k_ over a solve's pushes (with loads only)
    std::vector<float> loadBoundaryK_; ///< Σ boundaryK_ over the density solve's pushes (with loads only)
    WallPressure wall_;
    DensityContrast contrast_;         ///< several rest densities: Solenthaler & Pajarola 2008
    JacobiWeightScale weightScale_;    ///< the Jacobi weights' factor for supports beyond 2 spacings
    std::vector<float> scaledKappa_;   ///< κ̃ = κ ρ0_i/ρ0_ref for the wall pressure (several rest densities)
    PairKernels fluidF_;                     ///< W'(r)/r per fluid pair
    PairKernels wallF_;                      ///< W'(r)/r per fluid–boundary pair
    std::vector<glm::vec3> fluidGradient_;   ///< Σ_j m_j ∇W_ij
    std::vector<glm::vec3> wallGradient_;    ///< Σ_b V_b ∇W_ib
    std::vector<float> wallVelocityRate_;    ///< Σ_b V_b v_b·∇W_ib (moving walls only)
    std::vector<glm::vec4> positionMass_;    ///< (x_j, m_j); (x_j, 1) with a density contrast
    /// With a density contrast only: (x_j, m_j) for α, (x_j, μ_j) for the viscosity, then (x_j, m_j) for XSPH
    std::vector<glm::vec4> mixedRows_;
    /// (x_j, m_j k_j/ρ_j) of one iteration; in the density solve, between an iteration's start
    /// and its κ update, the predicted (x_j + Δt v_j, m_j), and in the divergence solve between
    /// iterations (v_j, 1/ρ_j) or (v_j, m_j/ρ_j) (one array for three: 16 bytes a particle)
    std::vector<glm::vec4> positionK_;
    std::vector<glm::vec3> wallMoved_;       ///< x_b + Δt v_b (moving boundaries only)
    XsphFilter xsph_;
    std::vector<glm::vec3> savedVelocity_;  ///< before a step that may be retaken (density contrast)
    double dtCap_ = 1e30;              ///< s; halved when a density solve diverges (density contrast)
    bool densityConverged_ = true;    ///< whether the last density solve reached its target
    bool densityDiverged_ = false;     ///< whether the last density solve diverged (density contrast)
    double lastDt_ = 1e-3;             ///< s; the divergence solve runs before this step's dt is known
};

}  // namespace tide
