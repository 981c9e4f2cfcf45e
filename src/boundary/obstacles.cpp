#include "boundary/obstacles.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/parallel.hpp"

namespace tide {

float signedDistance(const ObstacleDef& o, const glm::vec3& x, glm::vec3* normal) {
    if (o.shape == ObstacleDef::Shape::Sphere) {
        const glm::vec3 d = x - o.center;
        const float r = glm::length(d);
        if (normal) *normal = r > 0.0f ? d / r : glm::vec3(0, 1, 0);
        return r - o.radius;
    }
    // Box: outside, the distance to the nearest point; inside, minus the distance to the nearest face.
    const glm::vec3 centre = 0.5f * (o.min + o.max);
    const glm::vec3 half = 0.5f * (o.max - o.min);
    const glm::vec3 q = glm::abs(x - centre) - half;
    const glm::vec3 outside = glm::max(q, glm::vec3(0.0f));
    const float inside = std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
    if (normal) {
        if (glm::length(outside) > 0.0f) {
            *normal = glm::sign(x - centre) * outside / glm::length(outside);
        } else {
            const int axis = q.x >= q.y && q.x >= q.z ? 0 : (q.y >= q.z ? 1 : 2);
            *normal = glm::vec3(0.0f);
            (*normal)[axis] = x[axis] >= centre[axis] ? 1.0f : -1.0f;
        }
    }
    return glm::length(outside) + inside;
}

std::vector<glm::vec3> sampleObstacle(const ObstacleDef& o, const glm::vec3& origin, float spacing, float depth) {
    glm::vec3 lo = o.min, hi = o.max;
    if (o.shape == ObstacleDef::Shape::Sphere) {
        lo = o.center - glm::vec3(o.radius);
        hi = o.center + glm::vec3(o.radius);
    }
    std::vector<glm::vec3> points;
    const glm::ivec3 first(glm::floor((lo - origin) / spacing));
    const glm::ivec3 last(glm::ceil((hi - origin) / spacing));
    for (int k = first.z; k <= last.z; ++k)
        for (int j = first.y; j <= last.y; ++j)
            for (int i = first.x; i <= last.x; ++i) {
                const glm::vec3 x = origin + spacing * (glm::vec3(static_cast<float>(i), static_cast<float>(j),
                                                                   static_cast<float>(k)) + 0.5f);
                const float d = signedDistance(o, x);
                if (d <= 0.0f && d > -depth) points.push_back(x);
            }
    return points;
}

void projectOutOfObstacles(std::span<const ObstacleDef> obstacles, ParticleStore& particles, float margin,
                           int threads) {
    if (obstacles.empty()) return;
    parallelFor(particles.size(), threads, [&](std::uint32_t i) {
        for (const ObstacleDef& o : obstacles) {
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

}  // namespace tide
