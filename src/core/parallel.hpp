#pragma once
/// \file
/// The one parallel-for of the core. Static scheduling and per-index work keep results
/// bit-identical for any thread count: nothing is accumulated across indices inside it,
/// and the only reductions are min/max, which do not depend on order.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include <omp.h>

namespace tide {

/// Threads to use for a request of `requested` (0 or less = all cores).
inline int resolveThreadCount(int requested) {
    return requested > 0 ? requested : std::max(1, omp_get_num_procs());
}

/// Below this many indices a loop runs serially: the fork costs more than it saves.
inline constexpr std::uint32_t kParallelGrain = 256;

/// Call f(i) for i in [0, n) on `threads` threads.
template <class F>
void parallelFor(std::uint32_t n, int threads, F&& f) {
    const bool parallel = threads > 1 && n >= kParallelGrain;
#pragma omp parallel for schedule(static) num_threads(threads) if (parallel)
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(n); ++i) f(static_cast<std::uint32_t>(i));
}

/// Call f(first, last) for the blocks [first, last) of `block` consecutive indices (the last
/// block shorter) that cover [0, n), on `threads` threads: for passes that work a block at a time.
template <class F>
void parallelForBlocks(std::uint32_t n, std::uint32_t block, int threads, F&& f) {
    const std::uint32_t blocks = (n + block - 1) / block;
    const bool parallel = threads > 1 && n >= kParallelGrain;
#pragma omp parallel for schedule(static) num_threads(threads) if (parallel)
    for (std::int64_t b = 0; b < static_cast<std::int64_t>(blocks); ++b) {
        const auto first = static_cast<std::uint32_t>(b) * block;
        f(first, std::min(n, first + block));
    }
}

/// max over i in [0, n) of f(i), or `init` when n == 0.
template <class F>
float parallelMax(std::uint32_t n, int threads, F&& f, float init = -std::numeric_limits<float>::infinity()) {
    float result = init;
    const bool parallel = threads > 1 && n >= kParallelGrain;
#pragma omp parallel for schedule(static) num_threads(threads) if (parallel) reduction(max : result)
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(n); ++i)
        result = std::max(result, static_cast<float>(f(static_cast<std::uint32_t>(i))));
    return result;
}

/// Indices per block of a reduction that must not depend on the thread count: each block is
/// summed in order, then the blocks in order (parallelSum; World's per-step statistics).
inline constexpr std::uint32_t kReductionBlock = 4096;

/// Σ f(i) over i in [0, n), in double. The same for any thread count: fixed blocks of
/// indices are summed in order, then the blocks' sums in order.
template <class F>
double parallelSum(std::uint32_t n, int threads, F&& f) {
    constexpr std::uint32_t kBlock = kReductionBlock;
    const std::uint32_t blocks = (n + kBlock - 1) / kBlock;
    std::vector<double> partial(blocks, 0.0);
    const bool parallel = threads > 1 && blocks > 1;
#pragma omp parallel for schedule(static) num_threads(threads) if (parallel)
    for (std::int64_t b = 0; b < static_cast<std::int64_t>(blocks); ++b) {
        const auto first = static_cast<std::uint32_t>(b) * kBlock;
        const std::uint32_t last = std::min(n, first + kBlock);
        double sum = 0.0;
        for (std::uint32_t i = first; i < last; ++i) sum += f(i);
        partial[static_cast<std::size_t>(b)] = sum;
    }
    double total = 0.0;
    for (const double s : partial) total += s;
    return total;
}

}  // namespace tide
