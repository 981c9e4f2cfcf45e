#pragma once
// Obstacles as triangles for drawing: each shape tessellated (boxes, spheres, capped
// cylinders, a patch of each plane, meshes as they are), flat vertex normals.
#include <vector>

#include <glm/vec3.hpp>

#include <tide/defs.hpp>

namespace tide::render {

struct SolidVertex {
    glm::vec3 position;
    glm::vec3 normal;
};

/// Triangles (3 vertices each) of every obstacle; planes are drawn as squares `planeSize` wide
/// around their point.
std::vector<SolidVertex> tessellate(const std::vector<ObstacleDef>& obstacles, float planeSize);

}  // namespace tide::render
