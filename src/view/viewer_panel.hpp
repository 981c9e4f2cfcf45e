#pragma once
// The ImGui control panel: play/step/reset/speed, render mode and colours, legend, stats.
#include <tide/render/renderer.hpp>
#include <tide/render/snapshot.hpp>

#include "simulation_runner.hpp"

namespace tide::view {

/// What the panel shows besides the runner's status.
struct PanelState {
    render::RenderSettings* settings = nullptr;
    double fps = 0.0;
    glm::vec2 range{0.0f, 1.0f};  ///< the colour map's range in the last frame
};

/// Draw the panel (inside an ImGui frame); user actions go to `runner` as commands.
void drawPanel(const render::Snapshot& snapshot, const RunnerStatus& status, PanelState& state,
               SimulationRunner& runner);

}  // namespace tide::view
