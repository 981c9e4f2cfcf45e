#pragma once
/// \file
/// tide::World — one simulation: particles, materials, sources and a solver.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <tide/defs.hpp>
#include <tide/ocean.hpp>
#include <tide/particles.hpp>

namespace tide {
namespace comm {
class Communicator;
}
// A World split among processes (src/core/world_distributed.hpp): its options, gauges and counts.
struct FieldSamples;
struct DistributionOptions;
struct RankCounts;

/// Why addBlock() added nothing.
enum class AddStatus {
    Added,           ///< every particle of the block was added
    OutsideDomain,   ///< the block is not inside the container
    OverCapacity,    ///< the block would exceed WorldDef::capacity
};

/// Wall-clock seconds spent in each phase of the steps, summed since creation (the
/// benchmark's split of the cost of a particle-step).
struct PhaseSeconds {
    double neighborSearch = 0.0;     ///< grid, neighbour lists, reordering
    double density = 0.0;            ///< densities and the solver's per-step factors
    double pressureSolve = 0.0;      ///< pressure forces, or the iterations of an implicit solve
    double nonPressureForces = 0.0;  ///< gravity, viscosity, XSPH
    double integration = 0.0;        ///< time step, positions, walls and obstacles, emitters, statistics
    double coupling = 0.0;           ///< an ocean's coupling zones: relaxation, outflow, inflow
};

/// Figures of the last step and running totals.
struct WorldStats {
    std::uint64_t steps = 0;            ///< time steps taken since creation
    double lastDt = 0.0;                ///< s
    float maxSpeed = 0.0f;              ///< m/s, after the last step
    float meanDensityError = 0.0f;      ///< mean |ρ − ρ0| / ρ0 over all particles, last step
    float meanCompression = 0.0f;       ///< mean max(ρ − ρ0, 0) / ρ0 (SPlisHSPlasH's measure)
    std::uint64_t emitterCapacityHits = 0;  ///< layers an emitter could not emit: world full
    int lastPressureIterations = 0;     ///< iterations of the last step's pressure solve (0: explicit)
    // Running totals over every step since creation:
    std::uint64_t pressureIterationsSum = 0;
    std::uint64_t divergenceIterationsSum = 0;  ///< of them, dfsph's divergence-free solve's
    /// Steps whose pressure solve stopped (at solver.max_iterations, or diverging) short of
    /// its density tolerance: the fluid carries the compression left over into the next step.
    std::uint64_t unconvergedSolves = 0;
    /// Bit k set: the pressure solve of the step k steps before the last (0: the last) did not converge.
    std::uint32_t recentUnconverged = 0;
    double dtMin = 0.0;                 ///< s, shortest step (0 before the first)
    double dtMax = 0.0;                 ///< s, longest step
    double dtSum = 0.0;                 ///< s, simulated time stepped
    float maxMeanDensityError = 0.0f;   ///< largest per-step meanDensityError
    float maxMeanCompression = 0.0f;    ///< largest per-step meanCompression
    std::uint64_t oceanAdded = 0;       ///< particles an ocean's inflow strips added
    std::uint64_t oceanRemoved = 0;     ///< particles that left through an ocean's open sides
    double sumMeanDensityError = 0.0;   ///< Σ over steps of meanDensityError (÷ steps = average)
    PhaseSeconds phaseSeconds;          ///< where the steps' wall time went
};

/// What World::settle did.
struct SettleReport {
    double seconds = 0.0;        ///< simulated with the clock held, s
    std::uint64_t steps = 0;
    float maxSpeed = 0.0f;       ///< m/s, the fastest particle after the last settling step, before the velocities were zeroed
    bool quiet = false;          ///< ended early: the water had stayed below the quiet speed for kSettleQuietTime
};

/// How long (simulated, s) every particle must stay below World::settle's quiet speed for the
/// settling to end early.
inline constexpr double kSettleQuietTime = 0.5;

/// The fluid's state interpolated at a point (World::probe); NaN where no fluid is near.
struct ProbeSample {
    float density;       ///< kg/m³
    float pressure;      ///< Pa
    glm::vec3 velocity;  ///< m/s
};

/// A quantity the per-step divergence guard found bad.
enum class DivergedQuantity {
    Position,     ///< not finite
    Velocity,     ///< not finite
    Density,      ///< not finite
    Pressure,     ///< not finite
    Speed,        ///< finite but runaway: |v| Δt beyond kRunawaySupports support radii
    Compression,  ///< the whole fluid collapsed: mean compression beyond kCollapsedCompression
};

/// A particle moving further than this many kernel supports in one step has left every
/// neighbour it had: no stable time step (CFL ≤ 1 allows one support at most) does that.
inline constexpr float kRunawaySupports = 4.0f;
/// A liquid compressed by half on average has collapsed (e.g. a forced time step far beyond
/// stability): its mean max(ρ − ρ0, 0)/ρ0 above this stops the run.
inline constexpr float kCollapsedCompression = 0.5f;
/// Rest densities this many times apart: a dfsph run that diverges is told pcisph may hold
/// it (measured: layers at 5:1 and 25:1 that dfsph did not hold, docs/robustness.md).
inline constexpr float kFarApartDensities = 5.0f;

/// Where and how a run diverged: the step, and the first particle (lowest index) at fault.
struct Divergence {
    std::uint64_t step = 0;      ///< the step that produced it (WorldStats::steps, counting it)
    double time = 0.0;           ///< s, at the end of that step
    double dt = 0.0;             ///< s, that step's length
    std::uint32_t particle = 0;  ///< index in the particle store when it was found
    std::uint32_t id = 0;        ///< the particle's stable id
    DivergedQuantity quantity = DivergedQuantity::Position;
    /// The bad value: the non-finite component; Speed: |v| m/s; Compression: ρ kg/m³ of the
    /// most compressed particle.
    float value = 0.0f;
    /// The bound it broke: Speed: kRunawaySupports·h/Δt, m/s; Compression: the fluid's mean
    /// compression (above kCollapsedCompression); 0 for non-finite values.
    float limit = 0.0f;
    /// Of the 32 steps up to it, those whose pressure solve stopped short of its tolerance, and
    /// the solver.max_iterations they had: the usual way a pressure solve lets water collapse.
    int unconvergedOfLast32 = 0;
    int maxIterations = 0;
    /// The solver (SolverDef::method) and the largest over the smallest rest density of the
    /// materials: dfsph's Jacobi solve may not hold several densities far apart where pcisph
    /// does (docs/robustness.md § Thin layers of two densities), and the report says so.
    std::string solver;
    float densityRatio = 1.0f;
    /// One line for people, e.g. "step 12 (t = 0.034 s): particle 5 (id 7) has a non-finite velocity (nan)".
    [[nodiscard]] std::string describe() const;
};

/// Thrown by World::step when the state it produced has diverged; the World keeps the bad
/// state for inspection but refuses further steps until clear() or restoreState().
class DivergenceError : public std::runtime_error {
public:
    explicit DivergenceError(const Divergence& d) : std::runtime_error(d.describe()), divergence(d) {}
    Divergence divergence;
};

/// Where an obstacle is: the point x0 of its definition (its rest pose) is at
/// rotation · x0 + translation. Fixed obstacles: the identity.
struct ObstaclePose {
    glm::mat3 rotation{1.0f};
    glm::vec3 translation{0.0f};  ///< m
};

/// A solid the fluid can load: a face of the container, an obstacle or a wave paddle.
struct SolidInfo {
    enum class Kind { Wall, Obstacle, WaveMaker };
    Kind kind = Kind::Wall;
    /// Walls: the face, 2·axis + 1 on the max side (0 is −x, 3 is +y the lid, 4 is −z);
    /// obstacles and wave makers: their index among them.
    std::uint32_t index = 0;
    /// "wall_xmin", "wall_xmax", "wall_ymin" (the floor) … "wall_zmax"; the obstacle's name
    /// (ObstacleDef::name); "wavemaker<k>".
    std::string name;
};

/// The load the fluid puts on one solid: the reaction of the pressure and viscous forces the
/// solver applied to the fluid through the solid's boundary particles, pair by pair (all of a
/// step's pressure solves, e.g. dfsph's density and divergence solves), in N and N·m.
struct SolidLoad {
    glm::dvec3 pressureForce{0.0};
    glm::dvec3 viscousForce{0.0};  ///< viscosity and adhesion
    /// Of both, about the solid's reference point (ObstacleDef::loadReference; a wall face's
    /// centre; a paddle's boundary particles' centroid), summing (x_b − reference) × f_b.
    glm::dvec3 moment{0.0};
    [[nodiscard]] glm::dvec3 force() const { return pressureForce + viscousForce; }
};

/// Where a dynamic obstacle (a body the fluid moves) is and how it moves.
struct BodyState {
    std::uint32_t obstacle = 0;          ///< its index among the obstacles
    std::string name;                    ///< the obstacle's name
    glm::dvec3 position{0.0};            ///< centre of mass, m
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  ///< rotation from the rest pose (w, x, y, z)
    glm::dvec3 velocity{0.0};            ///< of the centre of mass, m/s
    glm::dvec3 angularVelocity{0.0};     ///< rad/s
    glm::dvec3 contactForce{0.0};        ///< from walls, obstacles and other bodies, N (mean over the last step)
    /// Each mooring line (BodyDynamicsDef::moorings, in order): its name and tension, N.
    struct Mooring {
        std::string name;
        double tension = 0.0;
    };
    std::vector<Mooring> moorings;
};

/// What an emitter has accumulated during a run (its EmitterDef is the scene's).
struct EmitterProgress {
    bool active = true;
    double travelled = -1.0;  ///< stream length since the last layer, m; < 0 before its first step
};

/// Everything of a World that evolves while it runs: restoring it into a World built from the
/// same definitions continues the run bit for bit (a checkpoint). Wave makers and moving
/// obstacles need nothing here: their motion is a function of time (random phases come from
/// their seed).
struct WorldState {
    double time = 0.0;                    ///< s
    float soundSpeed = 0.0f;              ///< m/s, 0 until the first step resolves it
    std::int32_t stepsSinceReorder = 0;   ///< the particle order is part of the arithmetic
    WorldStats stats;
    ParticleStore particles;              ///< every array, in the store's current order, and the next id
    std::vector<EmitterProgress> emitters;
    std::vector<double> solverState;      ///< scalars the solver carries between steps (see Solver)
    std::vector<double> bodyState;        ///< the dynamic obstacles' state (tide::bodies::BodySystem)
    /// The wave makers' active absorption (WaveMakerDef::absorption), per paddle that has it:
    /// its correction's offset, velocity and start time, the error's mean, its time, started.
    std::vector<double> paddleState;
};

/// Names of the solvers World accepts in SolverDef::method.
std::vector<std::string> solverNames();

/// Names of the viscosity models World accepts in SolverDef::viscosity.
std::vector<std::string> viscosityNames();

/// One simulation. Not copyable; move it or hold it by pointer.
///
/// Creation validates the WorldDef and throws std::invalid_argument naming the field
/// and value at fault. All units are SI.
class World {
public:
    explicit World(const WorldDef& def);
    ~World();
    World(World&&) noexcept;
    World& operator=(World&&) noexcept;
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    /// Add a material; its index is returned. Throws std::invalid_argument on bad values.
    MaterialIndex addMaterial(const MaterialDef& material);
    [[nodiscard]] const std::vector<MaterialDef>& materials() const;
    /// Mass of one particle of a material, kg (ρ0 times the volume a lattice particle fills).
    [[nodiscard]] float particleMass(MaterialIndex material) const;
    /// Set how two added materials meet (miscibility, dye diffusivity, surface tension; see
    /// MaterialPairDef), replacing an earlier setting of the same pair in either order.
    /// Throws std::invalid_argument naming the field at fault.
    void setMaterialPair(const MaterialPairDef& pair);
    /// The pairs set, in the order set (a replaced pair keeps its place).
    [[nodiscard]] const std::vector<MaterialPairDef>& materialPairs() const;
    /// Σ m_i c_i / Σ m_i: the mass-weighted mean dye concentration (0 without particles),
    /// which diffusion conserves.
    [[nodiscard]] double meanConcentration() const;

    /// Fill a box with particles: the points of the lattice the walls and obstacles are sampled
    /// on (cell corners at domainMin, in x at the first wave maker's face) whose cells lie
    /// inside the box. Leaves out points inside obstacles, within half a spacing of a moving
    /// obstacle other than a box or of a wave maker, and closer than 0.9 spacing to any
    /// boundary particle.
    /// Adds all of them or none (see AddStatus).
    AddStatus addBlock(const BlockDef& block);
    /// Whether a box lies inside the container (without walls: inside the periodic axes' extent).
    [[nodiscard]] bool insideDomain(const glm::vec3& min, const glm::vec3& max) const;
    /// Number of particles addBlock(block) would add.
    [[nodiscard]] std::uint32_t countBlock(const BlockDef& block) const;

    /// Add an obstacle (sampled as boundary particles), fixed or moving by its `motion`. Add
    /// obstacles before blocks: blocks leave out the lattice points that fall inside an
    /// obstacle (where it is at the time of adding). A moving obstacle is sampled where it
    /// lies inside the container at rest. Throws std::invalid_argument naming the field at fault.
    void addObstacle(const ObstacleDef& obstacle);
    /// The obstacles as defined (moving ones in their rest pose; see obstaclePose()).
    [[nodiscard]] const std::vector<ObstacleDef>& obstacles() const;
    /// Where obstacle `index` is at time t (its motion's pose; the identity when fixed).
    [[nodiscard]] ObstaclePose obstaclePose(std::uint32_t index, double t) const;
    /// Particles outside the container or inside an obstacle (moving ones where they are now): should always be 0.
    /// In a run split among processes, over every rank (collective).
    [[nodiscard]] std::uint32_t countEscapedParticles() const;

    /// Add a wave paddle (a moving boundary, see WaveMakerDef). Add it before obstacles and
    /// blocks: blocks leave out the lattice points behind its face, and the first paddle's
    /// face puts the cell corners of the lattice they are sampled on in x (so that the water
    /// continues the paddle's particles); the walls move onto that lattice too, while there are
    /// no obstacles or particles yet. Throws std::invalid_argument naming the field at fault.
    void addWaveMaker(const WaveMakerDef& waveMaker);
    [[nodiscard]] std::uint32_t waveMakerCount() const;
    /// Horizontal displacement of wave maker `index`'s face at the still-water level at time t, m.
    [[nodiscard]] float waveMakerDisplacement(std::uint32_t index, double t) const;
    /// Add a damping zone that absorbs waves (see DampingZoneDef).
    void addDampingZone(const DampingZoneDef& zone);

    /// Couple the domain (the near field) to a far-field sea (issue 43; docs/ocean.md): the
    /// sides in ocean.openSides lose their walls and get coupling zones of width
    /// oceanZoneWidth(ocean), where particle velocities relax towards the sea's, particles
    /// past the open face are removed and particles of `material` are added where the sea's
    /// water stands and none is. The sea's still water is at domainMin.y + ocean.depth. Call it
    /// before obstacles and blocks (the walls are sampled again) and once; then fillOcean().
    /// Throws std::invalid_argument naming the field at fault (ocean.*, a periodic open axis,
    /// a zone wider than the domain, a wave maker with an open -x side).
    void setOcean(const OceanDef& ocean, MaterialIndex material = 0);
    /// Fill the domain with the ocean's still water, up to its depth, on the lattice (leaving
    /// out solids as addBlock does). Call after obstacles.
    AddStatus fillOcean();
    /// Whether setOcean was called.
    [[nodiscard]] bool hasOcean() const;
    /// The ocean setOcean was given, or none.
    [[nodiscard]] std::optional<OceanDef> ocean() const;
    /// The far field's ramp factor now: 0 at t = 0, 1 after one peak period (1 without an ocean).
    [[nodiscard]] double oceanRamp() const;
    /// The far field's surface height y at (x, z) now (ramped in over the first peak period,
    /// as the zones see it), m. Throws std::logic_error without an ocean.
    [[nodiscard]] double oceanSurfaceHeight(double x, double z) const;

    /// Free-surface height y at (x, z), m: where the SPH colour field of the fluid crosses ½
    /// on the vertical line (DualSPHysics' gauge criterion); NaN where the line is dry. With an
    /// ocean, outside the domain's x–z extent: the far field's (oceanSurfaceHeight).
    [[nodiscard]] float surfaceHeight(float x, float z) const;
    /// Density, pressure and velocity interpolated at a point (Shepard-normalised SPH sum).
    [[nodiscard]] ProbeSample probe(const glm::vec3& point) const;
    /// The dynamic obstacles (ObstacleDef::dynamics), in the order added, as they are now.
    [[nodiscard]] std::vector<BodyState> bodies() const;
    /// Every solid the fluid can load, in the order of solidLoads(): the container's six faces
    /// (those a periodic axis or WorldDef::walls = false leaves out carry no load), then
    /// wave makers and obstacles in the order they were added.
    [[nodiscard]] const std::vector<SolidInfo>& solids() const;
    /// The index in solids() of the solid called `name`, or none.
    [[nodiscard]] std::optional<std::uint32_t> findSolid(const std::string& name) const;
    /// Each solid's load over the last step (zero before the first, or with WorldDef::loads off).
    [[nodiscard]] const std::vector<SolidLoad>& solidLoads() const;
    /// Each solid's load averaged over the time stepped since the last call (the momentum it
    /// exchanged with the fluid, divided by that time), and starts a new average. Zero when
    /// no time was stepped.
    std::vector<SolidLoad> takeMeanSolidLoads();
    /// Σ of the fluid particles' masses, kg.
    [[nodiscard]] double totalMass() const;

    /// Add a continuous source; returns its index for setEmitterActive().
    std::uint32_t addEmitter(const EmitterDef& emitter);
    /// Switch an emitter on or off (on when added).
    void setEmitterActive(std::uint32_t emitter, bool active);
    [[nodiscard]] std::uint32_t emitterCount() const;

    /// Take one time step of adaptive length, at most maxDt seconds; returns its length.
    /// Every step checks the state it produced (non-finite values, runaway speed, collapse)
    /// and throws DivergenceError naming the step, time, particle and quantity when it is bad.
    double step(double maxDt);
    /// Advance exactly `duration` seconds in as many adaptive steps as needed, calling
    /// `afterStep` (if given) after each one, e.g. to report progress.
    void advance(double duration, const std::function<void()>& afterStep = {});

    /// Pre-roll: let the particles find the arrangement in which they rest, before the run.
    /// A lattice is not one under pressure: water put on the cubic lattice of addBlock buckles
    /// under its hydrostatic pressure from the floor up, and moves for seconds while its
    /// particles rearrange and sink into a denser packing (max speeds of 0.07 m/s after 2 s
    /// in a 0.3 m tank; docs/robustness.md § Still water). This steps the solver for `seconds`
    /// of simulated time with the clock held at time(): moving boundaries stand still where
    /// they are, emitters emit nothing; with a `quietSpeed` > 0 it ends sooner, once every
    /// particle has stayed below that speed for kSettleQuietTime. Then every velocity is zeroed
    /// and the statistics start again; time() is unchanged. Throws std::invalid_argument naming
    /// settle.time or settle.speed for a negative or non-finite value, and DivergenceError as
    /// step() does. `afterStep` (if given) is called after each step, as advance() does: a
    /// host may report progress or throw to stop (Python's Ctrl-C), leaving the world as the
    /// last step left it.
    SettleReport settle(double seconds, float quietSpeed = 0.0f, const std::function<void()>& afterStep = {});

    [[nodiscard]] double time() const;
    [[nodiscard]] const ParticleStore& particles() const;
    /// Velocities of every particle, writable between steps, for interactive tools (a
    /// viewer's mouse push). Positions and the other arrays stay the solver's to change.
    [[nodiscard]] std::span<glm::vec3> velocities();
    /// Room for `particles` particles in every particle array (at most the capacity): the
    /// arrays then stay where they are while particles are added up to that count, so views
    /// of them that a caller holds (the Python module's numpy arrays) stay valid.
    void reserve(std::uint32_t particles);
    /// Finds the neighbour lists of the particles as they stand and sizes (and touches) the
    /// scratch the solver's steps use for them, so that the first step costs what the later
    /// do: a live application calls it at load time, after adding its particles (Fluid does, in
    /// addPoint). Fresh memory costs a page fault a page on first use, which made a live demo's
    /// first frame 2.5 times its median. Changes no result; does nothing in a run split among
    /// processes (its steps exchange particles first).
    void prepare();
    [[nodiscard]] const WorldStats& stats() const;
    [[nodiscard]] const WorldDef& def() const;
    /// Kernel support radius h, m.
    [[nodiscard]] float supportRadius() const;
    /// Worker threads the hot loops use.
    [[nodiscard]] int threads() const;
    /// Remove every particle and emitter, keep materials, reset time to 0.
    void clear();

    /// The divergence the last step found, if any (cleared by clear() and restoreState()).
    [[nodiscard]] const std::optional<Divergence>& divergence() const;
    /// A copy of everything that evolves (see WorldState), for checkpoints. In a World split
    /// among processes: this rank's piece (the particles it owns; the rest is the same on
    /// every rank). The pieces of all ranks, their particles joined, restore into an unsplit
    /// World built from the same definitions, which may then be split among any number.
    [[nodiscard]] WorldState saveState() const;
    /// Continue from a saved state. The World must have been built from the same definitions
    /// (materials, emitters, solver); a state that does not fit them (array sizes, material
    /// indices, emitter count, capacity, solver scalars) throws std::invalid_argument naming
    /// the mismatch and leaves the World unchanged. A split World throws std::logic_error
    /// (restore first, then split).
    void restoreState(WorldState state);

    struct Impl;  ///< the state (src/core/world_impl.hpp)

private:
    // A run split among processes (src/core/world_distributed.hpp) reaches into the state.
    friend void distributeWorld(World& world, comm::Communicator& comm, const DistributionOptions& options);
    friend RankCounts gatherRankCounts(const World& world, comm::Communicator& comm);
    friend ParticleStore gatherOwnedParticles(const World& world, comm::Communicator& comm);
    friend std::vector<std::uint32_t> ownedIndices(const World& world);
    friend FieldSamples sampleOverRanks(const World& world, comm::Communicator& comm,
                                         std::span<const glm::vec2> gauges, std::span<const glm::vec3> probes);
    std::unique_ptr<Impl> impl_;
};

}  // namespace tide
