#pragma once
/// \file
/// What each boundary particle does to each fluid particle in a step, recorded per pair so that
/// a solid's load is exactly the reaction of the forces the solver applied to the fluid
/// (Newton's third law pair by pair, as the boundary-particle coupling of Akinci et al. 2012,
/// "Versatile rigid-fluid coupling for incompressible SPH", eq. 10–11, defines the force on a
/// rigid body).
#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/scratch_resize.hpp"

namespace tide {

/// Per slot offset(i) + k of the fluid particles' boundary lists (StepContext::boundaryNeighbors),
/// what boundary particle k of fluid particle i applied to i during the step. Each fluid particle
/// writes only its own slots, so solvers record in their parallel loops without races.
struct WallLoads {
    /// N: pressure forces a solver integrates as accelerations (m_i a_ib: pcisph, wcsph, classic).
    std::vector<glm::vec3> pressureForce;
    /// N·s: pressure applied as velocity changes (m_i Δv_ib: dfsph's density and divergence solves).
    std::vector<glm::vec3> pressureImpulse;
    /// N: viscous and adhesion forces (m_i a_ib).
    std::vector<glm::vec3> viscousForce;

    /// Zeroes `slots` of each, for a new step.
    void reset(std::uint64_t slots) {
        for (std::vector<glm::vec3>* part : {&pressureForce, &pressureImpulse, &viscousForce}) {
            resizeScratch(*part, slots);
            std::fill(part->begin(), part->end(), glm::vec3(0.0f));
        }
    }
};

}  // namespace tide
