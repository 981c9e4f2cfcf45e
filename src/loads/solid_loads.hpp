#pragma once
/// \file
/// Turns the pair forces a step recorded (WallLoads) into each solid's load.
#include <cstdint>
#include <span>
#include <vector>

#include <tide/world.hpp>

#include "boundary/boundary_particles.hpp"
#include "comm/exact_sum.hpp"
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

/// The same loads as exact sums, for a run split among processes: nine accumulators a solid
/// (pressure force, viscous force and moment, x y z each), over the fluid particles whose
/// `skip` flag is 0 (a rank's own particles, not its ghosts). Exact sums add up to the same
/// bits in any order, so the loads summed over ranks do not depend on how the particles are
/// split (ExactSum, Neal 2015). `skip` may be empty (every particle counts).
std::vector<comm::ExactSum> exactSolidLoadTerms(const WallLoads& loads, const CrossNeighborList& boundaryNeighbors,
                                                const BoundaryParticles& boundary, std::uint32_t fluidCount,
                                                std::span<const std::uint8_t> skip, double dt,
                                                std::span<const glm::dvec3> references, const PeriodicBox& periodic,
                                                int threads);
/// Terms of exactSolidLoadTerms (summed over ranks) as loads.
std::vector<SolidLoad> solidLoadsOf(std::span<const comm::ExactSum> terms);

}  // namespace tide
