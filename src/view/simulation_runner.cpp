// The worker thread: commands, pacing, snapshots.
#include "simulation_runner.hpp"

#include <algorithm>
#include <chrono>
#include <exception>

#include <glm/geometric.hpp>

namespace tide::view {

namespace {
using Clock = std::chrono::steady_clock;
double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
}  // namespace

SimulationRunner::SimulationRunner(std::unique_ptr<SimulationSource> source, bool playing, double speed)
    : source_(std::move(source)), playing_(playing), speed_(speed) {
    workerStatus_.hasEmitters = source_->hasEmitters();
    publish();  // the window has a first frame before the worker runs
    thread_ = std::thread([this] { work(); });
}

SimulationRunner::~SimulationRunner() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void SimulationRunner::send(const Command& command) {
    {
        std::lock_guard lock(mutex_);
        commands_.push_back(command);
    }
    wake_.notify_all();
}

bool SimulationRunner::fetch(render::Snapshot& snapshot, RunnerStatus& status) {
    std::lock_guard lock(mutex_);
    status = status_;
    if (!fresh_) return false;
    std::swap(snapshot, middle_);
    fresh_ = false;
    return true;
}

void SimulationRunner::publish() {
    // A diverged world holds non-finite values: keep showing the last good state, with the error.
    const bool diverged = source_->world().divergence().has_value();
    if (!diverged) render::takeSnapshot(source_->world(), back_);
    workerStatus_.playing = playing_;
    workerStatus_.speed = speed_;
    workerStatus_.emitters = emitters_;
    std::lock_guard lock(mutex_);
    status_ = workerStatus_;
    if (diverged) return;
    // The three buffers rotate, so their own counters do not order them: number them here,
    // so the renderer uploads each new state once.
    back_.version = ++published_;
    std::swap(back_, middle_);
    fresh_ = true;
}

void SimulationRunner::apply(const Command& c) {
    switch (c.kind) {
        case Command::Kind::Play: playing_ = true; break;
        case Command::Kind::Pause: playing_ = false; break;
        case Command::Kind::Step: ++pendingSteps_; playing_ = false; break;
        case Command::Kind::Reset:
            source_->reset();
            workerStatus_.error.clear();
            break;
        case Command::Kind::Speed: speed_ = std::clamp(c.value, 0.01, 100.0); break;
        case Command::Kind::Emitters:
            emitters_ = c.flag;
            source_->setEmittersActive(c.flag);
            break;
        case Command::Kind::Push: {
            // Every particle near the cursor's ray gets the drag's velocity, fading with its
            // distance from the ray.
            World& world = source_->world();
            const auto& position = world.particles().position;
            const auto velocity = world.velocities();
            glm::vec3 deltaV = c.deltaV;
            if (world.def().dimensions == 2) deltaV.z = 0.0f;  // a 2D world's particles stay in the plane
            for (std::size_t i = 0; i < position.size(); ++i) {
                const glm::vec3 r = position[i] - c.origin;
                const float along = glm::dot(r, c.direction);
                if (along <= 0.0f) continue;
                const float distance = glm::length(r - along * c.direction);
                if (distance < c.radius) velocity[i] += deltaV * (1.0f - distance / c.radius);
            }
            break;
        }
    }
}

void SimulationRunner::work() {
    // Simulated seconds the worker may still take; grows with wall time × speed while playing
    // and is capped, so a simulation slower than real time never builds up a debt to repay.
    double budget = 0.0;
    auto last = Clock::now();
    auto lastPublish = last;
    auto rateStart = last;
    std::uint64_t particleSteps = 0, steps = 0;
    double simulated = 0.0;  // simulated seconds since rateStart
    for (;;) {
        std::vector<Command> commands;
        {
            std::unique_lock lock(mutex_);
            if (!playing_ && pendingSteps_ == 0 && commands_.empty() && !quit_)
                wake_.wait_for(lock, std::chrono::milliseconds(100));
            if (quit_) return;
            commands.swap(commands_);
        }
        bool changed = !commands.empty();
        try {
            for (const Command& c : commands) apply(c);
            const auto now = Clock::now();
            budget = playing_ ? std::min(budget + speed_ * seconds(now - last), 0.05 * std::max(speed_, 1.0)) : 0.0;
            last = now;
            if (pendingSteps_ > 0 || (playing_ && budget > 0.0)) {
                // One advance may be many solver steps (a Fluid frame): count the World's.
                const std::uint64_t before = source_->world().stats().steps;
                const double advanced = source_->advance();
                budget -= advanced;
                simulated += advanced;
                const std::uint64_t taken = source_->world().stats().steps - before;
                particleSteps += taken * source_->world().particles().size();
                steps += taken;
                pendingSteps_ = std::max(pendingSteps_ - 1, 0);
                changed = true;
            } else if (playing_) {
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            }
        } catch (const std::exception& e) {
            workerStatus_.error = e.what();
            playing_ = false;
            changed = true;
        }
        const auto now = Clock::now();
        if (seconds(now - rateStart) >= 1.0) {
            workerStatus_.particleStepsPerSecond = static_cast<double>(particleSteps) / seconds(now - rateStart);
            workerStatus_.stepsPerSecond = static_cast<double>(steps) / seconds(now - rateStart);
            workerStatus_.simulatedPerWallSecond = simulated / seconds(now - rateStart);
            particleSteps = steps = 0;
            simulated = 0.0;
            rateStart = now;
        }
        // Publish at most at screen rate, and at once after a command, so that a click shows.
        if (changed && (!commands.empty() || !playing_ || seconds(now - lastPublish) >= 1.0 / 60.0)) {
            publish();
            lastPublish = now;
        }
    }
}

}  // namespace tide::view
