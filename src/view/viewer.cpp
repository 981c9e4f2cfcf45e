// The viewer's window: GLFW, the render loop at screen rate, mouse and keys, clean exit on
// window close, Escape, SIGTERM or SIGINT.
#include <GL/glew.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <thread>

#include <glm/geometric.hpp>

#include <tide/render/camera.hpp>
#include <tide/render/renderer.hpp>
#include <tide/view/viewer.hpp>

#include "orbit_camera.hpp"
#include "simulation_runner.hpp"
#include "viewer_panel.hpp"

namespace tide::view {

namespace {

using Clock = std::chrono::steady_clock;

// Set by the signal handler, read by the loop: the only state a handler may touch.
volatile std::sig_atomic_t gStopRequested = 0;
extern "C" void requestStop(int) { gStopRequested = 1; }

/// Restores the previous SIGTERM/SIGINT handlers when the viewer returns.
struct SignalGuard {
    using Handler = void (*)(int);
    Handler term, interrupt;
    SignalGuard() : term(std::signal(SIGTERM, requestStop)), interrupt(std::signal(SIGINT, requestStop)) {
        gStopRequested = 0;
    }
    ~SignalGuard() {
        std::signal(SIGTERM, term);
        std::signal(SIGINT, interrupt);
    }
};

struct GlfwSession {
    bool ok = glfwInit() == GLFW_TRUE;
    ~GlfwSession() {
        if (ok) glfwTerminate();
    }
};

/// Mouse dragging state between frames.
struct Drag {
    bool active = false;
    int button = 0;
    double x = 0.0, y = 0.0;
};

}  // namespace

int runViewer(std::unique_ptr<SimulationSource> source, const ViewerOptions& options) {
    SignalGuard signals;
    glfwSetErrorCallback([](int code, const char* text) { std::fprintf(stderr, "tide-view: GLFW error %d: %s\n", code, text); });
    GlfwSession glfw;
    if (!glfw.ok) {
        std::fprintf(stderr, "tide-view: cannot start GLFW (is there a display? set DISPLAY or run under xvfb-run)\n");
        return 1;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
    if (!window) {
        std::fprintf(stderr, "tide-view: cannot open a window with OpenGL 3.3 core\n");
        return 1;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);

    int exitCode = 0;
    try {
        render::loadGlFunctions();
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working folder
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        ImGui_ImplOpenGL3_Init("#version 330 core");
        {
            render::Renderer renderer;
            render::RenderSettings settings = options.render;
            SimulationRunner runner(std::move(source), !options.paused, options.speed);
            render::Snapshot snapshot;
            RunnerStatus status;
            runner.fetch(snapshot, status);
            OrbitCamera orbit(options.camera ? render::fitClipPlanes(*options.camera, snapshot.domainMin, snapshot.domainMax)
                                             : render::defaultCamera(snapshot.domainMin, snapshot.domainMax));
            PanelState panel{&settings};
            Drag drag;
            const auto start = Clock::now();
            auto lastFrame = start;
            double fps = 0.0;

            while (!glfwWindowShouldClose(window) && !gStopRequested) {
                const auto frameStart = Clock::now();
                if (options.exitAfter > 0.0 && std::chrono::duration<double>(frameStart - start).count() > options.exitAfter)
                    break;
                glfwPollEvents();
                runner.fetch(snapshot, status);

                ImGui_ImplOpenGL3_NewFrame();
                ImGui_ImplGlfw_NewFrame();
                ImGui::NewFrame();
                const ImGuiIO& io = ImGui::GetIO();
                int windowWidth = 0, windowHeight = 0;
                glfwGetWindowSize(window, &windowWidth, &windowHeight);

                // Keys (when the panel is not typing); ImGui 1.86 indexes keys by GLFW key code.
                if (!io.WantCaptureKeyboard) {
                    if (ImGui::IsKeyPressed(GLFW_KEY_SPACE))
                        runner.send({status.playing ? Command::Kind::Pause : Command::Kind::Play});
                    if (ImGui::IsKeyPressed(GLFW_KEY_S)) runner.send({Command::Kind::Step});
                    if (ImGui::IsKeyPressed(GLFW_KEY_R)) runner.send({Command::Kind::Reset});
                    if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE)) glfwSetWindowShouldClose(window, GLFW_TRUE);
                }
                // Mouse (when not over the panel).
                double mx = 0.0, my = 0.0;
                glfwGetCursorPos(window, &mx, &my);
                if (!drag.active && !io.WantCaptureMouse) {
                    for (int b : {GLFW_MOUSE_BUTTON_LEFT, GLFW_MOUSE_BUTTON_RIGHT, GLFW_MOUSE_BUTTON_MIDDLE})
                        if (glfwGetMouseButton(window, b) == GLFW_PRESS) drag = {true, b, mx, my};
                    if (io.MouseWheel != 0.0f) orbit.zoom(io.MouseWheel);
                }
                if (drag.active) {
                    if (glfwGetMouseButton(window, drag.button) != GLFW_PRESS) {
                        drag.active = false;
                    } else {
                        const auto dx = static_cast<float>(mx - drag.x), dy = static_cast<float>(my - drag.y);
                        const bool shift = glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS;
                        if (drag.button == GLFW_MOUSE_BUTTON_MIDDLE || (drag.button == GLFW_MOUSE_BUTTON_LEFT && shift))
                            orbit.pan(dx, dy, windowHeight);
                        else if (drag.button == GLFW_MOUSE_BUTTON_LEFT)
                            orbit.orbit(dx, dy);
                        else if (dx != 0.0f || dy != 0.0f) {
                            // Push: the drag, as a velocity, given to the fluid around the cursor's ray.
                            const render::Camera c = orbit.camera();
                            const glm::vec3 forward = glm::normalize(c.target - c.eye);
                            const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
                            const glm::vec3 up = glm::cross(right, forward);
                            const glm::vec3 moved = (dx * right - dy * up) * orbit.pixelSize(windowHeight);
                            const float extent = glm::length(snapshot.domainMax - snapshot.domainMin);
                            const float frameTime = std::max(1.0f / 60.0f, static_cast<float>(io.DeltaTime));
                            glm::vec3 deltaV = moved / frameTime * 0.5f;
                            const float maxSpeed = 2.0f * std::sqrt(9.81f * std::max(extent, 0.01f));
                            if (glm::length(deltaV) > maxSpeed) deltaV *= maxSpeed / glm::length(deltaV);
                            Command push{Command::Kind::Push};
                            push.origin = c.eye;
                            push.direction = render::pixelRay(c, windowWidth, windowHeight,
                                                              {static_cast<float>(mx), static_cast<float>(my)});
                            push.radius = 0.08f * extent;
                            push.deltaV = deltaV;
                            runner.send(push);
                        }
                        drag.x = mx;
                        drag.y = my;
                    }
                }

                panel.fps = fps;
                drawPanel(snapshot, status, panel, runner);
                ImGui::Render();

                int width = 0, height = 0;
                glfwGetFramebufferSize(window, &width, &height);
                if (width > 0 && height > 0) {
                    renderer.draw(snapshot, orbit.camera(), settings, width, height, 0);
                    panel.range = renderer.lastRange();
                }
                ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
                glfwSwapBuffers(window);

                // Without vsync (e.g. under Xvfb) hold the loop near 60 Hz instead of spinning.
                const auto done = Clock::now();
                const auto minimum = std::chrono::microseconds(16000);
                if (done - frameStart < minimum) std::this_thread::sleep_for(minimum - (done - frameStart));
                const double frameSeconds = std::chrono::duration<double>(Clock::now() - lastFrame).count();
                lastFrame = Clock::now();
                fps = fps == 0.0 ? 1.0 / frameSeconds : 0.9 * fps + 0.1 / frameSeconds;
            }
        }  // the runner joins its worker, the renderer frees its GL objects, with the context current
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tide-view: %s\n", e.what());
        exitCode = 1;
    }
    glfwDestroyWindow(window);
    return exitCode;
}

}  // namespace tide::view
