#pragma once
/// \file
/// Position Based Fluids after Macklin & Müller 2013 ("Position Based Fluids", ACM TOG 32(4)),
/// for interactive use: a fixed step (SolverDef::maxDt, or shorter to land on a frame) and a
/// fixed number of Jacobi iterations (SolverDef::constraintIterations), so a step costs the
/// same however the fluid moves. Not for engineering accuracy: the density constraint is met
/// to what the iterations reach, not to a tolerance (docs/live.md).
///
/// One step (Algorithm 1): v += Δt g; x* = x + Δt v; then per iteration
///   C_i = ρ_i/ρ0_i − 1,  ρ_i = m_i Σ_j W_ij + ρ0_i Σ_b V_b W_ib                   (eq. 1)
///     (the density-contrast form of Solenthaler & Pajarola 2008, so several rest densities
///     meet at their own ρ0; walls and obstacles are Akinci et al. 2012 boundary particles),
///   λ_i = −C_i / (Σ_k w_k |∇_k C_i|² + ε)                                       (eq. 11)
///     with inverse-mass weights w_k ∝ 1/m_k (Macklin et al. 2014, "Unified particle
///     physics for real-time applications", eq. 4: heavy particles move less, so buoyancy
///     comes out right), clamped to C_i ≥ 0 (no tension at the free surface),
///   Δx_i = w_i [Σ_j (λ_i V_i + λ_j V_j + V̄ s_corr) ∇W_ij + λ_i Σ_b V_b ∇W_ib]    (eq. 12, 14)
///   s_corr = −k h² [(W_ij / W(Δq))ⁿ − (W(s) / W(Δq))ⁿ]₊, k 0.1, n 4, Δq 0.2 h   (eq. 13)
///     (k in units of h²: the paper's scenes have h ≈ 1; less its value at the rest spacing s,
///     so only pairs closer than that repel),
/// then v = (x* − x)/Δt, XSPH smoothing (eq. 17, SolverDef::xsph) and vorticity confinement
/// (eq. 15–16, SolverDef::vorticity). Density with the solver's kernel (the cubic spline, which
/// the particle masses are calibrated with), gradients with the spiky kernel as in the paper:
/// the spline's gradient vanishes as r → 0, and a particle pressed onto a wall or a neighbour
/// then had a large C over a tiny ∇C, a correction of a spacing per iteration (measured: the
/// seed's tank diverged at 0.6 s, 30 m/s, with the spline's gradient).
/// The iterations' pair loops run in SIMD lanes (solvers/pbf_pair_sums.hpp): two passes an
/// iteration, the λ pass (which leaves each pair's gradient factor and s_corr) and the correction.
/// The neighbour lists are the World's, found (as in Algorithm 1) at the predicted positions
/// x*: predict() moves the particles there before the World's search. Lists found at the
/// step's start missed the pairs that come into range over the step: the seed's tank at one
/// 1/60 s step a frame collapsed (mean compression 50 % at 1 s).

#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "solvers/solver.hpp"
#include "solvers/xsph_monaghan1989.hpp"

namespace tide {

class PbfMacklin2013 final : public Solver {
public:
    [[nodiscard]] std::string_view name() const override { return "pbf"; }
    [[nodiscard]] DensityKernel densityKernel() const override { return DensityKernel::Smoothing; }
    [[nodiscard]] bool usesWallPressure() const override { return false; }
    [[nodiscard]] bool recordsWallLoads() const override { return false; }
    void predict(ParticleStore& particles, const SolverDef& def, const glm::vec3& gravity, double maxDt,
                 int threads) override;
    double step(StepContext& ctx) override;
    void reserve(std::size_t particles, std::uint64_t slots) override;
    [[nodiscard]] std::vector<double> carriedState() const override { return {lastDt_}; }
    bool restoreCarriedState(std::span<const double> state) override {
        if (state.size() != 1) return false;
        lastDt_ = state[0];
        return true;
    }

private:
    /// λ_i (eq. 11) at the current predicted positions, and each pair's W'(r)/r and s_corr.
    void solveLambda(StepContext& ctx, float epsilon, bool lastIteration);
    /// Δx_i (eq. 14) from the λ and pair factors of solveLambda, `share` of it added to the
    /// positions (and to moved_), which it packs for the next λ pass.
    void applyCorrection(StepContext& ctx, float share);
    /// A split run's ghosts: their owners' λ (and correction rows), then their owners' corrected positions.
    void refreshGhostLambdas(StepContext& ctx);
    void refreshGhostPositions(StepContext& ctx);
    /// ε of eq. 11: a fraction of the denominator of a particle inside the rest lattice.
    [[nodiscard]] float relaxation(const StepContext& ctx);
    /// Vorticity confinement (eq. 15–16): v_i += Δt ε (N × ω_i).
    void confineVorticity(StepContext& ctx, float dt, float epsilon);

    std::vector<glm::vec3> moved_;       ///< Σ of the step's corrections Δx
    std::vector<float> volume_;          ///< V_i = m_i/ρ0_i
    std::vector<float> weight_;          ///< w_i = ρ0_ref/ρ0_i: inverse mass relative to material 0's (one lattice volume)
    std::vector<float> lambda_;          ///< λ_i, m²
    std::vector<glm::vec3> wallGradient_;  ///< Σ_b V_b ∇W_ib
    std::vector<glm::vec4> rows_;        ///< (x_j, V_j) for solveLambda (and XSPH's scratch)
    std::vector<glm::vec4> correctionRows_;  ///< (x_j, λ_j V_j) for applyCorrection
    std::vector<float> weightedVolume2_; ///< w_j V_j²
    std::vector<float> pairFactor_;      ///< W'(r)/r of the spiky kernel per pair slot
    std::vector<float> pairCorrection_;  ///< s_corr V̄ per pair slot, m⁵
    std::vector<glm::vec4> massRows_;    ///< (x_j, m_j) for XSPH's SIMD sums
    std::vector<glm::vec4> wallRows_;    ///< (x_b, 0), x_b + Δt v_b where boundaries move
    std::vector<glm::vec3> vorticity_;   ///< ω_i
    XsphFilter xsph_;
    double lastDt_ = 0.0;                ///< s; the last step's, for the share of a shorter one
    bool predicted_ = false;             ///< predict() moved the particles to x* for this step
    float latticeDenominator_ = 0.0f;    ///< Σ_j |∇_j C_i|² in the rest lattice (cached)
    float latticeKey_[2] = {0.0f, 0.0f}; ///< (h, spacing) it was computed for
};

}  // namespace tide
