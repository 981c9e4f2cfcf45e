#pragma once
/// \file
/// tide::render::Snapshot — a copy of what a renderer draws from a World, taken between
/// steps, so that drawing never reads a World that another thread is stepping.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include <tide/defs.hpp>
#include <tide/world.hpp>

namespace tide::render {

/// One material as a renderer needs it.
struct SnapshotMaterial {
    std::string name;
    glm::vec3 color{0.2f, 0.45f, 0.9f};  ///< linear RGB
    float restDensity = 1000.0f;         ///< kg/m³
};

/// Particle state (SoA, SI units) and the figures a viewer shows, at one instant.
struct Snapshot {
    std::vector<glm::vec3> position;       ///< m
    std::vector<glm::vec3> velocity;       ///< m/s
    std::vector<float> density;            ///< kg/m³
    std::vector<float> pressure;           ///< Pa
    std::vector<MaterialIndex> material;
    std::vector<SnapshotMaterial> materials;
    std::vector<ObstacleDef> obstacles;    ///< solids in their rest pose (meshes shared, not copied)
    std::vector<ObstaclePose> obstaclePoses;  ///< where each obstacle is at `time` (moving ones move)
    glm::vec3 domainMin{0.0f};             ///< container, m
    glm::vec3 domainMax{1.0f};
    float particleSpacing = 0.02f;         ///< m
    double time = 0.0;                     ///< simulated s
    glm::vec3 gravity{0.0f, -9.81f, 0.0f};  ///< m/s²
    /// An ocean scene's far field (World::ocean), drawn around the near field (the domain) to
    /// the horizon; its still water is at domainMin.y + ocean->depth.
    std::optional<OceanDef> ocean;
    double oceanRamp = 1.0;                ///< World::oceanRamp at `time`
    WorldStats stats;
    /// Changes whenever the particle data changes, so a renderer uploads each state once.
    std::uint64_t version = 0;

    [[nodiscard]] std::uint32_t size() const { return static_cast<std::uint32_t>(position.size()); }
};

/// Copy a World's particles and figures into `out`, reusing its memory; bumps `out.version`.
void takeSnapshot(const World& world, Snapshot& out);

}  // namespace tide::render
