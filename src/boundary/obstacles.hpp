#pragma once
/// \file
/// Fixed obstacles (boxes, spheres). Each is sampled like the container walls: the fluid's
/// own lattice continued inside the solid, kept only within a kernel support of its
/// surface, so a particle resting on it has rest density. After integration, particles that
/// got inside are projected back out through the nearest surface (half a spacing outside),
/// losing their inward normal speed.

#include <vector>

#include <glm/vec3.hpp>

#include <tide/defs.hpp>
#include <tide/particles.hpp>

namespace tide {

/// Signed distance from x to the obstacle's surface (negative inside) and the outward normal.
float signedDistance(const ObstacleDef& obstacle, const glm::vec3& x, glm::vec3* normal = nullptr);

/// Lattice points (min-aligned at `origin` + (k + ½)·spacing) inside the obstacle, no deeper than `depth`.
std::vector<glm::vec3> sampleObstacle(const ObstacleDef& obstacle, const glm::vec3& origin, float spacing, float depth);

/// Push particles that entered any obstacle back out, `margin` outside its surface.
void projectOutOfObstacles(std::span<const ObstacleDef> obstacles, ParticleStore& particles, float margin, int threads);

}  // namespace tide
