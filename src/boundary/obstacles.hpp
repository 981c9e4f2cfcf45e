#pragma once
/// \file
/// Obstacles: boxes, spheres, capped cylinders, half-spaces (planes) and closed triangle
/// meshes. Each is sampled like the container walls: the fluid's own lattice continued
/// inside the solid, kept only within a kernel support of its surface, so a particle resting
/// on it has rest density. After integration, particles that got inside are projected back
/// out through the nearest surface (a margin outside), losing their normal speed into it.
///
/// A moving obstacle (ObstacleDef::motion) keeps its shape in its rest frame: a particle is
/// tested at the rest-frame point RigidPose::toRest(x), pushed out along the rotated normal,
/// and loses only its normal speed into the obstacle relative to the obstacle's own velocity
/// there, so a pushing obstacle carries the fluid in front of it along.

#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include <tide/defs.hpp>
#include <tide/particles.hpp>

#include "boundary/rigid_motion.hpp"

namespace tide {

/// Signed distance from x to the obstacle's surface (negative inside) and the outward
/// normal (the direction in which the distance grows). Exact for every shape.
float signedDistance(const ObstacleDef& obstacle, const glm::vec3& x, glm::vec3* normal = nullptr);

/// The same for an obstacle moved to `pose` (the normal rotated with it).
float signedDistance(const ObstacleDef& obstacle, const RigidPose& pose, const glm::vec3& x, glm::vec3* normal = nullptr);

/// The shape's centre in its rest pose: a box's, sphere's or cylinder's centre, the plane's
/// point, the centre of a mesh's bounding box (where its loads' moments are taken by default).
glm::vec3 shapeCentre(const ObstacleDef& obstacle);

/// The obstacle's axis-aligned bounding box, clipped to [clipMin, clipMax] (a plane fills the clip box).
void obstacleBounds(const ObstacleDef& obstacle, const glm::vec3& clipMin, const glm::vec3& clipMax, glm::vec3& lo,
                    glm::vec3& hi);

/// How far outside a surface a lattice point may lie and still be the solid's, in spacings.
/// Surfaces through lattice points are common (round numbers); a point on one must be the
/// solid's or the fluid's by one rule, not by the rounding of each place that asks.
inline constexpr float kOnSurface = 1e-3f;

/// Lattice points origin + (k + ½)·spacing inside the obstacle (or on its surface, within
/// kOnSurface) and no deeper than `depth`, within the box [clipMin, clipMax], in a fixed
/// order for any thread count.
std::vector<glm::vec3> sampleObstacle(const ObstacleDef& obstacle, const glm::vec3& origin, float spacing, float depth,
                                      const glm::vec3& clipMin, const glm::vec3& clipMax, int threads = 1);

/// A floating box's particles: the points of its own lattice, `spacing` apart and centred on
/// the box, no deeper than `depth` inside, within [clipMin, clipMax] (an axis where the two
/// are equal, a 2D world's z, takes the one layer there), in a fixed order. On the fluid's
/// lattice a face through lattice points takes an extra row of particles that sit on it, so
/// the box acts half a spacing larger there: a 2D box of density 500 whose sides fell on
/// lattice columns floated 0.93 spacings high. Centred, the particles' envelope (half a
/// spacing outside the outermost ones) meets each face within a quarter spacing, exactly
/// where the box's sides are whole spacings. Along an axis where the box's lattice is the
/// fluid's (origin + (k + ½)·spacing) it takes the fluid's points to the bit, as
/// sampleObstacle does.
std::vector<glm::vec3> sampleBoxCentred(const ObstacleDef& box, const glm::vec3& origin, float spacing, float depth,
                                        const glm::vec3& clipMin, const glm::vec3& clipMax);

/// Push particles that entered any obstacle back out, `margin` outside its surface.
void projectOutOfObstacles(std::span<const ObstacleDef> obstacles, ParticleStore& particles, float margin, int threads);

/// Push particles that entered an obstacle at `pose` back out, `margin` outside its surface,
/// without velocity into it relative to its own.
void projectOutOfMovingObstacle(const ObstacleDef& obstacle, const RigidPose& pose, ParticleStore& particles,
                                float margin, int threads);

}  // namespace tide
