#pragma once
/// \file
/// tide::view — the real-time viewer (GLFW window, OpenGL 3.3, Dear ImGui panel). The
/// simulation steps on a worker thread while the window draws its latest snapshot, so the
/// interface stays at screen rate however slow the simulation is.
///
/// It shows anything that owns a World, through SimulationSource: a scene's World
/// (worldSource) or the seed's Fluid facade (fluidSource).

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <tide/fluid.hpp>
#include <tide/render/camera.hpp>
#include <tide/render/renderer.hpp>
#include <tide/world.hpp>

namespace tide::view {

/// A simulation the viewer drives. Only the viewer's worker thread calls these.
class SimulationSource {
public:
    virtual ~SimulationSource() = default;
    /// (Re)create the initial state.
    virtual void reset() = 0;
    /// Advance by one step of the source's choosing; returns the simulated seconds advanced.
    virtual double advance() = 0;
    [[nodiscard]] virtual const World& world() const = 0;
    /// Writable between steps, for the mouse push (World::velocities()).
    virtual World& world() = 0;
    /// Switch the source's emitters on or off (they start on).
    virtual void setEmittersActive(bool active) = 0;
    /// Whether the source has emitters worth a switch.
    [[nodiscard]] virtual bool hasEmitters() const = 0;
};

/// A World made by `make` (e.g. io::buildWorld of a scene), stepped one adaptive step at a time.
std::unique_ptr<SimulationSource> worldSource(std::function<World()> make);

/// A Fluid set up by `build` on a fresh Fluid (and again on reset); `perFrame` runs before
/// each frame of `frameTime` seconds (the seed's addPointTick emitters go there).
std::unique_ptr<SimulationSource> fluidSource(std::function<void(Fluid&)> build,
                                              std::function<void(Fluid&)> perFrame = {},
                                              float frameTime = 1.0f / 60.0f);

struct ViewerOptions {
    std::string title = "tide";
    int width = 1280;                          ///< window size, screen pixels
    int height = 720;
    std::optional<render::Camera> camera;      ///< empty: a 3/4 view of the container
    render::RenderSettings render;             ///< initial render settings
    bool paused = false;                       ///< start paused
    double speed = 1.0;                        ///< simulated seconds per wall second, at most
    double exitAfter = 0.0;                    ///< close after this many seconds (0: never), for scripts
};

/// Open the window and run until it is closed, Escape is pressed, or SIGTERM/SIGINT arrives.
/// Returns 0 then; 1 (with a message on stderr) when no window or GL 3.3 context can be made.
int runViewer(std::unique_ptr<SimulationSource> source, const ViewerOptions& options);

}  // namespace tide::view
