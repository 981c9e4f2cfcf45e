#pragma once
/// \file
/// The World's state and the steps of its machinery (World::Impl), shared by world.cpp
/// (building a world: materials, blocks, obstacles, wave makers, emitters, the ocean),
/// world_step.cpp (stepping, advancing, settling) and world_state.cpp (accessors,
/// checkpoints' state). Internal to tide::core.
#include <tide/world.hpp>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>
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
#include "comm/exact_sum.hpp"
#include "core/divergence_guard.hpp"
#include "core/field_sampling.hpp"
#include "core/kernels.hpp"
#include "core/material_pairs.hpp"
#include "core/parallel.hpp"
#include "core/periodic_box.hpp"
#include "core/planar.hpp"
#include "core/scratch_resize.hpp"
#include "core/validate.hpp"
#include "sources/active_absorption_schaffer_klopman2000.hpp"
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

/// Σ_k W(|k|·s) over the cubic lattice (the square one in 2D), W the solver's density kernel:
/// a lattice particle of mass ρ0 / this sum has exactly the rest density inside a filled
/// block, so blocks start at rest. (About ρ0 s³, in 2D ρ0 s² per metre of width.)
float latticeKernelSum(DensityKernel kernel, KernelShape shape, float spacing, float h, int dimensions);

struct WorldDistribution;  // core/world_distributed.hpp
/// Before the neighbour search of a split run: ghosts dropped, particles migrated to their
/// owners, new ghosts, the (cell, id) order; returns the grid's anchor.
const glm::vec3* exchangeParticles(World::Impl& w);
/// The split run's solver hooks.
const StepSharing* stepSharing(const World::Impl& w);
/// Whether particle i is a ghost (a copy of another rank's particle).
bool isGhost(const World::Impl& w, std::uint32_t i);
/// Σ over ranks of a sum each rank took exactly (statistics of a split run).
double sumOverRanks(const World::Impl& w, const comm::ExactSum& local);
std::uint64_t ownedOverRanks(const World::Impl& w);
std::uint64_t countOverRanks(const World::Impl& w, std::uint64_t local);
double maxOverRanks(const World::Impl& w, double local);
/// A split run's particles from `first` on (just emitted, the same on every rank): keeps
/// those in this rank's box, as owned particles.
void keepOwnedFrom(World::Impl& w, std::uint32_t first);
/// An ocean's outflow and inflow in a split run (the rest of Impl::couple): each rank removes
/// its particles past the open faces and fills the lattice points of its own cells; the added
/// particles take ids in the one order every rank count shares. Collective.
void coupleOverRanks(World::Impl& w, double end);
/// World::surfaceHeight at (x, z) over every rank's particles, the same on every rank
/// (collective): a paddle's absorber in a split run.
float surfaceHeightOverRanks(const World::Impl& w, float x, float z);
/// A split run's ghost flags (1: not this rank's), for bookings that must skip them.
const std::vector<std::uint8_t>* ghostFlags(const World::Impl& w);
/// A split run's contact impulses summed over the ranks (ContactImpulses::reduce).
void reduceContactImpulses(World::Impl& w);
/// A split run's loads of the step (sumSolidLoads over every rank's own particles, exactly).
std::vector<SolidLoad> solidLoadsOverRanks(const World::Impl& w, double dt);

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
        std::optional<ActiveAbsorption> absorber;  ///< a piston's, unless its absorption is off
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
    /// The near field's level over the far field's at time t (RelaxationZones::levelError),
    /// from every particle the zones have exchanged so far (every rank's), m.
    [[nodiscard]] double oceanLevelError(double t) const {
        return zones->levelError(static_cast<std::int64_t>(stats.oceanAdded) - static_cast<std::int64_t>(stats.oceanRemoved), t);
    }
    /// Relaxation, outflow and inflow of the ocean's zones over a step of dt ending at `end`.
    void couple(double end, double dt) {
        zones->relax(particles, end, dt, threads);
        if (distribution) {
            coupleOverRanks(*this, end);
            return;
        }
        stats.oceanRemoved += zones->removeOutflow(particles);
        const std::vector<WaveMaker::Face> faces = paddleFaces();
        stats.oceanAdded += zones->refill(particles, end, oceanLevelError(end), oceanMass(), oceanMaterial,
                                          materials[oceanMaterial].restDensity, def.capacity,
                                          [&](const glm::vec3& x) { return roomFor(x, Fill::Block, faces); }, threads);
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
    /// started), added to the running average; without `recorded` (the solver records none), 0.
    void sumLoads(double dt, bool recorded) {
        if (recorded && distribution)
            lastLoads = solidLoadsOverRanks(*this, dt);
        else if (recorded)
            sumSolidLoads(wallLoads, boundaryNeighbors, boundary, particles.size(), dt, solidReferences(time), periodic,
                          threads, lastLoads);
        else
            lastLoads.assign(solids.size(), SolidLoad{});
        loadImpulse.resize(solids.size());
        for (std::size_t s = 0; s < solids.size(); ++s) {
            loadImpulse[s].pressureForce += dt * lastLoads[s].pressureForce;
            loadImpulse[s].viscousForce += dt * lastLoads[s].viscousForce;
            loadImpulse[s].moment += dt * lastLoads[s].moment;
        }
        loadTime += dt;
    }

    static constexpr double kBodyContactDampingInFluid = 5.0;

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
        if (def.dimensions == 2) planarBody(body, d.freeAxes);
        body.contact.distance = def.particleSpacing;  // the thinnest film the fluid resolves
        // Overdamped: a body resting on a critically damped contact rang on it, driven by the
        // fluid load's step-to-step noise, and the water under it pushed back harder as it came
        // down than it let go as it went up: the dense box's floor carried 10 % less than
        // (ρ_b − ρ) g V (5.29 N for 5.89 N); at ζ = 5, 5.69 N, as the box held still gives.
        body.contact.dampingRatio = kBodyContactDampingInFluid;
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

    /// A 2D body as the body system sees it: a prism one metre wide across the plane (z from
    /// −½ to ½; a circle a cylinder along z), so its mass and inertia are per metre of width,
    /// as the loads are; it moves in x, y and rz only (unless fewer are free).
    static void planarBody(bodies::BodyDef& body, const std::vector<std::string>& free) {
        ObstacleDef& s = body.shape;
        if (s.shape == ObstacleDef::Shape::Box) {
            s.min.z = -0.5f;
            s.max.z = 0.5f;
        } else {  // a circle (validateObstacleDimensions refuses a polygon body)
            s.shape = ObstacleDef::Shape::Cylinder;
            s.axis = {0.0f, 0.0f, 1.0f};
            s.length = 1.0f;
            s.center.z = 0.0f;
        }
        if (body.centerOfMass) body.centerOfMass->z = 0.0;
        for (std::size_t k = 0; k < free.size(); ++k)
            if (free[k] != "x" && free[k] != "y" && free[k] != "rz")
                throw std::invalid_argument("obstacle.constraint.free[" + std::to_string(k) + "]: a 2D body moves in x, y and rz only, got \"" +
                                            free[k] + "\"");
        if (free.empty()) body.constraint = bodies::freeAxes({"x", "y", "rz"}, "obstacle.constraint.free");
        requireInPlane(2, "obstacle.velocity", glm::vec3(body.velocity));
        if (body.angularVelocity.x != 0.0 || body.angularVelocity.y != 0.0)
            throw std::invalid_argument("obstacle.angular_velocity: a 2D body turns about z only, got " + show(glm::vec3(body.angularVelocity)));
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
    /// An ocean particle's mass: its lattice cell is a layer tall (ocean::NearField::layer).
    [[nodiscard]] float oceanMass() const {
        return static_cast<float>(massOf(oceanMaterial) * zones->nearField().layer / def.particleSpacing);
    }

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
    /// `faces`: paddleFaces() at `time`, computed once for the many points a caller asks about.
    [[nodiscard]] bool roomFor(const glm::vec3& x, Fill fill, std::span<const WaveMaker::Face> faces) const {
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
        for (const WaveMaker::Face& face : faces)
            if (!(face.distanceInFront(x) > half)) return false;
        return fill == Fill::EmitterLayer || !boundary.anyCloserThan(x, kFillSeparation * def.particleSpacing);
    }

    /// Each paddle's face at `time` (roomFor).
    [[nodiscard]] std::vector<WaveMaker::Face> paddleFaces() const {
        std::vector<WaveMaker::Face> faces;
        for (const Paddle& paddle : paddles) faces.push_back(paddle.maker.face(time));
        return faces;
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

    /// Whether a paddle's absorber acts: when asked for, or by default (Automatic) in a tank
    /// whose far end absorbs, as issue 42 asks: a damping zone facing the paddle, a beach (a
    /// fixed plane sloping up away from it; a vertical wall reflects) or an ocean's open +x
    /// side. Until 2D dfsph's divergence solve acted, issue 42's 2D flume lost the water at the
    /// paddle at 8.5–9.1 s with it; now it runs 30 s with waves of 0.027–0.029 m for 0.03
    /// (docs/notes/waves.md § Active absorption).
    [[nodiscard]] bool absorbing(const Paddle& paddle) const {
        if (!paddle.absorber) return false;
        const WaveMakerDef::Absorption a = paddle.maker.def().absorption;
        return a == WaveMakerDef::Absorption::On || (a == WaveMakerDef::Absorption::Automatic && farEndAbsorbs());
    }
    [[nodiscard]] bool farEndAbsorbs() const {
        for (const DampingZoneDef& zone : dampingZones)
            if (zone.xEnd > zone.xStart) return true;
        for (const ObstacleDef& o : fixedObstacles)  // a slope rising away from the paddle, not a wall
            if (o.shape == ObstacleDef::Shape::Plane && o.normal.x < 0.0f && o.normal.y > 0.0f) return true;
        return (openFaces & 2u) != 0;
    }
    /// Active absorption (sources/active_absorption_schaffer_klopman2000.hpp): each absorbing
    /// paddle measures the surface at its gauge at the step's start and takes the correction
    /// velocity for the step.
    void absorbWaves() {
        for (Paddle& paddle : paddles) {
            if (!absorbing(paddle)) continue;
            WaveMaker& maker = paddle.maker;
            const float x = maker.def().x + static_cast<float>(maker.motion(time).x + paddle.absorber->gaugeDistance());
            const float z = 0.5f * (wallsMin().z + wallsMax().z);
            const float y = distribution ? surfaceHeightOverRanks(*this, x, z)
                                         : freeSurfaceHeight(particles, materials, periodic, kernel(), x, z);
            const double offset = maker.correction().at(time);
            const double still = static_cast<double>(def.domainMin.y) + maker.def().depth;
            const double velocity = paddle.absorber->correctionVelocity(time, y, still, offset, maker.correction().velocity);
            maker.setCorrection({offset, velocity, time});
        }
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
        const std::vector<WaveMaker::Face> faces = paddleFaces();
        lattice.forEach([&](const glm::vec3& x) { n += roomFor(x, fill, faces); });
        return n;
    }

    /// Appends the lattice's `count` points that have room for a particle (countLattice).
    void appendLattice(const Lattice& lattice, Fill fill, std::uint64_t count, const glm::vec3& velocity,
                       MaterialIndex material, float concentration = 0.0f) {
        const float m = massOf(material);
        const float rho0 = materials[material].restDensity;
        const bool everyPoint = obstacles.empty() && paddles.empty();
        particles.makeRoomFor(static_cast<std::uint32_t>(count));
        const std::vector<WaveMaker::Face> faces = paddleFaces();
        lattice.forEach([&](const glm::vec3& x) {
            if (everyPoint || roomFor(x, fill, faces)) particles.append(x, velocity, m, material, rho0, concentration);
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

    /// A run split among processes (core/world_distributed.hpp), or null.
    std::shared_ptr<WorldDistribution> distribution;

    void rebuildNeighbors() {
        const glm::vec3* anchor = distribution ? exchangeParticles(*this) : nullptr;
        grid.build(particles.position, h, threads, periodic, anchor);
        // A split run keeps the (cell, id) order every step instead.
        if (!anchor && def.reorderInterval > 0 && ++stepsSinceReorder >= def.reorderInterval) {
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
        if (emitters.empty()) return;
        // A split run: every rank emits every layer (the same ids on each) and keeps what falls
        // in its box; the capacity counts every rank's particles.
        const std::uint32_t before = particles.size();
        std::uint64_t held = distribution ? ownedOverRanks(*this) : particles.size();
        for (EmitterState& emitter : emitters) {
            const double dropped = emitter.advance(t0, dt, def.particleSpacing, [&](const Lattice& layer) {
                const std::uint64_t count = countLattice(layer, Fill::EmitterLayer);
                if (held + count > def.capacity) return false;
                appendLattice(layer, Fill::EmitterLayer, count, emitter.def.velocity, emitter.def.material, emitter.def.concentration);
                held += count;
                return true;
            });
            stats.emitterCapacityHits += dropped < 1.8e19 ? static_cast<std::uint64_t>(dropped) : ~std::uint64_t{0};
        }
        if (distribution && particles.size() > before) keepOwnedFrom(*this, before);
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
            comm::ExactSum exactError, exactCompression;  // a split run's: they must not depend on the split
            std::optional<Divergence> found;
        };
        const bool split = distribution != nullptr;
        constexpr std::uint32_t kBlock = kReductionBlock;
        const std::uint32_t count = particles.size();
        const std::uint32_t blockCount = (count + kBlock - 1) / kBlock;
        std::vector<Block> blocks(blockCount);
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1 && blockCount > 1)
        for (std::uint32_t b = 0; b < blockCount; ++b) {
            Block& block = blocks[b];
            DivergenceGuard guard(dt, h);
            for (std::uint32_t i = b * kBlock; i < std::min(count, (b + 1) * kBlock); ++i) {
                if (split && isGhost(*this, i)) continue;
                const double rho0 = materials[particles.material[i]].restDensity;
                const double error = (particles.density[i] - rho0) / rho0;
                block.errorSum += std::abs(error);
                block.compressionSum += std::max(error, 0.0);
                if (split) {
                    block.exactError.add(std::abs(error));
                    block.exactCompression.add(std::max(error, 0.0));
                }
                const double speed2 = glm::dot(particles.velocity[i], particles.velocity[i]);
                block.maxSpeed2 = std::max(block.maxSpeed2, speed2);
                guard.check(particles, i, speed2);
            }
            block.found = guard.found();
        }
        double errorSum = 0.0, compressionSum = 0.0, maxSpeed2 = 0.0;
        comm::ExactSum exactError, exactCompression;
        std::optional<Divergence> found;
        for (const Block& block : blocks) {
            errorSum += block.errorSum;
            compressionSum += block.compressionSum;
            exactError.merge(block.exactError);
            exactCompression.merge(block.exactCompression);
            maxSpeed2 = std::max(maxSpeed2, block.maxSpeed2);
            if (!found) found = block.found;
        }
        double n = std::max<double>(1.0, particles.size());
        if (split) {
            errorSum = sumOverRanks(*this, exactError);
            compressionSum = sumOverRanks(*this, exactCompression);
            maxSpeed2 = maxOverRanks(*this, maxSpeed2);
            n = std::max<double>(1.0, static_cast<double>(ownedOverRanks(*this)));
        }
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

}  // namespace tide
