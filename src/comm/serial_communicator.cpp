#include <cstdlib>
#include <stdexcept>

#include "comm/communicator.hpp"

namespace tide::comm {
namespace {

class SerialCommunicator final : public Communicator {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    std::string name() const override { return "serial"; }
    double max(double local) override { return local; }
    double min(double local) override { return local; }
    std::int64_t sum(std::int64_t local) override { return local; }
    ExactSum sum(const ExactSum& local) override { return local; }
    void sumInPlace(std::span<std::int64_t>) override {}
    std::vector<Message> exchange(std::vector<Message> outgoing) override {
        if (!outgoing.empty())
            throw std::invalid_argument("serial communicator: a message to rank " +
                                        std::to_string(outgoing.front().rank) + " (there is only rank 0)");
        return {};
    }
    std::vector<Bytes> gatherToRoot(std::span<const std::byte> local) override {
        return {Bytes(local.begin(), local.end())};
    }
    Bytes broadcastFromRoot(Bytes bytes) override { return bytes; }
    void barrier() override {}
    [[noreturn]] void abort(int code) override { std::exit(code); }
};

}  // namespace

std::unique_ptr<Communicator> makeSerialCommunicator() { return std::make_unique<SerialCommunicator>(); }

int launcherRankCount() {
    // Open MPI, MPICH/Hydra and Slurm's PMI each set one of these in every rank they start.
    for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_NTASKS"})
        if (const char* value = std::getenv(variable)) {
            const int n = std::atoi(value);
            if (n > 0) return n;
        }
    return 1;
}

bool startedByMpiLauncher() {
    for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
        if (std::getenv(variable) != nullptr) return true;
    return false;
}

#ifndef TIDE_WITH_MPI
bool mpiBuilt() { return false; }
std::unique_ptr<Communicator> makeMpiCommunicator(int*, char***) {
    throw std::runtime_error("tide was built without MPI (configure with -DTIDE_WITH_MPI=ON and libopenmpi-dev installed)");
}
#endif

}  // namespace tide::comm
