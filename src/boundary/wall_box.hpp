#pragma once
/// \file
/// The container: an axis-aligned box that no particle may leave. The fluid feels the
/// walls through boundary particles (see boundary_particles.hpp); this is the last line of
/// defence: after integration, particles are projected back inside (half a spacing from
/// the wall, where a lattice particle's centre sits) and lose their outward normal speed,
/// scaled by the restitution (the seed's wall collision).

#include <glm/vec3.hpp>

#include <tide/particles.hpp>

namespace tide {

struct WallBox {
    glm::vec3 min;
    glm::vec3 max;
    float margin;        ///< closest a particle centre may come to a wall, m
    float restitution;   ///< fraction of the normal speed reflected

    /// Push every particle back inside.
    void enforce(ParticleStore& particles, int threads) const;
};

}  // namespace tide
