// The Jacobi weights' scaling with the kernel support (solvers/jacobi_weight.hpp).
#include <gtest/gtest.h>

#include "solvers/jacobi_weight.hpp"

namespace {

using namespace tide;

// max_k G(k) on the simple cubic lattice, computed independently with numpy over the same
// 13³ grid of k in [0, π]³ (the cubic spline of bench/lattice_stability.py): 2.81 at 2
// spacings, 4.37 at 2.5, 7.45 at 3, 17.60 at 4.
TEST(JacobiWeight, LatticeGainMatchesTheFourierSum) {
    EXPECT_NEAR(latticeJacobiGain(2.0f), 2.81f, 0.01f);
    EXPECT_NEAR(latticeJacobiGain(2.5f), 4.37f, 0.01f);
    EXPECT_NEAR(latticeJacobiGain(3.0f), 7.45f, 0.01f);
    EXPECT_NEAR(latticeJacobiGain(4.0f), 17.60f, 0.02f);
}

// The default support keeps the tuned weights exactly, and wider ones keep ω max G where it
// was at 2 spacings: ½ · 2.81 for the density solve, inside Jacobi's bound of 2.
TEST(JacobiWeight, WiderSupportsKeepTheTunedMargin) {
    EXPECT_EQ(jacobiWeightScale(1.5f), 1.0f);
    EXPECT_EQ(jacobiWeightScale(2.0f), 1.0f);
    EXPECT_EQ(jacobiWeightScale(0.04f / 0.02f), 1.0f);
    for (const float s : {2.2f, 2.5f, 3.0f, 3.5f, 4.0f}) {
        const float scale = jacobiWeightScale(s);
        EXPECT_LT(scale, 1.0f) << s;
        EXPECT_NEAR(0.5f * scale * latticeJacobiGain(s), 0.5f * latticeJacobiGain(2.0f), 1e-4f) << s;
    }
    JacobiWeightScale cached;
    EXPECT_EQ(cached(3.0f, KernelShape::CubicSpline), jacobiWeightScale(3.0f));
    EXPECT_EQ(cached(2.0f, KernelShape::CubicSpline), 1.0f);
    EXPECT_EQ(cached(3.0f, KernelShape::WendlandC2), jacobiWeightScale(3.0f, KernelShape::WendlandC2));
}

// Wendland C2 (the same numpy sum with its gradient): 2.61 at 2 spacings, 3.84 at 2.5, 6.24
// at 3, 14.30 at 4. Below the cubic spline's 2.81 at 2 it keeps the tuned weights; wider, it
// scales them to the same margin.
TEST(JacobiWeight, WendlandKeepsTheCubicSplinesMargin) {
    constexpr KernelShape wendland = KernelShape::WendlandC2;
    EXPECT_NEAR(latticeJacobiGain(2.0f, wendland), 2.61f, 0.01f);
    EXPECT_NEAR(latticeJacobiGain(2.5f, wendland), 3.84f, 0.01f);
    EXPECT_NEAR(latticeJacobiGain(3.0f, wendland), 6.24f, 0.01f);
    EXPECT_NEAR(latticeJacobiGain(4.0f, wendland), 14.30f, 0.02f);
    EXPECT_EQ(jacobiWeightScale(2.0f, wendland), 1.0f);
    for (const float s : {2.5f, 3.0f, 4.0f})
        EXPECT_NEAR(jacobiWeightScale(s, wendland) * latticeJacobiGain(s, wendland), latticeJacobiGain(2.0f), 1e-4f) << s;
}

}  // namespace
