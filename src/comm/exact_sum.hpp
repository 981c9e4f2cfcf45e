#pragma once
/// \file
/// An exact, order-independent sum of doubles: a "small superaccumulator" (Neal 2015, "Fast
/// exact summation using small and large superaccumulators", arXiv:1505.05571, §3). Every
/// finite double is a 53-bit integer times a power of two; its bits are added, split over
/// 32-bit chunks, into 64-bit integer counters indexed by exponent, so the accumulated value
/// is the exact sum whatever the order of the terms, the threads or the ranks that add them.
/// Integer addition being associative, two accumulators combine by adding their counters
/// (rank sums: one MPI_SUM over the counters). Sums that decide control flow (convergence,
/// statistics) go through it so a run does not depend on how its particles are split.
///
/// Written here rather than taken from a library: Debian ships no exact summation (ReproBLAS
/// and Neal's xsum are not packaged), and the method is ~100 lines.

#include <array>
#include <cstdint>
#include <span>

namespace tide::comm {

class ExactSum {
public:
    /// Chunks of 32 bits covering every double from the smallest subnormal (2^-1074) to the
    /// largest finite value (< 2^1024), plus room for the carries of up to 2^63 terms.
    static constexpr int kChunkBits = 32;
    static constexpr int kChunks = 68;
    using Counters = std::array<std::int64_t, kChunks + 3>;  ///< chunks, then NaN, +inf, -inf counts

    void add(double x);
    /// Adds another accumulator's exact value (the order of merges does not matter).
    void merge(const ExactSum& other);

    /// The exact sum rounded to a double. Deterministic: it depends only on the exact value
    /// (the counters are first brought to their unique carried form), never on the order of
    /// the terms; within 2 ulp of the exact sum. NaN if a term was NaN or +inf met -inf.
    [[nodiscard]] double value() const;

    /// The counters, for a communicator to sum over ranks (`fromCounters` reads the result).
    [[nodiscard]] Counters counters() const;
    static ExactSum fromCounters(std::span<const std::int64_t, kChunks + 3> counters);

private:
    void carry();  ///< brings every chunk but the top one into [0, 2^32)

    std::array<std::int64_t, kChunks> chunk_{};
    std::int64_t nan_ = 0, posInf_ = 0, negInf_ = 0;
    std::uint32_t addsSinceCarry_ = 0;
};

}  // namespace tide::comm
