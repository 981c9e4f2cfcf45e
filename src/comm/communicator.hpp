#pragma once
/// \file
/// What the solvers and the World need from the processes they run on, and nothing more:
/// reductions that do not depend on the number of ranks, point-to-point exchanges of bytes
/// (ghost layers, migrating particles), gathers to rank 0 (frames, statistics) and a
/// job-wide abort. Two implementations: one process (`makeSerialCommunicator`, always
/// built) and MPI (`makeMpiCommunicator`, with TIDE_WITH_MPI). Code outside src/comm never
/// calls MPI itself.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "comm/exact_sum.hpp"

namespace tide::comm {

using Bytes = std::vector<std::byte>;

/// Bytes for, or from, another rank.
struct Message {
    int rank = 0;
    Bytes bytes;
};

/// What a rank has sent to other ranks through `exchange` (migration, ghosts, ghost
/// refreshes): the traffic a step costs. Reductions, gathers and broadcasts are not counted.
struct Traffic {
    std::uint64_t bytes = 0;
    std::uint64_t messages = 0;
};

class Communicator {
public:
    virtual ~Communicator() = default;

    [[nodiscard]] const Traffic& traffic() const { return traffic_; }

    [[nodiscard]] virtual int rank() const = 0;
    [[nodiscard]] virtual int size() const = 0;
    /// "serial" or "mpi".
    [[nodiscard]] virtual std::string name() const = 0;

    /// Over all ranks. Min and max do not depend on order; sums of integers are exact.
    virtual double max(double local) = 0;
    virtual double min(double local) = 0;
    virtual std::int64_t sum(std::int64_t local) = 0;
    /// The exact sum of every rank's accumulator, the same on every rank (ExactSum::value
    /// then gives the same double whatever the number of ranks).
    virtual ExactSum sum(const ExactSum& local) = 0;
    /// Element-wise sums of integers over all ranks, in place (e.g. particles per cell, for
    /// the partitioner's costs).
    virtual void sumInPlace(std::span<std::int64_t> values) = 0;

    /// Each rank sends `outgoing` (at most one message per destination, none to itself) and
    /// receives what the others sent it, sorted by source rank. Collective: every rank calls
    /// it, also with nothing to send.
    virtual std::vector<Message> exchange(std::vector<Message> outgoing) = 0;
    /// Rank 0 receives every rank's bytes, in rank order; the others receive nothing.
    virtual std::vector<Bytes> gatherToRoot(std::span<const std::byte> local) = 0;
    /// Rank 0's bytes on every rank.
    virtual Bytes broadcastFromRoot(Bytes bytes) = 0;
    virtual void barrier() = 0;

    /// Ends every rank of the job with `code` (a failing rank must never leave the others
    /// waiting in a collective).
    [[noreturn]] virtual void abort(int code) = 0;

protected:
    void countSent(std::size_t bytes) {
        traffic_.bytes += bytes;
        ++traffic_.messages;
    }

private:
    Traffic traffic_;
};

/// One process: rank 0 of 1.
std::unique_ptr<Communicator> makeSerialCommunicator();

/// True when tide was built with MPI (TIDE_WITH_MPI).
bool mpiBuilt();

/// The MPI communicator over MPI_COMM_WORLD: initialises MPI (MPI_THREAD_FUNNELED: OpenMP
/// threads never call it) on first use and finalises it at exit. Throws std::runtime_error
/// when tide was built without MPI.
std::unique_ptr<Communicator> makeMpiCommunicator(int* argc, char*** argv);

/// The number of processes an MPI launcher (mpirun/mpiexec, Slurm) started this one among, as
/// it tells them in the environment: 1 for a process started on its own.
int launcherRankCount();

/// Whether an MPI launcher (mpirun/mpiexec of Open MPI, or MPICH's Hydra) started this process,
/// with any number of ranks, 1 included (Slurm's variables alone do not say so: a batch
/// script's plain command has them too).
bool startedByMpiLauncher();

}  // namespace tide::comm
