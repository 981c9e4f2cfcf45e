// Tessellation of obstacle shapes for the renderer.
#include "obstacle_mesh.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include <tide/triangle_mesh.hpp>

namespace tide::render {

namespace {

constexpr float kPi = 3.14159265f;

void triangle(std::vector<SolidVertex>& out, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 cross = glm::cross(b - a, c - a);
    const float length = glm::length(cross);
    if (length <= 0.0f) return;
    const glm::vec3 n = cross / length;
    out.push_back({a, n});
    out.push_back({b, n});
    out.push_back({c, n});
}

void quad(std::vector<SolidVertex>& out, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d) {
    triangle(out, a, b, c);
    triangle(out, a, c, d);
}

/// Two unit vectors perpendicular to `axis` and to each other.
void basis(const glm::vec3& axis, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 helper = std::abs(axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    u = glm::normalize(glm::cross(axis, helper));
    v = glm::cross(axis, u);
}

void box(std::vector<SolidVertex>& out, const glm::vec3& lo, const glm::vec3& hi) {
    const glm::vec3 p[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                            {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    quad(out, p[0], p[3], p[2], p[1]);  // -z
    quad(out, p[4], p[5], p[6], p[7]);  // +z
    quad(out, p[0], p[4], p[7], p[3]);  // -x
    quad(out, p[1], p[2], p[6], p[5]);  // +x
    quad(out, p[0], p[1], p[5], p[4]);  // -y
    quad(out, p[3], p[7], p[6], p[2]);  // +y
}

void sphere(std::vector<SolidVertex>& out, const glm::vec3& centre, float radius) {
    constexpr int kRings = 16, kSegments = 32;
    const auto at = [&](int ring, int segment) {
        const float theta = kPi * static_cast<float>(ring) / kRings;
        const float phi = 2.0f * kPi * static_cast<float>(segment) / kSegments;
        return centre + radius * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    for (int r = 0; r < kRings; ++r)
        for (int s = 0; s < kSegments; ++s) {
            const glm::vec3 a = at(r, s), b = at(r, s + 1), c = at(r + 1, s + 1), d = at(r + 1, s);
            // Smooth normals: the sphere's own, not the facets'.
            const std::size_t first = out.size();
            if (r > 0) triangle(out, a, b, c);
            if (r < kRings - 1) triangle(out, a, c, d);
            for (std::size_t k = first; k < out.size(); ++k) out[k].normal = glm::normalize(out[k].position - centre);
        }
}

void cylinder(std::vector<SolidVertex>& out, const ObstacleDef& o) {
    constexpr int kSegments = 32;
    const glm::vec3 axis = glm::normalize(o.axis);
    glm::vec3 u, v;
    basis(axis, u, v);
    const glm::vec3 bottom = o.center - 0.5f * o.length * axis, top = o.center + 0.5f * o.length * axis;
    for (int s = 0; s < kSegments; ++s) {
        const float a0 = 2.0f * kPi * static_cast<float>(s) / kSegments, a1 = 2.0f * kPi * static_cast<float>(s + 1) / kSegments;
        const glm::vec3 r0 = o.radius * (std::cos(a0) * u + std::sin(a0) * v);
        const glm::vec3 r1 = o.radius * (std::cos(a1) * u + std::sin(a1) * v);
        const std::size_t first = out.size();
        quad(out, bottom + r0, bottom + r1, top + r1, top + r0);
        for (std::size_t k = first; k < out.size(); ++k) {
            const glm::vec3 radial = out[k].position - o.center;
            out[k].normal = glm::normalize(radial - glm::dot(radial, axis) * axis);
        }
        triangle(out, top, top + r0, top + r1);
        triangle(out, bottom, bottom + r1, bottom + r0);
    }
}

void plane(std::vector<SolidVertex>& out, const ObstacleDef& o, float size) {
    const glm::vec3 n = glm::normalize(o.normal);
    glm::vec3 u, v;
    basis(n, u, v);
    const float h = 0.5f * size;
    quad(out, o.point - h * u - h * v, o.point + h * u - h * v, o.point + h * u + h * v, o.point - h * u + h * v);
    for (std::size_t k = out.size() - 6; k < out.size(); ++k) out[k].normal = n;
}

/// A 2D world's shape (a circle, a polygon, a box through the plane) drawn as a slab
/// ±halfDepth about z = 0: the polygon's outline extruded, with its faces fanned from the centroid.
void prism(std::vector<SolidVertex>& out, const std::vector<glm::vec2>& outline, float halfDepth) {
    const std::size_t n = outline.size();
    glm::vec2 centre(0.0f);
    for (const glm::vec2& c : outline) centre += c / static_cast<float>(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec2 a = outline[i], b = outline[(i + 1) % n];
        quad(out, {a, -halfDepth}, {b, -halfDepth}, {b, halfDepth}, {a, halfDepth});
        triangle(out, {centre, halfDepth}, {a, halfDepth}, {b, halfDepth});
        triangle(out, {centre, -halfDepth}, {b, -halfDepth}, {a, -halfDepth});
    }
}

}  // namespace

std::vector<SolidVertex> tessellate(const std::vector<ObstacleDef>& obstacles, float planeSize,
                                    std::span<const ObstaclePose> poses) {
    std::vector<SolidVertex> out;
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
        const ObstacleDef& o = obstacles[k];
        const std::size_t first = out.size();
        // 2D worlds' solids: slabs a few per cent of the scene deep.
        const float halfDepth = 0.02f * planeSize;
        switch (o.shape) {
            case ObstacleDef::Shape::Box:
                if (o.max.z - o.min.z > 1.0e3f)  // a 2D box: a prism through the plane
                    box(out, {o.min.x, o.min.y, -halfDepth}, {o.max.x, o.max.y, halfDepth});
                else
                    box(out, o.min, o.max);
                break;
            case ObstacleDef::Shape::Circle: {
                constexpr int kSegments = 32;
                std::vector<glm::vec2> outline;
                for (int s = 0; s < kSegments; ++s) {
                    const float a = 2.0f * kPi * static_cast<float>(s) / kSegments;
                    outline.push_back(glm::vec2(o.center) + o.radius * glm::vec2(std::cos(a), std::sin(a)));
                }
                prism(out, outline, halfDepth);
                break;
            }
            case ObstacleDef::Shape::Polygon: prism(out, o.polygon, halfDepth); break;
            case ObstacleDef::Shape::Sphere: sphere(out, o.center, o.radius); break;
            case ObstacleDef::Shape::Cylinder: cylinder(out, o); break;
            case ObstacleDef::Shape::Plane: plane(out, o, planeSize); break;
            case ObstacleDef::Shape::Mesh:
                if (o.mesh) {
                    const auto& vertices = o.mesh->vertices();
                    for (const glm::uvec3& t : o.mesh->triangles()) triangle(out, vertices[t.x], vertices[t.y], vertices[t.z]);
                }
                break;
        }
        if (k < poses.size())
            for (std::size_t v = first; v < out.size(); ++v) {
                out[v].position = poses[k].rotation * out[v].position + poses[k].translation;
                out[v].normal = poses[k].rotation * out[v].normal;
            }
    }
    return out;
}

}  // namespace tide::render
