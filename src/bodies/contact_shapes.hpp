#pragma once
/// \file
/// The geometry contact needs of a shape in its rest pose: an exact signed distance with its
/// outward normal, and points on its surface that probe other shapes.

#include <vector>

#include <glm/vec3.hpp>

#include <tide/defs.hpp>

namespace tide::bodies {

/// A surface point that probes other shapes; `radius` > 0 makes it a sphere (a sphere body
/// is one point at its centre with its radius).
struct ContactProbe {
    glm::dvec3 point{0.0};
    double radius = 0.0;
};

struct ContactShape {
    ObstacleDef shape;                 ///< rest pose
    std::vector<ContactProbe> probes;  ///< rest pose
    int probesPerFace = 1;             ///< how many probes can touch a flat wall at once
    double boundingRadius = 0.0;       ///< about `center`, m (infinite for a plane)
    glm::dvec3 center{0.0};            ///< rest pose
};

/// Probes and bounds of `shape` (box, sphere, cylinder, mesh, plane).
ContactShape makeContactShape(const ObstacleDef& shape);

/// Signed distance (negative inside) from the rest-pose point p, and the outward unit normal.
double signedDistance(const ObstacleDef& shape, const glm::dvec3& p, glm::dvec3& normal);

}  // namespace tide::bodies
