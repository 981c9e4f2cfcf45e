#include "core/world_distributed.hpp"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <span>

#include "comm/domain_split.hpp"
#include "comm/particle_records.hpp"
#include "core/field_sampling.hpp"
#include "core/world_impl.hpp"
#include "loads/solid_loads.hpp"

namespace tide {

/// Ghost depth in cells: Adami's wall pressure of a wall particle within h of an owned
/// particle sums the fluid within h of it, up to 2h from the owned one.
constexpr int kGhostCells = 2;

struct WorldDistribution final : StepSharing {
    comm::Communicator* comm = nullptr;
    std::optional<comm::DomainSplit> split;
    comm::HaloPlan halo;
    std::vector<std::uint8_t> ghost;  ///< per particle of the store: 1 for a ghost
    glm::vec3 anchor{0.0f};

    void refreshGhosts(std::span<float> field) const override { halo.refresh(field, *comm); }
    void refreshGhosts(std::span<glm::vec3> field) const override { halo.refresh(field, *comm); }
    float maxOverRanks(float local) const override { return static_cast<float>(comm->max(static_cast<double>(local))); }
    std::span<const std::uint8_t> ghosts() const override { return ghost; }
    void sumOverRanks(std::span<comm::ExactSum> sums) const override {
        constexpr std::size_t kCounters = std::tuple_size_v<comm::ExactSum::Counters>;
        std::vector<std::int64_t> counters(sums.size() * kCounters);
        for (std::size_t s = 0; s < sums.size(); ++s) {
            const comm::ExactSum::Counters c = sums[s].counters();
            std::copy(c.begin(), c.end(), counters.begin() + static_cast<std::ptrdiff_t>(s * kCounters));
        }
        comm->sumInPlace(counters);
        for (std::size_t s = 0; s < sums.size(); ++s)
            sums[s] = comm::ExactSum::fromCounters(std::span<const std::int64_t, kCounters>(counters.data() + s * kCounters, kCounters));
    }
};

namespace {

void refuse(const std::string& what) {
    throw std::invalid_argument("distributed run: " + what + " cannot be split among processes yet");
}

}  // namespace

void distributeWorld(World& world, comm::Communicator& comm) {
    World::Impl& w = *world.impl_;
    const std::string& method = w.def.solver.method;
    if (method != "wcsph" && method != "dfsph" && method != "pcisph")
        refuse("solver.method \"" + method + "\" (wcsph, dfsph and pcisph can)");
    if (!w.emitters.empty()) refuse("an emitter");
    if (w.bodySystem) refuse("a floating body");
    if (!w.paddles.empty()) refuse("a wave maker");
    if (!w.movers.empty()) refuse("a moving obstacle");
    if (w.zones) refuse("an ocean");
    if (w.periodic.any) refuse("a periodic axis");
    if (w.pairTables.anyDiffusion()) refuse("dye diffusion");

    auto d = std::make_shared<WorldDistribution>();
    d->comm = &comm;
    d->anchor = w.def.domainMin;
    comm::CellGrid grid;
    for (int a = 0; a < 3; ++a)
        grid.cells[a] = std::max(1, static_cast<int>(std::ceil((w.def.domainMax[a] - w.def.domainMin[a]) / w.h)));
    // Every rank holds every particle now: the same costs, the same partition on each.
    comm::DomainSplit probe(grid, w.def.domainMin, w.h, {comm::CellBox{{0, 0, 0}, grid.cells}}, kGhostCells);
    std::vector<std::uint64_t> cost(static_cast<std::size_t>(grid.cellCount()), 0);
    for (const glm::vec3& x : w.particles.position) ++cost[static_cast<std::size_t>(probe.cellIndexOf(x))];
    d->split.emplace(grid, w.def.domainMin, w.h, comm::partitionRcb(grid, cost, comm.size()), kGhostCells);
    std::vector<std::uint8_t> keep(w.particles.size());
    for (std::uint32_t i = 0; i < w.particles.size(); ++i)
        keep[i] = d->split->ownerOf(d->split->cellOf(w.particles.position[i])) == comm.rank() ? 1 : 0;
    w.particles.retain(keep);
    d->ghost.assign(w.particles.size(), 0);
    w.distribution = std::move(d);
}

const glm::vec3* exchangeParticles(World::Impl& w) {
    WorldDistribution& d = *w.distribution;
    std::vector<std::uint8_t> owned(d.ghost.size());
    for (std::size_t i = 0; i < owned.size(); ++i) owned[i] = d.ghost[i] ? 0 : 1;
    w.particles.retain(owned);
    comm::migrate(w.particles, *d.split, *d.comm);
    d.halo = comm::appendGhosts(w.particles, *d.split, *d.comm);
    d.halo.follow(comm::sortByCellThenId(w.particles, *d.split));
    d.ghost.assign(w.particles.size(), 0);
    for (const auto& link : d.halo.links())
        for (const std::uint32_t i : link.receive) d.ghost[i] = 1;
    return &d.anchor;
}

const StepSharing* stepSharing(const World::Impl& w) { return w.distribution.get(); }

bool isGhost(const World::Impl& w, std::uint32_t i) { return w.distribution->ghost[i] != 0; }

double sumOverRanks(const World::Impl& w, const comm::ExactSum& local) {
    return w.distribution->comm->sum(local).value();
}

std::uint64_t ownedOverRanks(const World::Impl& w) {
    const auto& ghost = w.distribution->ghost;
    const auto owned = static_cast<std::int64_t>(std::count(ghost.begin(), ghost.end(), 0));
    return static_cast<std::uint64_t>(w.distribution->comm->sum(owned));
}

std::uint64_t countOverRanks(const World::Impl& w, std::uint64_t local) {
    return static_cast<std::uint64_t>(w.distribution->comm->sum(static_cast<std::int64_t>(local)));
}

double maxOverRanks(const World::Impl& w, double local) { return w.distribution->comm->max(local); }

const std::vector<std::uint8_t>* ghostFlags(const World::Impl& w) { return &w.distribution->ghost; }

void reduceContactImpulses(World::Impl& w) {
    w.contacts.reduce([&](std::span<comm::ExactSum> sums) { w.distribution->sumOverRanks(sums); });
}

std::vector<SolidLoad> solidLoadsOverRanks(const World::Impl& w, double dt) {
    std::vector<comm::ExactSum> terms =
        exactSolidLoadTerms(w.wallLoads, w.boundaryNeighbors, w.boundary, w.particles.size(), w.distribution->ghost, dt,
                            w.solidReferences(w.time), w.periodic, w.threads);
    w.distribution->sumOverRanks(terms);
    return solidLoadsOf(terms);
}

std::vector<std::uint32_t> ownedIndices(const World& world) {
    const World::Impl& w = *world.impl_;
    std::vector<std::uint32_t> owned;
    owned.reserve(w.particles.size());
    for (std::uint32_t i = 0; i < w.particles.size(); ++i)
        if (!w.distribution || !w.distribution->ghost[i]) owned.push_back(i);
    return owned;
}

namespace {

/// `all` ordered by id.
void sortById(ParticleStore& all) {
    std::vector<std::uint32_t> order(all.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return all.id[a] < all.id[b]; });
    all.permute(order);
}

}  // namespace

ParticleStore gatherOwnedParticles(const World& world, comm::Communicator& comm) {
    const std::vector<comm::Bytes> blocks = comm.gatherToRoot(comm::packParticles(world.particles(), ownedIndices(world)));
    ParticleStore all;
    for (const comm::Bytes& b : blocks) comm::appendPacked(all, b);
    sortById(all);
    return all;
}

ParticleStore ownedParticles(const World& world) {
    ParticleStore own;
    comm::appendPacked(own, comm::packParticles(world.particles(), ownedIndices(world)));
    sortById(own);
    return own;
}

FieldSamples sampleOverRanks(const World& world, comm::Communicator& comm, std::span<const glm::vec2> gauges,
                             std::span<const glm::vec3> probes) {
    const World::Impl& w = *world.impl_;
    const float h2 = w.h * w.h;
    const auto near = [&](const glm::vec3& x) {
        for (const glm::vec2& g : gauges)
            if ((x.x - g.x) * (x.x - g.x) + (x.z - g.y) * (x.z - g.y) < h2) return true;
        for (const glm::vec3& p : probes)
            if (glm::dot(x - p, x - p) < h2) return true;
        return false;
    };
    std::vector<std::uint32_t> sent;
    for (const std::uint32_t i : ownedIndices(world))
        if (near(w.particles.position[i])) sent.push_back(i);
    const std::vector<comm::Bytes> blocks = comm.gatherToRoot(comm::packParticles(w.particles, sent));
    FieldSamples samples;
    if (comm.rank() != 0) return samples;
    ParticleStore nearby;
    for (const comm::Bytes& b : blocks) comm::appendPacked(nearby, b);
    sortById(nearby);
    for (const glm::vec2& g : gauges)
        samples.heights.push_back(freeSurfaceHeight(nearby, w.materials, w.periodic, w.kernel(), g.x, g.y));
    for (const glm::vec3& p : probes) {
        const FieldSample f = sampleField(nearby, w.materials, w.periodic, w.kernel(), p);
        samples.probes.push_back({f.density, f.pressure, f.velocity});
    }
    return samples;
}

RankCounts gatherRankCounts(const World& world, comm::Communicator& comm) {
    const std::uint64_t counts[2] = {ownedIndices(world).size(), world.particles().size()};
    const std::vector<comm::Bytes> blocks = comm.gatherToRoot(std::as_bytes(std::span(counts)));
    RankCounts report;
    for (const comm::Bytes& b : blocks) {
        std::uint64_t c[2] = {0, 0};
        std::memcpy(c, b.data(), std::min(sizeof c, b.size()));
        report.owned.push_back(c[0]);
        report.ghosts.push_back(c[1] - c[0]);
    }
    return report;
}

}  // namespace tide
