// The exact sum behind every reduction that must not depend on how particles are split
// among threads and ranks (src/comm/exact_sum.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "comm/exact_sum.hpp"

namespace {

using tide::comm::ExactSum;
// GCC's and clang's 113-bit binary128 on x86, as the reference (an extension: said so).
__extension__ typedef __float128 Quad;

double exactSum(const std::vector<double>& terms) {
    ExactSum sum;
    for (const double x : terms) sum.add(x);
    return sum.value();
}

/// Terms over 12 decades and both signs, the spread of particle volumes, energies and errors.
std::vector<double> mixedTerms(std::size_t n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-20, 20);
    std::vector<double> terms(n);
    for (double& x : terms) x = std::ldexp(mantissa(rng), exponent(rng));
    return terms;
}

TEST(ExactSum, CancellationThatDoubleArithmeticLoses) {
    EXPECT_EQ(exactSum({1e100, 1.0, -1e100}), 1.0);
    EXPECT_EQ(exactSum({1.0, 1e-30, -1.0}), 1e-30);
    // The smallest subnormal survives beside the largest finite values.
    const double tiny = std::numeric_limits<double>::denorm_min();
    const double huge = std::numeric_limits<double>::max();
    EXPECT_EQ(exactSum({huge, tiny, -huge}), tiny);
    EXPECT_EQ(exactSum({huge, huge, -huge}), huge);
    EXPECT_EQ(exactSum({}), 0.0);
}

TEST(ExactSum, MatchesQuadPrecisionWhereThatIsExact) {
    // Terms within 2^-20..2^20 span 93 bits: __float128's 113-bit sum of them is exact.
    const std::vector<double> terms = mixedTerms(20000, 3);
    Quad reference = 0;
    for (const double x : terms) reference += x;
    EXPECT_EQ(exactSum(terms), static_cast<double>(reference));
}

TEST(ExactSum, DoesNotDependOnOrderOrOnHowTheTermsAreSplit) {
    std::vector<double> terms = mixedTerms(50000, 11);
    for (double& x : terms) x *= 1e-6 + std::fabs(x);  // more decades
    const double inOrder = exactSum(terms);
    std::mt19937 rng(5);
    for (int trial = 0; trial < 5; ++trial) {
        std::shuffle(terms.begin(), terms.end(), rng);
        // Split into uneven parts summed separately, then merged in reverse: what ranks do.
        const std::size_t parts = 1 + static_cast<std::size_t>(trial) * 2;
        std::vector<ExactSum> partial(parts);
        for (std::size_t i = 0; i < terms.size(); ++i) partial[(i * i + i / 7) % parts].add(terms[i]);
        ExactSum merged;
        for (std::size_t p = parts; p-- > 0;) merged.merge(partial[p]);
        EXPECT_EQ(merged.value(), inOrder) << "trial " << trial;
        // And through the counters a communicator sums.
        ExactSum::Counters total{};
        for (const ExactSum& s : partial) {
            const ExactSum::Counters c = s.counters();
            for (std::size_t k = 0; k < c.size(); ++k) total[k] += c[k];
        }
        EXPECT_EQ(ExactSum::fromCounters(total).value(), inOrder) << "trial " << trial;
    }
    // A plain double sum of the same terms does depend on the order (why this exists).
    double forward = 0, backward = 0;
    for (const double x : terms) forward += x;
    for (auto it = terms.rbegin(); it != terms.rend(); ++it) backward += *it;
    EXPECT_NE(forward, backward);
}

TEST(ExactSum, NonFiniteTermsGiveTheIeeeResult) {
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(exactSum({1.0, inf, 2.0}), inf);
    EXPECT_EQ(exactSum({-inf, 1.0}), -inf);
    EXPECT_TRUE(std::isnan(exactSum({inf, -inf})));
    EXPECT_TRUE(std::isnan(exactSum({1.0, std::nan("")})));
}

TEST(ExactSum, ManyEqualTermsStayExact) {
    // 12.6 million copies of 0.1: the counters grow far past 2^53 without losing a bit;
    // n * 0.1 (as a double) is exact in quad precision.
    ExactSum sum;
    const std::int64_t n = 3 << 22;
    for (std::int64_t i = 0; i < n; ++i) sum.add(0.1);
    EXPECT_EQ(sum.value(), static_cast<double>(static_cast<Quad>(0.1) * n));
}

}  // namespace
