// The control panel, in Dear ImGui.
#include "viewer_panel.hpp"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

namespace tide::view {

namespace {

ImU32 toImColor(const glm::vec3& c) {
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, 1.0f));
}

/// The colour map as a bar with its range, so colours can be read as numbers.
void drawLegend(render::ColorBy by, glm::vec2 range) {
    ImGui::Text("%s", render::colorByName(by));
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x, height = 14.0f;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    constexpr int kSegments = 16;
    for (int s = 0; s < kSegments; ++s) {
        const float t0 = static_cast<float>(s) / kSegments, t1 = static_cast<float>(s + 1) / kSegments;
        const ImU32 left = toImColor(render::colormap(t0)), right = toImColor(render::colormap(t1));
        draw->AddRectFilledMultiColor(ImVec2(origin.x + t0 * width, origin.y), ImVec2(origin.x + t1 * width, origin.y + height),
                                      left, right, right, left);
    }
    ImGui::Dummy(ImVec2(width, height));
    ImGui::Text("%.4g", static_cast<double>(range.x));
    char high[32];
    std::snprintf(high, sizeof high, "%.4g", static_cast<double>(range.y));
    ImGui::SameLine(std::max(0.0f, width - ImGui::CalcTextSize(high).x));
    ImGui::TextUnformatted(high);
}

/// A titled separator (ImGui 1.86 has no SeparatorText).
void section(const char* title) {
    ImGui::Separator();
    ImGui::TextDisabled("%s", title);
}

}  // namespace

void drawPanel(const render::Snapshot& snapshot, const RunnerStatus& status, PanelState& state,
               SimulationRunner& runner) {
    render::RenderSettings& settings = *state.settings;
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(300, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("tide");

    if (ImGui::Button(status.playing ? "Pause" : "Play"))
        runner.send({status.playing ? Command::Kind::Pause : Command::Kind::Play});
    ImGui::SameLine();
    if (ImGui::Button("Step")) runner.send({Command::Kind::Step});
    ImGui::SameLine();
    if (ImGui::Button("Reset")) runner.send({Command::Kind::Reset});
    float speed = static_cast<float>(status.speed);
    if (ImGui::SliderFloat("speed", &speed, 0.05f, 4.0f, "%.2fx", ImGuiSliderFlags_Logarithmic)) {
        Command c{Command::Kind::Speed};
        c.value = speed;
        runner.send(c);
    }
    if (status.hasEmitters) {
        bool emitters = status.emitters;
        if (ImGui::Checkbox("emitters on", &emitters)) {
            Command c{Command::Kind::Emitters};
            c.flag = emitters;
            runner.send(c);
        }
    }
    if (!status.error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "stopped: %s", status.error.c_str());

    section("view");
    int mode = settings.mode == render::RenderMode::Surface ? 1 : 0;
    ImGui::RadioButton("particles", &mode, 0);
    ImGui::SameLine();
    ImGui::RadioButton("water surface", &mode, 1);
    settings.mode = mode == 1 ? render::RenderMode::Surface : render::RenderMode::Particles;
    if (settings.mode == render::RenderMode::Particles) {
        int colorBy = static_cast<int>(settings.colorBy);
        ImGui::Combo("colour by", &colorBy, "material\0speed\0density\0pressure\0");
        settings.colorBy = static_cast<render::ColorBy>(colorBy);
        if (settings.colorBy != render::ColorBy::Material) drawLegend(settings.colorBy, state.range);
    } else {
        ImGui::SliderInt("smoothing", &settings.smoothingIterations, 0, 8);
        ImGui::Checkbox("foam", &settings.foam);
    }
    ImGui::SliderFloat("particle size", &settings.particleScale, 0.3f, 2.5f, "%.2f");
    ImGui::Checkbox("container", &settings.showContainer);

    section("materials");
    for (std::size_t m = 0; m < snapshot.materials.size() && m < render::kMaxRenderMaterials; ++m) {
        ImGui::PushID(static_cast<int>(m));
        bool visible = settings.visible[m];
        if (ImGui::Checkbox("##visible", &visible)) settings.visible[m] = visible;
        ImGui::SameLine();
        glm::vec3 colour = settings.color[m].r >= 0.0f ? settings.color[m] : snapshot.materials[m].color;
        if (ImGui::ColorEdit3(snapshot.materials[m].name.c_str(), &colour.x, ImGuiColorEditFlags_NoInputs))
            settings.color[m] = colour;
        ImGui::PopID();
    }

    section("stats");
    const WorldStats& s = snapshot.stats;
    ImGui::Text("particles      %u", snapshot.size());
    ImGui::Text("fps            %.0f", state.fps);
    ImGui::Text("sim time       %.3f s", snapshot.time);
    ImGui::Text("dt             %.2e s", s.lastDt);
    ImGui::Text("density error  %.3f %%", 100.0 * static_cast<double>(s.meanDensityError));
    ImGui::Text("particle-steps %.2f M/s", status.particleStepsPerSecond / 1e6);
    ImGui::Text("steps          %.0f /s", status.stepsPerSecond);
    ImGui::Text("sim s / wall s %.2f", status.simulatedPerWallSecond);

    section("mouse");
    ImGui::TextWrapped("left drag: orbit   middle or shift+left: pan   wheel: zoom   right drag: push the fluid   "
                       "space: play/pause   S: step   R: reset   Esc: quit");
    ImGui::End();
}

}  // namespace tide::view
