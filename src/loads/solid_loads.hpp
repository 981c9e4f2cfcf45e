#pragma once
/// \file
/// Turns the pair forces a step recorded (WallLoads) into each solid's load.
#include <cstdint>
#include <span>
#include <vector>

#include <tide/world.hpp>

#include "boundary/boundary_particles.hpp"
#include "core/periodic_box.hpp"
#include "loads/wall_loads.hpp"
#include "neighbors/neighbor_list.hpp"

namespace tide {

/// `out[s]` = the load on solid s (BoundaryParticles::solid) over a step of `dt` seconds: minus
/// the forces its boundary particles applied to the fluid, impulses divided by dt, and their
/// moment about `references[s]` at the boundary particles' positions. Sums run over fixed
/// chunks of fluid particles, in double, and the chunks add up in order: the same bits for any
/// thread count. `out` has one entry per reference.
void sumSolidLoads(const WallLoads& loads, const CrossNeighborList& boundaryNeighbors, const BoundaryParticles& boundary,
                   std::uint32_t fluidCount, double dt, std::span<const glm::dvec3> references,
                   const PeriodicBox& periodic, int threads, std::vector<SolidLoad>& out);

}  // namespace tide
