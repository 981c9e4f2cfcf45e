#pragma once
/// \file
/// A body's pose as the RigidPose that moving obstacles use (src/boundary/rigid_motion.hpp),
/// so a dynamic obstacle's boundary particles, strays and signed distances go through the
/// same code as a prescribed motion's: pivot = the centre of mass now, center = at rest.

#include <tide/bodies.hpp>

#include "boundary/rigid_motion.hpp"

namespace tide::bodies {

inline RigidPose poseOf(const RigidBody& body) {
    RigidPose p;
    p.rotation = glm::mat3(body.rotation());
    p.center = glm::vec3(body.massProperties().centerOfMass);
    p.pivot = glm::vec3(body.position());
    p.velocity = glm::vec3(body.velocity());
    p.acceleration = glm::vec3(body.acceleration());
    p.omega = glm::vec3(body.angularVelocity());
    p.alpha = glm::vec3(body.angularAcceleration());
    return p;
}

}  // namespace tide::bodies
