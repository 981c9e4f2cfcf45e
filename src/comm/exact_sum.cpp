#include "comm/exact_sum.hpp"

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
    if (std::isnan(x)) {
        ++nan_;
        return;
    }
    if (std::isinf(x)) {
        ++(x > 0 ? posInf_ : negInf_);
        return;
    }
    if (x == 0.0) return;
    int exponent = 0;
    const double fraction = std::frexp(std::fabs(x), &exponent);  // |x| = fraction * 2^exponent
    auto mantissa = static_cast<std::uint64_t>(std::ldexp(fraction, 53));  // exact: 53 bits
    int bit = exponent - 53 - kLowestExponent;  // |x| = mantissa * 2^(bit - 1074)
    if (bit < 0) {  // a subnormal: its low bits are zero, so the shift is exact
        mantissa >>= -bit;
        bit = 0;
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
