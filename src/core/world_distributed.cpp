#include "core/world_distributed.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
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
    DistributionOptions options;
    int stepsSinceCut = 0;
    double imbalanceAfterCut = 1.0;  ///< max/mean owned particles the last cut left
    double imbalanceNow = 1.0;       ///< as dueForRecut measured it
    std::uint64_t recuts = 0;        ///< re-cuts that moved a box

    /// Whether the boxes are cut again before this step's migration: the same answer on
    /// every rank (from reductions). `owned` is this rank's particle count.
    bool dueForRecut(std::uint32_t owned);
    /// Cuts the boxes again from where the owned particles are now (collective): rank 0
    /// gathers every rank's particles per cell, partitions, and sends the boxes round.
    void recut(const ParticleStore& owned);

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

/// The ranks' boxes for these per-cell particle counts. A scene that starts empty (its water
/// comes from emitters) is cut by cells, every cell counting one, and re-cut by its water as it
/// arrives. Throws, naming the counts, where the water fills fewer cells than there are ranks or
/// the grid has fewer cells than ranks.
std::vector<comm::CellBox> cutBoxes(const comm::CellGrid& grid, std::vector<std::uint64_t> cost, int ranks) {
    if (std::all_of(cost.begin(), cost.end(), [](std::uint64_t c) { return c == 0; }))
        std::fill(cost.begin(), cost.end(), std::uint64_t{1});
    return comm::partitionRcb(grid, cost, ranks);
}

}  // namespace

bool WorldDistribution::dueForRecut(std::uint32_t owned) {
    ++stepsSinceCut;
    if (comm->size() == 1) return false;
    if (options.rebalanceEvery > 0 && stepsSinceCut >= options.rebalanceEvery) return true;
    const double most = comm->max(static_cast<double>(owned));
    const double total = static_cast<double>(comm->sum(std::int64_t{owned}));
    const double imbalance = total > 0.0 ? most * comm->size() / total : 1.0;
    imbalanceNow = imbalance;
    return imbalance > options.rebalanceAbove && imbalance > 1.05 * imbalanceAfterCut;
}

void WorldDistribution::recut(const ParticleStore& owned) {
    stepsSinceCut = 0;
    const comm::CellGrid grid = split->grid();  // a copy: the split is replaced below
    // Sparse counts: (cell index, particles) for the cells this rank's particles are in.
    std::vector<std::int64_t> cells(owned.size());
    for (std::uint32_t i = 0; i < owned.size(); ++i) cells[i] = split->cellIndexOf(owned.position[i]);
    std::sort(cells.begin(), cells.end());
    std::vector<std::int64_t> counts;
    for (std::size_t i = 0; i < cells.size();) {
        std::size_t j = i;
        while (j < cells.size() && cells[j] == cells[i]) ++j;
        counts.push_back(cells[i]);
        counts.push_back(static_cast<std::int64_t>(j - i));
        i = j;
    }
    const std::vector<comm::Bytes> blocks = comm->gatherToRoot(std::as_bytes(std::span(counts)));
    // Rank 0's answer: the imbalance the boxes leave, then the boxes (none: keep the old ones).
    comm::Bytes answer;
    if (comm->rank() == 0) {
        std::vector<std::uint64_t> cost(static_cast<std::size_t>(grid.cellCount()), 0);
        for (const comm::Bytes& b : blocks) {
            std::vector<std::int64_t> pairs(b.size() / sizeof(std::int64_t));
            std::memcpy(pairs.data(), b.data(), pairs.size() * sizeof(std::int64_t));
            for (std::size_t k = 0; k + 1 < pairs.size(); k += 2) cost[static_cast<std::size_t>(pairs[k])] += static_cast<std::uint64_t>(pairs[k + 1]);
        }
        try {
            const std::vector<comm::CellBox> boxes = cutBoxes(grid, cost, comm->size());
            const double imbalance = comm::loadImbalance(comm::rankLoads(grid, cost, boxes, split->ghostCells()));
            answer.resize(sizeof imbalance + boxes.size() * sizeof(comm::CellBox));
            std::memcpy(answer.data(), &imbalance, sizeof imbalance);
            std::memcpy(answer.data() + sizeof imbalance, boxes.data(), boxes.size() * sizeof(comm::CellBox));
        } catch (const std::invalid_argument&) {
            // The water gathered where fewer boxes than ranks can hold it: keep the cut.
        }
    }
    answer = comm->broadcastFromRoot(std::move(answer));
    if (answer.empty()) {
        imbalanceAfterCut = imbalanceNow;  // the best there is: try again when it drifts further
        return;
    }
    std::memcpy(&imbalanceAfterCut, answer.data(), sizeof imbalanceAfterCut);
    std::vector<comm::CellBox> boxes((answer.size() - sizeof(double)) / sizeof(comm::CellBox));
    std::memcpy(boxes.data(), answer.data() + sizeof(double), boxes.size() * sizeof(comm::CellBox));
    const bool moved = !std::equal(boxes.begin(), boxes.end(), split->boxes().begin(), split->boxes().end(),
                                   [](const comm::CellBox& a, const comm::CellBox& b) { return a.lo == b.lo && a.hi == b.hi; });
    if (!moved) return;
    const glm::vec3 origin = split->origin();
    const glm::vec3 cellSize = split->cellSize();
    const int ghostCells = split->ghostCells();
    split.emplace(grid, origin, cellSize, std::move(boxes), ghostCells);
    ++recuts;
}

namespace {

void refuse(const std::string& what) {
    throw std::invalid_argument("distributed run: " + what + " cannot be split among processes yet");
}

}  // namespace

void distributeWorld(World& world, comm::Communicator& comm, const DistributionOptions& options) {
    World::Impl& w = *world.impl_;
    if (options.rebalanceEvery < 0)
        throw std::invalid_argument("rebalance every: must be 0 (by load) or a number of steps, got " +
                                    std::to_string(options.rebalanceEvery));
    if (!(options.rebalanceAbove >= 1.0))
        throw std::invalid_argument("rebalance above: a load imbalance (max/mean) must be at least 1, got " +
                                    std::to_string(options.rebalanceAbove));
    const std::string& method = w.def.solver.method;
    // The solvers that refresh their ghosts (StepContext::refreshGhosts) where a neighbour reads.
    if (method != "wcsph" && method != "dfsph" && method != "pcisph" && method != "classic" && method != "pbf")
        refuse("solver.method \"" + method + "\" (classic, wcsph, pcisph, dfsph and pbf can)");

    auto d = std::make_shared<WorldDistribution>();
    d->comm = &comm;
    d->options = options;
    d->anchor = w.def.domainMin;
    // Cells a support wide; on a periodic axis the period in whole cells (at least a support
    // wide each), so that the ghost ring reaches as far across the seam as elsewhere.
    comm::CellGrid grid;
    glm::vec3 cellSize(w.h);
    for (int a = 0; a < 3; ++a) {
        const float length = w.def.domainMax[a] - w.def.domainMin[a];
        grid.periodic[static_cast<std::size_t>(a)] = w.periodic.periodic(a);
        if (w.periodic.periodic(a)) {
            grid.cells[a] = std::max(1, static_cast<int>(std::floor(length / w.h)));
            cellSize[a] = length / static_cast<float>(grid.cells[a]);
        } else {
            grid.cells[a] = std::max(1, static_cast<int>(std::ceil(length / w.h)));
        }
    }
    // Every rank holds every particle now: the same costs, the same partition on each.
    comm::DomainSplit probe(grid, w.def.domainMin, cellSize, {comm::CellBox{{0, 0, 0}, grid.cells}}, kGhostCells);
    std::vector<std::uint64_t> cost(static_cast<std::size_t>(grid.cellCount()), 0);
    for (const glm::vec3& x : w.particles.position) ++cost[static_cast<std::size_t>(probe.cellIndexOf(x))];
    d->split.emplace(grid, w.def.domainMin, cellSize, cutBoxes(grid, cost, comm.size()), kGhostCells);
    d->imbalanceAfterCut = comm::loadImbalance(comm::rankLoads(grid, cost, d->split->boxes(), kGhostCells));
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
    if (d.dueForRecut(w.particles.size())) d.recut(w.particles);
    comm::migrate(w.particles, *d.split, *d.comm);
    d.halo = comm::appendGhosts(w.particles, *d.split, *d.comm);
    d.halo.follow(comm::sortByCellThenId(w.particles, *d.split));
    d.ghost.assign(w.particles.size(), 0);
    for (const auto& link : d.halo.links())
        for (const std::uint32_t i : link.receive) d.ghost[i] = 1;
    return &d.anchor;
}

void keepOwnedFrom(World::Impl& w, std::uint32_t first) {
    WorldDistribution& d = *w.distribution;
    const int self = d.comm->rank();
    std::vector<std::uint8_t> keep(w.particles.size(), 1);
    for (std::uint32_t i = first; i < w.particles.size(); ++i)
        keep[i] = d.split->ownerOf(d.split->cellOf(w.particles.position[i])) == self ? 1 : 0;
    w.particles.retain(keep);  // the particles before `first` (and the halo's indices) stay
    d.ghost.resize(w.particles.size(), 0);
}

void coupleOverRanks(World::Impl& w, double end) {
    WorldDistribution& d = *w.distribution;
    comm::Communicator& comm = *d.comm;
    const int self = comm.rank();
    // Outflow: particles and their ghost flags retained together (the step's statistics and
    // emitters read the flags by index); only owned particles count as removed.
    std::vector<std::uint8_t> keep(w.particles.size(), 1);
    std::int64_t removed = 0;
    for (std::uint32_t i = 0; i < w.particles.size(); ++i)
        if (w.zones->outside(w.particles.position[i])) {
            keep[i] = 0;
            removed += d.ghost[i] ? 0 : 1;
        }
    if (std::find(keep.begin(), keep.end(), std::uint8_t{0}) != keep.end()) {
        w.particles.retain(keep);
        std::vector<std::uint8_t> ghost;
        ghost.reserve(w.particles.size());
        for (std::size_t i = 0; i < keep.size(); ++i)
            if (keep[i]) ghost.push_back(d.ghost[i]);
        d.ghost = std::move(ghost);
    }
    w.stats.oceanRemoved += static_cast<std::uint64_t>(comm.sum(removed));
    // Inflow: this rank's cells only, judged against its particles and ghosts.
    const std::uint32_t first = w.particles.size();
    const std::uint32_t base = w.particles.nextId();
    std::vector<std::uint64_t> visits;
    const std::vector<WaveMaker::Face> faces = w.paddleFaces();
    w.zones->refill(
        w.particles, end, w.oceanLevelError(end), w.oceanMass(), w.oceanMaterial, w.materials[w.oceanMaterial].restDensity,
        std::numeric_limits<std::uint32_t>::max(),
        [&](const glm::vec3& x) { return d.split->ownerOf(d.split->cellOf(x)) == self && w.roomFor(x, World::Impl::Fill::Block, faces); },
        w.threads, &visits);
    d.ghost.resize(w.particles.size(), 0);
    // Every rank's added points in visiting order: the ids one process would give them.
    const std::vector<comm::Bytes> blocks = comm.gatherToRoot(std::as_bytes(std::span(visits)));
    comm::Bytes all;
    if (self == 0)
        for (const comm::Bytes& b : blocks) all.insert(all.end(), b.begin(), b.end());
    all = comm.broadcastFromRoot(std::move(all));
    std::vector<std::uint64_t> order(all.size() / sizeof(std::uint64_t));
    std::memcpy(order.data(), all.data(), order.size() * sizeof(std::uint64_t));
    std::sort(order.begin(), order.end());
    // At most the capacity, the first in that order kept (as one process stops adding).
    const std::uint64_t held = ownedOverRanks(w) - order.size();  // every rank's, before this inflow
    const std::uint64_t room = w.def.capacity > held ? w.def.capacity - held : 0;
    std::vector<std::uint8_t> kept(w.particles.size(), 1);
    bool dropped = false;
    for (std::size_t k = 0; k < visits.size(); ++k) {
        const auto at = static_cast<std::uint64_t>(std::lower_bound(order.begin(), order.end(), visits[k]) - order.begin());
        w.particles.id[first + k] = base + static_cast<std::uint32_t>(at);
        if (at >= room) {
            kept[first + k] = 0;
            dropped = true;
        }
    }
    const std::uint64_t added = std::min<std::uint64_t>(order.size(), room);
    if (dropped) {
        w.particles.retain(kept);
        d.ghost.resize(w.particles.size(), 0);
    }
    w.particles.setNextId(base + static_cast<std::uint32_t>(added));
    w.stats.oceanAdded += added;
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

namespace {

std::vector<std::uint32_t> ownedIndicesOf(const World::Impl& w) {
    std::vector<std::uint32_t> owned;
    owned.reserve(w.particles.size());
    for (std::uint32_t i = 0; i < w.particles.size(); ++i)
        if (!w.distribution || !w.distribution->ghost[i]) owned.push_back(i);
    return owned;
}

}  // namespace

std::vector<std::uint32_t> ownedIndices(const World& world) { return ownedIndicesOf(*world.impl_); }

void sortById(ParticleStore& all) {
    std::vector<std::uint32_t> order(all.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return all.id[a] < all.id[b]; });
    all.permute(order);
}

namespace {

/// The owned particles of every rank for which `near` holds, on rank 0 ordered by id (empty
/// on the others). Collective.
template <class Near>
ParticleStore gatherNear(const World::Impl& w, comm::Communicator& comm, const Near& near) {
    const ParticleStore& particles = w.particles;
    std::vector<std::uint32_t> sent;
    for (const std::uint32_t i : ownedIndicesOf(w))
        if (near(particles.position[i])) sent.push_back(i);
    const std::vector<comm::Bytes> blocks = comm.gatherToRoot(comm::packParticles(particles, sent));
    ParticleStore nearby;
    for (const comm::Bytes& b : blocks) comm::appendPacked(nearby, b);
    sortById(nearby);
    return nearby;
}

}  // namespace

float surfaceHeightOverRanks(const World::Impl& w, float x, float z) {
    comm::Communicator& comm = *w.distribution->comm;
    const float h2 = w.h * w.h;
    const ParticleStore nearby =
        gatherNear(w, comm, [&](const glm::vec3& p) { return (p.x - x) * (p.x - x) + (p.z - z) * (p.z - z) < h2; });
    float height = 0.0f;
    if (comm.rank() == 0) height = freeSurfaceHeight(nearby, w.materials, w.periodic, w.kernel(), x, z);
    comm::Bytes bytes(sizeof height);
    std::memcpy(bytes.data(), &height, sizeof height);
    bytes = comm.broadcastFromRoot(std::move(bytes));
    std::memcpy(&height, bytes.data(), sizeof height);
    return height;
}

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
    const ParticleStore nearby = gatherNear(w, comm, near);
    FieldSamples samples;
    if (comm.rank() != 0) return samples;
    for (const glm::vec2& g : gauges) {
        // As World::surfaceHeight: outside an ocean's near field, the far field's surface.
        const bool farField = w.zones && (g.x < w.def.domainMin.x || g.x > w.def.domainMax.x ||
                                          g.y < w.def.domainMin.z || g.y > w.def.domainMax.z);
        samples.heights.push_back(farField ? static_cast<float>(world.oceanSurfaceHeight(g.x, g.y))
                                           : freeSurfaceHeight(nearby, w.materials, w.periodic, w.kernel(), g.x, g.y));
    }
    for (const glm::vec3& p : probes) {
        const FieldSample f = sampleField(nearby, w.materials, w.periodic, w.kernel(), p);
        samples.probes.push_back({f.density, f.pressure, f.velocity});
    }
    return samples;
}

RankCounts gatherRankCounts(const World& world, comm::Communicator& comm) {
    const comm::Traffic traffic = comm.traffic();
    const std::uint64_t counts[4] = {ownedIndices(world).size(), world.particles().size(), traffic.bytes, traffic.messages};
    const std::vector<comm::Bytes> blocks = comm.gatherToRoot(std::as_bytes(std::span(counts)));
    RankCounts report;
    for (const comm::Bytes& b : blocks) {
        std::uint64_t c[4] = {0, 0, 0, 0};
        std::memcpy(c, b.data(), std::min(sizeof c, b.size()));
        report.owned.push_back(c[0]);
        report.ghosts.push_back(c[1] - c[0]);
        report.bytesSent.push_back(c[2]);
        report.messagesSent.push_back(c[3]);
    }
    const WorldDistribution* d = world.impl_->distribution.get();
    report.rebalances = d ? d->recuts : 0;
    return report;
}

}  // namespace tide
