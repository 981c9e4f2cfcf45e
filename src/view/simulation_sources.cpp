// The two SimulationSources: a World from a factory (scenes), and the seed's Fluid facade.
#include <tide/view/viewer.hpp>

namespace tide::view {

namespace {

class WorldSource final : public SimulationSource {
public:
    explicit WorldSource(std::function<World()> make) : make_(std::move(make)) { reset(); }

    void reset() override {
        world_ = std::make_unique<World>(make_());
        setEmittersActive(emittersActive_);
    }
    double advance() override { return world_->step(world_->def().solver.maxDt); }
    [[nodiscard]] const World& world() const override { return *world_; }
    World& world() override { return *world_; }
    void setEmittersActive(bool active) override {
        emittersActive_ = active;
        for (std::uint32_t e = 0; e < world_->emitterCount(); ++e) world_->setEmitterActive(e, active);
    }
    [[nodiscard]] bool hasEmitters() const override { return world_->emitterCount() > 0; }

private:
    std::function<World()> make_;
    std::unique_ptr<World> world_;
    bool emittersActive_ = true;
};

class FluidSource final : public SimulationSource {
public:
    FluidSource(std::function<void(Fluid&)> build, std::function<void(Fluid&)> perFrame, float frameTime)
        : build_(std::move(build)), perFrame_(std::move(perFrame)), frameTime_(frameTime) {
        reset();
    }

    void reset() override {
        fluid_.reset();
        build_(fluid_);
    }
    double advance() override {
        if (emittersActive_ && perFrame_) perFrame_(fluid_);
        fluid_.step(frameTime_);
        return frameTime_;
    }
    [[nodiscard]] const World& world() const override { return fluid_.world(); }
    World& world() override { return fluid_.world(); }
    void setEmittersActive(bool active) override { emittersActive_ = active; }
    [[nodiscard]] bool hasEmitters() const override { return static_cast<bool>(perFrame_); }

private:
    Fluid fluid_;
    std::function<void(Fluid&)> build_;
    std::function<void(Fluid&)> perFrame_;
    float frameTime_;
    bool emittersActive_ = true;
};

}  // namespace

std::unique_ptr<SimulationSource> worldSource(std::function<World()> make) {
    return std::make_unique<WorldSource>(std::move(make));
}

std::unique_ptr<SimulationSource> fluidSource(std::function<void(Fluid&)> build, std::function<void(Fluid&)> perFrame,
                                              float frameTime) {
    return std::make_unique<FluidSource>(std::move(build), std::move(perFrame), frameTime);
}

}  // namespace tide::view
