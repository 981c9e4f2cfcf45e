#pragma once
/// \file
/// tide::TriangleMesh — a closed triangle mesh with an exact signed distance, the geometry
/// of a mesh obstacle (ObstacleDef::Shape::Mesh). tide::io::loadMesh reads one from OBJ or PLY.

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/ext/vector_uint3.hpp>
#include <glm/vec3.hpp>

namespace tide {

/// A closed, consistently oriented triangle mesh (every edge joins exactly two triangles
/// that traverse it in opposite directions), immutable once made. Its signed distance is
/// exact: the nearest triangle, found through a bounding-volume hierarchy, signed by the
/// angle-weighted pseudo-normal of the nearest feature (Bærentzen & Aanæs 2005).
class TriangleMesh {
public:
    /// Vertices (m) and triangles (three vertex indices each). Vertices at identical
    /// positions are merged first; a mesh whose triangles all face inward is turned outward.
    /// Throws std::invalid_argument saying what is wrong when the mesh has no triangle, an
    /// index out of range, a non-finite vertex, a degenerate (zero-area) triangle, an edge
    /// with one triangle (a hole) or more than two, inconsistently oriented neighbours, or
    /// no enclosed volume.
    TriangleMesh(std::vector<glm::vec3> vertices, std::vector<glm::uvec3> triangles);
    ~TriangleMesh();
    TriangleMesh(TriangleMesh&&) noexcept;
    TriangleMesh& operator=(TriangleMesh&&) noexcept;
    TriangleMesh(const TriangleMesh&) = delete;
    TriangleMesh& operator=(const TriangleMesh&) = delete;

    /// Signed distance from x to the surface (negative inside), m; `normal` (if given) gets
    /// the outward unit direction in which the distance grows fastest.
    [[nodiscard]] float signedDistance(const glm::vec3& x, glm::vec3* normal = nullptr) const;
    /// As signedDistance(), but only looks for surface within `maxDistance` of x: returns
    /// false, leaving `distance` and `normal` untouched, when there is none (much cheaper
    /// for points far from the surface).
    bool signedDistanceWithin(const glm::vec3& x, float maxDistance, float& distance,
                              glm::vec3* normal = nullptr) const;

    /// Vertices after merging, m.
    [[nodiscard]] const std::vector<glm::vec3>& vertices() const;
    /// Triangles, counter-clockwise seen from outside.
    [[nodiscard]] const std::vector<glm::uvec3>& triangles() const;
    [[nodiscard]] glm::vec3 boundsMin() const;
    [[nodiscard]] glm::vec3 boundsMax() const;
    /// Enclosed volume, m³ (> 0).
    [[nodiscard]] double volume() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace tide
