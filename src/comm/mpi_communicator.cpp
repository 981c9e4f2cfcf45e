// The one file that calls MPI (compiled only with TIDE_WITH_MPI).
#include <mpi.h>

#include <climits>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "comm/communicator.hpp"

namespace tide::comm {
namespace {

/// MPI is initialised once per process and finalised at exit, after every communicator.
struct MpiSession {
    MpiSession(int* argc, char*** argv) {
        int initialised = 0;
        MPI_Initialized(&initialised);
        if (!initialised) {
            int provided = 0;
            // Funneled: only the thread that steps the World calls MPI; OpenMP workers never do.
            MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
            owns = true;
        }
        // A failing call ends the whole job (the default on MPI_COMM_WORLD; made explicit).
        MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_ARE_FATAL);
    }
    ~MpiSession() {
        int finalised = 0;
        MPI_Finalized(&finalised);
        if (owns && !finalised) MPI_Finalize();
    }
    bool owns = false;
};

int checkedCount(std::size_t bytes, const char* what) {
    if (bytes > static_cast<std::size_t>(INT_MAX))
        throw std::length_error(std::string("mpi communicator: ") + what + " of " + std::to_string(bytes) +
                                " bytes exceeds MPI's int count");
    return static_cast<int>(bytes);
}

class MpiCommunicator final : public Communicator {
public:
    MpiCommunicator() {
        MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
        MPI_Comm_size(MPI_COMM_WORLD, &size_);
    }
    int rank() const override { return rank_; }
    int size() const override { return size_; }
    std::string name() const override { return "mpi"; }

    double max(double local) override {
        double global = 0.0;
        MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
        return global;
    }
    double min(double local) override {
        double global = 0.0;
        MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
        return global;
    }
    std::int64_t sum(std::int64_t local) override {
        std::int64_t global = 0;
        MPI_Allreduce(&local, &global, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
        return global;
    }
    ExactSum sum(const ExactSum& local) override {
        // Carried counters are below 2^32 (the top one small): their integer sum over ranks
        // cannot overflow and does not depend on the order MPI adds them in.
        const ExactSum::Counters mine = local.counters();
        ExactSum::Counters all{};
        MPI_Allreduce(mine.data(), all.data(), static_cast<int>(mine.size()), MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
        return ExactSum::fromCounters(all);
    }

    void sumInPlace(std::span<std::int64_t> values) override {
        if (values.size() > static_cast<std::size_t>(INT_MAX))
            throw std::length_error("mpi communicator: a sum of " + std::to_string(values.size()) + " values");
        MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
    }

    std::vector<Message> exchange(std::vector<Message> outgoing) override {
        std::vector<long long> sendBytes(static_cast<std::size_t>(size_), 0), recvBytes(static_cast<std::size_t>(size_), 0);
        for (const Message& m : outgoing) {
            if (m.rank < 0 || m.rank >= size_ || m.rank == rank_)
                throw std::invalid_argument("mpi communicator: a message from rank " + std::to_string(rank_) +
                                            " to rank " + std::to_string(m.rank) + " of " + std::to_string(size_));
            sendBytes[static_cast<std::size_t>(m.rank)] = static_cast<long long>(m.bytes.size()) + 1;  // +1: "a message"
            countSent(m.bytes.size());
        }
        MPI_Alltoall(sendBytes.data(), 1, MPI_LONG_LONG, recvBytes.data(), 1, MPI_LONG_LONG, MPI_COMM_WORLD);
        std::vector<Message> incoming;
        std::vector<MPI_Request> requests;
        for (int source = 0; source < size_; ++source) {
            const long long n = recvBytes[static_cast<std::size_t>(source)];
            if (n == 0) continue;
            incoming.push_back(Message{source, Bytes(static_cast<std::size_t>(n - 1))});
        }
        requests.reserve(incoming.size() + outgoing.size());
        constexpr int kTag = 17;
        for (Message& m : incoming) {
            requests.emplace_back();
            MPI_Irecv(m.bytes.data(), checkedCount(m.bytes.size(), "a message"), MPI_BYTE, m.rank, kTag,
                      MPI_COMM_WORLD, &requests.back());
        }
        for (const Message& m : outgoing) {
            requests.emplace_back();
            MPI_Isend(m.bytes.data(), checkedCount(m.bytes.size(), "a message"), MPI_BYTE, m.rank, kTag,
                      MPI_COMM_WORLD, &requests.back());
        }
        MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
        return incoming;  // sorted by source: built in rank order
    }

    std::vector<Bytes> gatherToRoot(std::span<const std::byte> local) override {
        const int mine = checkedCount(local.size(), "a gathered block");
        std::vector<int> counts(rank_ == 0 ? static_cast<std::size_t>(size_) : 0);
        MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
        std::vector<int> offsets(counts.size(), 0);
        std::size_t total = 0;
        for (std::size_t r = 0; r < counts.size(); ++r) {
            offsets[r] = checkedCount(total, "a gather");
            total += static_cast<std::size_t>(counts[r]);
        }
        checkedCount(total, "a gather");
        Bytes all(total);
        MPI_Gatherv(local.data(), mine, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, 0, MPI_COMM_WORLD);
        std::vector<Bytes> blocks;
        for (std::size_t r = 0; r < counts.size(); ++r)
            blocks.emplace_back(all.begin() + offsets[r], all.begin() + offsets[r] + counts[r]);
        return blocks;
    }

    Bytes broadcastFromRoot(Bytes bytes) override {
        long long n = static_cast<long long>(bytes.size());
        MPI_Bcast(&n, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
        bytes.resize(static_cast<std::size_t>(n));
        MPI_Bcast(bytes.data(), checkedCount(bytes.size(), "a broadcast"), MPI_BYTE, 0, MPI_COMM_WORLD);
        return bytes;
    }

    void barrier() override { MPI_Barrier(MPI_COMM_WORLD); }
    [[noreturn]] void abort(int code) override {
        MPI_Abort(MPI_COMM_WORLD, code);
        std::exit(code);  // not reached: MPI_Abort ends the job
    }

private:
    int rank_ = 0;
    int size_ = 1;
};

}  // namespace

bool mpiBuilt() { return true; }

std::unique_ptr<Communicator> makeMpiCommunicator(int* argc, char*** argv) {
    static MpiSession session(argc, argv);
    return std::make_unique<MpiCommunicator>();
}

}  // namespace tide::comm
