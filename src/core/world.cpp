#include <tide/world.hpp>

#include "core/world_impl.hpp"

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
    if (s.smoothDensityError.value_or(false) && s.method != "dfsph")
        throw std::invalid_argument("solver.smoothDensityError: only the dfsph solver takes it, got solver \"" + s.method + "\"");
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
}  // namespace

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

World::World(const WorldDef& def) {
    const WorldDef resolved = withResolvedKernel(def);  // the kernel and support a 2D or 3D world gets by default
    validateWorldDef(resolved);
    impl_ = std::make_unique<Impl>(resolved);
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
    // A body's buoyancy is the volume its particles hold: a box samples its own lattice. Other
    // solids sample the fluid's, which the water around them starts on.
    auto points = dynamic && obstacle.shape == ObstacleDef::Shape::Box
                      ? sampleBoxCentred(obstacle, w.latticeOrigin, w.def.particleSpacing, w.h, clipMin, clipMax)
                      : sampleObstacle(obstacle, w.latticeOrigin, w.def.particleSpacing, w.h, clipMin, clipMax, w.threads);
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
    const std::vector<WaveMaker::Face> faces = w.paddleFaces();
    for (std::uint32_t i = 0; i < w.particles.size(); ++i) {
        if (w.distribution && isGhost(w, i)) continue;  // counted by its owner
        const glm::vec3& x = w.particles.position[i];
        bool out = false;
        for (int axis = 0; axis < 3 && w.def.walls; ++axis)  // a periodic axis has no outside
            out = out || (!w.periodic.periodic(axis) &&
                          !(x[axis] >= w.def.domainMin[axis] && x[axis] <= w.def.domainMax[axis]));
        for (const ObstacleDef& o : w.fixedObstacles) out = out || signedDistance(o, x) < 0.0f;
        for (const Impl::Mover& m : w.movers) out = out || signedDistance(w.obstacles[m.index], w.moverPose(m, w.time), x) < 0.0f;
        for (const WaveMaker::Face& face : faces) out = out || face.distanceInFront(x) < 0.0f;
        escaped += out;
    }
    if (w.distribution) return static_cast<std::uint32_t>(countOverRanks(w, escaped));
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
    checkRoomAboveWaves(def, static_cast<double>(d.domainMax.y - d.domainMin.y) - def.depth);
    WaveMaker maker(def, d.domainMin.y, g);
    // A wave tank's numerics unless the scene chose its own (docs/waves.md § Defaults).
    applyWaveNumerics(w.def.solver, w.def.dimensions, def.type != WaveMakerDef::Type::Solitary);
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
    std::optional<ActiveAbsorption> absorber;
    if (def.type == WaveMakerDef::Type::Piston && def.absorption != WaveMakerDef::Absorption::Off)
        absorber.emplace(def, maker.components(), g, d.particleSpacing);
    w.paddles.push_back({std::move(maker), begin, std::move(rest), std::move(absorber)});
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
    checkRoomAboveSea(ocean, static_cast<double>(height) - ocean.depth);
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
    const double depthOnLattice = near.stillWaterY - static_cast<double>(w.latticeOrigin.y);
    near.layer = depthOnLattice / oceanStillWaterLayers(depthOnLattice, near.spacing);
    const double g = std::max(1e-6, static_cast<double>(glm::length(w.def.gravity)));
    w.zones = std::make_unique<ocean::RelaxationZones>(ocean, near, g);
    w.oceanDef = ocean;
    w.oceanMaterial = material;
    w.openFaces = faces;
    // Its waves get a wave tank's numerics unless the scene chose its own (issue 42: "a scene
    // with a wave maker (or an ocean zone)"; docs/waves.md § Defaults).
    applyWaveNumerics(w.def.solver, w.def.dimensions, true);
    if (w.def.walls) w.sampleWalls();
}

AddStatus World::fillOcean() {
    Impl& w = *impl_;
    if (!w.zones) throw std::logic_error("fillOcean: no ocean (setOcean first)");
    // The domain's lattice across, the still water's layers up (oceanStillWaterLayers): its
    // surface stands at the far field's still water level whatever the depth and spacing.
    const ocean::NearField& near = w.zones->nearField();
    const Lattice across = w.blockLattice(w.wallsMin(), {w.wallsMax().x, w.wallsMin().y + w.def.particleSpacing, w.wallsMax().z});
    const auto layers = static_cast<std::uint32_t>(std::lround((near.stillWaterY - near.latticeOrigin.y) / near.layer));
    std::vector<glm::vec3> points;
    const std::vector<WaveMaker::Face> faces = w.paddleFaces();
    across.forEach([&](const glm::vec3& column) {
        for (std::uint32_t k = 0; k < layers; ++k) {
            const glm::vec3 x(column.x, static_cast<float>(near.latticeOrigin.y + (k + 0.5) * near.layer), column.z);
            if (w.roomFor(x, Impl::Fill::Block, faces)) points.push_back(x);
        }
    });
    if (w.particles.size() + points.size() > w.def.capacity) return AddStatus::OverCapacity;
    const float mass = w.oceanMass(), rho0 = w.materials[w.oceanMaterial].restDensity;
    w.particles.makeRoomFor(static_cast<std::uint32_t>(points.size()));
    for (const glm::vec3& x : points) w.particles.append(x, glm::vec3(0.0f), mass, w.oceanMaterial, rho0, 0.0f);
    return AddStatus::Added;
}

bool World::hasOcean() const { return impl_->zones != nullptr; }

std::optional<OceanDef> World::ocean() const {
    if (!impl_->zones) return std::nullopt;
    return impl_->oceanDef;
}

double World::oceanRamp() const { return impl_->zones ? impl_->zones->ramp(impl_->time) : 1.0; }

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

}  // namespace tide
