#pragma once
/// \file
/// The inner test of the neighbour search: which of a cell neighbourhood's candidates lie
/// within the radius of a query point, kept in order. SIMD lanes (Google Highway, chosen at
/// run time as in solvers/pair_sums.hpp): squared distances of a block of candidates, the
/// block's hits compressed to the front of a vector and stored whole, the output advancing
/// by their count. The lists come out exactly as a scalar loop writes them.

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#include "core/periodic_box.hpp"

namespace tide::within_radius {

/// Blocks are this many candidates at most: the candidate arrays are padded to a multiple
/// of it (with coordinates of +∞, never within reach), and the output needs this much room
/// past the hits.
inline constexpr std::size_t kBlock = 16;

/// Candidates in structure-of-arrays form; x, y, z and index readable up to count rounded up
/// to kBlock.
struct Candidates {
    const float* x = nullptr;
    const float* y = nullptr;
    const float* z = nullptr;
    const std::uint32_t* index = nullptr;
    std::size_t count = 0;
};

/// Writes to `out` the indices of the candidates with |q − x|² ≤ radius2 (distances to the
/// nearest image on the box's periodic axes), except `skip`, in candidate order; returns how
/// many. `out` must have room for count + kBlock indices.
std::size_t select(const Candidates& candidates, const glm::vec3& q, float radius2, std::uint32_t skip,
                   const PeriodicBox& box, std::uint32_t* out);

/// select, writing the hits' offsets j − base as 16 bits (base < 2^31) to `out` (room for
/// count + kBlock); returns how many, and sets `misfit` if an offset is outside [−32768, 32767]
/// (its entry is then clamped).
std::size_t selectOffsets(const Candidates& candidates, const glm::vec3& q, float radius2, std::uint32_t base,
                          const PeriodicBox& box, std::int16_t* out, bool& misfit);

}  // namespace tide::within_radius
