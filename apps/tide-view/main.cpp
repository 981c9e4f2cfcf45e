// `tide-view SCENE`: watch a scene simulate, in a window.
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>

#include <tide/io/scene.hpp>
#include <tide/view/viewer.hpp>

int main(int argc, char** argv) {
    CLI::App app{"tide-view: watch a scene simulate in real time (OpenGL 3.3 window)", "tide-view"};
    std::string sceneFile;
    tide::view::ViewerOptions options;
    std::string mode = "surface";
    std::string colorBy = "material";
    int threads = 0;
    app.add_option("scene", sceneFile, "Scene file (JSON)")->required();
    app.add_option("--width", options.width, "Window width")->check(CLI::Range(64, 16384));
    app.add_option("--height", options.height, "Window height")->check(CLI::Range(64, 16384));
    app.add_option("--mode", mode, "surface (water surface) or particles")->check(CLI::IsMember({"surface", "particles"}));
    app.add_option("--color-by", colorBy, "Particles mode: material, speed, density or pressure")
        ->check(CLI::IsMember({"material", "speed", "density", "pressure"}));
    app.add_option("--threads", threads, "Simulation worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
    app.add_option("--speed", options.speed, "Simulated seconds per wall second, at most")->check(CLI::Range(0.01, 100.0));
    app.add_flag("--paused", options.paused, "Start paused");
    app.add_option("--exit-after", options.exitAfter, "Close after this many seconds (for scripts)")
        ->check(CLI::NonNegativeNumber);
    app.footer("Left drag orbits, middle (or shift+left) drag pans, the wheel zooms, right drag pushes the fluid;\n"
               "space plays/pauses, S steps, R resets, Esc quits. Exit codes: 0 closed, 1 no window, 2 bad input.");
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return 2;
    }

    tide::io::Scene scene;
    try {
        scene = tide::io::loadScene(sceneFile);
    } catch (const tide::io::SceneError& e) {
        for (const std::string& problem : e.problems)
            std::fprintf(stderr, "%s%s%s\n", problem.rfind(sceneFile, 0) == 0 ? "" : sceneFile.c_str(),
                         problem.rfind(sceneFile, 0) == 0 ? "" : ": ", problem.c_str());
        return 2;
    }
    scene.world.threads = threads;
    options.title = "tide-view: " + (scene.name.empty() ? sceneFile : scene.name);
    options.render.mode = mode == "particles" ? tide::render::RenderMode::Particles : tide::render::RenderMode::Surface;
    // One layer in the plane has no depth for the water surface: a 2D scene shows its particles.
    if (scene.world.dimensions == 2) options.render.mode = tide::render::RenderMode::Particles;
    options.render.colorBy = colorBy == "speed"      ? tide::render::ColorBy::Speed
                             : colorBy == "density"  ? tide::render::ColorBy::Density
                             : colorBy == "pressure" ? tide::render::ColorBy::Pressure
                                                     : tide::render::ColorBy::Material;
    if (scene.camera) options.camera = tide::render::Camera{scene.camera->eye, scene.camera->target, scene.camera->fovDegrees};
    // Emitters run for the scene's whole end_time; the viewer runs on past it.
    try {
        tide::io::buildWorld(scene);  // bad obstacles etc. are reported here, before a window opens
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", sceneFile.c_str(), e.what());
        return 2;
    }
    // The scene's settle.time runs before the window shows the world (and again on a reset).
    return tide::view::runViewer(tide::view::worldSource([scene] {
                                     if (scene.settleTime > 0.0)
                                         std::fprintf(stderr, "tide-view: settling for up to %g s (settle.time) first...\n",
                                                      scene.settleTime);
                                     return tide::io::buildSettledWorld(scene);
                                 }),
                                 options);
}
