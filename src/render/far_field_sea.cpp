#include "far_field_sea.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <thread>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <tide/ocean.hpp>

#include "shaders.hpp"

namespace tide::render {

namespace {
/// Sectors around the camera, and how much wider each ring is than the last.
constexpr int kSectors = 192;
constexpr float kRingGrowth = 1.045f;

/// What a sea is made from: the renderer makes its sea again only when this changes.
std::string seaKeyOf(const OceanDef& ocean, float g) {
    const OceanWavesDef& w = ocean.waves;
    char key[512];
    std::snprintf(key, sizeof key, "%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %llu %d %d %.17g %.9g", static_cast<int>(w.type),
                  w.height, w.period, w.hs, w.tp, w.direction, w.spreading.value_or(-1.0), w.gamma.value_or(-1.0),
                  static_cast<unsigned long long>(w.seed), w.components, w.directions, ocean.depth, g);
    return key;
}

}  // namespace

FarFieldSea::FarFieldSea()
    : program_("far field", shaders::compose({shaders::kFarFieldVertex}).c_str(),
               shaders::compose({shaders::kSky, shaders::kDeepWater, shaders::kFarFieldFragment}).c_str()) {
    glGenVertexArrays(1, &vertexArray_);
    glGenBuffers(1, &vertexBuffer_);
    glGenBuffers(1, &indexBuffer_);
    glBindVertexArray(vertexArray_);
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(ocean::SurfacePoint), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(ocean::SurfacePoint),
                          reinterpret_cast<const void*>(offsetof(ocean::SurfacePoint, normal)));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
    glBindVertexArray(0);
}

FarFieldSea::~FarFieldSea() {
    glDeleteBuffers(1, &indexBuffer_);
    glDeleteBuffers(1, &vertexBuffer_);
    glDeleteVertexArrays(1, &vertexArray_);
}

void FarFieldSea::buildRings(float innerSpacing, float outerRadius) {
    // Ring 0 is the centre; ring j > 0 at radius r_j, r_1 = innerSpacing, r_{j+1} = max(r_j
    // growth, r_j + innerSpacing) up to outerRadius.
    std::vector<float> radii{0.0f};
    for (float r = innerSpacing; r < outerRadius * kRingGrowth; r = std::max(r * kRingGrowth, r + innerSpacing))
        radii.push_back(r);
    offsets_.assign(1, glm::dvec2(0.0));
    spacing_.assign(1, innerSpacing);
    for (std::size_t j = 1; j < radii.size(); ++j) {
        const float radial = radii[j] - radii[j - 1];
        const float around = 2.0f * std::numbers::pi_v<float> * radii[j] / static_cast<float>(kSectors);
        for (int s = 0; s < kSectors; ++s) {
            const double angle = 2.0 * std::numbers::pi * s / kSectors;
            offsets_.emplace_back(radii[j] * std::cos(angle), radii[j] * std::sin(angle));
            spacing_.push_back(std::max(radial, around));
        }
    }
    std::vector<std::uint32_t> indices;
    const auto at = [](std::size_t ring, int sector) {
        return static_cast<std::uint32_t>(1 + (ring - 1) * kSectors + static_cast<std::size_t>(sector % kSectors));
    };
    for (int s = 0; s < kSectors; ++s) indices.insert(indices.end(), {0u, at(1, s), at(1, s + 1)});
    for (std::size_t j = 1; j + 1 < radii.size(); ++j)
        for (int s = 0; s < kSectors; ++s)
            indices.insert(indices.end(), {at(j, s), at(j + 1, s), at(j + 1, s + 1), at(j, s), at(j + 1, s + 1), at(j, s + 1)});
    glBindVertexArray(vertexArray_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
                 GL_STATIC_DRAW);
    glBindVertexArray(0);
    indexCount_ = static_cast<GLsizei>(indices.size());
    rest_.resize(offsets_.size());
    points_.resize(offsets_.size());
    sampledTime_ = -1.0;
}

void FarFieldSea::update(const Snapshot& snapshot, const Camera& camera) {
    if (!snapshot.ocean) {
        sea_.reset();
        return;
    }
    const float g = glm::length(snapshot.gravity);
    const std::string key = seaKeyOf(*snapshot.ocean, g);
    if (!sea_ || key != seaKey_) {
        sea_ = std::make_unique<ocean::Sea>(ocean::Sea::fromDef(*snapshot.ocean, g));
        seaKey_ = key;
        sampledTime_ = -1.0;
    }
    // Fine enough near the camera for a particle spacing, out to just inside the far plane.
    const float inner = std::max(snapshot.particleSpacing, 1e-3f);
    const glm::vec2 rings(inner, 0.95f * camera.farPlane);
    if (rings != ringsFor_) {
        buildRings(rings.x, rings.y);
        ringsFor_ = rings;
    }
    // The centre under the eye, on a lattice of the innermost spacing: a moving camera then
    // samples the same points again instead of sliding the mesh through the waves.
    const glm::dvec2 centre = glm::round(glm::dvec2(camera.eye.x, camera.eye.z) / static_cast<double>(inner)) *
                              static_cast<double>(inner);
    if (snapshot.time == sampledTime_ && centre == sampledCentre_) return;
    for (std::size_t i = 0; i < offsets_.size(); ++i) rest_[i] = centre + offsets_[i];
    ocean::SurfaceSampling sampling;
    sampling.time = snapshot.time;
    sampling.ramp = snapshot.oceanRamp;
    sampling.stillWaterY = static_cast<double>(snapshot.domainMin.y) + snapshot.ocean->depth;
    ocean::sampleSurface(*sea_, rest_, spacing_, sampling, points_, static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(points_.size() * sizeof(ocean::SurfacePoint)), points_.data(),
                 GL_STREAM_DRAW);
    sampledTime_ = snapshot.time;
    sampledCentre_ = centre;
}

void FarFieldSea::draw(const Frame& frame, const Camera& camera, const Snapshot& snapshot, const WaterLook& water,
                       bool zones) const {
    if (!sea_ || indexCount_ == 0) return;
    if (zones && snapshot.ocean->openSides.empty()) return;
    program_.use();
    // Raised with the near field's drawn surface, so that the two meet at the open faces.
    const glm::mat4 lift(1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, water.surfaceLift, 0.0f, 1.0f);
    program_.set("uViewProjection", frame.projection * frame.view * lift);
    program_.set("uEye", camera.eye - glm::vec3(0.0f, water.surfaceLift, 0.0f));
    program_.set("uSunDirection", frame.sunDirection);
    program_.set("uWaterColor", water.color);
    program_.set("uAbsorption", water.absorption);
    program_.set("uSeaDepth", static_cast<float>(snapshot.ocean->depth));
    program_.set("uNearMin", glm::vec2(snapshot.domainMin.x, snapshot.domainMin.z));
    program_.set("uNearMax", glm::vec2(snapshot.domainMax.x, snapshot.domainMax.z));
    program_.set("uFogDistance", water.fogDistance);
    program_.set("uZones", zones ? 1 : 0);
    glm::vec4 open(0.0f);
    for (const OceanSide side : snapshot.ocean->openSides) open[static_cast<int>(side)] = 1.0f;  // -x, +x, -z, +z
    program_.set("uOpen", open);
    program_.set("uZoneWidth", static_cast<float>(oceanZoneWidth(*snapshot.ocean, glm::length(snapshot.gravity))));
    glBindVertexArray(vertexArray_);
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

}  // namespace tide::render
