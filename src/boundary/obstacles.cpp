#include "boundary/obstacles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/geometric.hpp>

#include <tide/triangle_mesh.hpp>

#include "core/parallel.hpp"

namespace tide {

namespace {

/// Signed distance to the 2D box |q| ≤ half around the origin and its gradient (q ≥ 0 per
/// component: the query is mirrored into the positive quadrant/octant by the caller).
template <class V>
float boxDistance(const V& q, const V& half, V& gradient) {
    const V d = q - half;
    const V outside = glm::max(d, V(0.0f));
    const float outsideLength = glm::length(outside);
    if (outsideLength > 0.0f) {
        gradient = outside / outsideLength;
        return outsideLength;
    }
    // Inside: minus the distance to the nearest face.
    int axis = 0;
    for (int a = 1; a < static_cast<int>(V::length()); ++a)
        if (d[a] > d[axis]) axis = a;
    gradient = V(0.0f);
    gradient[axis] = 1.0f;
    return d[axis];
}

/// Any unit vector perpendicular to a unit vector.
glm::vec3 perpendicular(const glm::vec3& a) {
    const glm::vec3 helper = std::abs(a.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(a, helper));
}

float boxSignedDistance(const ObstacleDef& o, const glm::vec3& x, glm::vec3* normal) {
    const glm::vec3 centre = 0.5f * (o.min + o.max);
    const glm::vec3 r = x - centre;
    glm::vec3 gradient;
    const float d = boxDistance(glm::abs(r), 0.5f * (o.max - o.min), gradient);
    if (normal) *normal = gradient * glm::vec3(r.x >= 0.0f ? 1 : -1, r.y >= 0.0f ? 1 : -1, r.z >= 0.0f ? 1 : -1);
    return d;
}

/// A capped cylinder is a 2D box in (distance from the axis, distance along the axis).
float cylinderSignedDistance(const ObstacleDef& o, const glm::vec3& x, glm::vec3* normal) {
    const glm::vec3 r = x - o.center;
    const float along = glm::dot(r, o.axis);
    const glm::vec3 radial = r - along * o.axis;
    const float rho = glm::length(radial);
    glm::vec2 gradient;
    const float d = boxDistance(glm::vec2(rho, std::abs(along)), glm::vec2(o.radius, 0.5f * o.length), gradient);
    if (normal) {
        const glm::vec3 outward = rho > 0.0f ? radial / rho : perpendicular(o.axis);
        *normal = gradient.x * outward + gradient.y * (along >= 0.0f ? 1.0f : -1.0f) * o.axis;
    }
    return d;
}

/// Signed distance in the x–y plane to a simple polygon (either winding): the nearest edge's
/// distance, negative inside by the crossing-number test; the gradient points away from it.
float polygonSignedDistance(const std::vector<glm::vec2>& polygon, const glm::vec3& x, glm::vec3* normal) {
    const glm::vec2 p(x.x, x.y);
    float best2 = std::numeric_limits<float>::infinity();
    glm::vec2 nearest(0.0f);
    bool inside = false;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0, k = n - 1; i < n; k = i++) {
        const glm::vec2 a = polygon[k], b = polygon[i];
        const glm::vec2 e = b - a;
        const float t = glm::clamp(glm::dot(p - a, e) / glm::dot(e, e), 0.0f, 1.0f);
        const glm::vec2 q = a + t * e;
        const float d2 = glm::dot(p - q, p - q);
        if (d2 < best2) {
            best2 = d2;
            nearest = q;
        }
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * e.x) inside = !inside;
    }
    const float d = std::sqrt(best2);
    if (normal) {
        const glm::vec2 away = d > 0.0f ? (p - nearest) / d : glm::vec2(0.0f, 1.0f);
        *normal = glm::vec3(inside ? -away : away, 0.0f);
    }
    return inside ? -d : d;
}

/// Whether x is more than `distance` outside the box [lo, hi].
bool fartherThan(const glm::vec3& x, const glm::vec3& lo, const glm::vec3& hi, float distance) {
    const glm::vec3 d = glm::max(glm::max(lo - x, x - hi), glm::vec3(0.0f));
    return glm::dot(d, d) > distance * distance;
}

}  // namespace

float signedDistance(const ObstacleDef& o, const glm::vec3& x, glm::vec3* normal) {
    switch (o.shape) {
        case ObstacleDef::Shape::Box: return boxSignedDistance(o, x, normal);
        case ObstacleDef::Shape::Sphere: {
            const glm::vec3 d = x - o.center;
            const float r = glm::length(d);
            if (normal) *normal = r > 0.0f ? d / r : glm::vec3(0, 1, 0);
            return r - o.radius;
        }
        case ObstacleDef::Shape::Cylinder: return cylinderSignedDistance(o, x, normal);
        case ObstacleDef::Shape::Plane:
            if (normal) *normal = o.normal;
            return glm::dot(x - o.point, o.normal);
        case ObstacleDef::Shape::Mesh: return o.mesh->signedDistance(x, normal);
        case ObstacleDef::Shape::Circle: {
            const glm::vec3 d(x.x - o.center.x, x.y - o.center.y, 0.0f);
            const float r = glm::length(d);
            if (normal) *normal = r > 0.0f ? d / r : glm::vec3(0, 1, 0);
            return r - o.radius;
        }
        case ObstacleDef::Shape::Polygon: return polygonSignedDistance(o.polygon, x, normal);
    }
    return std::numeric_limits<float>::infinity();
}

float signedDistance(const ObstacleDef& o, const RigidPose& pose, const glm::vec3& x, glm::vec3* normal) {
    const float d = signedDistance(o, pose.toRest(x), normal);
    if (normal) *normal = pose.rotate(*normal);
    return d;
}

glm::vec3 shapeCentre(const ObstacleDef& obstacle) {
    switch (obstacle.shape) {
        case ObstacleDef::Shape::Box: return 0.5f * (obstacle.min + obstacle.max);
        case ObstacleDef::Shape::Sphere:
        case ObstacleDef::Shape::Circle:
        case ObstacleDef::Shape::Cylinder: return obstacle.center;
        case ObstacleDef::Shape::Polygon: {
            // The area centroid of the polygon.
            double area = 0.0, cx = 0.0, cy = 0.0;
            const std::size_t n = obstacle.polygon.size();
            for (std::size_t i = 0; i < n; ++i) {
                const glm::vec2 a = obstacle.polygon[i], b = obstacle.polygon[(i + 1) % n];
                const double c = double{a.x} * b.y - double{b.x} * a.y;
                area += c;
                cx += (double{a.x} + b.x) * c;
                cy += (double{a.y} + b.y) * c;
            }
            return area != 0.0 ? glm::vec3(static_cast<float>(cx / (3.0 * area)), static_cast<float>(cy / (3.0 * area)), 0.0f)
                               : glm::vec3(0.0f);
        }
        case ObstacleDef::Shape::Plane: return obstacle.point;
        case ObstacleDef::Shape::Mesh:
            return obstacle.mesh ? 0.5f * (obstacle.mesh->boundsMin() + obstacle.mesh->boundsMax()) : glm::vec3(0.0f);
    }
    return glm::vec3(0.0f);
}

void obstacleBounds(const ObstacleDef& o, const glm::vec3& clipMin, const glm::vec3& clipMax, glm::vec3& lo,
                    glm::vec3& hi) {
    switch (o.shape) {
        case ObstacleDef::Shape::Box:
            lo = o.min;
            hi = o.max;
            break;
        case ObstacleDef::Shape::Sphere:
        case ObstacleDef::Shape::Circle:
            lo = o.center - glm::vec3(o.radius);
            hi = o.center + glm::vec3(o.radius);
            break;
        case ObstacleDef::Shape::Polygon:
            lo = glm::vec3(std::numeric_limits<float>::infinity());
            hi = -lo;
            for (const glm::vec2& c : o.polygon) {
                lo = glm::min(lo, glm::vec3(c, 0.0f));
                hi = glm::max(hi, glm::vec3(c, 0.0f));
            }
            break;
        case ObstacleDef::Shape::Cylinder: {
            // Per axis: half the length times the axis component, plus the cap disc's reach.
            const glm::vec3 a2 = o.axis * o.axis;
            const glm::vec3 half = 0.5f * o.length * glm::abs(o.axis) + o.radius * glm::sqrt(glm::max(1.0f - a2, 0.0f));
            lo = o.center - half;
            hi = o.center + half;
            break;
        }
        case ObstacleDef::Shape::Plane:
            lo = clipMin;
            hi = clipMax;
            break;
        case ObstacleDef::Shape::Mesh:
            lo = o.mesh->boundsMin();
            hi = o.mesh->boundsMax();
            break;
    }
    lo = glm::max(lo, clipMin);
    hi = glm::min(hi, clipMax);
}

std::vector<glm::vec3> sampleObstacle(const ObstacleDef& o, const glm::vec3& origin, float spacing, float depth,
                                      const glm::vec3& clipMin, const glm::vec3& clipMax, int threads) {
    glm::vec3 lo, hi;
    obstacleBounds(o, clipMin, clipMax, lo, hi);
    if (glm::any(glm::greaterThan(lo, hi))) return {};
    const glm::ivec3 first(glm::floor((lo - origin) / spacing));
    const glm::ivec3 last(glm::ceil((hi - origin) / spacing));
    const glm::ivec3 count = glm::max(last - first + 1, glm::ivec3(0));
    const float onSurface = kOnSurface * spacing;
    // One list per lattice row (y, z), joined in row order: the same points in the same
    // order for any thread count.
    std::vector<std::vector<glm::vec3>> rows(static_cast<std::size_t>(count.y) * static_cast<std::size_t>(count.z));
    parallelFor(static_cast<std::uint32_t>(rows.size()), threads, [&](std::uint32_t row) {
        const int j = first.y + static_cast<int>(row % static_cast<std::uint32_t>(count.y));
        const int k = first.z + static_cast<int>(row / static_cast<std::uint32_t>(count.y));
        for (int i = first.x; i <= last.x; ++i) {
            const glm::vec3 x = origin + spacing * (glm::vec3(static_cast<float>(i), static_cast<float>(j),
                                                              static_cast<float>(k)) + 0.5f);
            if (glm::any(glm::lessThan(x, clipMin)) || glm::any(glm::greaterThan(x, clipMax))) continue;
            float d;
            if (o.shape == ObstacleDef::Shape::Mesh) {
                // Only the surface within `depth` matters: far points cost a few box tests.
                if (!o.mesh->signedDistanceWithin(x, depth, d)) continue;
            } else {
                d = signedDistance(o, x);
            }
            if (d <= onSurface && d > -depth) rows[row].push_back(x);
        }
    });
    std::vector<glm::vec3> points;
    for (const auto& row : rows) points.insert(points.end(), row.begin(), row.end());
    return points;
}

std::vector<glm::vec3> sampleBoxCentred(const ObstacleDef& box, const glm::vec3& origin, float spacing, float depth,
                                        const glm::vec3& clipMin, const glm::vec3& clipMax) {
    glm::ivec3 count(1);
    glm::bvec3 planar(false), onLattice(false);
    glm::vec3 first(0.0f);  // the first point's coordinate, or its lattice index where onLattice
    for (int a = 0; a < 3; ++a) {
        planar[a] = clipMin[a] == clipMax[a];
        if (planar[a]) continue;
        count[a] = std::max(1, static_cast<int>(std::lround((box.max[a] - box.min[a]) / spacing)));
        first[a] = 0.5f * (box.min[a] + box.max[a]) - 0.5f * static_cast<float>(count[a] - 1) * spacing;
        const float index = (first[a] - origin[a]) / spacing - 0.5f;
        if (std::abs(index - std::round(index)) < kOnSurface) {
            onLattice[a] = true;
            first[a] = std::round(index);
        }
    }
    std::vector<glm::vec3> points;
    for (int k = 0; k < count.z; ++k)
        for (int j = 0; j < count.y; ++j)
            for (int i = 0; i < count.x; ++i) {
                const glm::ivec3 step(i, j, k);
                glm::vec3 x;
                float inside = std::numeric_limits<float>::infinity();  // distance to the nearest face
                for (int a = 0; a < 3; ++a) {
                    if (planar[a]) {
                        x[a] = clipMin[a];
                        continue;
                    }
                    x[a] = onLattice[a] ? origin[a] + spacing * (first[a] + static_cast<float>(step[a]) + 0.5f)
                                        : first[a] + static_cast<float>(step[a]) * spacing;
                    inside = std::min({inside, x[a] - box.min[a], box.max[a] - x[a]});
                }
                if (glm::any(glm::lessThan(x, clipMin)) || glm::any(glm::greaterThan(x, clipMax))) continue;
                if (inside < depth) points.push_back(x);
            }
    return points;
}

void projectOutOfObstacles(std::span<const ObstacleDef> obstacles, ParticleStore& particles, float margin,
                           int threads) {
    if (obstacles.empty()) return;
    parallelFor(particles.size(), threads, [&](std::uint32_t i) {
        for (const ObstacleDef& o : obstacles) {
            // A mesh's distance is a tree search: skip particles clearly outside its box.
            if (o.shape == ObstacleDef::Shape::Mesh &&
                fartherThan(particles.position[i], o.mesh->boundsMin(), o.mesh->boundsMax(), margin))
                continue;
            glm::vec3 normal;
            const float d = signedDistance(o, particles.position[i], &normal);
            if (d < margin) {
                particles.position[i] += (margin - d) * normal;
                const float vn = glm::dot(particles.velocity[i], normal);
                if (vn < 0.0f) particles.velocity[i] -= vn * normal;
            }
        }
    });
}

void projectOutOfMovingObstacle(const ObstacleDef& o, const RigidPose& pose, ParticleStore& particles, float margin,
                                int threads) {
    parallelFor(particles.size(), threads, [&](std::uint32_t i) {
        glm::vec3& x = particles.position[i];
        const glm::vec3 x0 = pose.toRest(x);
        if (o.shape == ObstacleDef::Shape::Mesh && fartherThan(x0, o.mesh->boundsMin(), o.mesh->boundsMax(), margin))
            return;
        glm::vec3 normal;
        const float d = signedDistance(o, x0, &normal);
        if (d >= margin) return;
        normal = pose.rotate(normal);
        x += (margin - d) * normal;
        glm::vec3& v = particles.velocity[i];
        const float into = glm::dot(v - pose.velocityAt(x), normal);
        if (into < 0.0f) v -= into * normal;
    });
}

}  // namespace tide
