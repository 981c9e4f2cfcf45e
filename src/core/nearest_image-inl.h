// PeriodicBox::nearestImage in SIMD lanes, for the Highway files (neighbors/within_radius.cpp,
// solvers/pair_sums.cpp). Compiled once per target: Highway's per-target include guard.
#if defined(TIDE_CORE_NEAREST_IMAGE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef TIDE_CORE_NEAREST_IMAGE_INL_H_
#undef TIDE_CORE_NEAREST_IMAGE_INL_H_
#else
#define TIDE_CORE_NEAREST_IMAGE_INL_H_
#endif

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace tide {
namespace HWY_NAMESPACE {

/// a − b on one axis, shifted by the period where the axis is periodic and that is shorter
/// (period 0 and half +∞ on the others), as PeriodicBox::nearestImage: exactly its values.
template <bool Periodic, class V>
HWY_INLINE V NearestImageDelta(V a, V b, float period, float half) {
    namespace hn = hwy::HWY_NAMESPACE;
    const hn::DFromV<V> d;
    V delta = hn::Sub(a, b);
    if constexpr (Periodic) {
        const V p = hn::Set(d, period), h = hn::Set(d, half);
        delta = hn::Sub(delta, hn::IfThenElseZero(hn::Gt(delta, h), p));
        delta = hn::Add(delta, hn::IfThenElseZero(hn::Lt(delta, hn::Neg(h)), p));
    }
    return delta;
}

}  // namespace HWY_NAMESPACE
}  // namespace tide
HWY_AFTER_NAMESPACE();

#endif  // TIDE_CORE_NEAREST_IMAGE_INL_H_
