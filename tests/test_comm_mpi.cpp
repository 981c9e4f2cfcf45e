// The MPI communicator on 1-4 ranks (ctest starts this under mpiexec; src/comm/). Every rank
// runs the same checks; the job's exit code is the same on all ranks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "comm/communicator.hpp"

namespace {

using namespace tide::comm;

Communicator* comm = nullptr;

Bytes text(const std::string& s) {
    Bytes b(s.size());
    std::memcpy(b.data(), s.data(), s.size());
    return b;
}
std::string text(const Bytes& b) { return std::string(reinterpret_cast<const char*>(b.data()), b.size()); }

TEST(CommMpi, RanksAreTheLaunchersOnes) {
    const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
    ASSERT_NE(size, nullptr) << "run under mpiexec";
    EXPECT_EQ(comm->size(), std::stoi(size));
    EXPECT_EQ(comm->rank(), std::stoi(std::getenv("OMPI_COMM_WORLD_RANK")));
    EXPECT_EQ(comm->name(), "mpi");
}

TEST(CommMpi, ReductionsSeeEveryRank) {
    const int n = comm->size(), r = comm->rank();
    EXPECT_EQ(comm->sum(std::int64_t{r + 1}), std::int64_t{n} * (n + 1) / 2);
    EXPECT_EQ(comm->max(static_cast<double>(r)), n - 1.0);
    EXPECT_EQ(comm->min(-static_cast<double>(r)), -(n - 1.0));
}

TEST(CommMpi, ExactSumIsTheSameDoubleOnAnyNumberOfRanks) {
    // The same 40,000 terms split among the ranks (cyclically): every rank count gives the
    // bits of the one-process exact sum.
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> terms(40000);
    for (std::size_t i = 0; i < terms.size(); ++i) terms[i] = std::ldexp(u(rng), static_cast<int>(i % 61) - 30);
    ExactSum whole, mine;
    for (std::size_t i = 0; i < terms.size(); ++i) {
        whole.add(terms[i]);
        if (static_cast<int>(i % static_cast<std::size_t>(comm->size())) == comm->rank()) mine.add(terms[i]);
    }
    const ExactSum total = comm->sum(mine);
    EXPECT_EQ(total.value(), whole.value());
}

TEST(CommMpi, ExchangeDeliversSparseMessagesSortedBySource) {
    const int n = comm->size(), r = comm->rank();
    // Each rank writes to its two ring neighbours (when they are other ranks) and, if it is
    // rank 0, to everybody: a pattern where some pairs exchange nothing.
    std::vector<Message> out;
    for (int to = 0; to < n; ++to) {
        const bool ring = to == (r + 1) % n || to == (r + n - 1) % n;
        if (to == r || !(ring || r == 0)) continue;
        out.push_back({to, text(std::to_string(r) + "->" + std::to_string(to))});
    }
    const std::vector<Message> in = comm->exchange(out);
    std::vector<int> expectedSources;
    for (int from = 0; from < n; ++from) {
        const bool ring = r == (from + 1) % n || r == (from + n - 1) % n;
        if (from != r && (ring || from == 0)) expectedSources.push_back(from);
    }
    ASSERT_EQ(in.size(), expectedSources.size());
    for (std::size_t k = 0; k < in.size(); ++k) {
        EXPECT_EQ(in[k].rank, expectedSources[k]);
        EXPECT_EQ(text(in[k].bytes), std::to_string(in[k].rank) + "->" + std::to_string(r));
    }
    // An empty message is still a message.
    std::vector<Message> empty;
    if (n > 1) empty.push_back({(r + 1) % n, {}});
    const std::vector<Message> got = comm->exchange(empty);
    ASSERT_EQ(got.size(), n > 1 ? 1u : 0u);
    if (n > 1) {
        EXPECT_TRUE(got[0].bytes.empty());
    }
}

TEST(CommMpi, GatherAndBroadcastGoThroughRankZero) {
    const std::string mine(static_cast<std::size_t>(comm->rank()) * 3, static_cast<char>('a' + comm->rank()));
    const Bytes bytes = text(mine);
    const std::vector<Bytes> all = comm->gatherToRoot(bytes);
    if (comm->rank() == 0) {
        ASSERT_EQ(all.size(), static_cast<std::size_t>(comm->size()));
        for (int r = 0; r < comm->size(); ++r)
            EXPECT_EQ(text(all[r]), std::string(static_cast<std::size_t>(r) * 3, static_cast<char>('a' + r)));
    } else {
        EXPECT_TRUE(all.empty());
    }
    const Bytes root = comm->broadcastFromRoot(comm->rank() == 0 ? text("from rank 0") : Bytes{});
    EXPECT_EQ(text(root), "from rank 0");
}

}  // namespace

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    std::unique_ptr<Communicator> mpi = makeMpiCommunicator(&argc, &argv);
    comm = mpi.get();
    // Every rank runs every test; the others print only their failures.
    if (comm->rank() != 0) GTEST_FLAG_SET(brief, true);
    const int failed = RUN_ALL_TESTS() != 0 ? 1 : 0;
    // One exit code for the whole job: a failure on any rank fails every rank.
    return comm->sum(std::int64_t{failed}) > 0 ? 1 : 0;
}
