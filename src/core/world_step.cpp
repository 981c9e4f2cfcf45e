// Stepping a World: one step of every phase (World::Impl::step), advancing by a duration,
// and the settling pre-roll.
#include "core/world_impl.hpp"

namespace tide {

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
    if (!held) w.absorbWaves();
    w.moveBoundaries(w.time);
    if (held) w.holdBoundaries();
    // Ocean zones hold their buffers over the solver's step from where they stand now.
    if (!w.zones) w.solver->predict(w.particles, w.def.solver, w.def.gravity, maxDt, w.threads);
    w.rebuildNeighbors();
    clock.lap(Phase::NeighborSearch);
    StepContext ctx{w.particles, w.neighbors, w.materials, w.def.solver, w.def.gravity, w.h,
                    w.def.particleSpacing, w.soundSpeed, w.boundary, w.boundaryNeighbors, w.boundaryFluidNeighbors,
                    w.boundaryNearFluid, w.periodic, w.viscosity, w.threads, maxDt};
    ctx.dimensions = w.def.dimensions;
    if (w.distribution) ctx.sharing = stepSharing(w);
    ctx.clock = &clock;
    w.pairTables.build(w.materials.size(), w.pairs);
    ctx.pairs = &w.pairTables;
    const bool loads = w.def.loads || w.bodySystem;  // bodies move by their loads
    const bool recordedWallLoads = loads && w.solver->recordsWallLoads();
    if (recordedWallLoads) {
        w.wallLoads.reset(w.boundaryNeighbors.slotCount());
        ctx.loads = &w.wallLoads;
    }
    if (w.zones) {
        w.zones->holdBegin(w.particles);
        clock.lap(Phase::Coupling);
    }
    const double dt = w.solver->step(ctx);
    // An ocean's buffers move with the far field, whatever the pressure did to them.
    if (w.zones) {
        clock.lap(Phase::Integration);
        w.zones->holdEnd(w.particles, w.time, dt, held, w.threads);
        clock.lap(Phase::Coupling);
    }
    if (loads) w.sumLoads(dt, recordedWallLoads);
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
    if (loads)
        w.contacts.begin(w.particles, w.solidReferences(w.time), w.periodic, w.distribution ? ghostFlags(w) : nullptr);
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
    if (loads && w.distribution) reduceContactImpulses(w);
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

}  // namespace tide
