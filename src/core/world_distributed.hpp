#pragma once
/// \file
/// A World split among processes (issue 47; docs/notes/mpi.md). Every rank builds the same
/// World from the same definitions, then `distributeWorld` keeps on each rank the particles of
/// its box of cells (comm::partitionRcb over the domain's cells, one kernel support wide,
/// weighted by particles). Each step then drops the ghosts, migrates particles to their
/// owners, takes new ghosts two cells deep, orders everything by (cell, id) and anchors the
/// neighbour grid at the domain's corner, so that every particle meets its neighbours in the
/// same order, and sums the same, on any number of ranks; the solver refreshes ghost fields
/// through StepContext::sharing. What is split so far: wcsph, dfsph and pcisph with walls and fixed obstacles;
/// anything else is refused when the World is distributed.

#include <tide/particles.hpp>
#include <tide/world.hpp>

#include "comm/communicator.hpp"

namespace tide {

/// Splits `world` among the ranks of `comm` (collective; every rank passes a World built from
/// the same definitions). Throws std::invalid_argument naming what cannot be split yet.
void distributeWorld(World& world, comm::Communicator& comm);

/// The particles every rank owns, gathered on rank 0 and ordered by id (the other ranks get
/// an empty store). Collective.
ParticleStore gatherOwnedParticles(const World& world, comm::Communicator& comm);

}  // namespace tide
