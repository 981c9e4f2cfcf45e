#pragma once
/// \file
/// The true 2D mode (WorldDef::dimensions = 2): a World of the x–y plane, every particle and
/// every solid at z = 0. The neighbour grid, the lattice of blocks and the solvers stay the
/// 3D ones: with no extent in z the grid has one cell layer there, a lattice one point, and
/// every pair vector a zero z, so nothing leaves the plane; what changes is the kernels'
/// normalisation (core/kernels.hpp) and the constants that count dimensions.

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include <glm/vec3.hpp>

#include <tide/defs.hpp>

#include "core/validate.hpp"

namespace tide {

/// Throws unless d.dimensions is 2 or 3, and, in 2D, unless gravity lies in the plane and z is not periodic.
inline void validateDimensions(const WorldDef& d) {
    if (d.dimensions != 2 && d.dimensions != 3)
        throw std::invalid_argument("dimensions: must be 2 or 3, got " + std::to_string(d.dimensions));
    if (d.dimensions != 2) return;
    if (d.gravity.z != 0.0f)
        throw std::invalid_argument("gravity: a 2D world's vectors lie in the x–y plane (z = 0), got " + show(d.gravity));
    if (d.periodic.z) throw std::invalid_argument("domain.periodic: a 2D world has no z axis to wrap");
}

/// The definition a 2D World runs with: the domain flattened to z = 0 (a 3D one unchanged).
inline WorldDef planarWorldDef(WorldDef d) {
    if (d.dimensions == 2) d.domainMin.z = d.domainMax.z = 0.0f;
    return d;
}

/// In a 2D world, throws unless v has z = 0 (`field` names it).
inline void requireInPlane(int dimensions, const std::string& field, const glm::vec3& v) {
    if (dimensions == 2 && v.z != 0.0f)
        throw std::invalid_argument(field + ": a 2D world's vectors lie in the x–y plane (z = 0), got " + show(v));
}

/// Half the depth in z a box obstacle gets in 2D, m: a prism through the plane, so its
/// signed distance at z = 0 is that of its x–y rectangle.
inline constexpr float kPlanarBoxHalfDepth = 1.0e4f;

/// Throws unless the polygon has ≥ 3 finite corners, an area, and no two edges crossing.
inline void validatePolygon(const std::vector<glm::vec2>& points) {
    const std::size_t n = points.size();
    if (n < 3) throw std::invalid_argument("obstacle.points: a polygon needs at least 3 points, got " + std::to_string(n));
    double area = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec2 a = points[i], b = points[(i + 1) % n];
        if (!std::isfinite(a.x) || !std::isfinite(a.y))
            throw std::invalid_argument("obstacle.points[" + std::to_string(i) + "]: must be finite");
        area += 0.5 * (double{a.x} * b.y - double{b.x} * a.y);
    }
    if (!(std::abs(area) > 0.0)) throw std::invalid_argument("obstacle.points: the polygon has no area");
    const auto cross = [](glm::vec2 o, glm::vec2 a, glm::vec2 b) {
        return double{a.x - o.x} * (b.y - o.y) - double{a.y - o.y} * (b.x - o.x);
    };
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;  // neighbours through the closing edge
            const glm::vec2 a = points[i], b = points[(i + 1) % n], c = points[j], d = points[(j + 1) % n];
            const double d1 = cross(a, b, c), d2 = cross(a, b, d), d3 = cross(c, d, a), d4 = cross(c, d, b);
            if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0)
                throw std::invalid_argument("obstacle.points: edges " + std::to_string(i) + " and " + std::to_string(j) +
                                            " of the polygon cross; give its corners in order around it");
        }
}

/// Refuses an obstacle whose shape or vectors do not fit the world's dimension, and puts a 2D
/// one in the plane (a box becomes a prism through it).
inline void validateObstacleDimensions(ObstacleDef& o, int dimensions) {
    using Shape = ObstacleDef::Shape;
    const bool planarShape = o.shape == Shape::Circle || o.shape == Shape::Polygon;
    if (dimensions == 3) {
        if (planarShape)
            throw std::invalid_argument(std::string("obstacle.type: \"") + (o.shape == Shape::Circle ? "circle" : "polygon") +
                                        "\" is a 2D shape; use it in a scene with \"dimensions\": 2");
        return;
    }
    if (o.shape == Shape::Sphere || o.shape == Shape::Cylinder || o.shape == Shape::Mesh)
        throw std::invalid_argument(std::string("obstacle.type: \"") +
                                    (o.shape == Shape::Sphere ? "sphere" : o.shape == Shape::Cylinder ? "cylinder" : "mesh") +
                                    "\" is a 3D shape; a 2D world takes box, plane, circle and polygon");
    // A 2D body is a box or circle: per metre of width, as the loads are (World::addBody).
    if (o.dynamics && o.shape == Shape::Polygon)
        throw std::invalid_argument("obstacle.dynamic: a polygon cannot be a floating body; in 2D a body is a box or a circle");
    if (o.shape == Shape::Box) {
        o.min.z = -kPlanarBoxHalfDepth;
        o.max.z = kPlanarBoxHalfDepth;
    }
    if (o.shape == Shape::Plane) {
        requireInPlane(2, "obstacle.normal", o.normal);
        o.point.z = 0.0f;
    }
    if (o.loadReference) requireInPlane(2, "obstacle.load_reference", *o.loadReference);
    const MotionDef& m = o.motion;
    requireInPlane(2, "obstacle.motion.velocity", m.velocity);
    requireInPlane(2, "obstacle.motion.amplitude", m.amplitude);
    requireInPlane(2, "obstacle.motion.center", m.center);
    if (m.type == MotionDef::Type::Rotation || m.type == MotionDef::Type::Table) {
        if (m.axis.x != 0.0f || m.axis.y != 0.0f)
            throw std::invalid_argument("obstacle.motion.axis: a 2D world rotates about z only, got " + show(m.axis));
    }
    for (const MotionKey& k : m.keys) requireInPlane(2, "obstacle.motion offset", k.offset);
}

}  // namespace tide
