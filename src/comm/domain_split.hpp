#pragma once
/// \file
/// A run split among ranks: the global cell grid laid over the domain, the box of cells each
/// rank owns (`partitionRcb`), and the two particle movements between ranks that a step
/// needs: migration (a particle goes to the rank owning its cell) and ghosts (copies of the
/// particles within one cell of another rank's box, appended after the owned ones).
/// Cells are one kernel support wide, so the ghosts are every particle a rank's own particles
/// can see. On periodic axes the ring wraps and ghosts keep their positions: the solvers'
/// nearest-image pair vector (PeriodicBox) finds them across the seam, as it does in one process.

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <glm/vec3.hpp>

#include <tide/particles.hpp>

#include "comm/communicator.hpp"
#include "comm/partition_rcb.hpp"

namespace tide::comm {

class DomainSplit {
public:
    /// `origin` is the grid's lower corner, `cellSize` its cells' width on each axis (at least
    /// one kernel support; on a periodic axis the period over a whole number of cells, so the
    /// ring across the seam is as deep as anywhere else), `ghostCells` the depth of the ghost
    /// ring in cells (2 where walls take the pressure of the fluid around them: a wall particle
    /// within h of an owned particle sums fluid up to 2h from it).
    DomainSplit(const CellGrid& grid, const glm::vec3& origin, const glm::vec3& cellSize, std::vector<CellBox> boxes,
                int ghostCells = 1);
    /// Cubic cells.
    DomainSplit(const CellGrid& grid, const glm::vec3& origin, float cellSize, std::vector<CellBox> boxes,
                int ghostCells = 1)
        : DomainSplit(grid, origin, glm::vec3(cellSize), std::move(boxes), ghostCells) {}

    [[nodiscard]] const CellGrid& grid() const { return grid_; }
    [[nodiscard]] const glm::vec3& origin() const { return origin_; }
    [[nodiscard]] const glm::vec3& cellSize() const { return cellSize_; }
    [[nodiscard]] const std::vector<CellBox>& boxes() const { return boxes_; }
    [[nodiscard]] int ranks() const { return static_cast<int>(boxes_.size()); }

    /// The cell holding x: wrapped on periodic axes, clamped into the grid on the others
    /// (a particle a wall has not yet pushed back stays with the cell at the edge).
    [[nodiscard]] std::array<int, 3> cellOf(const glm::vec3& x) const;
    /// Index of that cell in the global grid (x fastest): the order particles are kept in.
    [[nodiscard]] std::int64_t cellIndexOf(const glm::vec3& x) const;
    [[nodiscard]] int ownerOf(const std::array<int, 3>& cell) const;
    /// True when `cell` lies in rank r's box grown by the ghost depth (wrapping on periodic axes).
    [[nodiscard]] bool inRing(int r, const std::array<int, 3>& cell) const;
    [[nodiscard]] int ghostCells() const { return ghostCells_; }
    /// Ranks other than r whose boxes touch r's box grown by the ghost depth, ascending.
    [[nodiscard]] const std::vector<int>& neighbours(int r) const { return neighbours_[static_cast<std::size_t>(r)]; }

private:
    CellGrid grid_;
    glm::vec3 origin_;
    glm::vec3 cellSize_;
    std::vector<CellBox> boxes_;
    int ghostCells_;
    std::vector<std::vector<int>> neighbours_;
};

/// Sends every particle of `store` whose cell another rank owns to that rank, keeps the rest
/// (in their order) and appends what arrives, by source rank. Collective. The store must hold
/// no ghosts.
void migrate(ParticleStore& store, const DomainSplit& split, Communicator& comm);

/// Orders the store by global cell index, then by id, so that each particle meets its
/// neighbours in the same order whichever rank holds it. Returns the permutation applied
/// (new[k] = old[order[k]]), for a HaloPlan to follow.
std::vector<std::uint32_t> sortByCellThenId(ParticleStore& store, const DomainSplit& split);

/// Where the copies of particles go between ranks: per neighbouring rank, which of this
/// rank's particles it holds ghosts of (`send`) and where its particles' ghosts sit here
/// (`receive`), both in the order of the ghost exchange, so a field is refreshed on the
/// ghosts by sending just its values.
class HaloPlan {
public:
    struct Link {
        int rank = 0;
        std::vector<std::uint32_t> send;
        std::vector<std::uint32_t> receive;
    };

    [[nodiscard]] const std::vector<Link>& links() const { return links_; }
    [[nodiscard]] std::uint32_t ghostCount() const;
    /// After the store was permuted (new[k] = old[order[k]]): the indices follow their particles.
    void follow(std::span<const std::uint32_t> order);
    /// Copies each sent particle's value of `field` (one entry per particle of the store) into
    /// its ghosts on the other ranks. Collective.
    template <class T>
    void refresh(std::span<T> field, Communicator& comm) const;

private:
    friend HaloPlan appendGhosts(ParticleStore&, const DomainSplit&, Communicator&);
    Link& linkTo(int rank);
    std::vector<Link> links_;  ///< ascending rank
};

/// Appends after the store's particles (all owned) copies of the other ranks' particles
/// within the ghost depth of this rank's box, by source rank, each source's in its own order, and
/// returns the plan that refreshes them. Collective.
HaloPlan appendGhosts(ParticleStore& store, const DomainSplit& split, Communicator& comm);

template <class T>
void HaloPlan::refresh(std::span<T> field, Communicator& comm) const {
    static_assert(std::is_trivially_copyable_v<T>);
    std::vector<Message> outgoing;
    for (const Link& link : links_) {
        if (link.send.empty()) continue;
        Bytes bytes(link.send.size() * sizeof(T));
        for (std::size_t k = 0; k < link.send.size(); ++k) std::memcpy(bytes.data() + k * sizeof(T), &field[link.send[k]], sizeof(T));
        outgoing.push_back({link.rank, std::move(bytes)});
    }
    for (const Message& m : comm.exchange(std::move(outgoing))) {
        const auto link = std::find_if(links_.begin(), links_.end(), [&](const Link& l) { return l.rank == m.rank; });
        if (link == links_.end() || m.bytes.size() != link->receive.size() * sizeof(T))
            throw std::logic_error("halo refresh: " + std::to_string(m.bytes.size()) + " bytes from rank " +
                                   std::to_string(m.rank) + " that this rank holds no such ghosts of");
        for (std::size_t k = 0; k < link->receive.size(); ++k)
            std::memcpy(&field[link->receive[k]], m.bytes.data() + k * sizeof(T), sizeof(T));
    }
}

}  // namespace tide::comm
