#include "comm/exact_sum.hpp"

#include <bit>
#include <cmath>
#include <limits>

namespace tide::comm {
namespace {

constexpr std::int64_t kChunkBase = std::int64_t{1} << ExactSum::kChunkBits;
constexpr std::uint64_t kChunkMask = static_cast<std::uint64_t>(kChunkBase - 1);
// Each add changes a counter by less than 2^32: 2^30 adds leave a wide margin below 2^63.
constexpr std::uint32_t kAddsBetweenCarries = 1u << 30;
// Bit 0 of chunk 0 weighs 2^-1074, the smallest subnormal.
constexpr int kLowestExponent = -1074;

}  // namespace

void ExactSum::add(double x) {
    // The fields of the IEEE 754 binary64 itself rather than frexp/ldexp: a solver adds one
    // term per particle per iteration, and this is ~4× faster.
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const auto biased = static_cast<int>((bits >> 52) & 0x7ff);
    std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
    if (biased == 0x7ff) {
        if (mantissa != 0) ++nan_;
        else ++(x > 0 ? posInf_ : negInf_);
        return;
    }
    if (biased == 0 && mantissa == 0) return;  // ±0
    // A normal |x| = (2^52 + mantissa) 2^(biased - 1075), i.e. bit (biased - 1) above 2^-1074;
    // a subnormal is mantissa 2^-1074, bit 0.
    int bit = 0;
    if (biased != 0) {
        mantissa |= std::uint64_t{1} << 52;
        bit = biased - 1;
    }
    const int index = bit / kChunkBits;
    const int shift = bit % kChunkBits;
    // mantissa << shift spans up to 84 bits: its three 32-bit pieces, taken without overflow.
    const std::uint64_t low = (mantissa << shift) & kChunkMask;
    const std::uint64_t middle = (mantissa >> (kChunkBits - shift)) & kChunkMask;
    const std::uint64_t high = shift == 0 ? 0 : mantissa >> (2 * kChunkBits - shift);
    const std::int64_t sign = x < 0 ? -1 : 1;
    chunk_[index] += sign * static_cast<std::int64_t>(low);
    chunk_[index + 1] += sign * static_cast<std::int64_t>(middle);
    chunk_[index + 2] += sign * static_cast<std::int64_t>(high);
    if (++addsSinceCarry_ == kAddsBetweenCarries) carry();
}

void ExactSum::carry() {
    for (int i = 0; i + 1 < kChunks; ++i) {
        const std::int64_t over = chunk_[i] >> kChunkBits;  // floor division by 2^32
        chunk_[i] -= over * kChunkBase;
        chunk_[i + 1] += over;
    }
    addsSinceCarry_ = 0;
}

void ExactSum::merge(const ExactSum& other) {
    ExactSum carried = other;
    carried.carry();
    carry();
    for (int i = 0; i < kChunks; ++i) chunk_[i] += carried.chunk_[i];
    nan_ += other.nan_;
    posInf_ += other.posInf_;
    negInf_ += other.negInf_;
    carry();
}

double ExactSum::value() const {
    if (nan_ > 0 || (posInf_ > 0 && negInf_ > 0)) return std::numeric_limits<double>::quiet_NaN();
    if (posInf_ > 0) return std::numeric_limits<double>::infinity();
    if (negInf_ > 0) return -std::numeric_limits<double>::infinity();
    ExactSum magnitude = *this;
    magnitude.carry();
    // Carried, every chunk but the top is in [0, 2^32): the top chunk's sign is the sum's.
    const bool negative = magnitude.chunk_[kChunks - 1] < 0;
    if (negative) {
        for (auto& c : magnitude.chunk_) c = -c;
        magnitude.carry();
    }
    // From the most significant chunk down: the result is a function of the carried form,
    // which is unique for each exact value, so it never depends on the order of the adds.
    double result = 0.0;
    for (int i = kChunks - 1; i >= 0; --i)
        if (magnitude.chunk_[i] != 0)
            result += std::ldexp(static_cast<double>(magnitude.chunk_[i]), kLowestExponent + i * kChunkBits);
    return negative ? -result : result;
}

ExactSum::Counters ExactSum::counters() const {
    ExactSum carried = *this;
    carried.carry();
    Counters out{};
    for (int i = 0; i < kChunks; ++i) out[i] = carried.chunk_[i];
    out[kChunks] = nan_;
    out[kChunks + 1] = posInf_;
    out[kChunks + 2] = negInf_;
    return out;
}

ExactSum ExactSum::fromCounters(std::span<const std::int64_t, kChunks + 3> counters) {
    ExactSum sum;
    for (int i = 0; i < kChunks; ++i) sum.chunk_[i] = counters[i];
    sum.nan_ = counters[kChunks];
    sum.posInf_ = counters[kChunks + 1];
    sum.negInf_ = counters[kChunks + 2];
    sum.carry();
    return sum;
}

}  // namespace tide::comm
