#pragma once
/// \file
/// tide::Fluid — the seed's one-class API (SPEC.md §3), a thin facade over tide::World.
///
/// Units: positions and boxes are in the caller's world units (the seed's tank is 40 units
/// wide); FluidSettings::metresPerUnit maps them to metres (default 0.025: that tank is 1 m).
/// Time is in seconds; velocities (m/s) and gravity (m/s²) are physical, so the seed's
/// snippets — gravity (0, −9.8, 0), jets at 2 or 3 — behave like water in a ~1 m tank.
///
///     tide::Fluid fluid;
///     fluid.init(65535, {-20,-20,-20}, {20,20,20}, {0,0,0}, {0,0,0}, {0,-9.81f,0});
///     fluid.addPoint({-15,-10,-15}, {10,20,10}, {0,0,0});
///     while (running) { fluid.step(1.0f / 60); draw(fluid.getPosData(), fluid.getPointCounts()); }

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include <tide/defs.hpp>
#include <tide/world.hpp>

namespace tide {

/// A fluid as the seed describes it: (viscosity relative to water, rest density kg/m³, colour).
struct Material {
    float viscosity = 1.0f;                  ///< 1 = water; scaled by FluidSettings::waterViscosity
    float restDensity = 1000.0f;             ///< kg/m³
    glm::vec3 color{0.6f, 0.8f, 1.0f};       ///< default water is white-blue

    Material() = default;
    Material(float viscosityIn, float restDensityIn, const glm::vec3& colorIn)
        : viscosity(viscosityIn), restDensity(restDensityIn), color(colorIn) {}
};

/// One particle record of getPointBuf(), in world units; 40 bytes.
struct Point {
    glm::vec3 pos;               ///< world units
    glm::vec3 vel;               ///< m/s
    float density;               ///< kg/m³
    float pressure;              ///< Pa
    MaterialIndex material;
    std::uint16_t reserved = 0;
    std::uint32_t id;            ///< stable identity
};

/// How world units map to physics, and solver choices. Defaults run live: position based
/// fluids (liveSolver()) at a fixed cost per frame; seedSolver() runs the seed verbatim.
struct FluidSettings {
    float metresPerUnit = 0.025f;            ///< metres per world unit
    float particleSpacing = 1.0f;            ///< world units between particles
    /// Dynamic viscosity (Pa·s) that a Material viscosity of 1.0 stands for. Real water is
    /// 0.001; at the seed's resolution the explicit solver needs more to stay smooth.
    float waterViscosity = 0.5f;
    int threads = 0;                         ///< 0 = all cores
    SolverDef solver = liveSolver();         ///< method (pbf by default), iterations, time step limits
    /// pbf: steps per Fluid::step, each frameTime/substeps long, in [1, 100]: the same cost
    /// every frame. Other solvers take the steps their time-step limits need instead.
    int substeps = 2;

    /// The live preset: position based fluids (Macklin & Müller 2013, docs/live.md) with 4
    /// constraint iterations a step; steps up to 1/60 s (frames up to 1/30 s at 2 substeps).
    /// For interactive use, not engineering accuracy (the density error is what 4 iterations
    /// reach, ~1 % in a tank at rest, not a tolerance).
    static SolverDef liveSolver() {
        SolverDef s;
        s.method = "pbf";
        s.constraintIterations = 4;
        s.maxDt = 1.0f / 60.0f;
        return s;
    }
    /// The seed's solver: Müller et al. 2003 ("classic").
    static SolverDef seedSolver() {
        SolverDef s;
        s.method = "classic";
        return s;
    }
    /// The solver called `method` with its defaults: liveSolver() for "pbf", seedSolver() for
    /// "classic", SolverDef's for the others.
    static SolverDef solverNamed(const std::string& method) {
        if (method == "pbf") return liveSolver();
        if (method == "classic") return seedSolver();
        SolverDef s;
        s.method = method;
        return s;
    }
};

class Fluid {
public:
    Fluid();
    ~Fluid();
    Fluid(const Fluid&) = delete;
    Fluid& operator=(const Fluid&) = delete;

    /// Create the container (wall box) and fill `initFluidBox` with water (nothing when it is
    /// empty). Throws std::invalid_argument for an inverted box or bad settings.
    void init(std::uint32_t maxPointCounts, const glm::vec3& wallBox_min, const glm::vec3& wallBox_max,
              const glm::vec3& initFluidBox_min, const glm::vec3& initFluidBox_max, const glm::vec3& gravity,
              const FluidSettings& settings = {});
    /// Free everything; the fluid is empty until init() is called again.
    void reset();

    /// Fill a box with water moving at `velocity`. Returns false, adding nothing, when the
    /// block would exceed the capacity or lies outside the wall box (or before init()).
    bool addPoint(const glm::vec3& min, const glm::vec3& max, const glm::vec3& velocity);
    /// ... of a given material (throws std::invalid_argument for an unknown index).
    bool addPoint(const glm::vec3& min, const glm::vec3& max, const glm::vec3& velocity, MaterialIndex material);
    /// Continuous emitter through the outlet box [min, max]: call once per frame, before
    /// step(); during that step it emits layers one spacing apart. Returns false when the
    /// outlet lies outside the wall box or the fluid is full.
    bool addPointTick(const glm::vec3& min, const glm::vec3& max, const glm::vec3& velocity);
    bool addPointTick(const glm::vec3& min, const glm::vec3& max, const glm::vec3& velocity, MaterialIndex material);
    /// Register a material (copied); returns its index. Material 0 is water.
    MaterialIndex addMaterial(const Material& material);

    /// Advance the simulation by frameTime seconds: with pbf in FluidSettings::substeps equal
    /// steps (the same cost every frame; throws std::invalid_argument if a substep would
    /// exceed solver.maxDt), with the other solvers sub-stepped as stability requires.
    /// Throws tide::DivergenceError if a step diverges (see World::step); the particle
    /// records and positions then keep the last state read before it (or, if none was read
    /// since, that state with every non-finite value replaced by 0), so nothing draws NaN.
    void step(float frameTime);

    [[nodiscard]] unsigned getPointStride() const { return sizeof(Point); }
    [[nodiscard]] unsigned getPointCounts() const;
    /// Particle records, valid until the next non-const call.
    [[nodiscard]] const Point* getPointBuf() const;
    /// Packed xyz positions in world units, ready for a GL vertex buffer.
    float* getPosData();
    /// Material of particle i, in the order of getPosData().
    [[nodiscard]] MaterialIndex getMaterialIndex(unsigned i) const;

    /// Simulated time, s.
    [[nodiscard]] double time() const;
    [[nodiscard]] float metresPerUnit() const { return settings_.metresPerUnit; }
    /// The engine underneath (SI units), e.g. for statistics.
    [[nodiscard]] const World& world() const;
    /// ... writable, e.g. for a viewer to push particles (World::velocities()) between steps.
    [[nodiscard]] World& world();

private:
    struct TickEmitter {
        glm::vec3 min, max, velocity;
        MaterialIndex material;
        std::uint32_t id;
    };
    [[nodiscard]] glm::vec3 toMetres(const glm::vec3& world) const { return world * settings_.metresPerUnit; }
    void invalidateCaches();

    FluidSettings settings_;
    std::unique_ptr<World> world_;
    std::vector<TickEmitter> tickEmitters_;
    mutable std::vector<Point> points_;
    mutable bool pointsStale_ = true;
    std::vector<float> positions_;
    bool positionsStale_ = true;
};

}  // namespace tide
