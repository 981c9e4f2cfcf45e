#pragma once
// The viewer's worker thread. The World is not thread-safe, so only this thread touches it:
// it applies the window's commands between steps, steps at the requested speed, and
// publishes snapshots through a triple buffer (the worker fills one, one waits, the window
// reads one), so neither side ever waits for the other's copying.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include <glm/vec3.hpp>

#include <tide/render/snapshot.hpp>
#include <tide/view/viewer.hpp>

namespace tide::view {

/// One request from the window, applied by the worker between two steps.
struct Command {
    enum class Kind { Play, Pause, Step, Reset, Speed, Emitters, Push };
    Kind kind = Kind::Play;
    double value = 0.0;      ///< Speed: simulated seconds per wall second
    bool flag = false;       ///< Emitters: on
    glm::vec3 origin{0.0f};  ///< Push: the cursor's ray, from the eye
    glm::vec3 direction{0.0f};
    float radius = 0.0f;     ///< Push: particles this close to the ray are pushed, m
    glm::vec3 deltaV{0.0f};  ///< Push: velocity added at the ray, fading to 0 at radius, m/s
};

/// How the worker is doing, published with each snapshot.
struct RunnerStatus {
    bool playing = false;
    bool emitters = true;
    bool hasEmitters = false;
    double speed = 1.0;
    double particleStepsPerSecond = 0.0;
    double stepsPerSecond = 0.0;
    double simulatedPerWallSecond = 0.0;  ///< simulated seconds per wall second (1 = real time)
    std::string error;       ///< the step that threw, if one did (the worker then pauses)
};

class SimulationRunner {
public:
    SimulationRunner(std::unique_ptr<SimulationSource> source, bool playing, double speed);
    /// Stops and joins the worker.
    ~SimulationRunner();
    SimulationRunner(const SimulationRunner&) = delete;
    SimulationRunner& operator=(const SimulationRunner&) = delete;

    void send(const Command& command);
    /// Replace `snapshot` with the newest published one, if there is a newer one; returns
    /// whether it did. `status` is always refreshed.
    bool fetch(render::Snapshot& snapshot, RunnerStatus& status);

private:
    void work();
    void apply(const Command& command);
    void publish();

    std::unique_ptr<SimulationSource> source_;
    // Worker-only state.
    bool playing_;
    int pendingSteps_ = 0;  // Step commands not yet taken: each click is one step
    double speed_;
    bool emitters_ = true;
    render::Snapshot back_;
    std::uint64_t published_ = 0;
    RunnerStatus workerStatus_;
    // Shared, under mutex_.
    std::mutex mutex_;
    std::condition_variable wake_;
    std::vector<Command> commands_;
    render::Snapshot middle_;
    RunnerStatus status_;
    bool fresh_ = false;
    bool quit_ = false;
    std::thread thread_;
};

}  // namespace tide::view
