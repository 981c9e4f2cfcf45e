#pragma once
/// \file
/// A World split among processes (issue 47; docs/notes/mpi.md). Every rank builds the same
/// World from the same definitions, then `distributeWorld` keeps on each rank the particles of
/// its box of cells (comm::partitionRcb over the domain's cells, one kernel support wide,
/// weighted by particles). Each step then drops the ghosts, migrates particles to their
/// owners, takes new ghosts two cells deep, orders everything by (cell, id) and anchors the
/// neighbour grid at the domain's corner, so that every particle meets its neighbours in the
/// same order, and sums the same, on any number of ranks; the solver refreshes ghost fields
/// through StepContext::sharing. Walls, obstacles, paddles and bodies are boundary particles
/// every rank holds and moves alike; their loads are exact sums over the ranks, so bodies move
/// the same everywhere. Emitters emit on every rank and each keeps what falls in its box.
/// Gauges and probes: sampleOverRanks; checkpoints: World::saveState keeps the owned
/// particles. An ocean's inflow: each rank fills its own cells, ids in the one-process order
/// (coupleOverRanks).

#include <span>

#include <glm/vec2.hpp>

#include <tide/particles.hpp>
#include <tide/world.hpp>

#include "comm/communicator.hpp"

namespace tide {

/// When the boxes are cut again as the water moves. Re-cutting changes which rank steps a
/// particle, never the result: a rebalanced run equals one that never rebalanced, bit for bit.
struct DistributionOptions {
    /// Re-cut every this many steps whatever the load (0: only when the load drifts).
    int rebalanceEvery = 0;
    /// Re-cut when the busiest rank owns this many times the mean number of particles, and
    /// more than 1.05 times the imbalance the last cut left (boxes of whole cells cannot
    /// always do better; this stops re-cutting to no gain).
    double rebalanceAbove = 1.2;
};

/// Splits `world` among the ranks of `comm` (collective; every rank passes a World built from
/// the same definitions). Throws std::invalid_argument naming what cannot be split yet or a
/// bad option.
void distributeWorld(World& world, comm::Communicator& comm, const DistributionOptions& options = {});

/// The particles every rank owns, gathered on rank 0 and ordered by id (the other ranks get
/// an empty store). Collective.
ParticleStore gatherOwnedParticles(const World& world, comm::Communicator& comm);

/// The indices of the particles this rank owns (all of them in a World not split).
std::vector<std::uint32_t> ownedIndices(const World& world);

/// `all` ordered by id (the order of a gathered frame and of a joined checkpoint).
void sortById(ParticleStore& all);

/// This rank's own particles (not its ghosts), ordered by id: its piece of a frame.
ParticleStore ownedParticles(const World& world);

/// Wave gauges and probes of a split World: World::surfaceHeight at each gauge's (x, z) and
/// World::probe at each point, over every rank's particles. Each rank sends rank 0 the
/// particles it owns within a support of a gauge's vertical line or a probe's point; rank 0
/// evaluates them ordered by id, so the values are the same on any number of ranks (the other
/// ranks get empty lists). Collective.
struct FieldSamples {
    std::vector<float> heights;       ///< m; NaN for a dry gauge
    std::vector<ProbeSample> probes;  ///< NaN where no fluid is within a support
};
FieldSamples sampleOverRanks(const World& world, comm::Communicator& comm, std::span<const glm::vec2> gauges,
                             std::span<const glm::vec3> probes);

/// Particles each rank owns and the ghosts it holds now, and the bytes and messages it has
/// sent in exchanges so far, on rank 0 (the others get empty lists); how often the boxes
/// were cut again. Collective.
struct RankCounts {
    std::vector<std::uint64_t> owned, ghosts, bytesSent, messagesSent;
    std::uint64_t rebalances = 0;  ///< re-cuts that moved a box
};
RankCounts gatherRankCounts(const World& world, comm::Communicator& comm);

}  // namespace tide
