// Particles between ranks, in one process (src/comm/domain_split.hpp, particle_records.hpp):
// records that round-trip bit for bit, truncated records refused, and the one-rank case of
// migration and ghosts. The same code on 1-4 ranks is in test_comm_mpi.cpp.
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>

#include "comm/domain_split.hpp"
#include "comm/particle_records.hpp"

namespace {

using namespace tide::comm;

tide::ParticleStore someParticles(int n) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    tide::ParticleStore store;
    for (int i = 0; i < n; ++i) {
        store.append({u(rng), u(rng) * 0.5f, u(rng) * 0.3f}, {u(rng), u(rng), u(rng)}, 1e-3f + u(rng) * 1e-4f,
                     static_cast<tide::MaterialIndex>(i % 2), 1000.0f, u(rng));
        store.warmDivergence.back() = u(rng);
    }
    return store;
}

TEST(ParticleRecords, RoundTripEveryFieldBitForBit) {
    const tide::ParticleStore from = someParticles(50);
    const std::vector<std::uint32_t> pick{7, 3, 49, 0};
    const Bytes bytes = packParticles(from, pick);
    tide::ParticleStore to = someParticles(2);  // appended after what is there
    ASSERT_EQ(appendPacked(to, bytes), 4u);
    ASSERT_EQ(to.size(), 6u);
    for (std::size_t k = 0; k < pick.size(); ++k) {
        const std::uint32_t i = pick[k], j = static_cast<std::uint32_t>(2 + k);
        EXPECT_EQ(to.id[j], from.id[i]);
        EXPECT_EQ(to.position[j], from.position[i]);
        EXPECT_EQ(to.velocity[j], from.velocity[i]);
        EXPECT_EQ(to.mass[j], from.mass[i]);
        EXPECT_EQ(to.material[j], from.material[i]);
        EXPECT_EQ(to.concentration[j], from.concentration[i]);
        EXPECT_EQ(to.warmDivergence[j], from.warmDivergence[i]);
    }
    // New particles are numbered past every id that arrived.
    EXPECT_EQ(to.nextId(), 50u);
}

TEST(ParticleRecords, RefuseATruncatedRecord) {
    const tide::ParticleStore from = someParticles(3);
    const std::vector<std::uint32_t> all{0, 1, 2};
    Bytes bytes = packParticles(from, all);
    bytes.pop_back();
    tide::ParticleStore to;
    try {
        appendPacked(to, bytes);
        FAIL() << "a record one byte short was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("not a whole record of 3 particles"), std::string::npos) << e.what();
    }
    EXPECT_EQ(to.size(), 0u);
}

TEST(DomainSplit, OneRankKeepsEverythingInCellThenIdOrder) {
    tide::ParticleStore store = someParticles(400);
    const CellGrid grid{{10, 5, 3}, {true, false, false}};
    const DomainSplit split(grid, glm::vec3(0.0f), 0.1f, {CellBox{{0, 0, 0}, grid.cells}});
    const auto serial = makeSerialCommunicator();
    migrate(store, split, *serial);
    EXPECT_EQ(store.size(), 400u);
    sortByCellThenId(store, split);
    for (std::uint32_t i = 1; i < store.size(); ++i) {
        const auto a = split.cellIndexOf(store.position[i - 1]), b = split.cellIndexOf(store.position[i]);
        ASSERT_TRUE(a < b || (a == b && store.id[i - 1] < store.id[i])) << i;
    }
    // One rank has no other rank to take ghosts from (periodic images come from the pair
    // vector's nearest image, not from copies).
    EXPECT_EQ(appendGhosts(store, split, *serial).ghostCount(), 0u);
    // Outside the grid: wrapped on the periodic axis, clamped on the others.
    EXPECT_EQ(split.cellOf({-0.05f, 7.0f, -1.0f}), (std::array<int, 3>{9, 4, 0}));
}

}  // namespace
