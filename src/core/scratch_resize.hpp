#pragma once
/// \file
/// Growing arrays without doubling them. Scratch whose contents every use rewrites (per-pair
/// kernel factors, wall weights) is freed before it grows: a std::vector copies itself into a
/// block twice the size, and for ~30 MB of per-pair data the old and new blocks resident
/// together were the run's peak memory (+113 bytes a fluid particle on the 205k dam break, at
/// the step the pair count first outgrew the first step's). Buffers that keep their contents
/// grow by an eighth.

#include <algorithm>
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

/// Room for `size` elements, contents kept: when that outgrows the capacity it grows by an
/// eighth at least, where push_back doubles (buffers that keep their capacity from step to
/// step, such as the neighbour lists', would otherwise hold up to twice what they use).
template <class T>
void reserveGrowing(std::vector<T>& values, std::size_t size) {
    if (size > values.capacity()) values.reserve(std::max(size, values.capacity() + values.capacity() / 8));
}

/// Capacity for `capacity` elements, its pages touched (zero-filled) now, the size kept (contents
/// lost if it grows): scratch sized ahead of the steps that use it, so that their first one does
/// not pay for fresh memory. Each first touch of a page costs a page fault (measured here:
/// 3.6 ms a MB in this VM, against 0.05 ms to fill it again), which made a live demo's first
/// frame 2.5 times its median.
template <class T>
void reserveTouched(std::vector<T>& values, std::size_t capacity) {
    if (capacity <= values.capacity()) return;
    const std::size_t size = values.size();
    std::vector<T>().swap(values);
    values.resize(capacity);
    values.resize(size);
}

}  // namespace tide
