#pragma once
/// \file
/// Plain definition structs that describe a simulation, with sensible defaults.
/// They are validated once, when handed to tide::World; all quantities are SI.

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace tide {

class TriangleMesh;  // <tide/triangle_mesh.hpp>

/// Index of a material in a World (0 is the first material added).
using MaterialIndex = std::uint16_t;

/// Physical properties of one fluid.
struct MaterialDef {
    std::string name = "water";
    float restDensity = 1000.0f;            ///< kg/m³
    float viscosity = 0.001f;               ///< dynamic viscosity μ, Pa·s
    glm::vec3 color{0.2f, 0.45f, 0.9f};     ///< linear RGB in [0, 1], for renderers
    /// Adhesion β to walls and obstacles (Akinci, Akinci & Teschner 2013, eq. 6–7), ≥ 0: the
    /// boundary particles within a kernel support pull this fluid's particles towards them
    /// (a_i = −β Σ_b ρ0_i V_b A(r_ib) r̂_ib, A the paper's adhesion spline). Like γ of
    /// MaterialPairDef::surfaceTension it is a model parameter, not a physical one; 0 (the
    /// default) switches it off.
    float adhesion = 0.0f;
};

/// How two materials (or a material with itself, a == b) meet: World::setMaterialPair.
/// Pairs never set are immiscible. Fluids of different rest density
/// always keep their own density and do not mix (density-contrast SPH, Solenthaler &
/// Pajarola 2008); what a miscible pair exchanges is dye (ParticleStore::concentration).
struct MaterialPairDef {
    MaterialIndex a = 0;
    MaterialIndex b = 0;
    /// a ≠ b: dye diffuses across their interface at `diffusivity`. (A material is always
    /// miscible with itself.)
    bool miscible = false;
    /// Fickian diffusivity D of the dye concentration, m²/s (SPH form of Cleary & Monaghan
    /// 1999). For a ≠ b it needs `miscible`. A material's own D (pair a == a) defaults to the
    /// largest D of its miscible pairs, so dye that crosses an interface keeps spreading.
    /// Physical dyes in water are ~1e-9; visible mixing over seconds at centimetre spacings
    /// needs ~1e-4. The explicit update limits dt to 0.125 s²/D (s the particle spacing).
    float diffusivity = 0.0f;
    /// Surface or interface tension γ ≥ 0 of Akinci, Akinci & Teschner 2013 ("Versatile
    /// surface tension and adhesion for SPH fluids", ACM TOG 32(6)), cohesion plus curvature
    /// (solvers/surface_tension_akinci2013.hpp). A model parameter, not a tension in N/m:
    /// its effect depends on the rest density and little on the spacing.
    ///  - a == b: surface tension of a. Its particles attract each other (cohesion) and
    ///    smooth the surface they bound (curvature term), which shrinks a's free surface and
    ///    also every interface of a with another material (a does not attract the other one).
    ///  - a ≠ b: interface tension between a and b: the same terms with the signs that push a
    ///    and b particles apart, so the a–b interface shrinks (a blob of b in a rounds up).
    /// 0 (the default) switches it off, at no cost. Limits dt (the force criterion, see there).
    float surfaceTension = 0.0f;
};

/// Pressure from density.
enum class EquationOfState {
    Linear,  ///< p = κ (ρ − ρ0), κ = c² (Müller et al. 2003)
    Tait,    ///< p = B ((ρ/ρ0)^7 − 1), B = ρ0 c² / 7 (Becker & Teschner 2007)
};

/// The smoothing kernel of the SPH sums (dfsph, pcisph, wcsph; classic keeps Müller's).
enum class KernelShape {
    CubicSpline,  ///< Monaghan 1992: the default; at 2 spacings the cheapest
    /// Wendland 1995 C2, as DualSPHysics' default: stable against particle pairing (Dehnen &
    /// Aly 2012), so wide supports (3 spacings) stay ordered; there standing waves keep
    /// linear theory's frequency (within 0.5 %, the cubic spline at 2 spacings 2.5–3.3 % off:
    /// docs/waves.md). At 2 spacings it is too narrow (+15 %).
    WendlandC2,
    /// The world's choice (the default, resolveAutomaticKernel): Wendland C2 in 2D, the cubic
    /// spline in 3D. At 2 spacings a 2D particle has 9 neighbours (3D: 27), too few to carry
    /// a wave: issue 42's 2D flume at 12.5 mm kept 0.0206 / 0.0170 m of a 0.03 m wave at 1.5 /
    /// 2.0 m with the cubic spline, 0.0280 / 0.0246 m with Wendland C2 at 3 spacings (25
    /// neighbours), at the same cost (fewer pressure iterations). docs/notes/waves.md.
    Automatic,
};
/// The support a world gives Wendland C2 unless it sets supportRatio, in spacings.
inline constexpr float kWendlandSupportRatio = 3.0f;
/// The support a world gives the cubic spline (and the classic solver's kernels) unless it sets supportRatio.
inline constexpr float kCubicSplineSupportRatio = 2.0f;

/// How the pressure/viscosity solver runs and how its time step is chosen.
struct SolverDef {
    /// Solver name, see tide::solverNames(): dfsph, pcisph, wcsph, classic (the seed's Müller 2003),
    /// pbf (position based fluids, Macklin & Müller 2013: for interactive use, docs/live.md).
    std::string method = "dfsph";
    KernelShape kernel = KernelShape::Automatic;  ///< scene key solver.kernel
    EquationOfState equationOfState = EquationOfState::Linear;
    /// Numerical speed of sound, m/s (classic, wcsph). 0 picks 10 × the free-fall speed
    /// over the domain height, which keeps density variations near 1 %.
    float soundSpeed = 0.0f;
    /// Negative pressures (tension) pull free-surface particles into clumps; clamp them
    /// to zero by default, as most SPH codes do.
    bool clampNegativePressure = true;
    /// Viscosity model by name, see tide::viscosityNames(): `morris` (Morris et al. 1997),
    /// `monaghan` (Monaghan 2005), `muller` (Müller et al. 2003), all physical (driven by
    /// the materials' Pa·s, no-slip walls), or `xsph` (no physical viscosity: XSPH smoothing
    /// alone). Empty: the solver's own (classic: muller, the others: morris).
    std::string viscosity;
    /// XSPH velocity smoothing ε (Monaghan 1989), in [0, 1]: an artificial viscosity that
    /// damps particle-scale noise, applied on top of any model; 0 switches it off.
    /// Negative: the solver's own default (classic 0.25, the others 0.01).
    float xsph = -1.0f;
    /// dfsph: heavy-ball momentum of the density solve (Polyak 1964), in [0, 0.95]: each
    /// Jacobi update adds this fraction of the last. Fewer iterations (8.9 instead of 15.5 a
    /// step at 0.7 on the benchmark dam break); waves keep more height without it in one flume
    /// and less in another (docs/waves.md § Defaults): 0 switches it off. Negative: the
    /// solver's default, 0.7. Unused with several rest densities (it overshoots their
    /// interfaces) and by the other solvers.
    float momentum = -1.0f;
    /// dfsph: Fickian particle shifting (Lind et al. 2012), in [0, 1]: after each step every
    /// particle with a full neighbourhood and no wall within reach moves by
    /// δr = −shifting · s² · Σ_j V_j ∇W_ij (s the particle spacing), down the gradient of the
    /// particle concentration, so the packing stays even without storing the energy the
    /// pressure's own regularisation would. Waves keep their height far longer (docs/waves.md:
    /// 0.2 took a 2 cm flume's loss at 5 wave lengths from 48 % to 22–28 %); 0 (the default)
    /// switches it off. Negative (the default): automatic, 0.2 in a world with a wave maker
    /// (the wave settings, docs/waves.md § Defaults), else 0.
    float shifting = -1.0f;
    /// dfsph: the share, in [0, 1], of the pressure force's self-term on the smoothed pressure
    /// taken in the difference form. The symmetric force Σ_j m_j (κ_i/ρ_i + κ_j/ρ_j) ∇W_ij holds
    /// −(κ_i/ρ_i) Σ_j m_j ∇W_ij, which vanishes only on an even packing with a full
    /// neighbourhood: under the hydrostatic pressure it stiffens the packing and pushes the
    /// surface layers out, and waves run fast (+3–4 %) and decay into particle-scale motion
    /// (measured: the gain comes from its smooth part at the surface). The difference form
    /// Σ_j V_j (κ_j − κ_i) ∇W_ij of incompressible SPH (Cummins & Rudman 1999; Lind et al.
    /// 2012) has none. After the density solve,
    /// v_i += share · Δt · 2 κ̄_i/ρ_i (Σ_j m_j ∇W_ij + ρ0 Σ_b V_b ∇W_ib), κ̄ the Shepard mean of κ
    /// over i's neighbours, so the fluctuation κ_i − κ̄_i keeps its regularisation. Meant with
    /// `shifting`, which keeps the packing even instead (docs/waves.md: 0.5 with shifting 0.2
    /// took a 2 cm flume's loss at 5 wave lengths from 22 % to 15 %). The price: still water
    /// is busier, and its pressure reads 2–7 % above ρgd (the solve makes up for the surface
    /// push taken out). 0 switches it off. Negative (the default): automatic, 0.5 in a world
    /// with a wave maker, else 0.
    float differenceForm = -1.0f;
    /// dfsph: the density solve drives the kernel average of the compression left,
    /// ē_i = Σ_j W_ij e_j / Σ_j W_ij (its own term included), to its target instead of each
    /// particle's own e_i: a Shepard (1968) filter of the residual, the zeroth-order form of
    /// the density filters of weakly compressible SPH (Colagrossi & Landrini 2003 use the
    /// first-order, MLS one on the density itself). The particle-scale part of the
    /// compression a wave's strain makes in the packing is then not projected out each step,
    /// and that projection is where much of a wave's height went: a 2D progressive wave at
    /// 8 mm (5 particles per H) lost 2.3 % a wave length with it against 4.3 %, at the price
    /// of busier still water (docs/notes/waves.md § Smoothing the density solve's residual).
    /// Costs a kernel sum per iteration (+16 % a step there). Unset (the default): automatic,
    /// on in a 2D world with regular or irregular waves or an ocean (sources/wave_numerics.hpp),
    /// else off.
    std::optional<bool> smoothDensityError;
    /// Incompressible solvers (dfsph, pcisph) iterate until the mean compression
    /// (ρ − ρ0)/ρ0 is below this (0.001 = 0.1 %).
    float maxDensityError = 0.001f;
    /// dfsph's divergence-free solve iterates until the mean compression rate times the step,
    /// (Dρ/Dt) Δt/ρ0, is below this (SPlisHSPlasH's maxErrorV, whose DamBreakModel.json takes
    /// 0.1 % against 0.05 % for the density). Negative: maxDensityError.
    float maxDivergenceError = -1.0f;
    int minIterations = 2;                  ///< pressure iterations at least
    /// dfsph's divergence-free solve: iterations at least; −1: minIterations. SPlisHSPlasH takes
    /// 1, which speeds dam breaks (fewer jets) but stirs still water at short steps
    /// (docs/performance.md), so the default stays minIterations.
    int minDivergenceIterations = -1;
    /// dfsph's divergence-free solve starts from this fraction of the last step's κᵛ (the warm
    /// start of Bender & Koschier 2017 §4.3), in [0, 1]. Applying it is a pair pass a step; 0
    /// skips it. Where the solve stops at its minimum either way (the benchmark corner dam
    /// break: 1.00 iteration a step) that pass buys nothing (1–6 % of the 200k run's wall time), but
    /// elsewhere it saves iterations (SPlisHSPlasH's model dam break: 6.5 against 7.0 a
    /// step), and settled still water moves more without it (0.04 against < 0.02 m/s).
    float divergenceWarmStart = 0.5f;
    int maxIterations = 100;                ///< pressure iterations at most
    float cflNumber = 0.4f;                 ///< dt ≤ cfl · h / (c + |v|max)
    float forceNumber = 0.25f;              ///< dt ≤ forceNumber · √(h / |a|max)
    float minDt = 1e-6f;                    ///< s; a step never goes below this
    float maxDt = 5e-3f;                    ///< s
    /// pbf: Jacobi iterations of the density constraints per step, in [1, 100]. A step costs
    /// about this many pairs of passes over the neighbour lists; more keep deep water denser.
    int constraintIterations = 4;
    /// pbf: vorticity confinement ε (Macklin & Müller 2013, eq. 16), m/s, in [0, 10]: restores
    /// swirl the position corrections and XSPH damp; 0 (the default) switches it off.
    float vorticity = 0.0f;
};

/// What a World is: its container, gravity, resolution and solver.
struct WorldDef {
    /// 3, or 2 for a vertical slice in the x–y plane: particles at z = 0, kernels normalised
    /// per area, masses per metre of width (ρ s²), walls on the domain's x and y faces only.
    /// In 2D the domain's, gravity's and every added shape's z is 0 (the World sets the
    /// domain's, refuses non-zero z in vectors), and obstacles are boxes, planes, circles and
    /// polygons (spheres, cylinders and meshes are 3D only; circles and polygons 2D only).
    int dimensions = 3;
    glm::vec3 domainMin{0.0f, 0.0f, 0.0f};  ///< container corner, m
    glm::vec3 domainMax{1.0f, 1.0f, 1.0f};  ///< container corner, m
    /// Keep particles inside the domain box: walls of boundary particles on the lattice blocks
    /// fill, at the first and last whole cells inside the box (up to a spacing inside a face
    /// that is not on it), so water put against any wall meets it at the lattice's spacing.
    bool walls = true;
    /// Periodic axes: no walls across them, a particle leaving through max re-enters at min,
    /// and particles interact across the seam (nearest image). A periodic axis must be at
    /// least 2 kernel supports long; make it a whole number of spacings so blocks tile it.
    glm::bvec3 periodic{false, false, false};
    float wallRestitution = 0.0f;           ///< fraction of normal speed kept when hitting a wall
    glm::vec3 gravity{0.0f, -9.81f, 0.0f};  ///< m/s²
    float particleSpacing = 0.02f;          ///< initial distance between particles, m
    /// Kernel support radius h / particle spacing; 0 (the default): the kernel's own
    /// (kCubicSplineSupportRatio, kWendlandSupportRatio), resolveAutomaticKernel.
    float supportRatio = 0.0f;
    std::uint32_t capacity = 1u << 22;      ///< most particles the world may hold
    int threads = 0;                        ///< worker threads; 0 = all cores
    int reorderInterval = 25;               ///< steps between re-sorting particles by grid cell
    /// Record the load the fluid puts on every solid each step (World::solidLoads): a few per
    /// cent of a step where much fluid touches solids; off, none is computed.
    bool loads = true;
    SolverDef solver;
};

/// Fills what `d` leaves automatic: the kernel (Wendland C2 in 2D for the solvers that use
/// the SPH sums' kernels, the cubic spline otherwise; classic keeps Müller's kernels) and the
/// support ratio (the kernel's own). Set fields stay. World and the scene reader call it.
inline void resolveAutomaticKernel(WorldDef& d) {
    if (d.solver.kernel == KernelShape::Automatic)
        d.solver.kernel = d.dimensions == 2 && d.solver.method != "classic" ? KernelShape::WendlandC2 : KernelShape::CubicSpline;
    if (d.supportRatio == 0.0f)
        d.supportRatio = d.solver.kernel == KernelShape::WendlandC2 ? kWendlandSupportRatio : kCubicSplineSupportRatio;
}
/// `d` with its automatic kernel and support ratio resolved.
[[nodiscard]] inline WorldDef withResolvedKernel(WorldDef d) {
    resolveAutomaticKernel(d);
    return d;
}

/// One row of a motion table (MotionDef::Type::Table): the obstacle's pose at `time`.
struct MotionKey {
    double time = 0.0;       ///< s (shifted by MotionDef::startTime)
    glm::vec3 offset{0.0f};  ///< displacement from the rest pose, m
    float angle = 0.0f;      ///< rotation about MotionDef::axis through MotionDef::center, rad
};

/// A prescribed rigid motion of an obstacle (ObstacleDef::motion). A point x0 of the obstacle
/// at rest is at  c + d(t) + R(θ(t)) (x0 − c)  at time t: R the rotation by θ about `axis`
/// (right-hand rule) through the pivot c = `center`, d the displacement. With τ = t −
/// startTime (nothing moves while τ < 0) and the ramp r(τ) = ½(1 − cos(π τ/rampTime)) (1
/// after rampTime):
///   Translation: d = velocity ∫r dτ + amplitude r(τ) sin(2π τ/period), θ = 0;
///   Rotation:    θ = angularVelocity ∫r dτ + angularAmplitude r(τ) sin(2π τ/period), d = 0;
///   Table:       d and θ interpolated in `keys` at τ (cubic Hermite, Catmull–Rom tangents,
///                zero velocity at the first and last row; the first row is held before it,
///                the last one after it).
struct MotionDef {
    enum class Type {
        None,         ///< the obstacle is fixed
        Translation,  ///< steady and/or oscillating translation
        Rotation,     ///< steady and/or oscillating rotation about an axis
        Table,        ///< a time series of displacement and angle (a CSV file in scenes)
    };
    Type type = Type::None;
    glm::vec3 velocity{0.0f};        ///< Translation: steady velocity, m/s
    glm::vec3 amplitude{0.0f};       ///< Translation: oscillation amplitude per axis, m
    glm::vec3 axis{0.0f, 1.0f, 0.0f};  ///< Rotation, Table: rotation axis (normalised when added)
    glm::vec3 center{0.0f};          ///< Rotation, Table: the pivot, a point on the axis at rest, m
    float angularVelocity = 0.0f;    ///< Rotation: steady rate, rad/s
    float angularAmplitude = 0.0f;   ///< Rotation: oscillation amplitude, rad
    float period = 0.0f;             ///< oscillation period, s (> 0 when an amplitude is set)
    double startTime = 0.0;          ///< s; the obstacle rests in its rest pose before
    float rampTime = 0.0f;           ///< s; Translation, Rotation: smooth start (0: impulsive)
    std::vector<MotionKey> keys;     ///< Table: rows at strictly increasing times
};

/// A mooring line of a floating body: a linear spring with slack (tension k (ℓ − L) while its
/// length ℓ exceeds L, else none) from a point of the body to a fixed anchor inside the domain.
struct MooringLineDef {
    std::string name;            ///< its tension's column, `<name>_tension`; default `<body>_mooring<k>`
    glm::vec3 fairlead{0.0f};    ///< the body's point, m, in its rest pose
    glm::vec3 anchor{0.0f};      ///< m, inside the domain
    double length = 0.0;         ///< unstretched length L, m (> 0)
    double stiffness = 0.0;      ///< k, N/m (> 0)
    double damping = 0.0;        ///< N s/m along the line while taut (>= 0)
};

/// How an obstacle moves when the fluid moves it (ObstacleDef::dynamics): a rigid body of six
/// degrees of freedom, coupled both ways (tide::bodies: exact mass properties from the shape,
/// gravity, the fluid's load every step, contact with walls, fixed obstacles and other bodies).
struct BodyDynamicsDef {
    std::optional<double> density;            ///< kg/m³; exactly one of density and mass
    std::optional<double> mass;               ///< kg
    std::optional<glm::vec3> centerOfMass;    ///< m, rest pose; default the shape's
    glm::vec3 velocity{0.0f};                 ///< initial velocity of the centre of mass, m/s
    glm::vec3 angularVelocity{0.0f};          ///< initial, rad/s
    /// The degrees of freedom left free, of "x", "y", "z" (translations) and "rx", "ry", "rz"
    /// (rotations about the world axes): {"y"} heaves only, {"x", "y", "rz"} moves in the x–y
    /// plane. Empty: all six.
    std::vector<std::string> freeAxes;
    /// Mooring lines: linear springs with slack from a point of the body to a fixed anchor.
    std::vector<MooringLineDef> moorings;
};

/// A solid the fluid flows around, sampled as boundary particles: fixed, or moving by a
/// prescribed `motion`. Which fields matter depends on the shape; World::addObstacle
/// validates them.
struct ObstacleDef {
    enum class Shape {
        Box,       ///< axis-aligned box `min`..`max`
        Sphere,    ///< `center`, `radius`
        Cylinder,  ///< capped: `center`, `axis`, `radius`, `length` (cap to cap)
        Plane,     ///< the half-space behind `point` + `normal`: the fluid is on the normal's side
        Mesh,      ///< a closed triangle mesh, `mesh`
        Circle,    ///< 2D worlds only: `center` (z = 0), `radius`
        Polygon,   ///< 2D worlds only: the simple polygon `polygon` (x, y), either winding
    };
    Shape shape = Shape::Box;
    glm::vec3 min{0.0f};                 ///< box corner, m
    glm::vec3 max{0.0f};                 ///< box corner, m
    glm::vec3 center{0.0f};              ///< sphere or cylinder centre, m
    float radius = 0.0f;                 ///< sphere or cylinder radius, m
    glm::vec3 axis{0.0f, 1.0f, 0.0f};    ///< cylinder axis (normalised when added)
    float length = 0.0f;                 ///< cylinder length along its axis, m
    glm::vec3 point{0.0f};               ///< a point on the plane, m
    glm::vec3 normal{0.0f, 1.0f, 0.0f};  ///< plane normal, pointing out of the solid (normalised when added)
    std::shared_ptr<const TriangleMesh> mesh;  ///< the mesh (shared, immutable), in metres
    std::vector<glm::vec2> polygon;      ///< polygon corners in order, m (≥ 3, no self-crossing)
    /// How it moves (not a plane); the fields above describe its rest pose.
    MotionDef motion;
    /// What its loads are called (World::solids, forces.csv columns); empty: "obstacle<k>",
    /// k its index among the obstacles. Unique among the world's solids.
    std::string name;
    /// The point its moment is taken about, in the rest pose (it moves with the obstacle);
    /// unset: the shape's centre (box, sphere and cylinder centre, the plane's point, the
    /// centre of the mesh's bounding box).
    std::optional<glm::vec3> loadReference;
    /// Set: the fluid moves it (a floating or sinking body; not a plane, no `motion`).
    std::optional<BodyDynamicsDef> dynamics;
};

/// A box filled with particles on a cubic lattice.
struct BlockDef {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    glm::vec3 velocity{0.0f};
    MaterialIndex material = 0;
    float concentration = 0.0f;  ///< initial dye concentration of its particles, ≥ 0
};

/// A continuous source: a flat outlet that emits one layer of particles each time the
/// stream has travelled one particle spacing, so the stream has no gaps at any step size.
struct EmitterDef {
    glm::vec3 min{0.0f};                    ///< outlet corner (one extent is usually 0)
    glm::vec3 max{0.0f};
    glm::vec3 velocity{1.0f, 0.0f, 0.0f};   ///< m/s, must be non-zero
    MaterialIndex material = 0;
    double start = 0.0;                     ///< s
    double end = std::numeric_limits<double>::infinity();  ///< s
    float concentration = 0.0f;             ///< dye concentration of the emitted particles, ≥ 0
};


/// A sea-state spectrum for irregular waves (WaveMakerDef::spectrum).
struct WaveSpectrumDef {
    enum class Type {
        None,               ///< regular waves: WaveMakerDef::waveHeight and period
        Jonswap,            ///< JONSWAP (Hasselmann et al. 1973), peak enhancement `gamma`
        PiersonMoskowitz,   ///< Pierson & Moskowitz 1964 (JONSWAP with γ = 1)
    };
    Type type = Type::None;
    float significantHeight = 0.0f;  ///< Hs = 4√m0, m
    float peakPeriod = 0.0f;         ///< Tp, s
    float gamma = 3.3f;              ///< JONSWAP peak enhancement factor, ≥ 1
    std::uint32_t seed = 1;          ///< random phases (std::mt19937)
    int components = 64;             ///< sinusoids the spectrum is split into
    float minFrequency = 0.5f;       ///< lowest component, in units of the peak frequency 1/Tp
    float maxFrequency = 3.0f;       ///< highest component, in units of the peak frequency
};

/// A wave paddle at the x = `x` end of a flume (the fluid lies on its +x side): a slab of
/// boundary particles over the full height and width of the domain, moved by linear
/// wavemaker theory (Biesel transfer function, Dean & Dalrymple §6.2).
struct WaveMakerDef {
    enum class Type {
        Piston,    ///< translates along x
        Flap,      ///< rotates about a hinge on the floor (y = domain min) at x
        Solitary,  ///< a piston moved once along Goring's 1978 trajectory: one solitary wave of waveHeight
    };
    Type type = Type::Piston;
    float x = 0.0f;             ///< paddle face at rest, m
    float depth = 0.3f;         ///< still-water depth at the paddle, m
    float waveHeight = 0.0f;    ///< H of regular waves, crest to trough, m
    float period = 0.0f;        ///< T of regular waves, s
    float rampTime = 2.0f;      ///< s; the stroke grows as ½(1 − cos(π t/ramp)) up to this time
    WaveSpectrumDef spectrum;   ///< irregular waves instead of waveHeight/period, when its type is not None
    /// Order of the generation theory (scene key wavemaker.order, DualSPHysics' waveorder):
    /// 1, linear (the paddle also radiates spurious free second-order waves), or 2, with the
    /// second-order correction of the stroke that cancels them (Schäffer 1996, a piston only:
    /// the second harmonic of regular waves; every pair's super- and subharmonics of a spectrum).
    int order = 1;
    /// Active absorption at the paddle (scene key wavemaker.absorption; Schäffer & Klopman
    /// 2000, sources/active_absorption_schaffer_klopman2000.hpp): the piston also moves with the
    /// waves arriving at it, measured a few spacings in front of its face, so waves reflected in
    /// the tank leave it instead of building up. Automatic: on for a piston making regular or
    /// irregular waves in a tank whose far end absorbs (a damping zone, a beach: a fixed plane
    /// sloping up away from the paddle, or an ocean's open +x side), else off. On: a piston
    /// making regular or irregular waves; refused for a flap or a solitary wave.
    enum class Absorption { Automatic, On, Off };
    Absorption absorption = Absorption::Automatic;
};

/// A damping zone (sponge layer): velocities of particles between `xStart` and `xEnd` are
/// relaxed towards zero after each step, by a factor rising quadratically from 0 at xStart
/// to 1 at xEnd and beyond (Altomare et al. 2017, the DualSPHysics damping zone).
struct DampingZoneDef {
    float xStart = 0.0f;   ///< m, no damping here
    float xEnd = 1.0f;     ///< m, full damping here (may be below xStart: the zone then faces −x)
    float strength = 10.0f; ///< relaxation rate β at full damping, 1/s: v ← v (1 − β Δt s²)
};

}  // namespace tide
