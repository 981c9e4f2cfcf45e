#pragma once
/// \file
/// Uniform random numbers that are the same on every platform: std::mt19937_64's output
/// sequence is fixed by the C++ standard, but std::uniform_real_distribution's mapping of it
/// (and std::shuffle's) is left to the library, so the mapping is done here from raw bits.

#include <cstdint>
#include <random>

namespace tide::ocean {

/// Uniform in [0, 1): the top 53 bits of one 64-bit draw, times 2⁻⁵³ (exact in a double).
inline double uniform01(std::mt19937_64& random) {
    return static_cast<double>(random() >> 11) * 0x1.0p-53;
}

/// Uniform integer in [0, n), n ≥ 1 (the bias of the multiply is below 2⁻⁴⁰ for n < 2¹³).
inline int uniformIndex(std::mt19937_64& random, int n) {
    return static_cast<int>(uniform01(random) * n);
}

}  // namespace tide::ocean
