#pragma once
/// \file
/// Mooring line loads on a body (MooringDef): the force at the fairlead for its current
/// position and velocity, and a line's stiffness for choosing a stable sub-step.

#include <string>

#include <tide/bodies.hpp>

namespace tide::bodies {

/// Throws std::invalid_argument naming `path` and the field at fault.
void validateMooring(const MooringDef& def, const std::string& path);

/// The line's tension and its force on the body; `up` is the unit vertical (against gravity).
MooringReading mooringLoad(const MooringDef& def, const glm::dvec3& fairlead, const glm::dvec3& fairleadVelocity,
                           const glm::dvec3& up);

/// An upper bound of the line's axial stiffness dT/dℓ, N/m, and its damping, N s/m.
double mooringStiffness(const MooringDef& def);
double mooringDamping(const MooringDef& def);

}  // namespace tide::bodies
