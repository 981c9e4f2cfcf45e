#include <tide/world.hpp>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <tide/bodies.hpp>

#include "bodies/body_pose.hpp"
#include "boundary/boundary_particles.hpp"
#include "boundary/damping_zone.hpp"
#include "boundary/obstacles.hpp"
#include "boundary/rigid_motion.hpp"
#include "boundary/wall_box.hpp"
#include "core/divergence_guard.hpp"
#include "core/field_sampling.hpp"
#include "core/kernels.hpp"
#include "core/material_pairs.hpp"
#include "core/parallel.hpp"
#include "core/periodic_box.hpp"
#include "core/planar.hpp"
#include "core/scratch_resize.hpp"
#include "core/validate.hpp"
#include "loads/contact_impulses.hpp"
#include "loads/solid_loads.hpp"
#include "loads/wall_loads.hpp"
#include "neighbors/neighbor_list.hpp"
#include "neighbors/uniform_grid.hpp"
#include "ocean/relaxation_zone.hpp"
#include "solvers/diffusion_cleary1999.hpp"
#include "solvers/solver.hpp"
#include "sources/emitter.hpp"
#include "sources/lattice.hpp"
#include "sources/wave_maker.hpp"
#include "sources/wave_numerics.hpp"

namespace tide {

namespace {

void validateWorldDef(const WorldDef& d) {
    validateDimensions(d);
    for (int axis = 0; axis < 3; ++axis) {
        requireFinite("domain.min", d.domainMin[axis]);
        requireFinite("domain.max", d.domainMax[axis]);
        if (!(d.domainMax[axis] > d.domainMin[axis]) && !(axis == 2 && d.dimensions == 2))
            throw std::invalid_argument("domain: max must exceed min on every axis, got min " + show(d.domainMin) +
                                        " max " + show(d.domainMax));
        requireFinite("gravity", d.gravity[axis]);
    }
    requirePositive("particleSpacing", d.particleSpacing);
    requireInRange("supportRatio", d.supportRatio, 1.0f, 4.0f);
    const float support = d.particleSpacing * d.supportRatio;
    for (int axis = 0; axis < 3; ++axis)
        if (d.periodic[axis] && !(d.domainMax[axis] - d.domainMin[axis] >= 2.0f * support))
            throw std::invalid_argument(std::string("domain.periodic: the periodic ") + "xyz"[axis] + " axis is " +
                                        show(d.domainMax[axis] - d.domainMin[axis]) +
                                        " m long, less than 2 kernel supports (2 × " + show(support) + " m)");
    requireInRange("wallRestitution", d.wallRestitution, 0.0f, 1.0f);
    if (d.capacity == 0) throw std::invalid_argument("capacity: must be > 0, got 0");
    if (d.threads < 0) throw std::invalid_argument("threads: must be >= 0, got " + std::to_string(d.threads));
    if (d.reorderInterval < 0)
        throw std::invalid_argument("reorderInterval: must be >= 0, got " + std::to_string(d.reorderInterval));
    const SolverDef& s = d.solver;
    if (!(s.soundSpeed >= 0.0f) || !std::isfinite(s.soundSpeed))
        throw std::invalid_argument("solver.soundSpeed: must be >= 0 (0 = automatic), got " + show(s.soundSpeed));
    if (s.xsph >= 0.0f) requireInRange("solver.xsph", s.xsph, 0.0f, 1.0f);
    if (s.momentum >= 0.0f) requireInRange("solver.momentum", s.momentum, 0.0f, 0.95f);
    if (!(s.shifting < 0.0f)) requireInRange("solver.shifting", s.shifting, 0.0f, 1.0f);
    if (s.shifting > 0.0f && s.method != "dfsph")
        throw std::invalid_argument("solver.shifting: only the dfsph solver shifts particles, got " + show(s.shifting) +
                                    " with solver \"" + s.method + "\"");
    if (!(s.differenceForm < 0.0f)) requireInRange("solver.differenceForm", s.differenceForm, 0.0f, 1.0f);
    if (s.differenceForm > 0.0f && s.method != "dfsph")
        throw std::invalid_argument("solver.differenceForm: only the dfsph solver takes it, got " + show(s.differenceForm) +
                                    " with solver \"" + s.method + "\"");
    requireInRange("solver.maxDensityError", s.maxDensityError, 1e-6f, 0.5f);
    if (s.maxDivergenceError >= 0.0f) requireInRange("solver.maxDivergenceError", s.maxDivergenceError, 1e-6f, 0.5f);
    if (s.minDivergenceIterations < -1)
        throw std::invalid_argument("solver.minDivergenceIterations: must be >= 0 (or -1: minIterations), got " +
                                    std::to_string(s.minDivergenceIterations));
    requireInRange("solver.divergenceWarmStart", s.divergenceWarmStart, 0.0f, 1.0f);
    if (s.minIterations < 0 || s.maxIterations < std::max(1, s.minIterations))
        throw std::invalid_argument("solver.maxIterations: must be >= max(1, minIterations), got " +
                                    std::to_string(s.maxIterations));
    if (s.constraintIterations < 1 || s.constraintIterations > 100)
        throw std::invalid_argument("solver.constraintIterations: must be in [1, 100], got " +
                                    std::to_string(s.constraintIterations));
    requireInRange("solver.vorticity", s.vorticity, 0.0f, 10.0f);
    requireInRange("solver.cflNumber", s.cflNumber, 1e-4f, 1.0f);
    requireInRange("solver.forceNumber", s.forceNumber, 1e-4f, 1.0f);
    requirePositive("solver.minDt", s.minDt);
    requirePositive("solver.maxDt", s.maxDt);
    if (s.minDt > s.maxDt)
        throw std::invalid_argument("solver.minDt: must not exceed solver.maxDt (" + show(s.maxDt) + "), got " +
                                    show(s.minDt));
}

void validateMaterial(const MaterialDef& m) {
    requirePositive("material.restDensity", m.restDensity);
    if (!(m.viscosity >= 0.0f) || !std::isfinite(m.viscosity))
        throw std::invalid_argument("material.viscosity: must be >= 0 Pa·s, got " + show(m.viscosity));
    if (!(m.adhesion >= 0.0f) || !std::isfinite(m.adhesion))
        throw std::invalid_argument("material.adhesion: must be >= 0, got " + show(m.adhesion));
}

/// Σ_k W(|k|·s) over the cubic lattice (the square one in 2D), W the solver's density kernel:
/// a lattice particle of mass ρ0 / this sum has exactly the rest density inside a filled
/// block, so blocks start at rest. (About ρ0 s³, in 2D ρ0 s² per metre of width.)
float latticeKernelSum(DensityKernel kernel, KernelShape shape, float spacing, float h, int dimensions) {
    const kernels::Poly6 poly6(h, dimensions);
    const kernels::SmoothingKernel smoothing(h, shape, dimensions);
    const int reach = static_cast<int>(std::ceil(h / spacing));
    const int reachZ = dimensions == 2 ? 0 : reach;
    double sum = 0.0;
    for (int z = -reachZ; z <= reachZ; ++z)
        for (int y = -reach; y <= reach; ++y)
            for (int x = -reach; x <= reach; ++x) {
                const glm::vec3 r = spacing * glm::vec3(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
                sum += kernel == DensityKernel::Poly6 ? poly6.valueSq(glm::dot(r, r)) : smoothing.value(glm::length(r));
            }
    return static_cast<float>(sum);
}

}  // namespace

struct World::Impl {
    WorldDef def;
    int threads;
    float h;
    /// The smoothing kernel of the solver's sums, which the gauges, probes and dye diffusion read too.
    [[nodiscard]] kernels::SmoothingKernel kernel() const {
        return kernels::SmoothingKernel(h, def.solver.kernel, def.dimensions);
    }
    std::unique_ptr<Solver> solver;
    float latticeSum;
    PeriodicBox periodic;
    ViscosityModel viscosity;
    std::vector<MaterialDef> materials;
    /// The largest over the smallest rest density of the materials (1 for none).
    [[nodiscard]] float restDensityRatio() const {
        float lo = 0.0f, hi = 0.0f;
        for (const MaterialDef& m : materials) {
            lo = lo == 0.0f ? m.restDensity : std::min(lo, m.restDensity);
            hi = std::max(hi, m.restDensity);
        }
        return lo > 0.0f ? hi / lo : 1.0f;
    }
    std::vector<MaterialPairDef> pairs;
    MaterialPairs pairTables;  ///< built from materials and pairs at every step
    DyeDiffusion diffusion;
    ParticleStore particles;
    UniformGrid grid;
    NeighborList neighbors;
    BoundaryParticles boundary;
    CrossNeighborList boundaryNeighbors;       ///< boundary particles near each fluid particle
    CrossNeighborList boundaryFluidNeighbors;  ///< fluid particles near each boundary particle near fluid
    /// The boundary particles within h of fluid, ascending (the wall pressure's queries): a
    /// container's shell outnumbers the fluid (2.7 to 1 in the 50k benchmark dam break) and
    /// most of it is far from the water; lists and per-step arrays sized to all of it cost
    /// ~16 bytes a boundary particle.
    std::vector<std::uint32_t> boundaryNearFluid;
    std::vector<std::uint8_t> boundaryMarks;  ///< scratch of findBoundaryNearFluid (a byte a boundary particle)
    std::vector<EmitterState> emitters;
    std::vector<ObstacleDef> obstacles;        ///< all of them, as defined
    std::vector<ObstacleDef> fixedObstacles;   ///< those without motion
    /// A moving obstacle (obstacles[index]) and its boundary particles [begin, begin + rest.size()).
    struct Mover {
        std::uint32_t index;
        RigidMotion motion;
        std::uint32_t begin;
        std::vector<glm::vec3> rest;
        int body = -1;  ///< a dynamic obstacle's index in `bodies`: its pose is the body's, not `motion`'s
    };
    /// The dynamic obstacles' rigid bodies (made with the first), and each one's mover.
    std::unique_ptr<bodies::BodySystem> bodySystem;
    std::vector<bodies::BodyDef> bodyDefs;
    std::vector<std::uint32_t> bodyMovers;
    /// Where mover m is at time t: a body where it is now (it moves by stepping, not by t).
    [[nodiscard]] RigidPose moverPose(const Mover& m, double t) const {
        return m.body >= 0 ? bodies::poseOf(bodySystem->body(static_cast<std::size_t>(m.body))) : m.motion.pose(t);
    }
    std::vector<Mover> movers;
    /// A wave paddle and its boundary particles [begin, begin + rest.size()).
    struct Paddle {
        WaveMaker maker;
        std::uint32_t begin;
        std::vector<glm::vec3> rest;
    };
    std::vector<Paddle> paddles;
    /// Where the lattice of blocks and obstacles has a cell corner: the domain's corner, but
    /// in x the first wave maker's face (its particles continue the fluid's lattice from there).
    /// io::estimate counts blocks by the same rule.
    glm::vec3 latticeOrigin;
    glm::vec3 wallsOrigin;  ///< latticeOrigin when the walls were sampled (wallPlanes)
    std::vector<DampingZoneDef> dampingZones;
    /// An ocean's coupling zones (setOcean), the faces they open (no walls there) and the
    /// material their inflow adds.
    std::unique_ptr<ocean::RelaxationZones> zones;
    OceanDef oceanDef;
    unsigned openFaces = 0;
    MaterialIndex oceanMaterial = 0;
    /// The wall box's planes, unbounded across periodic axes and open faces.
    [[nodiscard]] std::pair<glm::dvec3, glm::dvec3> wallLimits(double inf) const {
        glm::dvec3 lo = def.domainMin, hi = def.domainMax;
        for (int axis = 0; axis < 3; ++axis) {
            const bool across = periodic.periodic(axis) || (axis == 2 && def.dimensions == 2);  // nor across the 2D plane
            if (across || (openFaces >> (2 * axis) & 1u)) lo[axis] = -inf;
            if (across || (openFaces >> (2 * axis + 1) & 1u)) hi[axis] = inf;
        }
        return {lo, hi};
    }
    /// Relaxation, outflow and inflow of the ocean's zones over a step of dt ending at `end`.
    void couple(double end, double dt) {
        zones->relax(particles, end, dt, threads);
        stats.oceanRemoved += zones->removeOutflow(particles);
        stats.oceanAdded += zones->refill(particles, end, massOf(oceanMaterial), oceanMaterial,
                                          materials[oceanMaterial].restDensity, def.capacity,
                                          [&](const glm::vec3& x) { return roomFor(x, Fill::Block); });
    }
    /// Loads: the solids (six wall faces, then paddles and obstacles as added; their index is
    /// BoundaryParticles::solid), each obstacle's reference point at rest, the pair forces of
    /// the step, the last step's loads and the momentum exchanged since takeMeanSolidLoads().
    std::vector<SolidInfo> solids;
    std::vector<glm::vec3> obstacleReferences;
    WallLoads wallLoads;
    std::vector<SolidLoad> lastLoads;
    std::vector<SolidLoad> loadImpulse;
    double loadTime = 0.0;
    ContactImpulses contacts;
    std::vector<std::uint16_t> fixedObstacleSolids;  ///< the solid of each of fixedObstacles
    [[nodiscard]] std::uint16_t solidOfObstacle(std::uint32_t index) const {
        for (std::size_t s = 0; s < solids.size(); ++s)
            if (solids[s].kind == SolidInfo::Kind::Obstacle && solids[s].index == index) return static_cast<std::uint16_t>(s);
        return 0;
    }
    [[nodiscard]] std::uint16_t solidOfPaddle(std::uint32_t index) const {
        for (std::size_t s = 0; s < solids.size(); ++s)
            if (solids[s].kind == SolidInfo::Kind::WaveMaker && solids[s].index == index) return static_cast<std::uint16_t>(s);
        return 0;
    }
    double time = 0.0;
    float soundSpeed = 0.0f;  ///< resolved at the first step when SolverDef::soundSpeed is 0
    int stepsSinceReorder = 0;
    WorldStats stats;
    std::optional<Divergence> divergence;  ///< set by the step that diverged

    explicit Impl(const WorldDef& d)
        : def(planarWorldDef(d)), threads(resolveThreadCount(d.threads)), h(d.particleSpacing * d.supportRatio),
          solver(makeSolver(d.solver.method)),
          latticeSum(latticeKernelSum(solver->densityKernel(), d.solver.kernel, d.particleSpacing, h, d.dimensions)),
          periodic(PeriodicBox::make(d.domainMin, d.domainMax, d.periodic)),
          viscosity(viscosityModel(d.solver.viscosity, solver->defaultViscosity())),
          latticeOrigin(def.domainMin), wallsOrigin(def.domainMin), soundSpeed(d.solver.soundSpeed) {
        // 2D: solids are sampled at origin + (k + ½) s; this puts their one z layer at z = 0.
        if (def.dimensions == 2) latticeOrigin.z = wallsOrigin.z = -0.5f * def.particleSpacing;
        boundary.periodic = periodic;
        if (def.walls) sampleWalls();
        for (std::uint32_t face = 0; face < 6; ++face)
            solids.push_back({SolidInfo::Kind::Wall, face, std::string("wall_") + "xyz"[face / 2] + (face % 2 ? "max" : "min")});
    }

    /// Each solid's reference point at time t (boundary particles where they are at t).
    [[nodiscard]] std::vector<glm::dvec3> solidReferences(double t) const {
        std::vector<glm::dvec3> refs(solids.size(), glm::dvec3(0.0));
        const glm::vec3 lo = wallsMin(), hi = wallsMax();
        for (std::size_t s = 0; s < solids.size(); ++s) {
            const SolidInfo& solid = solids[s];
            if (solid.kind == SolidInfo::Kind::Wall) {
                glm::vec3 centre = 0.5f * (lo + hi);
                const int axis = static_cast<int>(solid.index / 2);
                centre[axis] = solid.index % 2 ? hi[axis] : lo[axis];
                refs[s] = centre;
            } else if (solid.kind == SolidInfo::Kind::Obstacle) {
                const glm::vec3 rest = obstacleReferences[solid.index];
                refs[s] = rest;
                for (const Mover& m : movers)
                    if (m.index == solid.index) {
                        const RigidPose pose = moverPose(m, t);
                        refs[s] = pose.pivot + pose.rotation * (rest - pose.center);
                    }
            } else {
                const Paddle& paddle = paddles[solid.index];
                glm::dvec3 sum(0.0);
                for (std::size_t k = 0; k < paddle.rest.size(); ++k) sum += glm::dvec3(boundary.position[paddle.begin + k]);
                refs[s] = sum / std::max<double>(1.0, static_cast<double>(paddle.rest.size()));
            }
        }
        return refs;
    }

    /// The container's walls, a shell as deep as the support, between wallsMin and wallsMax
    /// on the lattice as it is now.
    /// The step's loads from the pairs the solver recorded (boundary particles where the step
    /// started), added to the running average.
    void sumLoads(double dt) {
        sumSolidLoads(wallLoads, boundaryNeighbors, boundary, particles.size(), dt, solidReferences(time), periodic,
                      threads, lastLoads);
        loadImpulse.resize(solids.size());
        for (std::size_t s = 0; s < solids.size(); ++s) {
            loadImpulse[s].pressureForce += dt * lastLoads[s].pressureForce;
            loadImpulse[s].viscousForce += dt * lastLoads[s].viscousForce;
            loadImpulse[s].moment += dt * lastLoads[s].moment;
        }
        loadTime += dt;
    }

    /// Makes the rigid body of a dynamic obstacle (the body system with the first, meeting the
    /// walls and every fixed obstacle); returns its index. Throws naming the field at fault.
    int addBody(const ObstacleDef& obstacle) {
        const BodyDynamicsDef& d = *obstacle.dynamics;
        bodies::BodyDef body;
        body.name = "obstacle " + obstacle.name;
        body.shape = obstacle;
        body.shape.dynamics.reset();
        body.density = d.density;
        body.mass = d.mass;
        if (d.centerOfMass) body.centerOfMass = glm::dvec3(*d.centerOfMass);
        body.velocity = glm::dvec3(d.velocity);
        body.angularVelocity = glm::dvec3(d.angularVelocity);
        if (!d.freeAxes.empty()) body.constraint = bodies::freeAxes(d.freeAxes, "obstacle.constraint.free");
        body.contact.distance = def.particleSpacing;  // the thinnest film the fluid resolves
        for (std::size_t k = 0; k < d.moorings.size(); ++k) {
            const MooringLineDef& line = d.moorings[k];
            bodies::MooringDef m;
            m.name = line.name.empty() ? obstacle.name + "_mooring" + std::to_string(k) : line.name;
            m.fairlead = glm::dvec3(line.fairlead);
            m.anchor = glm::dvec3(line.anchor);
            m.length = line.length;
            m.stiffness = line.stiffness;
            m.damping = line.damping;
            body.moorings.push_back(m);
        }
        const std::vector<double> before = bodySystem ? bodySystem->saveState() : std::vector<double>{};
        bodyDefs.push_back(body);
        try {
            makeBodySystem(bodyDefs.size() - 1);
            if (!before.empty()) bodySystem->restoreState(before);
            (void)bodySystem->addBody(body);
            bodySystem->validatePlacement(0.5 * def.particleSpacing);
        } catch (...) {
            bodyDefs.pop_back();  // the world stays as it was
            makeBodySystem(bodyDefs.size());
            if (!bodyDefs.empty()) bodySystem->restoreState(before);
            else bodySystem.reset();
            throw;
        }
        return static_cast<int>(bodyDefs.size() - 1);
    }

    /// The body system afresh: the walls, the fixed obstacles and the first `count` bodyDefs.
    void makeBodySystem(std::size_t count) {
        {
            bodySystem = std::make_unique<bodies::BodySystem>(glm::dvec3(def.gravity));
            if (def.walls) {
                glm::dvec3 lo = wallsMin(), hi = wallsMax();
                const auto [openLo, openHi] = wallLimits(1e30);
                for (int axis = 0; axis < 3; ++axis) {
                    if (openLo[axis] == -1e30) lo[axis] = -1e30;
                    if (openHi[axis] == 1e30) hi[axis] = 1e30;
                }
                bodySystem->setWalls(lo, hi);
            }
            for (std::size_t k = 0; k < fixedObstacles.size(); ++k) bodySystem->addFixedObstacle(fixedObstacles[k], fixedObstacles[k].name);
            for (std::size_t k = 0; k < count; ++k) (void)bodySystem->addBody(bodyDefs[k]);
        }
    }

    /// Moves every body one step of dt under the load the fluid put on it in the step (its
    /// pair forces; the moment taken about its centre of mass).
    void stepBodies(double dt) {
        std::vector<glm::dvec3> forces, moments;
        const std::vector<glm::dvec3> refs = solidReferences(time);
        for (const std::uint32_t mover : bodyMovers) {
            const Mover& m = movers[mover];
            const std::uint16_t s = solidOfObstacle(m.index);
            const SolidLoad& load = lastLoads[s];
            const glm::dvec3 centre = bodySystem->body(static_cast<std::size_t>(m.body)).position();
            forces.push_back(load.force());
            moments.push_back(load.moment + glm::cross(refs[s] - centre, load.force()));
        }
        bodySystem->step(dt, forces, moments);
    }

    void resetLoads() {
        lastLoads.assign(solids.size(), SolidLoad{});
        loadImpulse.assign(solids.size(), SolidLoad{});
        loadTime = 0.0;
    }

    void sampleWalls() {
        wallsOrigin = latticeOrigin;
        const int layers = static_cast<int>(std::ceil(h / def.particleSpacing));
        boundary.sampleBoxShell(wallsMin(), wallsMax(), def.particleSpacing, layers, 1.0f / latticeSum, h, threads, openFaces,
                                def.dimensions);
    }

    /// Where the walls stand: on the lattice blocks fill (cell corners at latticeOrigin when
    /// they were sampled), at the first and last whole cells inside the domain (on a periodic
    /// axis, at its ends). A block
    /// against a wall then meets it a spacing from its particles on either side; with the walls
    /// at domain.min and domain.max a block against a max-side wall started up to a spacing
    /// short of it and fell into the gap (the stirred tank, 0.4 m at 1.5 cm: 1.1–1.3 m/s at its
    /// far edge within 0.1 s).
    [[nodiscard]] glm::vec3 wallsMin() const { return wallPlanes().first; }
    [[nodiscard]] glm::vec3 wallsMax() const { return wallPlanes().second; }
    [[nodiscard]] std::pair<glm::vec3, glm::vec3> wallPlanes() const {
        glm::vec3 min = def.domainMin, max = def.domainMax;
        const float s = def.particleSpacing;
        for (int axis = 0; axis < 3; ++axis) {
            if (periodic.periodic(axis)) continue;
            const float o = wallsOrigin[axis];
            const float first = std::ceil((def.domainMin[axis] - o) / s - kOnSurface);
            const float last = std::floor((def.domainMax[axis] - o) / s + kOnSurface);
            if (last - first < 1.0f) continue;  // not one whole cell: the domain's own faces
            // A face on the lattice stays where it is, to the bit.
            const auto onLattice = [&](float face, float cells) {
                const float plane = o + cells * s;
                return std::abs(plane - face) <= kOnSurface * s ? face : plane;
            };
            min[axis] = onLattice(def.domainMin[axis], first);
            max[axis] = onLattice(def.domainMax[axis], last);
        }
        return {min, max};
    }

    [[nodiscard]] float massOf(MaterialIndex m) const { return materials[m].restDensity / latticeSum; }

    /// A block as this world fills it: in 2D on the plane z = 0 (its z extent dropped).
    [[nodiscard]] BlockDef inPlane(BlockDef block) const {
        if (def.dimensions == 2) {
            requireInPlane(2, "block.velocity", block.velocity);
            block.min.z = block.max.z = 0.0f;
        }
        return block;
    }

    /// Whether a lattice lies inside the walls and within one period of every periodic axis.
    [[nodiscard]] bool insideDomain(const Lattice& lattice) const {
        const glm::vec3 last = lattice.first + lattice.spacing * glm::vec3(lattice.count - 1u);
        const float slack = 1e-5f * glm::length(def.domainMax - def.domainMin);
        const auto [min, max] = wallPlanes();  // the walls may stand inside the domain's faces
        for (int axis = 0; axis < 3; ++axis) {
            if (!def.walls && !periodic.periodic(axis)) continue;
            if (lattice.first[axis] < min[axis] - slack || last[axis] > max[axis] + slack) return false;
        }
        return true;
    }

    /// What a lattice of new particles fills: a block (on the lattice of the solids' particles)
    /// or an emitter's layer (on its own, moving off at once).
    enum class Fill { Block, EmitterLayer };

    /// Whether a lattice point has room for a new particle. A block's point may come nearer a
    /// fixed solid, to the solver's fill clearance, where the solid's particles fill the
    /// lattice up to its surface; but no nearer than kFillSeparation spacings to any boundary
    /// particle. On one lattice with the solids' particles that holds by itself, and it keeps
    /// points out where the lattices differ, which would start pressed against the solid's
    /// particles. So may it come nearer a moving box, whose particles lie in its faces' planes
    /// and carry them along (half a spacing off it, the row under a stirring paddle stayed
    /// empty and the water jumped into it at 1.2 m/s). Other moving solids keep the half
    /// spacing a particle fills off their surfaces: their outermost particles are a staircase
    /// that sweeps its notches once it turns (filled up to the surface, the spinning cylinder's
    /// third ring read 0.32 of ωR against Couette's 0.41). An emitter's layer (on its own
    /// lattice, moving off at once) keeps the half spacing off every surface.
    [[nodiscard]] bool roomFor(const glm::vec3& x, Fill fill) const {
        constexpr float kFillSeparation = 0.9f;
        const float half = 0.499f * def.particleSpacing;
        const float clearance =
            fill == Fill::Block ? std::max(solver->fillClearance(), kOnSurface) * def.particleSpacing : half;
        for (const ObstacleDef& o : fixedObstacles)
            if (!(signedDistance(o, x) > clearance)) return false;
        for (const Mover& m : movers) {
            const ObstacleDef& o = obstacles[m.index];
            const float keep = fill == Fill::Block && o.shape == ObstacleDef::Shape::Box ? clearance : half;
            if (!(signedDistance(o, moverPose(m, time), x) > keep)) return false;
        }
        for (const Paddle& paddle : paddles)
            if (!(paddle.maker.distanceInFront(time, x) > half)) return false;
        return fill == Fill::EmitterLayer || !boundary.anyCloserThan(x, kFillSeparation * def.particleSpacing);
    }

    /// Whether a step advances the clock (World::step) or holds it (World::settle).
    enum class Clock { Runs, Held };
    /// One step of at most maxDt (World::step, whose body this is). With the clock held the
    /// moving boundaries stand still where they are at `time`, nothing is emitted and `time`
    /// stays.
    double step(double maxDt, Clock clock);

    /// Moving boundaries at rest where they stand (a held clock): no velocity, no acceleration.
    void holdBoundaries() {
        if (paddles.empty() && movers.empty()) return;
        for (std::size_t b = 0; b < boundary.velocity.size(); ++b)
            if (boundary.movable[b]) {
                boundary.velocity[b] = glm::vec3(0.0f);
                boundary.acceleration[b] = glm::vec3(0.0f);
            }
        boundary.maxSpeed = 0.0f;
    }

    /// Puts the boundary particles of paddles and moving obstacles where their motion has
    /// them at time t, with their velocities and accelerations.
    void moveBoundaries(double t) {
        if (paddles.empty() && movers.empty()) return;
        for (const Paddle& paddle : paddles) {
            const std::size_t n = paddle.rest.size();
            paddle.maker.place(t, paddle.rest, std::span(boundary.position).subspan(paddle.begin, n),
                               std::span(boundary.velocity).subspan(paddle.begin, n),
                               std::span(boundary.acceleration).subspan(paddle.begin, n));
        }
        for (const Mover& m : movers) {
            const RigidPose pose = moverPose(m, t);
            parallelFor(static_cast<std::uint32_t>(m.rest.size()), threads, [&](std::uint32_t k) {
                const std::uint32_t b = m.begin + k;
                const glm::vec3 x = pose.place(m.rest[k]);
                boundary.position[b] = periodic.wrap(x);
                boundary.velocity[b] = pose.velocityAt(x);
                boundary.acceleration[b] = pose.accelerationAt(x);
            });
        }
        float fastest2 = 0.0f;
        for (std::size_t b = 0; b < boundary.velocity.size(); ++b)
            if (boundary.movable[b]) fastest2 = std::max(fastest2, glm::dot(boundary.velocity[b], boundary.velocity[b]));
        boundary.maxSpeed = std::sqrt(fastest2);
        boundary.grid.build(boundary.position, h, threads, periodic);
    }

    /// The points a block [min, max] holds: on the domain's lattice, where the walls and
    /// obstacles are sampled.
    [[nodiscard]] Lattice blockLattice(const glm::vec3& min, const glm::vec3& max) const {
        return Lattice::onDomainLattice(min, max, def.particleSpacing, latticeOrigin);
    }

    /// How many of the lattice's points have room for a particle (roomFor). Against walls
    /// alone every one has.
    [[nodiscard]] std::uint64_t countLattice(const Lattice& lattice, Fill fill) const {
        if (obstacles.empty() && paddles.empty()) return lattice.size();
        std::uint64_t n = 0;
        lattice.forEach([&](const glm::vec3& x) { n += roomFor(x, fill); });
        return n;
    }

    /// Appends the lattice's `count` points that have room for a particle (countLattice).
    void appendLattice(const Lattice& lattice, Fill fill, std::uint64_t count, const glm::vec3& velocity,
                       MaterialIndex material, float concentration = 0.0f) {
        const float m = massOf(material);
        const float rho0 = materials[material].restDensity;
        const bool everyPoint = obstacles.empty() && paddles.empty();
        particles.makeRoomFor(static_cast<std::uint32_t>(count));
        lattice.forEach([&](const glm::vec3& x) {
            if (everyPoint || roomFor(x, fill)) particles.append(x, velocity, m, material, rho0, concentration);
        });
    }

    /// The speed of sound: given, or 10 × the fastest speed the scene can reach by falling
    /// through the domain or by its initial/emitted velocities (density varies by ~(v/c)²).
    void resolveSoundSpeed() {
        if (soundSpeed > 0.0f) return;
        const glm::vec3 extent = def.domainMax - def.domainMin;
        const float g = glm::length(def.gravity);
        const float height = g > 0.0f ? std::abs(glm::dot(extent, def.gravity / g)) : std::max({extent.x, extent.y, extent.z});
        float reference = std::sqrt(2.0f * (g > 0.0f ? g : 9.81f) * height);
        for (const glm::vec3& v : particles.velocity) reference = std::max(reference, glm::length(v));
        for (const EmitterState& e : emitters) reference = std::max(reference, glm::length(e.def.velocity));
        soundSpeed = 10.0f * reference;
    }

    void rebuildNeighbors() {
        grid.build(particles.position, h, threads, periodic);
        if (def.reorderInterval > 0 && ++stepsSinceReorder >= def.reorderInterval) {
            // One permutation for every array: particles of a cell become contiguous in memory.
            const auto order = grid.sortedParticles();
            particles.permute(std::vector<std::uint32_t>(order.begin(), order.end()));
            grid.build(particles.position, h, threads, periodic);
            stepsSinceReorder = 0;
        }
        neighbors.build(grid, particles.position, h, threads);
        boundaryNeighbors.build(boundary.grid, boundary.position, particles.position, h, threads);
        if (solver->usesWallPressure()) {
            findBoundaryNearFluid();
            boundaryFluidNeighbors.build(grid, particles.position, boundary.position, h, threads, boundaryNearFluid);
        }
    }

    /// The boundary particles some fluid particle's wall list names: the same pairs the
    /// boundary-to-fluid search would find, as both test the same distance.
    void findBoundaryNearFluid() {
        boundaryMarks.assign(boundary.position.size(), 0);
        // Threads may mark the same byte: relaxed atomic stores, plain stores on x86.
        parallelFor(particles.size(), threads, [&](std::uint32_t i) {
            for (const std::uint32_t b : boundaryNeighbors.of(i))
                std::atomic_ref<std::uint8_t>(boundaryMarks[b]).store(1, std::memory_order_relaxed);
        });
        boundaryNearFluid.clear();
        for (std::uint32_t b = 0; b < boundaryMarks.size(); ++b)
            if (boundaryMarks[b]) {
                reserveGrowing(boundaryNearFluid, boundaryNearFluid.size() + 1);
                boundaryNearFluid.push_back(b);
            }
    }

    void emit(double t0, double dt) {
        for (EmitterState& emitter : emitters) {
            const double dropped = emitter.advance(t0, dt, def.particleSpacing, [&](const Lattice& layer) {
                const std::uint64_t count = countLattice(layer, Fill::EmitterLayer);
                if (particles.size() + count > def.capacity) return false;
                appendLattice(layer, Fill::EmitterLayer, count, emitter.def.velocity, emitter.def.material, emitter.def.concentration);
                return true;
            });
            stats.emitterCapacityHits += dropped < 1.8e19 ? static_cast<std::uint64_t>(dropped) : ~std::uint64_t{0};
        }
    }

    /// The step's statistics; returns the divergence the same pass over the particles found.
    std::optional<Divergence> updateStats(double dt) {
        ++stats.steps;
        stats.lastDt = dt;
        stats.dtMin = stats.steps == 1 ? dt : std::min(stats.dtMin, dt);
        stats.dtMax = std::max(stats.dtMax, dt);
        stats.dtSum += dt;
        // Fixed blocks of particles, each summed in order and then combined in block order,
        // so the sums and the guard's first bad particle do not depend on the thread count.
        struct Block {
            double errorSum = 0.0, compressionSum = 0.0, maxSpeed2 = 0.0;
            std::optional<Divergence> found;
        };
        constexpr std::uint32_t kBlock = kReductionBlock;
        const std::uint32_t count = particles.size();
        const std::uint32_t blockCount = (count + kBlock - 1) / kBlock;
        std::vector<Block> blocks(blockCount);
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1 && blockCount > 1)
        for (std::uint32_t b = 0; b < blockCount; ++b) {
            Block& block = blocks[b];
            DivergenceGuard guard(dt, h);
            for (std::uint32_t i = b * kBlock; i < std::min(count, (b + 1) * kBlock); ++i) {
                const double rho0 = materials[particles.material[i]].restDensity;
                const double error = (particles.density[i] - rho0) / rho0;
                block.errorSum += std::abs(error);
                block.compressionSum += std::max(error, 0.0);
                const double speed2 = glm::dot(particles.velocity[i], particles.velocity[i]);
                block.maxSpeed2 = std::max(block.maxSpeed2, speed2);
                guard.check(particles, i, speed2);
            }
            block.found = guard.found();
        }
        double errorSum = 0.0, compressionSum = 0.0, maxSpeed2 = 0.0;
        std::optional<Divergence> found;
        for (const Block& block : blocks) {
            errorSum += block.errorSum;
            compressionSum += block.compressionSum;
            maxSpeed2 = std::max(maxSpeed2, block.maxSpeed2);
            if (!found) found = block.found;
        }
        const double n = std::max<double>(1.0, particles.size());
        stats.meanDensityError = static_cast<float>(errorSum / n);
        stats.meanCompression = static_cast<float>(compressionSum / n);
        stats.maxSpeed = static_cast<float>(std::sqrt(maxSpeed2));
        stats.maxMeanDensityError = std::max(stats.maxMeanDensityError, stats.meanDensityError);
        stats.maxMeanCompression = std::max(stats.maxMeanCompression, stats.meanCompression);
        stats.sumMeanDensityError += stats.meanDensityError;
        if (!found && stats.meanCompression > kCollapsedCompression) found = mostCompressed();
        return found;
    }

    /// The collapsed fluid's most compressed particle, as a Divergence.
    [[nodiscard]] Divergence mostCompressed() const {
        Divergence d;
        d.quantity = DivergedQuantity::Compression;
        d.limit = stats.meanCompression;
        float worstRatio = -1.0f;
        for (std::uint32_t i = 0; i < particles.size(); ++i) {
            const float ratio = particles.density[i] / materials[particles.material[i]].restDensity;
            if (ratio > worstRatio) {
                worstRatio = ratio;
                d.particle = i;
                d.id = particles.id[i];
                d.value = particles.density[i];
            }
        }
        return d;
    }
};

World::World(const WorldDef& def) {
    validateWorldDef(def);
    impl_ = std::make_unique<Impl>(def);
}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

MaterialIndex World::addMaterial(const MaterialDef& material) {
    validateMaterial(material);
    if (impl_->materials.size() >= std::numeric_limits<MaterialIndex>::max())
        throw std::invalid_argument("materials: at most 65535 materials, got one more");
    impl_->materials.push_back(material);
    return static_cast<MaterialIndex>(impl_->materials.size() - 1);
}

const std::vector<MaterialDef>& World::materials() const { return impl_->materials; }

void World::setMaterialPair(const MaterialPairDef& pair) {
    Impl& w = *impl_;
    for (const MaterialIndex m : {pair.a, pair.b})
        if (m >= w.materials.size())
            throw std::invalid_argument("materialPair.materials: no material " + std::to_string(m));
    if (!(pair.diffusivity >= 0.0f) || !std::isfinite(pair.diffusivity))
        throw std::invalid_argument("materialPair.diffusivity: must be >= 0 m²/s, got " + show(pair.diffusivity));
    if (!(pair.surfaceTension >= 0.0f) || !std::isfinite(pair.surfaceTension))
        throw std::invalid_argument("materialPair.surfaceTension: must be >= 0, got " + show(pair.surfaceTension));
    if (pair.a != pair.b && !pair.miscible && pair.diffusivity > 0.0f)
        throw std::invalid_argument("materialPair.diffusivity: " + show(pair.diffusivity) +
                                    " m²/s between immiscible materials \"" + w.materials[pair.a].name + "\" and \"" +
                                    w.materials[pair.b].name + "\" (set miscible)");
    if (pair.a == pair.b && pair.miscible)
        throw std::invalid_argument("materialPair.miscible: a material is always miscible with itself (\"" +
                                    w.materials[pair.a].name + "\")");
    for (MaterialPairDef& existing : w.pairs)
        if ((existing.a == pair.a && existing.b == pair.b) || (existing.a == pair.b && existing.b == pair.a)) {
            existing = pair;
            return;
        }
    w.pairs.push_back(pair);
}

const std::vector<MaterialPairDef>& World::materialPairs() const { return impl_->pairs; }

double World::meanConcentration() const {
    const ParticleStore& p = impl_->particles;
    double mass = 0.0, dye = 0.0;
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        mass += p.mass[i];
        dye += static_cast<double>(p.mass[i]) * p.concentration[i];
    }
    return mass > 0.0 ? dye / mass : 0.0;
}

float World::particleMass(MaterialIndex material) const {
    if (material >= impl_->materials.size())
        throw std::invalid_argument("material: no material " + std::to_string(material));
    return impl_->massOf(material);
}

namespace {
void validateBox(const char* what, const glm::vec3& min, const glm::vec3& max) {
    for (int axis = 0; axis < 3; ++axis) {
        requireFinite(what, min[axis]);
        requireFinite(what, max[axis]);
        if (min[axis] > max[axis])
            throw std::invalid_argument(std::string(what) + ": min " + show(min) + " exceeds max " + show(max));
    }
}
}  // namespace

bool World::insideDomain(const glm::vec3& min, const glm::vec3& max) const {
    return impl_->insideDomain(Lattice(min, max, impl_->def.particleSpacing));
}

std::uint32_t World::countBlock(const BlockDef& blockIn) const {
    const BlockDef block = impl_->inPlane(blockIn);
    const Lattice lattice = impl_->blockLattice(block.min, block.max);
    return static_cast<std::uint32_t>(std::min<std::uint64_t>(impl_->countLattice(lattice, Impl::Fill::Block), 0xffffffffu));
}

AddStatus World::addBlock(const BlockDef& blockIn) {
    const BlockDef block = impl_->inPlane(blockIn);
    validateBox("block", block.min, block.max);
    if (block.material >= impl_->materials.size())
        throw std::invalid_argument("block.material: no material " + std::to_string(block.material));
    const Lattice lattice = impl_->blockLattice(block.min, block.max);
    if (!impl_->insideDomain(lattice)) return AddStatus::OutsideDomain;
    if (!(block.concentration >= 0.0f) || !std::isfinite(block.concentration))
        throw std::invalid_argument("block.concentration: must be finite and >= 0, got " + show(block.concentration));
    const std::uint64_t count = impl_->countLattice(lattice, Impl::Fill::Block);
    if (impl_->particles.size() + count > impl_->def.capacity) return AddStatus::OverCapacity;
    impl_->appendLattice(lattice, Impl::Fill::Block, count, block.velocity, block.material, block.concentration);
    return AddStatus::Added;
}

void World::addObstacle(const ObstacleDef& def) {
    Impl& w = *impl_;
    ObstacleDef obstacle = def;
    const auto unit = [](const char* field, const glm::vec3& v) {
        for (int axis = 0; axis < 3; ++axis) requireFinite(field, v[axis]);
        if (!(glm::length(v) > 0.0f)) throw std::invalid_argument(std::string(field) + ": must be non-zero, got " + show(v));
        return glm::normalize(v);
    };
    switch (obstacle.shape) {
        case ObstacleDef::Shape::Box: validateBox("obstacle", obstacle.min, obstacle.max); break;
        case ObstacleDef::Shape::Sphere:
            for (int axis = 0; axis < 3; ++axis) requireFinite("obstacle.center", obstacle.center[axis]);
            requirePositive("obstacle.radius", obstacle.radius);
            break;
        case ObstacleDef::Shape::Cylinder:
            for (int axis = 0; axis < 3; ++axis) requireFinite("obstacle.center", obstacle.center[axis]);
            obstacle.axis = unit("obstacle.axis", obstacle.axis);
            requirePositive("obstacle.radius", obstacle.radius);
            requirePositive("obstacle.length", obstacle.length);
            break;
        case ObstacleDef::Shape::Plane:
            for (int axis = 0; axis < 3; ++axis) requireFinite("obstacle.point", obstacle.point[axis]);
            obstacle.normal = unit("obstacle.normal", obstacle.normal);
            break;
        case ObstacleDef::Shape::Mesh:
            if (!obstacle.mesh) throw std::invalid_argument("obstacle.mesh: a mesh obstacle needs a mesh, got none");
            break;
        case ObstacleDef::Shape::Circle:
            requireFinite("obstacle.center", obstacle.center.x);
            requireFinite("obstacle.center", obstacle.center.y);
            requirePositive("obstacle.radius", obstacle.radius);
            obstacle.center.z = 0.0f;
            break;
        case ObstacleDef::Shape::Polygon: validatePolygon(obstacle.polygon); break;
        default: throw std::invalid_argument("obstacle.shape: unknown shape");
    }
    validateObstacleDimensions(obstacle, w.def.dimensions);
    obstacle.motion = validatedMotion(obstacle.motion, "obstacle.motion");
    const bool dynamic = obstacle.dynamics.has_value();
    if (dynamic && obstacle.motion.type != MotionDef::Type::None)
        throw std::invalid_argument("obstacle.dynamic: a body the fluid moves has no prescribed motion; drop one of them");
    if (dynamic && obstacle.shape == ObstacleDef::Shape::Plane)
        throw std::invalid_argument("obstacle.dynamic: a plane cannot be a body (it is infinite); use a box");
    const bool moves = obstacle.motion.type != MotionDef::Type::None || dynamic;
    if (moves && obstacle.shape == ObstacleDef::Shape::Plane)
        throw std::invalid_argument("obstacle.motion: a plane cannot move (it is sampled only inside the container); use a box");
    // Sample up to the outside of the wall shell (a plane is infinite), or across one period
    // of a periodic axis; boundary particles that coincide with earlier ones (the shell, an
    // overlapping obstacle) are not repeated.
    // A moving obstacle only inside the walls: it must not double the shell where they meet.
    const float shell = moves && w.def.walls ? 0.0f : std::ceil(w.h / w.def.particleSpacing) * w.def.particleSpacing;
    glm::vec3 clipMin = w.def.domainMin - shell, clipMax = w.def.domainMax + shell;
    if (w.def.dimensions == 2) clipMin.z = clipMax.z = 0.0f;  // the one layer in the plane
    for (int axis = 0; axis < 3; ++axis)
        if (w.periodic.periodic(axis)) {
            clipMin[axis] = w.def.domainMin[axis];
            clipMax[axis] = w.def.domainMax[axis];
        }
    auto points = sampleObstacle(obstacle, w.latticeOrigin, w.def.particleSpacing, w.h, clipMin, clipMax, w.threads);
    for (glm::vec3& x : points) x = w.periodic.wrap(x);
    const auto index = static_cast<std::uint32_t>(w.obstacles.size());
    if (obstacle.name.empty()) obstacle.name = "obstacle" + std::to_string(index);
    if (findSolid(obstacle.name))
        throw std::invalid_argument("obstacle.name: \"" + obstacle.name + "\" is taken by another solid; names must be unique");
    if (obstacle.loadReference)
        for (int axis = 0; axis < 3; ++axis) requireFinite("obstacle.load_reference", (*obstacle.loadReference)[axis]);
    const int body = dynamic ? w.addBody(obstacle) : -1;  // first: it may refuse the body
    const auto solid = static_cast<std::uint16_t>(w.solids.size());
    w.solids.push_back({SolidInfo::Kind::Obstacle, index, obstacle.name});
    w.obstacleReferences.push_back(obstacle.loadReference ? *obstacle.loadReference : shapeCentre(obstacle));
    w.obstacles.push_back(obstacle);
    if (!moves) {
        if (w.bodySystem) w.bodySystem->addFixedObstacle(obstacle, obstacle.name);
        w.boundary.add(points, 1.0f / w.latticeSum, 0.5f * w.def.particleSpacing, w.h, w.threads, solid);
        w.fixedObstacles.push_back(obstacle);
        w.fixedObstacleSolids.push_back(solid);
        return;
    }
    const std::uint32_t begin = w.boundary.addMoving(points, 1.0f / w.latticeSum, solid);
    w.movers.push_back({index, RigidMotion(obstacle.motion), begin, std::move(points), body});
    if (dynamic) w.bodyMovers.push_back(static_cast<std::uint32_t>(w.movers.size() - 1));
    w.moveBoundaries(w.time);
}

const std::vector<ObstacleDef>& World::obstacles() const { return impl_->obstacles; }

const std::vector<SolidInfo>& World::solids() const { return impl_->solids; }

std::vector<BodyState> World::bodies() const {
    const Impl& w = *impl_;
    std::vector<BodyState> out;
    for (const std::uint32_t mover : w.bodyMovers) {
        const Impl::Mover& m = w.movers[mover];
        const bodies::RigidBody& b = w.bodySystem->body(static_cast<std::size_t>(m.body));
        out.push_back({m.index, w.obstacles[m.index].name, b.position(), b.orientation(), b.velocity(), b.angularVelocity(),
                       b.contactForce(), {}});
        for (std::size_t k = 0; k < b.def().moorings.size(); ++k)
            out.back().moorings.push_back({b.def().moorings[k].name, b.moorings()[k].tension});
    }
    return out;
}

std::optional<std::uint32_t> World::findSolid(const std::string& name) const {
    for (std::size_t s = 0; s < impl_->solids.size(); ++s)
        if (impl_->solids[s].name == name) return static_cast<std::uint32_t>(s);
    return std::nullopt;
}

const std::vector<SolidLoad>& World::solidLoads() const {
    Impl& w = *impl_;
    w.lastLoads.resize(w.solids.size());  // zero before the first step
    return w.lastLoads;
}

std::vector<SolidLoad> World::takeMeanSolidLoads() {
    Impl& w = *impl_;
    std::vector<SolidLoad> mean(w.solids.size());
    if (w.loadTime > 0.0)
        for (std::size_t s = 0; s < std::min(mean.size(), w.loadImpulse.size()); ++s) {
            mean[s].pressureForce = w.loadImpulse[s].pressureForce / w.loadTime;
            mean[s].viscousForce = w.loadImpulse[s].viscousForce / w.loadTime;
            mean[s].moment = w.loadImpulse[s].moment / w.loadTime;
        }
    w.loadImpulse.assign(w.solids.size(), SolidLoad{});
    w.loadTime = 0.0;
    return mean;
}

ObstaclePose World::obstaclePose(std::uint32_t index, double t) const {
    const Impl& w = *impl_;
    if (index >= w.obstacles.size()) throw std::invalid_argument("obstacle: no obstacle " + std::to_string(index));
    for (const Impl::Mover& m : w.movers)
        if (m.index == index) {
            const RigidPose pose = w.moverPose(m, t);
            return {pose.rotation, pose.pivot - pose.rotation * pose.center};
        }
    return {};
}

std::uint32_t World::countEscapedParticles() const {
    const Impl& w = *impl_;
    std::uint32_t escaped = 0;
    for (const glm::vec3& x : w.particles.position) {
        bool out = false;
        for (int axis = 0; axis < 3 && w.def.walls; ++axis)  // a periodic axis has no outside
            out = out || (!w.periodic.periodic(axis) &&
                          !(x[axis] >= w.def.domainMin[axis] && x[axis] <= w.def.domainMax[axis]));
        for (const ObstacleDef& o : w.fixedObstacles) out = out || signedDistance(o, x) < 0.0f;
        for (const Impl::Mover& m : w.movers) out = out || signedDistance(w.obstacles[m.index], w.moverPose(m, w.time), x) < 0.0f;
        for (const Impl::Paddle& paddle : w.paddles) out = out || paddle.maker.distanceInFront(w.time, x) < 0.0f;
        escaped += out;
    }
    return escaped;
}

void World::addWaveMaker(const WaveMakerDef& def) {
    Impl& w = *impl_;
    const WorldDef& d = w.def;
    if (def.type != WaveMakerDef::Type::Piston && def.type != WaveMakerDef::Type::Flap &&
        def.type != WaveMakerDef::Type::Solitary)
        throw std::invalid_argument("wavemaker.type: unknown type");
    requireFinite("wavemaker.x", def.x);
    if (!(def.x > d.domainMin.x && def.x < d.domainMax.x))
        throw std::invalid_argument("wavemaker.x: must lie inside the domain (" + show(d.domainMin.x) + ", " +
                                    show(d.domainMax.x) + "), got " + show(def.x));
    requirePositive("wavemaker.depth", def.depth);
    if (def.depth > d.domainMax.y - d.domainMin.y)
        throw std::invalid_argument("wavemaker.depth: must not exceed the domain height " +
                                    show(d.domainMax.y - d.domainMin.y) + ", got " + show(def.depth));
    if (!(def.rampTime >= 0.0f) || !std::isfinite(def.rampTime))
        throw std::invalid_argument("wavemaker.ramp_time: must be >= 0, got " + show(def.rampTime));
    const WaveSpectrumDef& sp = def.spectrum;
    if (def.type == WaveMakerDef::Type::Solitary) {
        requirePositive("wavemaker.wave_height", def.waveHeight);  // one wave: no period, no spectrum
    } else if (sp.type == WaveSpectrumDef::Type::None) {
        requirePositive("wavemaker.wave_height", def.waveHeight);
        requirePositive("wavemaker.period", def.period);
    } else {
        requirePositive("wavemaker.spectrum.hs", sp.significantHeight);
        requirePositive("wavemaker.spectrum.tp", sp.peakPeriod);
        requireInRange("wavemaker.spectrum.gamma", sp.gamma, 1.0f, 20.0f);
        if (sp.components < 1 || sp.components > 10000)
            throw std::invalid_argument("wavemaker.spectrum.components: must be in [1, 10000], got " +
                                        std::to_string(sp.components));
        requirePositive("wavemaker.spectrum.min_frequency", sp.minFrequency);
        if (!(sp.maxFrequency > sp.minFrequency) || !std::isfinite(sp.maxFrequency))
            throw std::invalid_argument("wavemaker.spectrum.max_frequency: must exceed min_frequency (" +
                                        show(sp.minFrequency) + "), got " + show(sp.maxFrequency));
    }
    const float g = glm::length(d.gravity);
    if (!(g > 0.0f)) throw std::invalid_argument("wavemaker: needs gravity, got " + show(d.gravity));
    checkWaveFitsTank(def, d.domainMax.x - def.x, d.particleSpacing, g);
    WaveMaker maker(def, d.domainMin.y, g);
    // A wave tank's numerics unless the scene chose its own (docs/waves.md § Defaults).
    applyWaveNumerics(w.def.solver);
    if (w.paddles.empty()) {
        // The fluid's lattice starts at the first paddle's face in x; the walls move onto it
        // while nothing else is there (wave makers come before obstacles and blocks).
        w.latticeOrigin.x = def.x;
        if (d.walls && w.obstacles.empty() && w.particles.size() == 0) w.sampleWalls();
    }
    const int layers = static_cast<int>(std::ceil(w.h / d.particleSpacing));
    // Across the tank between the walls, on their lattice.
    std::vector<glm::vec3> rest = maker.sample(w.wallsMin(), w.wallsMax(), d.particleSpacing, layers);
    const auto solid = static_cast<std::uint16_t>(w.solids.size());
    w.solids.push_back({SolidInfo::Kind::WaveMaker, static_cast<std::uint32_t>(w.paddles.size()),
                        "wavemaker" + std::to_string(w.paddles.size())});
    const std::uint32_t begin = w.boundary.addMoving(rest, 1.0f / w.latticeSum, solid);
    w.paddles.push_back({std::move(maker), begin, std::move(rest)});
    w.moveBoundaries(w.time);
}

std::uint32_t World::waveMakerCount() const { return static_cast<std::uint32_t>(impl_->paddles.size()); }

float World::waveMakerDisplacement(std::uint32_t index, double t) const {
    if (index >= impl_->paddles.size())
        throw std::invalid_argument("waveMaker: no wave maker " + std::to_string(index));
    return static_cast<float>(impl_->paddles[index].maker.motion(t).x);
}

void World::addDampingZone(const DampingZoneDef& zone) {
    requireFinite("damping.x_start", zone.xStart);
    requireFinite("damping.x_end", zone.xEnd);
    if (zone.xStart == zone.xEnd)
        throw std::invalid_argument("damping.x_end: must differ from x_start, got " + show(zone.xEnd));
    requirePositive("damping.strength", zone.strength);
    impl_->dampingZones.push_back(zone);
}

void World::setOcean(const OceanDef& ocean, MaterialIndex material) {
    Impl& w = *impl_;
    validateOcean(ocean);
    if (w.zones) throw std::invalid_argument("ocean: the world has an ocean already");
    if (material >= w.materials.size())
        throw std::invalid_argument("ocean.material: no material " + std::to_string(material));
    if (!w.obstacles.empty() || w.particles.size() != 0)
        throw std::invalid_argument("ocean: set it before obstacles and particles (the walls are sampled again)");
    const float height = w.def.domainMax.y - w.def.domainMin.y;
    if (!(ocean.depth <= height))
        throw std::invalid_argument("ocean.depth: must not exceed the domain height " + show(height) + ", got " +
                                    show(static_cast<float>(ocean.depth)));
    unsigned faces = 0;
    for (std::size_t i = 0; i < ocean.openSides.size(); ++i) {
        const OceanSide side = ocean.openSides[i];
        const int axis = side == OceanSide::MinusX || side == OceanSide::PlusX ? 0 : 2;
        const std::string where = "ocean.open_sides[" + std::to_string(i) + "]";
        if (w.periodic.periodic(axis))
            throw std::invalid_argument(where + ": " + oceanSideName(side) + " is on a periodic axis (domain.periodic)");
        if (side == OceanSide::MinusX && !w.paddles.empty())
            throw std::invalid_argument(where + ": -x has the wave maker on it: a side is either open or a paddle");
        faces |= 1u << (2 * axis + (side == OceanSide::PlusX || side == OceanSide::PlusZ ? 1 : 0));
    }
    ocean::NearField near;
    near.min = w.wallsMin();
    near.max = w.wallsMax();
    near.stillWaterY = static_cast<double>(w.def.domainMin.y) + ocean.depth;
    near.spacing = w.def.particleSpacing;
    near.latticeOrigin = w.latticeOrigin;
    const double g = std::max(1e-6, static_cast<double>(glm::length(w.def.gravity)));
    w.zones = std::make_unique<ocean::RelaxationZones>(ocean, near, g);
    w.oceanDef = ocean;
    w.oceanMaterial = material;
    w.openFaces = faces;
    if (w.def.walls) w.sampleWalls();
}

AddStatus World::fillOcean() {
    const Impl& w = *impl_;
    if (!w.zones) throw std::logic_error("fillOcean: no ocean (setOcean first)");
    BlockDef block;
    block.min = w.wallsMin();
    block.max = w.wallsMax();
    block.max.y = static_cast<float>(static_cast<double>(w.def.domainMin.y) + w.oceanDef.depth);
    block.material = w.oceanMaterial;
    return addBlock(block);
}

bool World::hasOcean() const { return impl_->zones != nullptr; }

double World::oceanSurfaceHeight(double x, double z) const {
    const Impl& w = *impl_;
    if (!w.zones) throw std::logic_error("oceanSurfaceHeight: no ocean (setOcean first)");
    return w.zones->surfaceY(x, z, w.time);
}

float World::surfaceHeight(float x, float z) const {
    const Impl& w = *impl_;
    if (w.zones && (x < w.def.domainMin.x || x > w.def.domainMax.x || z < w.def.domainMin.z || z > w.def.domainMax.z))
        return static_cast<float>(oceanSurfaceHeight(x, z));
    return freeSurfaceHeight(w.particles, w.materials, w.periodic, w.kernel(), x, z);
}

ProbeSample World::probe(const glm::vec3& point) const {
    const Impl& w = *impl_;
    const FieldSample s = sampleField(w.particles, w.materials, w.periodic, w.kernel(), point);
    return {s.density, s.pressure, s.velocity};
}

double World::totalMass() const {
    double sum = 0.0;
    for (const float m : impl_->particles.mass) sum += m;
    return sum;
}

std::uint32_t World::addEmitter(const EmitterDef& emitterIn) {
    EmitterDef emitter = emitterIn;
    if (impl_->def.dimensions == 2) {
        requireInPlane(2, "emitter.velocity", emitter.velocity);
        emitter.min.z = emitter.max.z = 0.0f;
    }
    validateBox("emitter", emitter.min, emitter.max);
    if (emitter.material >= impl_->materials.size())
        throw std::invalid_argument("emitter.material: no material " + std::to_string(emitter.material));
    if (!(glm::length(emitter.velocity) > 0.0f) || !std::isfinite(glm::length(emitter.velocity)))
        throw std::invalid_argument("emitter.velocity: must be non-zero and finite, got " + show(emitter.velocity));
    if (!(emitter.end > emitter.start))
        throw std::invalid_argument("emitter.end: must be after emitter.start");
    if (!(emitter.concentration >= 0.0f) || !std::isfinite(emitter.concentration))
        throw std::invalid_argument("emitter.concentration: must be finite and >= 0, got " + show(emitter.concentration));
    if (!impl_->insideDomain(Lattice(emitter.min, emitter.max, impl_->def.particleSpacing)))
        throw std::invalid_argument("emitter: outlet " + show(emitter.min) + ".." + show(emitter.max) +
                                    " lies outside the domain's walls, " + show(impl_->wallsMin()) + ".." +
                                    show(impl_->wallsMax()));
    impl_->emitters.push_back(EmitterState{emitter});
    return static_cast<std::uint32_t>(impl_->emitters.size() - 1);
}

void World::setEmitterActive(std::uint32_t emitter, bool active) {
    if (emitter >= impl_->emitters.size())
        throw std::invalid_argument("emitter: no emitter " + std::to_string(emitter));
    impl_->emitters[emitter].active = active;
}

std::uint32_t World::emitterCount() const { return static_cast<std::uint32_t>(impl_->emitters.size()); }

double World::step(double maxDt) {
    if (!(maxDt > 0.0))
        throw std::invalid_argument("maxDt: must be > 0, got " + std::to_string(maxDt));
    return impl_->step(maxDt, Impl::Clock::Runs);
}

double World::Impl::step(double maxDt, Clock clockMode) {
    Impl& w = *this;
    if (w.divergence) throw DivergenceError(*w.divergence);  // stepping garbage makes more garbage
    const bool held = clockMode == Clock::Held;
    PhaseClock clock(w.stats.phaseSeconds);
    w.resolveSoundSpeed();
    w.moveBoundaries(w.time);
    if (held) w.holdBoundaries();
    w.rebuildNeighbors();
    clock.lap(Phase::NeighborSearch);
    StepContext ctx{w.particles, w.neighbors, w.materials, w.def.solver, w.def.gravity, w.h,
                    w.def.particleSpacing, w.soundSpeed, w.boundary, w.boundaryNeighbors, w.boundaryFluidNeighbors,
                    w.boundaryNearFluid, w.periodic, w.viscosity, w.threads, maxDt};
    ctx.dimensions = w.def.dimensions;
    ctx.clock = &clock;
    w.pairTables.build(w.materials.size(), w.pairs);
    ctx.pairs = &w.pairTables;
    const bool loads = w.def.loads || w.bodySystem;  // bodies move by their loads
    if (loads) {
        w.wallLoads.reset(w.boundaryNeighbors.slotCount());
        ctx.loads = &w.wallLoads;
    }
    if (w.zones) w.zones->holdBegin(w.particles);
    const double dt = w.solver->step(ctx);
    // An ocean's buffers move with the far field, whatever the pressure did to them.
    if (w.zones) w.zones->holdEnd(w.particles, w.time, dt, held, w.threads);
    if (loads) w.sumLoads(dt);
    // Bodies move over the step under its load (weak coupling: the fluid saw them where they
    // were at its start); the strays are then pushed out of them where they end.
    if (w.bodySystem && !held) w.stepBodies(dt);
    // Where the step ends: with the clock held (settle), where it started.
    const double end = held ? w.time : w.time + dt;
    // Dye spreads over this step's neighbour lists at the positions the solver moved to.
    if (w.pairTables.anyDiffusion())
        w.diffusion.apply(w.particles, w.neighbors, w.periodic, w.pairTables, w.kernel(), static_cast<float>(dt), w.threads);
    w.stats.lastPressureIterations = ctx.pressureIterations;
    w.stats.pressureIterationsSum += static_cast<std::uint64_t>(ctx.pressureIterations);
    w.stats.divergenceIterationsSum += static_cast<std::uint64_t>(ctx.divergenceIterations);
    w.stats.unconvergedSolves += ctx.pressureConverged ? 0 : 1;
    w.stats.recentUnconverged = (w.stats.recentUnconverged << 1) | (ctx.pressureConverged ? 0u : 1u);
    const float margin = w.solver->wallMargin() * w.def.particleSpacing;
    // The projections below stop strays: the normal speed they take away is momentum the
    // solid absorbs, part of its load (with loads on, each stage's change is booked to it).
    if (loads) w.contacts.begin(w.particles, w.solidReferences(w.time), w.periodic);
    // Moving obstacles first: where one squeezes a particle against a wall, the wall wins.
    for (const Impl::Mover& m : w.movers) {
        projectOutOfMovingObstacle(w.obstacles[m.index], w.moverPose(m, end), w.particles, margin, w.threads);
        if (loads) w.contacts.book(w.particles, w.threads, [&](std::uint32_t, const glm::vec3&) { return w.solidOfObstacle(m.index); });
    }
    if (w.def.walls) {
        // No walls across a periodic axis, the 2D plane, nor on an ocean's open sides.
        const auto [lo, hi] = w.wallLimits(std::numeric_limits<double>::infinity());
        const WallBox walls{glm::vec3(lo), glm::vec3(hi), margin, w.def.wallRestitution};
        walls.enforce(w.particles, w.threads);
        // The face that pushed: along the largest change, the min face for a push towards +.
        if (loads)
            w.contacts.book(w.particles, w.threads, [](std::uint32_t, const glm::vec3& dv) {
                const glm::vec3 a = glm::abs(dv);
                const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.z >= a.y ? 2 : 1);
                return static_cast<std::uint16_t>(BoundaryParticles::kWallFace + 2 * axis + (dv[axis] > 0.0f ? 0 : 1));
            });
    }
    if (!loads) {
        projectOutOfObstacles(w.fixedObstacles, w.particles, margin, w.threads);
    } else {
        // One at a time (the same arithmetic: each particle meets them in the same order).
        for (std::size_t k = 0; k < w.fixedObstacles.size(); ++k) {
            projectOutOfObstacles(std::span(w.fixedObstacles).subspan(k, 1), w.particles, margin, w.threads);
            w.contacts.book(w.particles, w.threads, [&](std::uint32_t, const glm::vec3&) { return w.fixedObstacleSolids[k]; });
        }
    }
    for (const Impl::Paddle& paddle : w.paddles) {
        paddle.maker.project(end, w.particles, margin, w.threads);
        if (loads) {
            const auto solid = w.solidOfPaddle(static_cast<std::uint32_t>(&paddle - w.paddles.data()));
            w.contacts.book(w.particles, w.threads, [&](std::uint32_t, const glm::vec3&) { return solid; });
        }
    }
    if (loads) w.contacts.finish(dt, w.lastLoads, w.loadImpulse);
    applyDampingZones(w.dampingZones, w.particles, dt, w.threads);
    if (w.zones) {
        clock.lap(Phase::Integration);
        w.couple(end, dt);
        clock.lap(Phase::Coupling);
    }
    if (w.periodic.any)
        parallelFor(w.particles.size(), w.threads, [&](std::uint32_t i) {
            w.particles.position[i] = w.periodic.wrap(w.particles.position[i]);
        });
    std::optional<Divergence> diverged = w.updateStats(dt);
    if (!held) w.emit(w.time, dt);
    w.time = end;
    clock.lap(Phase::Integration);
    if (diverged) {
        diverged->step = w.stats.steps;
        diverged->time = w.time;
        diverged->dt = dt;
        diverged->unconvergedOfLast32 = std::popcount(w.stats.recentUnconverged);
        diverged->maxIterations = w.def.solver.maxIterations;
        diverged->solver = w.def.solver.method;
        diverged->densityRatio = w.restDensityRatio();
        w.divergence = diverged;
        throw DivergenceError(*diverged);
    }
    return dt;
}

void World::advance(double duration, const std::function<void()>& afterStep) {
    if (!(duration >= 0.0) || !std::isfinite(duration))
        throw std::invalid_argument("duration: must be finite and >= 0, got " + std::to_string(duration));
    const double end = impl_->time + duration;
    // Steps shorter than a nanosecond only chase round-off.
    while (end - impl_->time > 1e-9) {
        step(end - impl_->time);
        if (afterStep) afterStep();
    }
    impl_->time = std::max(impl_->time, end);
}

SettleReport World::settle(double seconds, float quietSpeed, const std::function<void()>& afterStep) {
    if (!(seconds >= 0.0) || !std::isfinite(seconds))
        throw std::invalid_argument("settle.time: must be finite and >= 0, got " + std::to_string(seconds));
    if (!(quietSpeed >= 0.0f) || !std::isfinite(quietSpeed))
        throw std::invalid_argument("settle.speed: must be finite and >= 0, got " + std::to_string(quietSpeed));
    Impl& w = *impl_;
    SettleReport report;
    double quietSince = 0.0;  // settling time since which every step's fastest particle was below quietSpeed
    // Steps of at most what is left, as advance() takes them, but on a held clock.
    while (seconds - report.seconds > 1e-9) {
        report.seconds += w.step(seconds - report.seconds, Impl::Clock::Held);
        ++report.steps;
        if (afterStep) afterStep();
        if (!(w.stats.maxSpeed < quietSpeed)) quietSince = report.seconds;
        if (report.seconds - quietSince >= kSettleQuietTime) {
            report.quiet = true;
            break;
        }
    }
    report.maxSpeed = w.stats.maxSpeed;
    for (glm::vec3& v : w.particles.velocity) v = glm::vec3(0.0f);
    w.stats = WorldStats{};
    w.resetLoads();
    return report;
}

double World::time() const { return impl_->time; }
const ParticleStore& World::particles() const { return impl_->particles; }
std::span<glm::vec3> World::velocities() { return impl_->particles.velocity; }
void World::reserve(std::uint32_t particles) {
    impl_->particles.reserve(std::min(particles, impl_->def.capacity));
}
const WorldStats& World::stats() const { return impl_->stats; }
const WorldDef& World::def() const { return impl_->def; }
float World::supportRadius() const { return impl_->h; }
int World::threads() const { return impl_->threads; }

void World::clear() {
    Impl& w = *impl_;
    w.particles.clear();
    w.emitters.clear();
    w.time = 0.0;
    w.stats = WorldStats{};
    w.soundSpeed = w.def.solver.soundSpeed;
    w.stepsSinceReorder = 0;
    w.divergence.reset();
    w.resetLoads();
}

const std::optional<Divergence>& World::divergence() const { return impl_->divergence; }

WorldState World::saveState() const {
    const Impl& w = *impl_;
    WorldState s;
    s.time = w.time;
    s.soundSpeed = w.soundSpeed;
    s.stepsSinceReorder = w.stepsSinceReorder;
    s.stats = w.stats;
    s.particles = w.particles;
    for (const EmitterState& e : w.emitters) s.emitters.push_back({e.active, e.travelled});
    s.solverState = w.solver->carriedState();
    if (w.bodySystem) s.bodyState = w.bodySystem->saveState();
    return s;
}

namespace {
[[noreturn]] void misfit(const std::string& what) {
    throw std::invalid_argument("state: " + what + " (was it saved from another scene?)");
}

void checkFits(const WorldState& s, std::size_t materials, std::size_t emitters, std::uint32_t capacity) {
    if (!std::isfinite(s.time) || s.time < 0.0) misfit("time must be finite and >= 0, got " + std::to_string(s.time));
    if (!std::isfinite(s.soundSpeed) || s.soundSpeed < 0.0f) misfit("sound speed must be finite and >= 0");
    if (s.stepsSinceReorder < 0) misfit("steps since reorder must be >= 0");
    const ParticleStore& p = s.particles;
    const std::size_t n = p.position.size();
    const std::size_t sizes[] = {p.velocity.size(), p.acceleration.size(), p.density.size(), p.pressure.size(),
                                 p.mass.size(), p.warmKappa.size(), p.warmDivergence.size(), p.concentration.size(),
                                 p.material.size(), p.id.size()};
    for (const std::size_t size : sizes)
        if (size != n) misfit("particle arrays differ in length (" + std::to_string(size) + " vs " + std::to_string(n) + ")");
    if (n > capacity) misfit(std::to_string(n) + " particles exceed the capacity " + std::to_string(capacity));
    // A saved state passed the divergence guard: anything else is damage, and would, e.g.,
    // give the grid an infinite extent.
    constexpr float kFar = 1e18f;
    const auto sane = [&](const glm::vec3& v) {
        return std::abs(v.x) < kFar && std::abs(v.y) < kFar && std::abs(v.z) < kFar;  // false for NaN
    };
    for (std::size_t i = 0; i < n; ++i) {
        if (!sane(p.position[i]) || !sane(p.velocity[i]) || !sane(p.acceleration[i]) || !std::isfinite(p.density[i]) ||
            !std::isfinite(p.pressure[i]) || !(p.mass[i] > 0.0f) || !std::isfinite(p.mass[i]) ||
            !std::isfinite(p.warmKappa[i]) || !std::isfinite(p.warmDivergence[i]) || !(p.concentration[i] >= 0.0f) ||
            !std::isfinite(p.concentration[i]))
            misfit("particle " + std::to_string(i) + " has a non-finite or absurd value");
        if (p.material[i] >= materials)
            misfit("particle " + std::to_string(i) + " has material " + std::to_string(p.material[i]) + " of " +
                   std::to_string(materials));
        if (p.id[i] >= p.nextId())
            misfit("particle " + std::to_string(i) + " has id " + std::to_string(p.id[i]) + ", not below the next id " +
                   std::to_string(p.nextId()));
    }
    if (s.emitters.size() != emitters)
        misfit(std::to_string(s.emitters.size()) + " emitters saved, the world has " + std::to_string(emitters));
    for (const EmitterProgress& e : s.emitters)
        if (!std::isfinite(e.travelled)) misfit("an emitter's travelled distance is not finite");
    for (const double x : s.solverState)
        if (!std::isfinite(x)) misfit("a solver scalar is not finite");
}
}  // namespace

void World::restoreState(WorldState state) {
    Impl& w = *impl_;
    checkFits(state, w.materials.size(), w.emitters.size(), w.def.capacity);
    if (!w.bodySystem && !state.bodyState.empty()) misfit("the state holds floating bodies, this world has none");
    const std::vector<double> bodiesBefore = w.bodySystem ? w.bodySystem->saveState() : std::vector<double>{};
    if (w.bodySystem) {
        try {
            w.bodySystem->restoreState(state.bodyState);
        } catch (const std::exception& e) {
            w.bodySystem->restoreState(bodiesBefore);
            misfit(std::string("its floating bodies do not fit this world's: ") + e.what());
        }
    }
    const std::vector<double> solverBefore = w.solver->carriedState();
    if (!w.solver->restoreCarriedState(state.solverState)) {
        if (w.bodySystem) w.bodySystem->restoreState(bodiesBefore);
        misfit(std::to_string(state.solverState.size()) + " solver scalars saved, the " + w.def.solver.method +
               " solver carries " + std::to_string(solverBefore.size()));
    }
    // Nothing below can fail: the World changes all at once or not at all.
    w.time = state.time;
    w.soundSpeed = state.soundSpeed;
    w.stepsSinceReorder = state.stepsSinceReorder;
    w.stats = state.stats;
    w.particles = std::move(state.particles);
    for (std::size_t e = 0; e < w.emitters.size(); ++e) {
        w.emitters[e].active = state.emitters[e].active;
        w.emitters[e].travelled = state.emitters[e].travelled;
    }
    w.divergence.reset();
    w.resetLoads();  // a checkpoint is taken where the run starts a new average
    w.moveBoundaries(w.time);
}

}  // namespace tide
