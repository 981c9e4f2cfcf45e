#pragma once
/// \file
/// The sums that decide a solver's control flow (its convergence tests), over the particles
/// this process owns and then over every process: exact (comm::ExactSum, Neal 2015), so that
/// a solve takes the same iterations whatever the thread count and however its World is split
/// among processes (issue 47). Ghost copies of other ranks' particles are left out.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "comm/exact_sum.hpp"
#include "core/parallel.hpp"
#include "solvers/solver.hpp"

namespace tide::owned_sums {

/// Whether particle i is owned here (every particle is on one process).
[[nodiscard]] inline bool owned(std::span<const std::uint8_t> ghosts, std::uint32_t i) {
    return ghosts.empty() || ghosts[i] == 0;
}

/// Σ f(i) over the owned particles, this rank's share: fixed blocks on threads, merged
/// exactly, so the order of blocks and threads cannot matter.
template <class F>
[[nodiscard]] comm::ExactSum localSum(const StepContext& ctx, F&& f) {
    const std::uint32_t n = ctx.particles.size();
    const auto ghosts = ctx.sharing ? ctx.sharing->ghosts() : std::span<const std::uint8_t>{};
    const std::uint32_t blocks = (n + kReductionBlock - 1) / kReductionBlock;
    std::vector<comm::ExactSum> partial(blocks);
    parallelFor(blocks, ctx.threads, [&](std::uint32_t b) {
        const std::uint32_t last = std::min(n, (b + 1) * kReductionBlock);
        for (std::uint32_t i = b * kReductionBlock; i < last; ++i)
            if (owned(ghosts, i)) partial[b].add(static_cast<double>(f(i)));
    });
    comm::ExactSum total;
    for (const comm::ExactSum& s : partial) total.merge(s);
    return total;
}

/// The mean of f(i) over every rank's owned particles (0 without particles).
template <class F>
[[nodiscard]] double mean(const StepContext& ctx, F&& f) {
    std::vector<comm::ExactSum> sums(2);
    sums[0] = localSum(ctx, f);
    sums[1] = localSum(ctx, [](std::uint32_t) { return 1.0; });
    if (ctx.sharing) ctx.sharing->sumOverRanks(sums);
    return sums[0].value() / std::max(1.0, sums[1].value());
}

/// The convergence measure of a solve with several materials: the largest over materials of
/// the mean of error(i)/ρ0_i over that material's particles, so that every material, not
/// only their mix, ends within the tolerance (a light layer is a minority of the particles
/// and the mean over all of them hid a heavy layer 23 % over it, measured at 5:1 in dfsph).
template <class F>
[[nodiscard]] double worstMaterialMean(const StepContext& ctx, F&& error) {
    const ParticleStore& p = ctx.particles;
    const std::size_t materials = ctx.materials.size();
    const auto ghosts = ctx.sharing ? ctx.sharing->ghosts() : std::span<const std::uint8_t>{};
    // Sums, then counts, per material.
    std::vector<comm::ExactSum> sums(2 * materials);
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        if (!owned(ghosts, i)) continue;
        const std::uint32_t m = p.material[i];
        sums[m].add(static_cast<double>(error(i) / ctx.materials[m].restDensity));
        sums[materials + m].add(1.0);
    }
    if (ctx.sharing) ctx.sharing->sumOverRanks(sums);
    double worst = 0.0;
    for (std::size_t m = 0; m < materials; ++m) {
        const double count = sums[materials + m].value();
        if (count > 0.0) worst = std::max(worst, sums[m].value() / count);
    }
    return worst;
}

}  // namespace tide::owned_sums
