#pragma once
/// \file
/// Resizing scratch arrays whose contents every use rewrites (per-pair kernel factors, wall
/// weights): growing a std::vector copies it into a block twice the size, and for ~30 MB of
/// per-pair data the old and new blocks resident together were the run's peak memory
/// (+113 bytes a fluid particle on the 205k dam break, at the step the pair count first
/// outgrew the first step's).

#include <cstddef>
#include <vector>

namespace tide {

/// Resizes `values` to `size`; when that outgrows its capacity the old block is freed first
/// (contents lost) and the new one has an eighth more room, so slow growth reallocates rarely.
template <class T>
void resizeScratch(std::vector<T>& values, std::size_t size) {
    if (size > values.capacity()) {
        std::vector<T>().swap(values);
        values.reserve(size + size / 8);
    }
    values.resize(size);
}

}  // namespace tide
