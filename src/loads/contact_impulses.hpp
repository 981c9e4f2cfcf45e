#pragma once
/// \file
/// The momentum the projections after a step take from strays (World::step: walls, obstacles
/// and paddles push particles back out and remove their speed into the solid), booked to the
/// solid that pushed, so that loads close the fluid's momentum balance.
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/geometric.hpp>

#include <tide/particles.hpp>
#include <tide/world.hpp>

#include "comm/exact_sum.hpp"
#include "core/parallel.hpp"
#include "core/periodic_box.hpp"

namespace tide {

class ContactImpulses {
public:
    /// Starts a step's booking: remembers the velocities, and where each solid's moments are taken.
    /// In a run split among processes `ghosts` flags the particles this rank does not own: they
    /// are not booked, and the impulses are summed exactly (ExactSum), so that reduce() gives the
    /// same bits on any number of ranks.
    void begin(const ParticleStore& p, std::span<const glm::dvec3> references, const PeriodicBox& periodic,
               const std::vector<std::uint8_t>* ghosts = nullptr) {
        before_.assign(p.velocity.begin(), p.velocity.end());
        references_.assign(references.begin(), references.end());
        periodic_ = periodic;
        totals_.assign(references.size(), SolidLoad{});
        ghosts_ = ghosts;
        exact_.assign(ghosts ? references.size() * kTerms : 0, comm::ExactSum{});
    }

    /// Books every velocity changed since the last call, m_i Δv_i given to the fluid, to solid
    /// `solidOf(i, Δv_i)`. Fixed chunks summed in order: the same bits for any thread count.
    template <class SolidOf>
    void book(const ParticleStore& p, int threads, SolidOf&& solidOf) {
        const std::size_t solids = totals_.size();
        const auto n = p.size();
        const std::uint32_t chunks = (n + kChunk - 1) / kChunk;
        if (ghosts_) {
            bookExactly(p, threads, solidOf);
            return;
        }
        partial_.assign(static_cast<std::size_t>(chunks) * solids, SolidLoad{});
        parallelFor(chunks, threads, [&](std::uint32_t c) {
            SolidLoad* sums = partial_.data() + static_cast<std::size_t>(c) * solids;
            for (std::uint32_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i) {
                const glm::vec3 dv = p.velocity[i] - before_[i];
                if (dv == glm::vec3(0.0f)) continue;
                before_[i] = p.velocity[i];
                const std::uint16_t s = solidOf(i, dv);
                if (s >= solids) continue;
                const glm::dvec3 impulse = impulseOf(p, i, dv);
                sums[s].pressureForce += impulse;
                sums[s].moment += momentOf(p, i, s, impulse);
            }
        });
        for (std::uint32_t c = 0; c < chunks; ++c)
            for (std::size_t s = 0; s < solids; ++s) {
                totals_[s].pressureForce += partial_[static_cast<std::size_t>(c) * solids + s].pressureForce;
                totals_[s].moment += partial_[static_cast<std::size_t>(c) * solids + s].moment;
            }
    }

    /// A split run's totals, summed over the ranks by `sumOverRanks` (StepSharing's), before finish().
    template <class SumOverRanks>
    void reduce(SumOverRanks&& sumOverRanks) {
        if (!ghosts_) return;
        sumOverRanks(std::span<comm::ExactSum>(exact_));
        for (std::size_t s = 0; s < totals_.size(); ++s)
            for (int a = 0; a < 3; ++a) {
                totals_[s].pressureForce[a] = exact_[kTerms * s + static_cast<std::size_t>(a)].value();
                totals_[s].moment[a] = exact_[kTerms * s + 3 + static_cast<std::size_t>(a)].value();
            }
    }

    /// Adds the booked impulses' reaction, as forces over the step of `dt` seconds, to the
    /// step's loads (as pressure: contact is normal) and their impulse to the running sums.
    void finish(double dt, std::vector<SolidLoad>& step, std::vector<SolidLoad>& impulses) const {
        if (!(dt > 0.0)) return;
        step.resize(totals_.size());
        impulses.resize(totals_.size());
        for (std::size_t s = 0; s < totals_.size(); ++s) {
            step[s].pressureForce -= totals_[s].pressureForce / dt;
            step[s].moment -= totals_[s].moment / dt;
            impulses[s].pressureForce -= totals_[s].pressureForce;
            impulses[s].moment -= totals_[s].moment;
        }
    }

private:
    static constexpr std::uint32_t kChunk = 2048;
    static constexpr std::size_t kTerms = 6;  ///< impulse x y z, moment x y z

    /// m_i Δv_i, and its moment about solid s's reference.
    static glm::dvec3 impulseOf(const ParticleStore& p, std::uint32_t i, const glm::vec3& dv) {
        return static_cast<double>(p.mass[i]) * glm::dvec3(dv);
    }
    glm::dvec3 momentOf(const ParticleStore& p, std::uint32_t i, std::uint16_t s, const glm::dvec3& impulse) const {
        return glm::cross(glm::dvec3(periodic_.delta(p.position[i], glm::vec3(references_[s]))), impulse);
    }

    /// book() in a split run: this rank's own particles, each term added exactly.
    template <class SolidOf>
    void bookExactly(const ParticleStore& p, int threads, SolidOf&& solidOf) {
        const std::size_t terms = exact_.size();
        const auto n = p.size();
        const std::uint32_t chunks = (n + kChunk - 1) / kChunk;
        std::vector<comm::ExactSum> partial(static_cast<std::size_t>(chunks) * terms);
        parallelFor(chunks, threads, [&](std::uint32_t c) {
            comm::ExactSum* sums = partial.data() + static_cast<std::size_t>(c) * terms;
            for (std::uint32_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i) {
                const glm::vec3 dv = p.velocity[i] - before_[i];
                if (dv == glm::vec3(0.0f) || (*ghosts_)[i]) continue;
                before_[i] = p.velocity[i];
                const std::uint16_t s = solidOf(i, dv);
                if (s >= totals_.size()) continue;
                const glm::dvec3 impulse = impulseOf(p, i, dv), moment = momentOf(p, i, s, impulse);
                for (int a = 0; a < 3; ++a) {
                    sums[kTerms * s + static_cast<std::size_t>(a)].add(impulse[a]);
                    sums[kTerms * s + 3 + static_cast<std::size_t>(a)].add(moment[a]);
                }
            }
        });
        for (std::uint32_t c = 0; c < chunks; ++c)
            for (std::size_t t = 0; t < terms; ++t) exact_[t].merge(partial[static_cast<std::size_t>(c) * terms + t]);
    }

    const std::vector<std::uint8_t>* ghosts_ = nullptr;
    std::vector<comm::ExactSum> exact_;  ///< split runs: per solid, kTerms exact sums
    std::vector<glm::vec3> before_;
    std::vector<glm::dvec3> references_;
    PeriodicBox periodic_;
    std::vector<SolidLoad> totals_;   ///< Σ m Δv given to the fluid, and its moment, per solid
    std::vector<SolidLoad> partial_;  ///< per chunk and solid
};

}  // namespace tide
