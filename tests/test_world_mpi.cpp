// A World split among 1-4 ranks (src/core/world_distributed.hpp) steps exactly as on one:
// a dam break's particles, bit for bit, its time steps and its pressure iterations, for each
// solver (classic, wcsph, pcisph, dfsph, pbf). ctest starts this under
// mpiexec; rank 0 also runs the split World on a one-process communicator as the reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <string>
#include <memory>
#include <vector>

#include "comm/communicator.hpp"
#include "core/world_distributed.hpp"

namespace {

using namespace tide;

comm::Communicator* mpi = nullptr;

struct RunResult {
    ParticleStore particles;  ///< on rank 0, by id
    std::vector<double> steps;
    std::vector<int> iterations;  ///< the pressure solve's, per step
    std::uint32_t held = 0;   ///< this rank's particles at the end, owned and ghosts
    std::vector<glm::dvec3> loads;  ///< every solid's force, per step
    std::uint64_t rebalances = 0;   ///< re-cuts that moved a box
};

void expectSameParticles(const ParticleStore& a, const ParticleStore& b) {
    ASSERT_EQ(a.id, b.id);
    const std::size_t n = a.size();
    EXPECT_EQ(std::memcmp(a.position.data(), b.position.data(), n * sizeof(glm::vec3)), 0);
    EXPECT_EQ(std::memcmp(a.velocity.data(), b.velocity.data(), n * sizeof(glm::vec3)), 0);
    EXPECT_EQ(std::memcmp(a.density.data(), b.density.data(), n * sizeof(float)), 0);
}

/// Called with the World once split and after every step (collective).
using StepCheck = std::function<void(const World&)>;

RunResult damBreak(comm::Communicator& comm, const std::string& method, int steps, const DistributionOptions& options = {},
                   const StepCheck& check = {}) {
    // A 0.2 m column in a 0.6 x 0.4 x 0.08 m tank at 1 cm (3,200 particles), with a block in its path.
    WorldDef def;
    def.solver.method = method;
    def.domainMax = {0.6f, 0.4f, 0.08f};
    def.particleSpacing = 0.01f;
    def.threads = 1;
    World world(def);
    world.addMaterial(MaterialDef{});
    ObstacleDef block;
    block.min = {0.3f, 0.0f, 0.0f};
    block.max = {0.35f, 0.06f, 0.08f};
    block.name = "block";
    world.addObstacle(block);
    world.addBlock({{0.0f, 0.0f, 0.0f}, {0.2f, 0.2f, 0.08f}, {0.0f, 0.0f, 0.0f}, 0});
    distributeWorld(world, comm, options);
    if (check) check(world);
    RunResult run;
    for (int s = 0; s < steps; ++s) {
        run.steps.push_back(world.step(1.0));
        if (check) check(world);
        run.iterations.push_back(world.stats().lastPressureIterations);
        for (const SolidLoad& load : world.solidLoads()) run.loads.push_back(load.force());
    }
    run.held = world.particles().size();
    run.particles = gatherOwnedParticles(world, comm);
    run.rebalances = gatherRankCounts(world, comm).rebalances;
    return run;
}

class WorldMpi : public testing::TestWithParam<const char*> {};

TEST_P(WorldMpi, DamBreakIsBitIdenticalOnAnyNumberOfRanks) {
    // The iterative solvers take longer steps: fewer of them reach the same flow (pcisph's
    // impact steps take up to ~140 iterations and halvings: 15 of them).
    const std::string method = GetParam();
    const int steps = method == "wcsph" ? 120 : method == "classic" ? 200 : method == "dfsph" || method == "pbf" ? 40 : 15;
    const RunResult split = damBreak(*mpi, method, steps);
    // Really split: with several ranks each holds only part of the water, plus ghosts.
    const std::int64_t total = mpi->sum(std::int64_t{mpi->rank() == 0 ? split.particles.size() : 0u});
    const std::int64_t held = mpi->sum(std::int64_t{split.held});
    if (mpi->size() > 1) {
        EXPECT_LT(split.held, total);
        EXPECT_GT(held, total);
    }
    const auto serial = comm::makeSerialCommunicator();
    if (mpi->rank() != 0) return;
    const RunResult one = damBreak(*serial, method, steps);
    ASSERT_EQ(split.particles.size(), one.particles.size());
    EXPECT_GT(one.particles.size(), 500u);
    EXPECT_EQ(split.steps, one.steps);
    EXPECT_EQ(split.iterations, one.iterations);
    // Every solid's load, every step, to the bit (exact sums over the ranks' own particles).
    ASSERT_EQ(split.loads.size(), one.loads.size());
    for (std::size_t k = 0; k < one.loads.size(); ++k)
        ASSERT_EQ(split.loads[k], one.loads[k]) << "solid " << k % (one.loads.size() / one.steps.size()) << " at step " << k / (one.loads.size() / one.steps.size());
    if (method != "wcsph" && method != "classic") {  // the explicit two have no pressure iterations
        EXPECT_GT(*std::max_element(one.iterations.begin(), one.iterations.end()), 1);
    }
    const std::size_t n = one.particles.size();
    EXPECT_EQ(split.particles.id, one.particles.id);
    EXPECT_EQ(std::memcmp(split.particles.position.data(), one.particles.position.data(), n * sizeof(glm::vec3)), 0);
    EXPECT_EQ(std::memcmp(split.particles.velocity.data(), one.particles.velocity.data(), n * sizeof(glm::vec3)), 0);
    EXPECT_EQ(std::memcmp(split.particles.density.data(), one.particles.density.data(), n * sizeof(float)), 0);
    // The column has fallen: the comparison is of a flow, not of water at rest.
    float fastest = 0.0f;
    for (const glm::vec3& v : one.particles.velocity) fastest = std::max(fastest, glm::length(v));
    EXPECT_GT(fastest, 0.3f);
}

TEST(WorldMpiRebalance, CuttingTheBoxesAgainEveryFiveStepsLosesNothingAndChangesNothing) {
    // Acceptance 3 of issue 47: migration and re-cutting forced every 5 steps. Every step the
    // particle count, the ids and the total mass are exact; the end equals a run that never re-cut.
    DistributionOptions never;
    never.rebalanceAbove = 1e9;
    const RunResult plain = damBreak(*mpi, "dfsph", 80, never);
    std::vector<std::uint32_t> ids;
    double mass = 0.0;
    int checkedSteps = 0;
    const StepCheck check = [&](const World& world) {
        const ParticleStore all = gatherOwnedParticles(world, *mpi);
        ++checkedSteps;
        if (mpi->rank() != 0) return;
        double m = 0.0;
        for (const float mi : all.mass) m += mi;  // in id order: the same sum every step
        if (ids.empty()) {
            ids = all.id;
            mass = m;
            return;
        }
        ASSERT_EQ(all.id, ids) << "step " << checkedSteps;
        ASSERT_EQ(m, mass) << "step " << checkedSteps;
    };
    DistributionOptions every5;
    every5.rebalanceEvery = 5;
    const RunResult recut = damBreak(*mpi, "dfsph", 80, every5, check);
    EXPECT_EQ(checkedSteps, 81);  // the start and every step
    // The column's fall moves the water between boxes: the cuts really move.
    if (mpi->size() > 1) {
        EXPECT_GE(recut.rebalances, 1u) << "of 16 re-cuts";
    }
    EXPECT_EQ(plain.rebalances, 0u);
    if (mpi->rank() != 0) return;
    EXPECT_GT(ids.size(), 500u);
    EXPECT_EQ(recut.steps, plain.steps);
    EXPECT_EQ(recut.iterations, plain.iterations);
    expectSameParticles(recut.particles, plain.particles);
}

TEST(WorldMpiRebalance, RefusesBadOptionsNamingThem) {
    WorldDef def;
    def.domainMax = {0.2f, 0.2f, 0.2f};
    World world(def);
    world.addMaterial(MaterialDef{});
    world.addBlock({{0.0f, 0.0f, 0.0f}, {0.1f, 0.1f, 0.1f}, {0.0f, 0.0f, 0.0f}, 0});
    const auto serial = comm::makeSerialCommunicator();
    DistributionOptions bad;
    bad.rebalanceEvery = -1;
    EXPECT_THROW(
        try { distributeWorld(world, *serial, bad); } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("rebalance every"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("-1"), std::string::npos) << e.what();
            throw;
        },
        std::invalid_argument);
    bad = {};
    bad.rebalanceAbove = 0.5;
    EXPECT_THROW(distributeWorld(world, *serial, bad), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Solvers, WorldMpi, testing::Values("wcsph", "dfsph", "pcisph", "classic", "pbf"));

}  // namespace

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    std::unique_ptr<comm::Communicator> communicator = comm::makeMpiCommunicator(&argc, &argv);
    mpi = communicator.get();
    if (mpi->rank() != 0) GTEST_FLAG_SET(brief, true);
    const int failed = RUN_ALL_TESTS() != 0 ? 1 : 0;
    return mpi->sum(std::int64_t{failed}) > 0 ? 1 : 0;
}
