#pragma once
/// \file
/// Damping zone (sponge layer) that absorbs waves at the end of a flume: after each step the
/// velocity of a particle at x is relaxed towards zero,
///   v ← v · max(0, 1 − β Δt s²),   s = (x − x_start)/(x_end − x_start) clamped to [0, 1],
/// a factor rising quadratically along the zone so that waves entering it are not reflected
/// by a sudden change (Altomare, Domínguez, Crespo, González-Cao, Suzuki, Gómez-Gesteira &
/// Troch 2017, "Long-crested wave generation and absorption for SPH-based DualSPHysics
/// model", Coastal Engineering 127, §2.4; the sponge layer idea after Clément 1996).
/// Beyond x_end the damping stays at its full strength.

#include <span>

#include <tide/defs.hpp>
#include <tide/particles.hpp>

namespace tide {

/// Applies every zone to the particles' velocities after a step of length dt.
void applyDampingZones(std::span<const DampingZoneDef> zones, ParticleStore& particles, double dt, int threads);

}  // namespace tide
