// `tide render`: simulate a scene and draw frame k (time k/fps) offscreen into
// OUT/frame_NNNNN.png with the viewer's renderer; optionally encode them as MP4 with ffmpeg.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <tide/io/scene.hpp>
#include <tide/render/camera.hpp>
#include <tide/render/headless.hpp>
#include <tide/render/renderer.hpp>
#include <tide/render/snapshot.hpp>

#include "commands.hpp"
#include "output_folder.hpp"
#include "png_file.hpp"
#include "progress.hpp"

extern char** environ;

namespace tide::cli {

namespace fs = std::filesystem;

namespace {

/// The first executable called `name` on PATH; empty when there is none.
fs::path findOnPath(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::string list = path ? path : "/usr/bin:/bin";
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t end = std::min(list.find(':', start), list.size());
        const fs::path candidate = fs::path(list.substr(start, end - start)) / name;
        if (end > start && ::access(candidate.c_str(), X_OK) == 0) return candidate;
        start = end + 1;
    }
    return {};
}

/// Run a program (no shell, so no quoting trouble) and return its exit status, -1 if it
/// could not start or was killed.
int runProgram(const fs::path& program, const std::vector<std::string>& arguments) {
    std::vector<char*> argv;
    std::vector<std::string> storage{program.string()};
    storage.insert(storage.end(), arguments.begin(), arguments.end());
    for (std::string& a : storage) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (posix_spawn(&pid, program.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return -1;
    int status = 0;
    if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status)) return -1;
    return WEXITSTATUS(status);
}

std::string frameName(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", frame);
    return name;
}

}  // namespace

int renderCommand(const RenderOptions& o) {
    io::Scene scene;
    try {
        scene = io::loadScene(o.scene);
    } catch (const io::SceneError& e) {
        reportSceneProblems(o.scene, e.problems);
        return kExitBadInput;
    }
    if (o.endTime) scene.endTime = *o.endTime;
    if (!checkEndTime(scene, o.endTime.has_value(), o.scene)) return kExitBadInput;
    scene.world.threads = o.threads;
    fs::path ffmpeg;
    if (!o.video.empty()) {
        ffmpeg = findOnPath("ffmpeg");
        if (ffmpeg.empty()) {
            std::fprintf(stderr, "--video %s: ffmpeg was not found on PATH (install Debian's ffmpeg)\n", o.video.c_str());
            return kExitBadInput;
        }
    }
    const fs::path dir = o.out.empty() ? fs::path("out") / (fs::path(o.scene).stem().string() + "_render") : fs::path(o.out);
    scene.world.capacity = static_cast<std::uint32_t>(
        std::min<std::uint64_t>(io::estimate(scene).totalParticles + 1, 0xfffffff0ull));

    std::optional<World> world;
    try {
        world.emplace(io::buildWorld(scene));
        prepareOutputFolder(dir, o.force);
    } catch (const io::SceneError& e) {
        reportSceneProblems(o.scene, e.problems);
        return kExitBadInput;
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "%s: %s\n", o.scene.c_str(), e.what());
        return kExitBadInput;
    } catch (const OutputFolderError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return kExitBadInput;
    }

    render::RenderSettings settings;
    settings.mode = o.mode == "particles" ? render::RenderMode::Particles : render::RenderMode::Surface;
    // The water surface is built from the particles' depth and thickness, which one layer in
    // the plane does not have (it drew nothing): a 2D scene is drawn as particles.
    if (scene.world.dimensions == 2 && settings.mode == render::RenderMode::Surface) {
        std::printf("2D scene: drawn as particles (the surface mode needs a fluid's depth)\n");
        settings.mode = render::RenderMode::Particles;
    }
    // An ocean's near field is a window onto the sea, not a container: no box around it.
    if (scene.ocean) settings.showContainer = false;
    settings.colorBy = o.colorBy == "speed"      ? render::ColorBy::Speed
                       : o.colorBy == "density"  ? render::ColorBy::Density
                       : o.colorBy == "pressure" ? render::ColorBy::Pressure
                                                 : render::ColorBy::Material;
    const glm::vec3 lo = scene.world.domainMin, hi = scene.world.domainMax;
    const render::Camera camera =
        scene.camera ? render::fitClipPlanes({scene.camera->eye, scene.camera->target, scene.camera->fovDegrees}, lo, hi)
                     : render::defaultCamera(lo, hi);

    const int frames = io::framesAfterTheFirst(scene);
    const auto start = std::chrono::steady_clock::now();
    std::uint64_t particleSteps = 0;
    try {
        render::HeadlessContext context;
        render::Renderer renderer;
        render::OffscreenImage image(o.width, o.height);
        render::Snapshot snapshot;
        if (scene.settleTime > 0.0) settleAndReport(*world, scene.settleTime, scene.settleSpeed, o.quiet);
        Progress progress(scene.endTime, frames, o.quiet);
        for (int frame = 0; frame <= frames; ++frame) {
            if (frame > 0)
                world->advance(frame / scene.output.fps - world->time(), [&] {
                    particleSteps += world->particles().size();
                    progress.step(world->time(), frame, world->particles().size(), particleSteps);
                });
            render::takeSnapshot(*world, snapshot);
            renderer.draw(snapshot, camera, settings, o.width, o.height, image.framebuffer());
            writePng(dir / frameName(frame), o.width, o.height, image.readRgba());
            progress.frame(world->time(), frame, world->particles().size(), particleSteps);
        }
        progress.finish();
        if (!o.quiet)
            std::printf("%d frames of %dx%d in %s (%.1f s wall; %s)\n", frames + 1, o.width, o.height,
                        dir.string().c_str(),
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                        context.description().c_str());
    } catch (const std::runtime_error& e) {
        std::fprintf(stderr, "tide render: %s\n", e.what());
        return kExitRunFailed;
    }

    if (!ffmpeg.empty()) {
        // Even sizes for yuv420p, which every player reads.
        const int status = runProgram(ffmpeg, {"-y", "-loglevel", "error", "-framerate", std::to_string(scene.output.fps),
                                               "-i", (dir / "frame_%05d.png").string(), "-vf",
                                               "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", o.video});
        if (status != 0) {
            std::fprintf(stderr, "tide render: ffmpeg failed (exit %d) writing %s\n", status, o.video.c_str());
            return kExitRunFailed;
        }
        if (!o.quiet) std::printf("video %s\n", o.video.c_str());
    }
    return kExitOk;
}

}  // namespace tide::cli
