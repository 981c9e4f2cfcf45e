// `tide render` as a user runs it, judged by pixel statistics against rules (never against a
// stored image): frames of the asked size, water where the fluid is and sky elsewhere, each
// material's colour in particle mode; bad flags refused; the scene's camera key checked.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <stb/stb_image.h>  // implemented by Debian's libstb

#include <tide/render/camera.hpp>

#include "cli_support.hpp"

namespace {

namespace fs = std::filesystem;

using tide::testing::Result;
using tide::testing::run;

fs::path scratchRoot() { return fs::temp_directory_path() / ("tide_render_test_" + std::to_string(::getpid())); }

/// Removes this process's scratch folder after the tests.
struct ScratchCleanup : ::testing::Environment {
    void TearDown() override { fs::remove_all(scratchRoot()); }
};
[[maybe_unused]] auto* const kCleanup = ::testing::AddGlobalTestEnvironment(new ScratchCleanup);

fs::path scratch(const std::string& name) {
    const fs::path dir = scratchRoot() / name;
    fs::remove_all(dir);
    fs::create_directories(dir.parent_path());
    return dir;
}

fs::path writeScene(const std::string& name, const std::string& text) {
    const fs::path file = scratch(name + ".json");
    std::ofstream(file) << text;
    return file;
}

const std::string kTide = TIDE_BIN;

// A tank 0.4 × 0.3 × 0.3 m, seen from the front and above by the scene's camera.
const glm::vec3 kTankMax{0.4f, 0.3f, 0.3f};
const tide::render::Camera kCamera{{0.2f, 0.3f, 0.75f}, {0.2f, 0.1f, 0.15f}, 50.0f};
constexpr float kSpacing = 0.02f;

std::string tankScene(const std::string& materials, const std::string& blocks, const std::string& end = "0.05") {
    return R"({"name": "render test", "domain": {"min": [0, 0, 0], "max": [0.4, 0.3, 0.3]},
  "particle_spacing": 0.02, "end_time": )" + end + R"(, "materials": )" + materials + R"(, "blocks": )" + blocks + R"(,
  "output": {"fps": 20},
  "camera": {"eye": [0.2, 0.3, 0.75], "target": [0.2, 0.1, 0.15], "fov": 50}})";
}

struct Image {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
    [[nodiscard]] glm::vec3 at(int x, int y) const {
        const auto i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x));
        return glm::vec3(rgb[i], rgb[i + 1], rgb[i + 2]);
    }
};

Image readPng(const fs::path& file) {
    Image image;
    int channels = 0;
    unsigned char* data = stbi_load(file.c_str(), &image.width, &image.height, &channels, 3);
    if (!data) return image;
    image.rgb.assign(data, data + 3 * image.width * image.height);
    stbi_image_free(data);
    return image;
}

/// Where the ray through a pixel first enters the box lo..hi (slab test); negative: it misses.
float rayHitsBox(const glm::vec3& origin, const glm::vec3& dir, const glm::vec3& lo, const glm::vec3& hi) {
    const glm::vec3 inv = 1.0f / dir;
    const glm::vec3 t0 = (lo - origin) * inv, t1 = (hi - origin) * inv;
    const glm::vec3 near = glm::min(t0, t1), far = glm::max(t0, t1);
    const float enter = std::max({near.x, near.y, near.z}), leave = std::min({far.x, far.y, far.z});
    return enter <= leave && leave > 0.0f ? enter : -1.0f;
}

/// Share of the pixels whose ray satisfies `select` that satisfy `colour`; counts them in `n`.
double share(const Image& image, const std::function<bool(const glm::vec3& dir)>& select,
             const std::function<bool(const glm::vec3& rgb)>& colour, int& n,
             const tide::render::Camera& camera = kCamera) {
    n = 0;
    int good = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3 dir = tide::render::pixelRay(camera, image.width, image.height,
                                                         {static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f});
            if (!select(dir)) continue;
            ++n;
            if (colour(image.at(x, y))) ++good;
        }
    return n ? static_cast<double>(good) / n : 0.0;
}

// The renderer's sky runs from a pale horizon to a blue zenith: bright, blue the strongest.
bool skyLike(const glm::vec3& c) { return c.b >= 170.0f && c.b >= c.g && c.g >= c.r && c.r >= 40.0f; }
// Water over sand: dark blue-green, its red well below both green and blue, far from the sky.
bool waterLike(const glm::vec3& c) {
    return c.r < 110.0f && c.g > c.r + 30.0f && c.b > c.r + 30.0f && c.b < 200.0f;
}

TEST(RenderCli, WritesPngFramesOfTheAskedSizeAndNothingElse) {
    const fs::path scene = writeScene("size", tankScene(R"([{"name": "water", "density": 1000}])",
                                                        R"([{"min": [0, 0, 0], "max": [0.4, 0.1, 0.3]}])", "0.1"));
    const fs::path out = scratch("size_out");
    const Result r = run(kTide + " render " + scene.string() + " --out " + out.string() +
                         " --width 256 --height 192 --threads 1 --quiet");
    ASSERT_EQ(r.exit, 0) << r.output;
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(out)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"frame_00000.png", "frame_00001.png", "frame_00002.png"}));
    for (const std::string& name : names) {
        int w = 0, h = 0, channels = 0;
        ASSERT_TRUE(stbi_info((out / name).c_str(), &w, &h, &channels)) << name;
        EXPECT_EQ(w, 256) << name;
        EXPECT_EQ(h, 192) << name;
    }
}

TEST(RenderCli, WaterSurfaceShowsWaterWhereTheFluidIsAndSkyElsewhere) {
    const glm::vec3 waterMax{0.4f, 0.12f, 0.3f};
    const fs::path scene = writeScene("surface", tankScene(R"([{"name": "water", "density": 1000}])",
                                                           R"([{"min": [0, 0, 0], "max": [0.4, 0.12, 0.3]}])"));
    const fs::path out = scratch("surface_out");
    const Result r = run(kTide + " render " + scene.string() + " --out " + out.string() +
                         " --width 256 --height 192 --threads 1 --quiet --mode surface");
    ASSERT_EQ(r.exit, 0) << r.output;
    const Image image = readPng(out / "frame_00000.png");  // the block as built, not yet moved
    ASSERT_EQ(image.width, 256);

    // Fluid: rays that enter the water block (shrunk by a spacing, away from its fuzzy edges).
    const glm::vec3 inset(kSpacing);
    int fluidPixels = 0, skyPixels = 0;
    const double water = share(image, [&](const glm::vec3& d) { return rayHitsBox(kCamera.eye, d, inset, waterMax - inset) > 0.0f; },
                               waterLike, fluidPixels);
    // Sky: rays above the horizon that miss the whole tank (grown a little for its edges).
    const double sky = share(image, [&](const glm::vec3& d) {
        return d.y > 0.02f && rayHitsBox(kCamera.eye, d, -inset, kTankMax + inset) < 0.0f;
    }, skyLike, skyPixels);
    const int total = image.width * image.height;
    std::printf("water-coloured: %.3f of %d fluid pixels; sky-coloured: %.3f of %d sky pixels\n", water, fluidPixels,
                sky, skyPixels);
    ASSERT_GT(fluidPixels, total / 20) << "the test's camera should see the water";
    ASSERT_GT(skyPixels, total / 20) << "the test's camera should see the sky";
    EXPECT_GT(water, 0.9) << "of " << fluidPixels << " pixels looking at the water";
    EXPECT_GT(sky, 0.97) << "of " << skyPixels << " pixels looking at the sky";
    // And the water is not the sky's colour anywhere it is seen.
    int n = 0;
    EXPECT_LT(share(image, [&](const glm::vec3& d) { return rayHitsBox(kCamera.eye, d, inset, waterMax - inset) > 0.0f; },
                    skyLike, n), 0.01);
}

// An ocean scene (issue 43): the far field's sea around the near field to the horizon, where
// a tank scene shows the sand-coloured ground; the sky stays above the horizon.
TEST(RenderCli, OceanShowsTheSeaToTheHorizonAroundTheNearField) {
    const fs::path scene = writeScene("ocean", R"({"name": "ocean render test",
  "domain": {"min": [0, 0, 0], "max": [0.6, 0.3, 0.6]}, "particle_spacing": 0.03, "end_time": 1.1,
  "solver": {"method": "dfsph", "max_dt": 0.005},
  "materials": [{"name": "water", "density": 1000, "color": [0.1, 0.35, 0.75]}],
  "ocean": {"depth": 0.15, "waves": {"type": "regular", "height": 0.02, "period": 1.0},
            "zone_width": 0.2, "open_sides": ["-x", "+x", "-z", "+z"]},
  "output": {"fps": 10},
  "camera": {"eye": [0.3, 0.6, 1.8], "target": [0.3, 0.15, 0.3], "fov": 50}})");
    const fs::path out = scratch("ocean_out");
    const Result r = run(kTide + " render " + scene.string() + " --out " + out.string() +
                         " --width 256 --height 192 --threads 1 --quiet");
    ASSERT_EQ(r.exit, 0) << r.output;
    const Image image = readPng(out / "frame_00011.png");  // the far field ramped in over its 1 s period
    ASSERT_EQ(image.width, 256);
    const tide::render::Camera camera{{0.3f, 0.6f, 1.8f}, {0.3f, 0.15f, 0.3f}, 50.0f};
    const glm::vec3 nearMin(-0.05f, -1.0f, -0.05f), nearMax(0.65f, 1.0f, 0.65f);
    // Below the horizon (by a margin for the waves) and off the near field: the sea.
    const auto seaRay = [&](const glm::vec3& d) {
        return d.y < -0.05f && rayHitsBox(camera.eye, d, nearMin, nearMax) < 0.0f;
    };
    // The sea: blue over red by a margin, as deep water or the sky it reflects at grazing.
    const auto seaLike = [](const glm::vec3& c) { return c.b > c.r + 40.0f && c.b >= c.g; };
    int seaPixels = 0, skyPixels = 0;
    const double sea = share(image, seaRay, seaLike, seaPixels, camera);
    const double sky = share(image, [](const glm::vec3& d) { return d.y > 0.05f; }, skyLike, skyPixels, camera);
    std::printf("sea-coloured: %.3f of %d far-field pixels; sky-coloured: %.3f of %d\n", sea, seaPixels, sky, skyPixels);
    ASSERT_GT(seaPixels, image.width * image.height / 10) << "the test's camera should see the far field";
    EXPECT_GT(sea, 0.98);
    EXPECT_GT(sky, 0.97);
    // The sea is not flat: its waves make the colour vary along the rows of far-field pixels.
    double widest = 0.0;
    for (int y = 0; y < image.height; ++y) {
        double lo = 255.0, hi = 0.0;
        for (int x = 0; x < image.width; ++x) {
            if (!seaRay(tide::render::pixelRay(camera, image.width, image.height, glm::vec2(x + 0.5f, y + 0.5f)))) continue;
            lo = std::min<double>(lo, image.at(x, y).b);
            hi = std::max<double>(hi, image.at(x, y).b);
        }
        widest = std::max(widest, hi - lo);
    }
    EXPECT_GT(widest, 10.0) << "the widest range of blue along a row of far-field pixels";
    // No seam at the open face nearest the camera (z = 0.6): the mean colour of a strip across
    // the middle of its zone (the far field half blended over the particles' surface) is that
    // of the strip just outside the face, to within the waves' own variation: 7.2 apart, where
    // the particles' surface alone (before the zones' blend) read 56 apart.
    glm::dvec3 inside(0.0), outside(0.0);
    int nIn = 0, nOut = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3 d = tide::render::pixelRay(camera, image.width, image.height, glm::vec2(x + 0.5f, y + 0.5f));
            if (d.y >= 0.0f) continue;
            const glm::vec3 hit = camera.eye + d * ((0.15f - camera.eye.y) / d.y);  // on still water
            if (hit.x < 0.1f || hit.x > 0.5f) continue;
            if (hit.z > 0.45f && hit.z < 0.55f) inside += glm::dvec3(image.at(x, y)), ++nIn;
            if (hit.z > 0.6f && hit.z < 0.63f) outside += glm::dvec3(image.at(x, y)), ++nOut;
        }
    ASSERT_GT(nIn, 50);
    ASSERT_GT(nOut, 50);
    const double seam = glm::length(inside / double(nIn) - outside / double(nOut));
    std::printf("seam at the +z face: mean colour across its zone (%.0f %.0f %.0f), outside (%.0f %.0f %.0f): %.1f apart\n",
                inside.x / nIn, inside.y / nIn, inside.z / nIn, outside.x / nOut, outside.y / nOut, outside.z / nOut, seam);
    EXPECT_LT(seam, 15.0);
}

TEST(RenderCli, ParticleModeShowsEachMaterialsColour) {
    const fs::path scene = writeScene(
        "materials",
        tankScene(R"([{"name": "red", "density": 1000, "color": [0.9, 0.1, 0.1]},
                      {"name": "green", "density": 1000, "color": [0.1, 0.8, 0.15]}])",
                  R"([{"min": [0, 0, 0], "max": [0.16, 0.12, 0.3], "material": "red"},
                      {"min": [0.24, 0, 0], "max": [0.4, 0.12, 0.3], "material": "green"}])"));
    const fs::path out = scratch("materials_out");
    const Result r = run(kTide + " render " + scene.string() + " --out " + out.string() +
                         " --width 256 --height 192 --threads 1 --quiet --mode particles --color-by material");
    ASSERT_EQ(r.exit, 0) << r.output;
    const Image image = readPng(out / "frame_00000.png");
    ASSERT_EQ(image.width, 256);
    const glm::vec3 inset(kSpacing);
    const auto red = [](const glm::vec3& c) { return c.r > c.g + 50.0f && c.r > c.b + 50.0f; };
    const auto green = [](const glm::vec3& c) { return c.g > c.r + 50.0f && c.g > c.b + 40.0f; };
    int n = 0;
    const auto hitsLeft = [&](const glm::vec3& d) {
        return rayHitsBox(kCamera.eye, d, inset, glm::vec3(0.16f, 0.12f, 0.3f) - inset) > 0.0f;
    };
    const auto hitsRight = [&](const glm::vec3& d) {
        return rayHitsBox(kCamera.eye, d, glm::vec3(0.24f, 0.0f, 0.0f) + inset, glm::vec3(0.4f, 0.12f, 0.3f) - inset) > 0.0f;
    };
    EXPECT_GT(share(image, hitsLeft, red, n), 0.85) << n << " pixels";
    EXPECT_GT(n, 500);
    EXPECT_GT(share(image, hitsRight, green, n), 0.85) << n << " pixels";
    EXPECT_GT(n, 500);
    EXPECT_LT(share(image, hitsLeft, green, n), 0.02);
}

TEST(RenderCli, ObstaclesAreDrawnAndHideTheWaterBehindThem) {
    // Water at the back of the tank, a box obstacle in front of it (between it and the camera).
    std::string text = tankScene(R"([{"name": "water", "density": 1000}])",
                                 R"([{"min": [0, 0, 0], "max": [0.4, 0.14, 0.1]}])");
    text.insert(text.rfind('}'), R"(, "obstacles": [{"type": "box", "min": [0.12, 0, 0.16], "max": [0.28, 0.2, 0.24]}])");
    const fs::path scene = writeScene("obstacle", text);
    const fs::path out = scratch("obstacle_out");
    const Result r = run(kTide + " render " + scene.string() + " --out " + out.string() +
                         " --width 256 --height 192 --threads 1 --quiet --mode surface");
    ASSERT_EQ(r.exit, 0) << r.output;
    const Image image = readPng(out / "frame_00000.png");
    ASSERT_EQ(image.width, 256);
    const glm::vec3 obstacleMin(0.12f, 0.0f, 0.16f), obstacleMax(0.28f, 0.2f, 0.24f), margin(0.005f);
    const auto grey = [](const glm::vec3& c) {
        return std::abs(c.r - c.g) < 25.0f && std::abs(c.g - c.b) < 25.0f && c.r > 30.0f && c.r < 200.0f;
    };
    int n = 0;
    const auto hitsObstacle = [&](const glm::vec3& d) {
        return rayHitsBox(kCamera.eye, d, obstacleMin + margin, obstacleMax - margin) > 0.0f;
    };
    EXPECT_GT(share(image, hitsObstacle, grey, n), 0.95) << n << " pixels";
    EXPECT_GT(n, 500);
    EXPECT_LT(share(image, hitsObstacle, waterLike, n), 0.02) << "water drawn over the obstacle in front of it";
}

TEST(RenderCli, RefusesBadSizesNamingTheFlagAndValue) {
    const fs::path scene = writeScene("bad", tankScene(R"([{"name": "water", "density": 1000}])", "[]"));
    for (const auto& [flags, flag, value] : std::vector<std::array<std::string, 3>>{
             {"--width 0", "--width", "0"}, {"--height 99999", "--height", "99999"}, {"--width abc", "--width", "abc"}}) {
        const fs::path out = scratch("bad_out");
        const Result r = run(kTide + " render " + scene.string() + " --out " + out.string() + " " + flags);
        EXPECT_EQ(r.exit, 2) << flags << ": " << r.output;
        EXPECT_NE(r.output.find(flag), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(value), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(out)) << "nothing is written on bad input";
    }
}

TEST(RenderCli, VideoThroughFfmpegOrAClearErrorWithoutIt) {
    const fs::path scene = writeScene("video", tankScene(R"([{"name": "water", "density": 1000}])",
                                                         R"([{"min": [0, 0, 0], "max": [0.4, 0.1, 0.3]}])", "0.1"));
    const fs::path out = scratch("video_out");
    const fs::path video = scratch("video.mp4");
    Result r = run(kTide + " render " + scene.string() + " --out " + out.string() + " --video " + video.string() +
                   " --width 64 --height 48 --threads 1 --quiet");
    ASSERT_EQ(r.exit, 0) << r.output;
    EXPECT_GT(fs::file_size(video), 100u);

    r = run("env PATH=/nonexistent " + kTide + " render " + scene.string() + " --out " + scratch("nf").string() +
            " --video " + scratch("nf.mp4").string() + " --width 64 --height 48 --quiet");
    EXPECT_EQ(r.exit, 2) << r.output;
    EXPECT_NE(r.output.find("--video"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("ffmpeg"), std::string::npos) << r.output;
}

TEST(SceneCamera, BadCamerasAreNamedByFieldAndValue) {
    const std::string base = R"({"domain": {"min": [0, 0, 0], "max": [0.2, 0.2, 0.2]}, "particle_spacing": 0.02,
  "end_time": 0.1, "materials": [{"name": "water", "density": 1000}], "camera": )";
    for (const auto& [camera, field, value] : std::vector<std::array<std::string, 3>>{
             {R"({"eye": [1, 1, 1], "target": [0, 0, 0], "fov": 0})", "camera.fov", "0"},
             {R"({"eye": [1, 1, 1], "target": [0, 0, 0], "fov": 200})", "camera.fov", "200"},
             {R"({"eye": [1, 1], "target": [0, 0, 0]})", "camera.eye", "[1,1]"},
             {R"({"target": [0, 0, 0]})", "camera.eye", "missing"},
             {R"({"eye": [1, 1, 1], "target": [1, 1, 1]})", "camera.target", "[1, 1, 1]"},
             {R"({"eye": [1, 1, 1], "target": [0, 0, 0], "fv": 30})", "camera.fv", "did you mean \"fov\""}}) {
        const fs::path scene = writeScene("camera", base + camera + "}");
        const Result r = run(kTide + " validate " + scene.string());
        EXPECT_EQ(r.exit, 2) << camera << ": " << r.output;
        EXPECT_NE(r.output.find(field), std::string::npos) << camera << ": " << r.output;
        EXPECT_NE(r.output.find(value), std::string::npos) << camera << ": " << r.output;
    }
    const fs::path good = writeScene("camera", base + R"({"eye": [1, 1, 1], "target": [0, 0, 0], "fov": 60}})");
    const Result r = run(kTide + " validate " + good.string());
    EXPECT_EQ(r.exit, 0) << r.output;
}

}  // namespace
