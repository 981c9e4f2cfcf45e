// A World's accessors, clearing it, and the state a checkpoint saves and restores.
#include "core/world_impl.hpp"

namespace tide {

double World::time() const { return impl_->time; }
const ParticleStore& World::particles() const { return impl_->particles; }
std::span<glm::vec3> World::velocities() { return impl_->particles.velocity; }
void World::reserve(std::uint32_t particles) {
    impl_->particles.reserve(std::min(particles, impl_->def.capacity));
}
void World::prepare() {
    Impl& w = *impl_;
    if (w.distribution) return;
    // The step's own search, without its reordering (which would change when particles move in memory).
    w.grid.build(w.particles.position, w.h, w.threads, w.periodic);
    w.neighbors.build(w.grid, w.particles.position, w.h, w.threads);
    w.boundaryNeighbors.build(w.boundary.grid, w.boundary.position, w.particles.position, w.h, w.threads);
    w.solver->reserve(w.particles.size(), w.neighbors.slotCount());
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
    for (Impl::Paddle& paddle : w.paddles)
        if (paddle.absorber) {
            paddle.maker.setCorrection({});
            paddle.absorber->setState({});
        }
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
    if (w.distribution) {
        // A split World's piece of the state: the particles this rank owns, not the copies
        // of its neighbours' (issue 47: each rank writes its own, any number of ranks reads
        // them all back; core/world_distributed.hpp).
        std::vector<std::uint8_t> owned(s.particles.size());
        const std::vector<std::uint8_t>& ghost = *ghostFlags(w);
        for (std::size_t i = 0; i < owned.size(); ++i) owned[i] = ghost[i] ? 0 : 1;
        s.particles.retain(owned);
    }
    for (const EmitterState& e : w.emitters) s.emitters.push_back({e.active, e.travelled});
    s.solverState = w.solver->carriedState();
    if (w.bodySystem) s.bodyState = w.bodySystem->saveState();
    for (const Impl::Paddle& paddle : w.paddles) {
        if (!paddle.absorber) continue;
        const WaveMaker::Correction& c = paddle.maker.correction();
        const ActiveAbsorption::State& a = paddle.absorber->state();
        s.paddleState.insert(s.paddleState.end(), {c.offset, c.velocity, c.since, a.mean, a.lastTime, a.started ? 1.0 : 0.0});
    }
    return s;
}

namespace {
constexpr std::size_t kPaddleScalars = 6;  ///< per absorbing paddle, in saveState's order

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
    if (w.distribution)
        throw std::logic_error("restoreState: restore the whole state before distributeWorld splits the World");
    checkFits(state, w.materials.size(), w.emitters.size(), w.def.capacity);
    std::size_t absorbers = 0;
    for (const Impl::Paddle& paddle : w.paddles) absorbers += paddle.absorber ? 1 : 0;
    // Empty: a checkpoint from before active absorption; its paddles resume uncorrected.
    if (!state.paddleState.empty() && state.paddleState.size() != kPaddleScalars * absorbers)
        misfit(std::to_string(state.paddleState.size()) + " wave maker scalars saved, this world's absorbing paddles carry " +
               std::to_string(kPaddleScalars * absorbers));
    for (const double x : state.paddleState)
        if (!std::isfinite(x)) misfit("a wave maker scalar is not finite");
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
    std::size_t k = 0;
    for (Impl::Paddle& paddle : w.paddles) {
        if (!paddle.absorber) continue;
        if (state.paddleState.empty()) {
            paddle.maker.setCorrection({});
            paddle.absorber->setState({});
            continue;
        }
        const double* v = state.paddleState.data() + kPaddleScalars * k++;
        paddle.maker.setCorrection({v[0], v[1], v[2]});
        paddle.absorber->setState({v[3], v[4], v[5] != 0.0});
    }
    w.divergence.reset();
    w.resetLoads();  // a checkpoint is taken where the run starts a new average
    w.moveBoundaries(w.time);
}

}  // namespace tide
