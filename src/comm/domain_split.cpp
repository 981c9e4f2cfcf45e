#include "comm/domain_split.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "comm/particle_records.hpp"

namespace tide::comm {
namespace {

/// Distance in cells from c to [lo, hi) on an axis of n cells (0 inside).
int gapTo(int c, int lo, int hi, int n, bool periodic) {
    auto gap = [&](int v) { return v < lo ? lo - v : (v >= hi ? v - hi + 1 : 0); };
    return periodic ? std::min({gap(c), gap(c - n), gap(c + n)}) : gap(c);
}

/// Smallest |x - y| between cells x in [blo, bhi) and y in [clo, chi).
int intervalDistance(int blo, int bhi, int clo, int chi) { return std::max({0, clo - bhi + 1, blo - chi + 1}); }

}  // namespace

DomainSplit::DomainSplit(const CellGrid& grid, const glm::vec3& origin, const glm::vec3& cellSize, std::vector<CellBox> boxes,
                         int ghostCells)
    : grid_(grid), origin_(origin), cellSize_(cellSize), boxes_(std::move(boxes)), ghostCells_(ghostCells),
      neighbours_(boxes_.size()) {
    for (int a = 0; a < 3; ++a)
        if (!(cellSize[a] > 0.0f))
            throw std::invalid_argument("domain split: cell size must be positive, got " + std::to_string(cellSize[a]) +
                                        " on axis " + std::to_string(a));
    if (ghostCells < 1) throw std::invalid_argument("domain split: ghost depth must be at least 1 cell, got " + std::to_string(ghostCells));
    for (std::size_t r = 0; r < boxes_.size(); ++r)
        for (std::size_t o = 0; o < boxes_.size(); ++o) {
            bool touch = o != r;
            for (int a = 0; a < 3 && touch; ++a) {
                const CellBox &b = boxes_[r], &c = boxes_[o];
                const int n = grid_.cells[a];
                int distance = intervalDistance(b.lo[a], b.hi[a], c.lo[a], c.hi[a]);
                if (grid_.periodic[a])
                    distance = std::min({distance, intervalDistance(b.lo[a], b.hi[a], c.lo[a] - n, c.hi[a] - n),
                                         intervalDistance(b.lo[a], b.hi[a], c.lo[a] + n, c.hi[a] + n)});
                touch = distance <= ghostCells_;
            }
            if (touch) neighbours_[r].push_back(static_cast<int>(o));
        }
}

std::array<int, 3> DomainSplit::cellOf(const glm::vec3& x) const {
    std::array<int, 3> cell{};
    for (int a = 0; a < 3; ++a) {
        const int n = grid_.cells[a];
        const double t = std::floor(static_cast<double>(x[a] - origin_[a]) / cellSize_[a]);
        const int c = std::isfinite(t) ? static_cast<int>(std::clamp(t, -1e9, 1e9)) : 0;
        cell[a] = grid_.periodic[a] ? ((c % n) + n) % n : std::clamp(c, 0, n - 1);
    }
    return cell;
}

std::int64_t DomainSplit::cellIndexOf(const glm::vec3& x) const {
    const auto c = cellOf(x);
    return grid_.index(c[0], c[1], c[2]);
}

int DomainSplit::ownerOf(const std::array<int, 3>& cell) const {
    for (std::size_t r = 0; r < boxes_.size(); ++r) {
        const CellBox& b = boxes_[r];
        if (cell[0] >= b.lo[0] && cell[0] < b.hi[0] && cell[1] >= b.lo[1] && cell[1] < b.hi[1] && cell[2] >= b.lo[2] &&
            cell[2] < b.hi[2])
            return static_cast<int>(r);
    }
    throw std::logic_error("domain split: a cell no rank owns");
}

bool DomainSplit::inRing(int r, const std::array<int, 3>& cell) const {
    const CellBox& b = boxes_[static_cast<std::size_t>(r)];
    for (int a = 0; a < 3; ++a)
        if (gapTo(cell[a], b.lo[a], b.hi[a], grid_.cells[a], grid_.periodic[a]) > ghostCells_) return false;
    return true;
}

void migrate(ParticleStore& store, const DomainSplit& split, Communicator& comm) {
    const int self = comm.rank();
    std::vector<std::vector<std::uint32_t>> leaving(static_cast<std::size_t>(comm.size()));
    std::vector<std::uint8_t> keep(store.size(), 1);
    for (std::uint32_t i = 0; i < store.size(); ++i) {
        const int owner = split.ownerOf(split.cellOf(store.position[i]));
        if (owner == self) continue;
        leaving[static_cast<std::size_t>(owner)].push_back(i);
        keep[i] = 0;
    }
    std::vector<Message> outgoing;
    for (int r = 0; r < comm.size(); ++r)
        if (!leaving[static_cast<std::size_t>(r)].empty())
            outgoing.push_back({r, packParticles(store, leaving[static_cast<std::size_t>(r)])});
    store.retain(keep);
    for (const Message& m : comm.exchange(std::move(outgoing))) appendPacked(store, m.bytes);
}

std::vector<std::uint32_t> sortByCellThenId(ParticleStore& store, const DomainSplit& split) {
    std::vector<std::int64_t> cell(store.size());
    for (std::uint32_t i = 0; i < store.size(); ++i) cell[i] = split.cellIndexOf(store.position[i]);
    std::vector<std::uint32_t> order(store.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return cell[a] != cell[b] ? cell[a] < cell[b] : store.id[a] < store.id[b];
    });
    store.permute(order);
    return order;
}

std::uint32_t HaloPlan::ghostCount() const {
    std::size_t n = 0;
    for (const Link& link : links_) n += link.receive.size();
    return static_cast<std::uint32_t>(n);
}

HaloPlan::Link& HaloPlan::linkTo(int rank) {
    auto at = std::lower_bound(links_.begin(), links_.end(), rank, [](const Link& l, int r) { return l.rank < r; });
    if (at == links_.end() || at->rank != rank) at = links_.insert(at, Link{rank, {}, {}});
    return *at;
}

void HaloPlan::follow(std::span<const std::uint32_t> order) {
    std::vector<std::uint32_t> newIndex(order.size());
    for (std::uint32_t k = 0; k < order.size(); ++k) newIndex[order[k]] = k;
    for (Link& link : links_) {
        for (std::uint32_t& i : link.send) i = newIndex[i];
        for (std::uint32_t& i : link.receive) i = newIndex[i];
    }
}

HaloPlan appendGhosts(ParticleStore& store, const DomainSplit& split, Communicator& comm) {
    const int self = comm.rank();
    const std::vector<int>& candidates = split.neighbours(self);
    std::vector<std::vector<std::uint32_t>> toSend(candidates.size());
    for (std::uint32_t i = 0; i < store.size(); ++i) {
        const auto cell = split.cellOf(store.position[i]);
        for (std::size_t k = 0; k < candidates.size(); ++k)
            if (split.inRing(candidates[k], cell)) toSend[k].push_back(i);
    }
    HaloPlan plan;
    std::vector<Message> outgoing;
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        if (toSend[k].empty()) continue;
        outgoing.push_back({candidates[k], packParticles(store, toSend[k])});
        plan.linkTo(candidates[k]).send = std::move(toSend[k]);
    }
    for (const Message& m : comm.exchange(std::move(outgoing))) {
        const std::uint32_t first = store.size();
        const std::uint32_t count = appendPacked(store, m.bytes);
        std::vector<std::uint32_t>& receive = plan.linkTo(m.rank).receive;
        for (std::uint32_t k = 0; k < count; ++k) receive.push_back(first + k);
    }
    return plan;
}

}  // namespace tide::comm
