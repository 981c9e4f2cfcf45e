#include "loads/solid_loads.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

#include "core/parallel.hpp"

namespace tide {

namespace {
/// Fluid particles a chunk sums: fixed, so the grouping of the sums never depends on threads.
constexpr std::uint32_t kChunk = 2048;

/// What the solid of boundary particle b takes from its pair with a fluid particle, slot `slot`:
/// the reaction of what b applied to the fluid (impulses divided by the step), and its moment.
struct PairLoad {
    glm::dvec3 pressure, viscous, moment;
};
PairLoad pairLoadOf(const WallLoads& loads, std::uint64_t slot, double perSecond, const glm::vec3& at,
                    const glm::dvec3& reference, const PeriodicBox& periodic) {
    PairLoad l;
    l.pressure = -(glm::dvec3(loads.pressureForce[slot]) + perSecond * glm::dvec3(loads.pressureImpulse[slot]));
    l.viscous = -glm::dvec3(loads.viscousForce[slot]);
    l.moment = glm::cross(glm::dvec3(periodic.delta(at, glm::vec3(reference))), l.pressure + l.viscous);
    return l;
}
}  // namespace

void sumSolidLoads(const WallLoads& loads, const CrossNeighborList& boundaryNeighbors, const BoundaryParticles& boundary,
                   std::uint32_t fluidCount, double dt, std::span<const glm::dvec3> references,
                   const PeriodicBox& periodic, int threads, std::vector<SolidLoad>& out) {
    const std::size_t solids = references.size();
    out.assign(solids, SolidLoad{});
    if (fluidCount == 0 || solids == 0 || !(dt > 0.0)) return;
    const std::uint32_t chunks = (fluidCount + kChunk - 1) / kChunk;
    std::vector<SolidLoad> partial(static_cast<std::size_t>(chunks) * solids);
    const double perSecond = 1.0 / dt;
    parallelFor(chunks, threads, [&](std::uint32_t c) {
        SolidLoad* sums = partial.data() + static_cast<std::size_t>(c) * solids;
        const std::uint32_t end = std::min(fluidCount, (c + 1) * kChunk);
        for (std::uint32_t i = c * kChunk; i < end; ++i) {
            const auto walls = boundaryNeighbors.of(i);
            const std::uint64_t slot = boundaryNeighbors.offset(i);
            for (std::size_t k = 0; k < walls.size(); ++k) {
                const std::uint32_t b = walls[k];
                const std::uint16_t s = boundary.solid[b];
                if (s >= solids) continue;
                const PairLoad pair = pairLoadOf(loads, slot + k, perSecond, boundary.position[b], references[s], periodic);
                SolidLoad& load = sums[s];
                load.pressureForce += pair.pressure;
                load.viscousForce += pair.viscous;
                load.moment += pair.moment;
            }
        }
    });
    for (std::uint32_t c = 0; c < chunks; ++c)
        for (std::size_t s = 0; s < solids; ++s) {
            const SolidLoad& part = partial[static_cast<std::size_t>(c) * solids + s];
            out[s].pressureForce += part.pressureForce;
            out[s].viscousForce += part.viscousForce;
            out[s].moment += part.moment;
        }
}

std::vector<comm::ExactSum> exactSolidLoadTerms(const WallLoads& loads, const CrossNeighborList& boundaryNeighbors,
                                                const BoundaryParticles& boundary, std::uint32_t fluidCount,
                                                std::span<const std::uint8_t> skip, double dt,
                                                std::span<const glm::dvec3> references, const PeriodicBox& periodic,
                                                int threads) {
    constexpr std::size_t kTerms = 9;
    const std::size_t solids = references.size();
    std::vector<comm::ExactSum> total(solids * kTerms);
    if (fluidCount == 0 || solids == 0 || !(dt > 0.0)) return total;
    const std::uint32_t chunks = (fluidCount + kChunk - 1) / kChunk;
    std::vector<comm::ExactSum> partial(static_cast<std::size_t>(chunks) * solids * kTerms);
    const double perSecond = 1.0 / dt;
    parallelFor(chunks, threads, [&](std::uint32_t c) {
        comm::ExactSum* sums = partial.data() + static_cast<std::size_t>(c) * solids * kTerms;
        const std::uint32_t end = std::min(fluidCount, (c + 1) * kChunk);
        for (std::uint32_t i = c * kChunk; i < end; ++i) {
            if (!skip.empty() && skip[i]) continue;
            const auto walls = boundaryNeighbors.of(i);
            const std::uint64_t slot = boundaryNeighbors.offset(i);
            for (std::size_t k = 0; k < walls.size(); ++k) {
                const std::uint32_t b = walls[k];
                const std::uint16_t s = boundary.solid[b];
                if (s >= solids) continue;
                // sumSolidLoads' terms, each added exactly.
                const PairLoad pair = pairLoadOf(loads, slot + k, perSecond, boundary.position[b], references[s], periodic);
                comm::ExactSum* solid = sums + static_cast<std::size_t>(s) * kTerms;
                for (int a = 0; a < 3; ++a) {
                    solid[a].add(pair.pressure[a]);
                    solid[3 + a].add(pair.viscous[a]);
                    solid[6 + a].add(pair.moment[a]);
                }
            }
        }
    });
    for (std::uint32_t c = 0; c < chunks; ++c)
        for (std::size_t t = 0; t < solids * kTerms; ++t) total[t].merge(partial[static_cast<std::size_t>(c) * solids * kTerms + t]);
    return total;
}

std::vector<SolidLoad> solidLoadsOf(std::span<const comm::ExactSum> terms) {
    std::vector<SolidLoad> out(terms.size() / 9);
    for (std::size_t s = 0; s < out.size(); ++s)
        for (int a = 0; a < 3; ++a) {
            out[s].pressureForce[a] = terms[9 * s + static_cast<std::size_t>(a)].value();
            out[s].viscousForce[a] = terms[9 * s + 3 + static_cast<std::size_t>(a)].value();
            out[s].moment[a] = terms[9 * s + 6 + static_cast<std::size_t>(a)].value();
        }
    return out;
}

}  // namespace tide
