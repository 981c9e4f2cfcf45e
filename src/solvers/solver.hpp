#pragma once
/// \file
/// The solver interface: one virtual call per step, plain loops inside. Solvers are
/// created by name (SolverDef::method) through makeSolver().

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <tide/defs.hpp>
#include <tide/particles.hpp>

#include "boundary/boundary_particles.hpp"
#include "comm/exact_sum.hpp"
#include "core/kernels.hpp"
#include "core/material_pairs.hpp"
#include "core/phase_clock.hpp"
#include "core/periodic_box.hpp"
#include "loads/wall_loads.hpp"
#include "neighbors/neighbor_list.hpp"
#include "solvers/viscosity.hpp"

namespace tide {

/// What a solver needs when its World is split among processes (src/core/world_distributed.hpp):
/// the particles it holds include ghost copies of other ranks' particles, whose fields it
/// computed from an incomplete neighbourhood. Before a loop reads a field it computed from
/// neighbours, it refreshes the ghosts' copy from their owners; maxima are taken over every
/// rank (including fresh ghosts in a max is harmless: they are copies).
class StepSharing {
public:
    virtual ~StepSharing() = default;
    virtual void refreshGhosts(std::span<float> field) const = 0;
    virtual void refreshGhosts(std::span<glm::vec3> field) const = 0;
    [[nodiscard]] virtual float maxOverRanks(float local) const = 0;
    /// 1 for each ghost in the store, 0 for a particle this rank owns.
    [[nodiscard]] virtual std::span<const std::uint8_t> ghosts() const = 0;
    /// Replaces each accumulator by its sum over every rank (collective; one exchange).
    virtual void sumOverRanks(std::span<comm::ExactSum> sums) const = 0;
};

/// Everything a solver sees during one step.
struct StepContext {
    ParticleStore& particles;
    const NeighborList& neighbors;
    std::span<const MaterialDef> materials;
    const SolverDef& solver;
    glm::vec3 gravity;
    float supportRadius;     ///< h, m
    float particleSpacing;   ///< m
    float soundSpeed;        ///< c, m/s
    const BoundaryParticles& boundary;      ///< static walls (may be empty)
    const CrossNeighborList& boundaryNeighbors;  ///< boundary particles near each fluid particle
    /// Fluid particles near each boundary particle near fluid: its list a is boundary
    /// particle boundaryNearFluid[a]'s (built only for solvers that use the wall pressure).
    const CrossNeighborList& boundaryFluidNeighbors;
    std::span<const std::uint32_t> boundaryNearFluid;  ///< boundary particles within h of fluid, ascending
    PeriodicBox periodic;    ///< the domain's periodic axes
    ViscosityModel viscosity;  ///< SolverDef::viscosity resolved (the solver's own when not named)
    int threads;
    double maxDt;            ///< the step may not be longer (e.g. to land on a frame time)
    int pressureIterations = 0;  ///< out: iterations the pressure solve took this step
    int divergenceIterations = 0;  ///< out: of them, dfsph's divergence-free solve's (0 for the others)
    /// out: false when the pressure solve stopped (at max_iterations, or diverging) short of
    /// its density tolerance; explicit solvers leave it true.
    bool pressureConverged = true;
    PhaseClock* clock = nullptr;  ///< where a solver books the phases of its step (may be null)
    const MaterialPairs* pairs = nullptr;  ///< per-pair diffusivity and surface tension (may be null: none)
    /// Where the solver records what each boundary particle applies to each fluid particle,
    /// slot boundaryNeighbors.offset(i) + k (loads/wall_loads.hpp), or null: loads are off.
    WallLoads* loads = nullptr;
    /// Fluid rows a solver keeps packed for the SIMD pair sums (solvers/pair_sums.hpp), current
    /// while it computes the non-pressure forces, or null: (x_j, m_j) and (v_j, 1/ρ_j); or,
    /// with several rest densities, (x_j, μ_j) as viscosityRows and (v_j, m_j/ρ_j).
    const glm::vec4* positionMassRows = nullptr;
    const glm::vec4* velocityRows = nullptr;
    const glm::vec4* viscosityRows = nullptr;
    /// The world's dimension (WorldDef::dimensions): 2 normalises the kernels per area.
    int dimensions = 3;
    /// A World split among processes, or null: one process (then the two below do nothing).
    const StepSharing* sharing = nullptr;
    void refreshGhosts(std::span<float> field) const {
        if (sharing) sharing->refreshGhosts(field);
    }
    void refreshGhosts(std::span<glm::vec3> field) const {
        if (sharing) sharing->refreshGhosts(field);
    }
    [[nodiscard]] float maxOverRanks(float local) const { return sharing ? sharing->maxOverRanks(local) : local; }

    /// x_a − x_b to the nearest periodic image: every pair vector of a solver, fluid–fluid
    /// and fluid–boundary, goes through this (the plain difference without periodic axes).
    [[nodiscard]] glm::vec3 delta(const glm::vec3& a, const glm::vec3& b) const { return periodic.delta(a, b); }
    /// The smoothing kernel of the sums (SolverDef::kernel), support h.
    [[nodiscard]] kernels::SmoothingKernel kernel() const {
        return kernels::SmoothingKernel(supportRadius, solver.kernel, dimensions);
    }
    /// Müller's Poly6 (classic's density, the XSPH filter), support h.
    [[nodiscard]] kernels::Poly6 poly6() const { return kernels::Poly6(supportRadius, dimensions); }
    /// Books the time since the last lap to `phase`.
    void lap(Phase phase) const {
        if (clock) clock->lap(phase);
    }
};

/// The kernel a solver computes density with (Smoothing: SolverDef::kernel): particle masses
/// are calibrated with it.
enum class DensityKernel { Poly6, Smoothing };

/// A pressure/viscosity solver. step() computes densities and forces for the current
/// positions, picks a stable dt ≤ ctx.maxDt, and advances velocities and positions.
/// Boundaries and sources are applied by the World after it returns.
class Solver {
public:
    virtual ~Solver() = default;
    [[nodiscard]] virtual std::string_view name() const = 0;
    [[nodiscard]] virtual DensityKernel densityKernel() const = 0;
    /// Closest a particle centre may come to a wall or obstacle, in particle spacings: where
    /// the projection after each step puts strays back.
    [[nodiscard]] virtual float wallMargin() const { return 0.1f; }
    /// How far outside a solid's surface a block's point must lie to be filled, in particle
    /// spacings. The solid's boundary particles fill its lattice points up to the surface, so
    /// any point outside continues the lattice at rest density; the few within wallMargin()
    /// are moved out to it by the first step.
    [[nodiscard]] virtual float fillClearance() const { return 0.0f; }
    /// The viscosity model when SolverDef::viscosity names none.
    [[nodiscard]] virtual ViscosityModel defaultViscosity() const { return ViscosityModel::Morris1997; }
    /// Whether step() reads StepContext::boundaryFluidNeighbors (built only then).
    [[nodiscard]] virtual bool usesWallPressure() const { return true; }
    /// Whether step() writes StepContext::loads (otherwise the fluid's loads on solids are 0
    /// and the World neither clears nor sums the per-pair records).
    [[nodiscard]] virtual bool recordsWallLoads() const { return true; }
    /// Called before the neighbour search of a step of at most maxDt: a solver whose lists must
    /// be found where the particles are predicted to go (pbf, Macklin & Müller 2013, Algorithm
    /// 1, lines 1–7) moves them there and then step() does not. The default does nothing.
    virtual void predict(ParticleStore& /*particles*/, const SolverDef& /*def*/, const glm::vec3& /*gravity*/,
                         double /*maxDt*/, int /*threads*/) {}
    /// Returns the length of the step taken, s.
    virtual double step(StepContext& ctx) = 0;
    /// Sizes (and touches) the per-particle and per-pair scratch step() will use for about
    /// `particles` particles with `slots` pair slots in their neighbour lists, so that the first
    /// step costs what the later do (World::prepare). Changes no result; the default does nothing.
    virtual void reserve(std::size_t /*particles*/, std::uint64_t /*slots*/) {}
    /// Scalars the solver carries from one step to the next (not per particle: those live in
    /// the ParticleStore), for checkpoints; restoring them continues the run bit for bit.
    [[nodiscard]] virtual std::vector<double> carriedState() const { return {}; }
    /// Takes back what carriedState() gave; false (changing nothing) if it has the wrong size.
    virtual bool restoreCarriedState(std::span<const double> state) { return state.empty(); }
};

/// Creates the solver called `name`; throws std::invalid_argument for an unknown name.
std::unique_ptr<Solver> makeSolver(std::string_view name);

}  // namespace tide
