#pragma once
// Obstacles as triangles for drawing: each shape tessellated (boxes, spheres, capped
// cylinders, a patch of each plane, meshes as they are), flat vertex normals.
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include <tide/defs.hpp>
#include <tide/world.hpp>

namespace tide::render {

struct SolidVertex {
    glm::vec3 position;
    glm::vec3 normal;
};

/// Triangles (3 vertices each) of every obstacle, each moved to its pose (`poses`, one per
/// obstacle, or empty: all at rest); planes are drawn as squares `planeSize` wide around their point.
std::vector<SolidVertex> tessellate(const std::vector<ObstacleDef>& obstacles, float planeSize,
                                    std::span<const ObstaclePose> poses = {});

}  // namespace tide::render
