// The neighbour search's distance test of within_radius.hpp, compiled once per instruction
// set by Highway's foreach_target and dispatched at run time.
#include "neighbors/within_radius.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "neighbors/within_radius.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "core/nearest_image-inl.h"

HWY_BEFORE_NAMESPACE();
namespace tide::within_radius {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::CappedTag<float, kBlock>;
using DU = hn::RebindToUnsigned<D>;
using V = hn::Vec<D>;

template <bool Periodic>
HWY_INLINE V Delta(V q, V x, float period, float half) {
    return tide::HWY_NAMESPACE::NearestImageDelta<Periodic>(q, x, period, half);
}

/// The query's test against candidates t …: their indices, and which of them are within
/// reach and not `skip`.
struct Block {
    hn::Vec<DU> index;
    hn::Mask<DU> hit;
};
template <bool Periodic>
struct Test {
    V qx, qy, qz, r2;
    hn::Vec<DU> skipped;

    Test(const glm::vec3& q, float radius2, std::uint32_t skip)
        : qx(hn::Set(D(), q.x)), qy(hn::Set(D(), q.y)), qz(hn::Set(D(), q.z)), r2(hn::Set(D(), radius2)),
          skipped(hn::Set(DU(), skip)) {}

    HWY_INLINE Block operator()(const Candidates& c, std::size_t t, const PeriodicBox& box) const {
        const D d;
        const DU du;
        const V dx = Delta<Periodic>(qx, hn::LoadU(d, c.x + t), box.period.x, box.half.x);
        const V dy = Delta<Periodic>(qy, hn::LoadU(d, c.y + t), box.period.y, box.half.y);
        const V dz = Delta<Periodic>(qz, hn::LoadU(d, c.z + t), box.period.z, box.half.z);
        const auto index = hn::LoadU(du, c.index + t);
        // Unfused and in the scalar loop's order (this file is built with -ffp-contract=off):
        // the same pairs on every CPU. Padding lanes sit at +∞ and fail the test.
        const V d2 = hn::Add(hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy)), hn::Mul(dz, dz));
        return {index, hn::And(hn::RebindMask(du, hn::Le(d2, r2)), hn::Ne(index, skipped))};
    }
};

template <bool Periodic>
std::size_t SelectT(const Candidates& c, const glm::vec3& q, float radius2, std::uint32_t skip, const PeriodicBox& box,
                    std::uint32_t* out) {
    const DU du;
    const Test<Periodic> test(q, radius2, skip);
    std::size_t size = 0;
    for (std::size_t t = 0; t < c.count; t += hn::Lanes(du)) {
        const Block block = test(c, t, box);
        hn::StoreU(hn::Compress(block.index, block.hit), du, out + size);
        size += hn::CountTrue(du, block.hit);
    }
    return size;
}

/// SelectT's test, writing offsets from `base` (the query, which is skipped).
template <bool Periodic>
std::size_t SelectOffsetsT(const Candidates& c, const glm::vec3& q, float radius2, std::uint32_t base,
                           const PeriodicBox& box, std::int16_t* out, bool& misfit) {
    const DU du;
    const hn::RebindToSigned<D> di;
    const hn::Rebind<std::int16_t, D> d16;
    const Test<Periodic> test(q, radius2, base);
    const auto origin = hn::Set(di, static_cast<std::int32_t>(base));
    const auto lowest = hn::Set(di, -32768), highest = hn::Set(di, 32767);
    auto outside = hn::FirstN(di, 0);
    std::size_t size = 0;
    for (std::size_t t = 0; t < c.count; t += hn::Lanes(du)) {
        const Block block = test(c, t, box);
        const auto offset = hn::Sub(hn::BitCast(di, block.index), origin);
        const auto hit = hn::RebindMask(di, block.hit);
        outside = hn::Or(outside, hn::And(hit, hn::Or(hn::Lt(offset, lowest), hn::Gt(offset, highest))));
        hn::StoreU(hn::DemoteTo(d16, hn::Compress(offset, hit)), d16, out + size);
        size += hn::CountTrue(du, block.hit);
    }
    if (!hn::AllFalse(di, outside)) misfit = true;
    return size;
}

std::size_t SelectOffsetsImpl(const Candidates& candidates, const glm::vec3& q, float radius2, std::uint32_t base,
                              const PeriodicBox& box, std::int16_t* out, bool& misfit) {
    return box.any ? SelectOffsetsT<true>(candidates, q, radius2, base, box, out, misfit)
                   : SelectOffsetsT<false>(candidates, q, radius2, base, box, out, misfit);
}

std::size_t SelectImpl(const Candidates& candidates, const glm::vec3& q, float radius2, std::uint32_t skip,
                       const PeriodicBox& box, std::uint32_t* out) {
    return box.any ? SelectT<true>(candidates, q, radius2, skip, box, out)
                   : SelectT<false>(candidates, q, radius2, skip, box, out);
}

}  // namespace HWY_NAMESPACE
}  // namespace tide::within_radius
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace tide::within_radius {

HWY_EXPORT(SelectImpl);
HWY_EXPORT(SelectOffsetsImpl);

std::size_t select(const Candidates& candidates, const glm::vec3& q, float radius2, std::uint32_t skip,
                   const PeriodicBox& box, std::uint32_t* out) {
    return HWY_DYNAMIC_DISPATCH(SelectImpl)(candidates, q, radius2, skip, box, out);
}

std::size_t selectOffsets(const Candidates& candidates, const glm::vec3& q, float radius2, std::uint32_t base,
                          const PeriodicBox& box, std::int16_t* out, bool& misfit) {
    return HWY_DYNAMIC_DISPATCH(SelectOffsetsImpl)(candidates, q, radius2, base, box, out, misfit);
}

}  // namespace tide::within_radius
#endif  // HWY_ONCE
