#pragma once
/// \file
/// Dye diffusion between miscible materials: the SPH second derivative of Cleary & Monaghan
/// 1999, "Conduction modelling using smoothed particle hydrodynamics" (J. Comput. Phys. 148,
/// eq. 9, written there for heat with conductivities k_i), for a concentration c with
/// diffusivity D, Dc/Dt = (1/ρ) ∇·(ρ D ∇c):
///   dc_i/dt = Σ_j m_j/(ρ_i ρ_j) (ρ_i + ρ_j) D_ij (c_i − c_j) (r_ij·∇W_ij)/(r_ij² + η²),
/// η² = 0.01 ĥ² (ĥ = support/2), D_ij from MaterialPairs (0 between immiscible materials). The
/// paper's pair conductivity 4 k_i k_j/(k_i + k_j) is 2ρD for one fluid; with a diffusivity
/// given per pair, (ρ_i + ρ_j) D_ij is its counterpart. Each pair's term is m_j K_ij (c_i − c_j)
/// with K_ij = K_ji, so m_i Δc_i = −m_j Δc_j: Σ_i m_i c_i is conserved to round-off.
/// Explicit in time, stable for D Δt/s² ≤ 1/8 (the solvers' viscous step limit covers D).

#include <vector>

#include "core/material_pairs.hpp"
#include "solvers/solver.hpp"

namespace tide {

class DyeDiffusion {
public:
    /// c_i += Δt dc_i/dt over the step's neighbour lists at the current positions.
    void apply(ParticleStore& p, const NeighborList& neighbors, const PeriodicBox& box, const MaterialPairs& pairs,
               const kernels::SmoothingKernel& w, float dt, int threads);

private:
    std::vector<float> rate_;
};

}  // namespace tide
