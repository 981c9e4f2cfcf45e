#include <tide/fluid.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/validate.hpp"

namespace tide {

namespace {
MaterialDef toMaterialDef(const Material& m, float waterViscosity, std::string name) {
    if (!(m.viscosity >= 0.0f) || !std::isfinite(m.viscosity))
        throw std::invalid_argument("Material.viscosity: must be >= 0 (relative to water), got " + show(m.viscosity));
    MaterialDef def;
    def.name = std::move(name);
    def.restDensity = m.restDensity;
    def.viscosity = m.viscosity * waterViscosity;
    def.color = m.color;
    return def;
}

/// A diverged world may hold NaN or infinities; what the facade hands out to draw never does.
float finite(float v) { return std::isfinite(v) ? v : 0.0f; }
glm::vec3 finite(const glm::vec3& v) { return {finite(v.x), finite(v.y), finite(v.z)}; }

constexpr int kMaxSubsteps = 100;

bool hasVolume(const glm::vec3& min, const glm::vec3& max) {
    return max.x > min.x && max.y > min.y && max.z > min.z;
}
}  // namespace

Fluid::Fluid() = default;
Fluid::~Fluid() = default;

void Fluid::init(std::uint32_t maxPointCounts, const glm::vec3& wallBox_min, const glm::vec3& wallBox_max,
                 const glm::vec3& initFluidBox_min, const glm::vec3& initFluidBox_max, const glm::vec3& gravity,
                 const FluidSettings& settings) {
    requirePositive("FluidSettings.metresPerUnit", settings.metresPerUnit);
    requirePositive("FluidSettings.particleSpacing", settings.particleSpacing);
    if (settings.substeps < 1 || settings.substeps > kMaxSubsteps)
        throw std::invalid_argument("FluidSettings.substeps: must be in [1, " + std::to_string(kMaxSubsteps) + "], got " +
                                    std::to_string(settings.substeps));
    if (!(settings.waterViscosity >= 0.0f) || !std::isfinite(settings.waterViscosity))
        throw std::invalid_argument("FluidSettings.waterViscosity: must be >= 0 Pa·s, got " +
                                    show(settings.waterViscosity));
    WorldDef def;
    def.domainMin = wallBox_min * settings.metresPerUnit;
    def.domainMax = wallBox_max * settings.metresPerUnit;
    def.gravity = gravity;
    def.particleSpacing = settings.particleSpacing * settings.metresPerUnit;
    def.capacity = maxPointCounts;
    def.threads = settings.threads;
    def.solver = settings.solver;
    auto world = std::make_unique<World>(def);  // validates; nothing changes if it throws
    world->addMaterial(toMaterialDef(Material{}, settings.waterViscosity, "water"));

    settings_ = settings;
    world_ = std::move(world);
    tickEmitters_.clear();
    invalidateCaches();
    if (hasVolume(initFluidBox_min, initFluidBox_max)) addPoint(initFluidBox_min, initFluidBox_max, glm::vec3(0.0f));
}

void Fluid::reset() {
    world_.reset();
    tickEmitters_.clear();
    points_.clear();
    points_.shrink_to_fit();
    positions_.clear();
    positions_.shrink_to_fit();
    invalidateCaches();
}

bool Fluid::addPoint(const glm::vec3& min, const glm::vec3& max, const glm::vec3& velocity) {
    return addPoint(min, max, velocity, 0);
}

bool Fluid::addPoint(const glm::vec3& min, const glm::vec3& max, const glm::vec3& velocity, MaterialIndex material) {
    if (!world_) return false;
    BlockDef block{toMetres(min), toMetres(max), velocity, material};
    const bool added = world_->addBlock(block) == AddStatus::Added;
    if (added) {
        world_->prepare();  // at load time: the first frame then costs what the others do
        invalidateCaches();
    }
    return added;
}

bool Fluid::addPointTick(const glm::vec3& min, const glm::vec3& max, const glm::vec3& velocity) {
    return addPointTick(min, max, velocity, 0);
}

bool Fluid::addPointTick(const glm::vec3& min, const glm::vec3& max, const glm::vec3& velocity,
                         MaterialIndex material) {
    if (!world_ || !world_->insideDomain(toMetres(min), toMetres(max))) return false;
    std::uint32_t id = 0;
    bool found = false;
    for (const TickEmitter& e : tickEmitters_) {
        if (e.min == min && e.max == max && e.velocity == velocity && e.material == material) {
            id = e.id;
            found = true;
            break;
        }
    }
    if (!found) {
        EmitterDef def;
        def.min = toMetres(min);
        def.max = toMetres(max);
        def.velocity = velocity;
        def.material = material;
        def.start = world_->time();
        id = world_->addEmitter(def);
        tickEmitters_.push_back({min, max, velocity, material, id});
    }
    world_->setEmitterActive(id, true);
    const auto layer = world_->countBlock({toMetres(min), toMetres(max), velocity, material});
    return world_->particles().size() + layer <= world_->def().capacity;
}

MaterialIndex Fluid::addMaterial(const Material& material) {
    if (!world_) throw std::logic_error("Fluid::addMaterial: call init() first");
    const auto index = world_->materials().size();
    return world_->addMaterial(toMaterialDef(material, settings_.waterViscosity, "material " + std::to_string(index)));
}

void Fluid::step(float frameTime) {
    if (!world_) return;
    if (!(frameTime >= 0.0f) || !std::isfinite(frameTime))
        throw std::invalid_argument("Fluid::step frameTime: must be finite and >= 0, got " + show(frameTime));
    const bool fixedSteps = settings_.solver.method == "pbf";
    const double substep = static_cast<double>(frameTime) / settings_.substeps;
    if (fixedSteps && substep > settings_.solver.maxDt)
        throw std::invalid_argument("Fluid::step frameTime: " + show(frameTime) + " s in " +
                                    std::to_string(settings_.substeps) + " substeps exceeds solver.maxDt (" +
                                    show(settings_.solver.maxDt) + " s) a substep; raise FluidSettings.substeps");
    try {
        // pbf: one step each (its step is the time asked for, up to maxDt), so a frame costs
        // the same however the fluid moves; if the machine is slower than real time, the
        // simulated time slows down instead of the frames piling up.
        if (fixedSteps && frameTime > 0.0f)
            for (int k = 0; k < settings_.substeps; ++k) world_->advance(substep);
        else
            world_->advance(frameTime);
    } catch (const DivergenceError&) {
        // The caches still hold the last frame the caller read, if it read one.
        for (const TickEmitter& e : tickEmitters_) world_->setEmitterActive(e.id, false);
        throw;
    }
    // A tick emitter runs for the frame it was called in; the next call switches it on again.
    for (const TickEmitter& e : tickEmitters_) world_->setEmitterActive(e.id, false);
    invalidateCaches();
}

unsigned Fluid::getPointCounts() const { return world_ ? world_->particles().size() : 0u; }

const Point* Fluid::getPointBuf() const {
    if (!world_) return nullptr;
    if (pointsStale_) {
        const ParticleStore& p = world_->particles();
        const float toUnits = 1.0f / settings_.metresPerUnit;
        points_.resize(p.size());
        for (std::uint32_t i = 0; i < p.size(); ++i)
            points_[i] = Point{finite(p.position[i]) * toUnits, finite(p.velocity[i]), finite(p.density[i]),
                               finite(p.pressure[i]), p.material[i], 0, p.id[i]};
        pointsStale_ = false;
    }
    return points_.data();
}

float* Fluid::getPosData() {
    if (!world_) return nullptr;
    if (positionsStale_) {
        const ParticleStore& p = world_->particles();
        const float toUnits = 1.0f / settings_.metresPerUnit;
        positions_.resize(std::size_t{3} * p.size());
        for (std::uint32_t i = 0; i < p.size(); ++i) {
            const glm::vec3 x = finite(p.position[i]) * toUnits;
            positions_[3 * i + 0] = x.x;
            positions_[3 * i + 1] = x.y;
            positions_[3 * i + 2] = x.z;
        }
        positionsStale_ = false;
    }
    return positions_.data();
}

MaterialIndex Fluid::getMaterialIndex(unsigned i) const {
    if (i >= getPointCounts())
        throw std::out_of_range("Fluid::getMaterialIndex: particle " + std::to_string(i) + " of " +
                                std::to_string(getPointCounts()));
    return world_->particles().material[i];
}

double Fluid::time() const { return world_ ? world_->time() : 0.0; }

const World& Fluid::world() const {
    if (!world_) throw std::logic_error("Fluid::world: call init() first");
    return *world_;
}

World& Fluid::world() {
    if (!world_) throw std::logic_error("Fluid::world: call init() first");
    // The caller may change velocities: the cached point records would go stale.
    invalidateCaches();
    return *world_;
}

void Fluid::invalidateCaches() {
    pointsStale_ = true;
    positionsStale_ = true;
}

}  // namespace tide
