// The MPI communicator on 1-4 ranks (ctest starts this under mpiexec; src/comm/). Every rank
// runs the same checks; the job's exit code is the same on all ranks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "comm/communicator.hpp"
#include "comm/domain_split.hpp"
#include "comm/particle_records.hpp"

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


TEST(CommMpi, IntegerSumsInPlace) {
    std::vector<std::int64_t> v{1, comm->rank(), -2};
    comm->sumInPlace(v);
    const std::int64_t n = comm->size();
    EXPECT_EQ(v, (std::vector<std::int64_t>{n, n * (n - 1) / 2, -2 * n}));
}

/// 3000 particles scattered over a 1 x 0.5 x 0.6 m domain with cells of 0.1 m, the same on
/// every rank (one seed), each with its own velocity, mass, warm starts and dye.
tide::ParticleStore scatteredParticles() {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    tide::ParticleStore store;
    for (int i = 0; i < 3000; ++i) {
        // Denser towards x = 0, so the cost-balanced boxes differ in size.
        const glm::vec3 x(u(rng) * u(rng) * 0.999f, u(rng) * 0.499f, u(rng) * 0.599f);
        store.append(x, glm::vec3(u(rng), -u(rng), 0.5f), 1e-3f * (1.0f + u(rng)), static_cast<tide::MaterialIndex>(i % 3),
                     1000.0f + u(rng), u(rng));
        store.warmKappa.back() = u(rng);
        store.pressure.back() = 100.0f * u(rng);
    }
    return store;
}

/// Chebyshev distance in cells from `cell` to the box, across periodic seams.
int cellsToBox(const std::array<int, 3>& cell, const CellBox& box, const CellGrid& grid) {
    int worst = 0;
    for (int a = 0; a < 3; ++a) {
        int best = 1 << 20;
        for (int shift : {-1, 0, 1}) {
            if (shift != 0 && !grid.periodic[a]) continue;
            const int c = cell[a] + shift * grid.cells[a];
            best = std::min(best, c < box.lo[a] ? box.lo[a] - c : (c >= box.hi[a] ? c - box.hi[a] + 1 : 0));
        }
        worst = std::max(worst, best);
    }
    return worst;
}

TEST(CommMpi, MigrationAndGhostsMoveExactlyTheRightParticles) {
    const tide::ParticleStore all = scatteredParticles();
    for (const bool periodicX : {false, true}) {
        SCOPED_TRACE(periodicX ? "periodic in x" : "walls");
        const CellGrid grid{{10, 5, 6}, {periodicX, false, false}};
        // Costs: particles per cell, each rank counting only the ones it starts with.
        const int n = comm->size(), self = comm->rank();
        tide::ParticleStore mine;
        std::vector<std::uint32_t> start;
        for (std::uint32_t i = 0; i < all.size(); ++i)
            if (static_cast<int>(i % static_cast<std::uint32_t>(n)) == self) start.push_back(i);
        const Bytes packed = packParticles(all, start);
        tide::comm::appendPacked(mine, packed);
        DomainSplit probe(grid, glm::vec3(0.0f), 0.1f, {CellBox{{0, 0, 0}, grid.cells}});
        std::vector<std::int64_t> perCell(static_cast<std::size_t>(grid.cellCount()), 0);
        for (std::uint32_t i = 0; i < mine.size(); ++i) ++perCell[static_cast<std::size_t>(probe.cellIndexOf(mine.position[i]))];
        comm->sumInPlace(perCell);
        const std::vector<std::uint64_t> cost(perCell.begin(), perCell.end());
        const DomainSplit split(grid, glm::vec3(0.0f), 0.1f, partitionRcb(grid, cost, n));

        migrate(mine, split, *comm);
        sortByCellThenId(mine, split);
        // Every particle is now with the owner of its cell, bit for bit as it was made.
        for (std::uint32_t i = 0; i < mine.size(); ++i) {
            ASSERT_EQ(split.ownerOf(split.cellOf(mine.position[i])), self);
            const std::uint32_t id = mine.id[i];
            EXPECT_EQ(mine.position[i], all.position[id]);
            EXPECT_EQ(mine.velocity[i], all.velocity[id]);
            EXPECT_EQ(mine.mass[i], all.mass[id]);
            EXPECT_EQ(mine.warmKappa[i], all.warmKappa[id]);
            EXPECT_EQ(mine.concentration[i], all.concentration[id]);
            EXPECT_EQ(mine.material[i], all.material[id]);
            if (i > 0) {
                const auto before = split.cellIndexOf(mine.position[i - 1]), here = split.cellIndexOf(mine.position[i]);
                EXPECT_TRUE(before < here || (before == here && mine.id[i - 1] < mine.id[i]));
            }
        }
        // Nothing lost or doubled: the count, the set of ids and the mass are exact.
        EXPECT_EQ(comm->sum(std::int64_t{mine.size()}), std::int64_t{all.size()});
        std::vector<std::byte> idBytes(mine.size() * sizeof(std::uint32_t));
        std::memcpy(idBytes.data(), mine.id.data(), idBytes.size());
        const std::vector<Bytes> ids = comm->gatherToRoot(idBytes);
        if (self == 0) {
            std::vector<std::uint32_t> seen;
            for (const Bytes& b : ids) {
                const std::size_t k = seen.size();
                seen.resize(k + b.size() / sizeof(std::uint32_t));
                std::memcpy(seen.data() + k, b.data(), b.size());
            }
            std::sort(seen.begin(), seen.end());
            std::vector<std::uint32_t> expected(all.size());
            std::iota(expected.begin(), expected.end(), 0u);
            EXPECT_EQ(seen, expected);
        }
        ExactSum massHere, massAll;
        for (const float m : mine.mass) massHere.add(m);
        for (const float m : all.mass) massAll.add(m);
        EXPECT_EQ(comm->sum(massHere).value(), massAll.value());

        // Ghosts: exactly the other ranks' particles within one cell of this rank's box.
        const std::uint32_t owned = mine.size();
        HaloPlan plan = appendGhosts(mine, split, *comm);
        const std::uint32_t ghosts = plan.ghostCount();
        ASSERT_EQ(mine.size(), owned + ghosts);
        std::set<std::uint32_t> expected;
        for (std::uint32_t i = 0; i < all.size(); ++i) {
            const auto cell = split.cellOf(all.position[i]);
            if (split.ownerOf(cell) != self && cellsToBox(cell, split.boxes()[static_cast<std::size_t>(self)], grid) <= 1)
                expected.insert(i);
        }
        const std::set<std::uint32_t> got(mine.id.begin() + owned, mine.id.end());
        EXPECT_EQ(got.size(), ghosts) << "a ghost arrived twice";
        EXPECT_EQ(got, expected);
        for (std::uint32_t i = owned; i < mine.size(); ++i) EXPECT_EQ(mine.position[i], all.position[mine.id[i]]);
        if (n == 1) {
            EXPECT_EQ(ghosts, 0u);
        }

        // Sorted again with the ghosts among the owned particles, as a step orders them, the
        // plan follows; a refresh then copies each owner's new values onto its ghosts.
        plan.follow(sortByCellThenId(mine, split));
        std::vector<std::uint8_t> isGhost(mine.size(), 0);
        for (const auto& link : plan.links())
            for (const std::uint32_t i : link.receive) isGhost[i] = 1;
        for (std::uint32_t i = 0; i < mine.size(); ++i) {
            mine.pressure[i] = isGhost[i] ? -1.0f : 0.5f * static_cast<float>(mine.id[i]);
            mine.velocity[i] = isGhost[i] ? glm::vec3(-1.0f) : glm::vec3(static_cast<float>(mine.id[i]), 1.0f, 2.0f);
        }
        plan.refresh(std::span<float>(mine.pressure), *comm);
        plan.refresh(std::span<glm::vec3>(mine.velocity), *comm);
        for (std::uint32_t i = 0; i < mine.size(); ++i) {
            EXPECT_EQ(mine.pressure[i], 0.5f * static_cast<float>(mine.id[i])) << (isGhost[i] ? "ghost " : "owned ") << i;
            EXPECT_EQ(mine.velocity[i].x, static_cast<float>(mine.id[i]));
        }
    }
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
