// Kernel properties: normalisation, gradients and Laplacians against finite differences.
#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/kernels.hpp"
#include "solvers/pair_kernels.hpp"

namespace {

using namespace tide::kernels;
using tide::KernelShape;

SmoothingKernel cubicSpline(float h) { return SmoothingKernel(h, KernelShape::CubicSpline); }
SmoothingKernel wendland(float h) { return SmoothingKernel(h, KernelShape::WendlandC2); }

/// ∫ W dV = ∫_0^h 4π r² W(r) dr by composite Simpson in double.
double integrate(const std::function<float(float)>& w, double h, int intervals = 20000) {
    const double dr = h / intervals;
    double sum = 0.0;
    for (int k = 0; k <= intervals; ++k) {
        const double r = k * dr;
        const double f = 4.0 * pi * r * r * w(static_cast<float>(r));
        sum += (k == 0 || k == intervals ? 1.0 : (k % 2 ? 4.0 : 2.0)) * f;
    }
    return sum * dr / 3.0;
}

class KernelNormalisation : public ::testing::TestWithParam<float> {};

TEST_P(KernelNormalisation, EachKernelIntegratesToOne) {
    const float h = GetParam();
    EXPECT_NEAR(integrate([&](float r) { return Poly6(h).value(r); }, h), 1.0, 1e-3);
    EXPECT_NEAR(integrate([&](float r) { return Spiky(h).value(r); }, h), 1.0, 1e-3);
    EXPECT_NEAR(integrate([&](float r) { return Viscosity(h).value(r); }, h), 1.0, 1e-3);
    EXPECT_NEAR(integrate([&](float r) { return cubicSpline(h).value(r); }, h), 1.0, 1e-3);
    EXPECT_NEAR(integrate([&](float r) { return wendland(h).value(r); }, h), 1.0, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(SupportRadii, KernelNormalisation, ::testing::Values(0.04f, 1.0f, 2.5f));

/// ∫ f dA = ∫_0^h 2π r f(r) dr (2D) or ∫_0^h 4π r² f(r) dr (3D), composite Simpson in double.
double integrateRadially(const std::function<double(double)>& f, double h, int dimensions, int intervals = 200000) {
    const double dr = h / intervals;
    double sum = 0.0;
    for (int k = 0; k <= intervals; ++k) {
        const double r = k * dr;
        const double shell = dimensions == 2 ? 2.0 * pi * r : 4.0 * pi * r * r;
        sum += (k == 0 || k == intervals ? 1.0 : (k % 2 ? 4.0 : 2.0)) * shell * f(r);
    }
    return sum * dr / 3.0;
}

// The 2D normalisations (∫ W dA = 1: cubic spline 40/(7π h²), Wendland C2 7/(π h²), Poly6
// 4/(π h⁸), Spiky 10/(π h⁵), Müller's viscosity kernel 10/(3π h²)) and the 3D ones, to 1e-4.
TEST_P(KernelNormalisation, EachKernelIntegratesToOneIn2DAnd3D) {
    const float h = GetParam();
    for (const int d : {2, 3}) {
        const auto area = [&](auto kernel) {
            return integrateRadially([&](double r) { return double{kernel.value(static_cast<float>(r))}; }, h, d);
        };
        EXPECT_NEAR(area(SmoothingKernel(h, KernelShape::CubicSpline, d)), 1.0, 1e-4) << "cubic spline, d = " << d;
        EXPECT_NEAR(area(SmoothingKernel(h, KernelShape::WendlandC2, d)), 1.0, 1e-4) << "Wendland C2, d = " << d;
        EXPECT_NEAR(area(Poly6(h, d)), 1.0, 1e-4) << "poly6, d = " << d;
        EXPECT_NEAR(area(Spiky(h, d)), 1.0, 1e-4) << "spiky, d = " << d;
        EXPECT_NEAR(area(Viscosity(h, d)), 1.0, 2e-3) << "viscosity, d = " << d;  // 1/r at 0: Simpson converges slowly
        // Müller's viscosity Laplacian: second moment ∫ r² ∇²W = 2d (so Σ V_j (v_j − v_i) ∇²W ≈ ∇²v).
        const Viscosity v(h, d);
        EXPECT_NEAR(integrateRadially([&](double r) { return r * r * v.laplacian(static_cast<float>(r)); }, h, d), 2.0 * d,
                    1e-3)
            << "viscosity Laplacian moment, d = " << d;
    }
}

/// Checks gradient and Laplacian of a kernel against central differences of its value.
template <class K>
void expectDerivativesMatchFiniteDifferences(const K& kernel, float h) {
    const float qs[] = {0.2f, 0.35f, 0.5f, 0.7f, 0.9f};
    float lapScale = 0.0f;
    for (float q : qs) lapScale = std::max(lapScale, std::abs(kernel.laplacian(q * h)));
    const glm::vec3 directions[] = {{1, 0, 0}, {0.6f, 0.8f, 0}, {0.48f, -0.6f, 0.64f}};
    for (const glm::vec3& dir : directions) {
        for (float q : qs) {
            const glm::vec3 x = q * h * dir;
            const float r = glm::length(x);
            const float e = 1e-3f * h;
            glm::vec3 fd;
            for (int a = 0; a < 3; ++a) {
                glm::vec3 step(0.0f);
                step[a] = e;
                fd[a] = (kernel.value(glm::length(x + step)) - kernel.value(glm::length(x - step))) / (2.0f * e);
            }
            const glm::vec3 grad = kernel.gradient(x, r);
            EXPECT_LT(glm::length(grad - fd), 1e-2f * glm::length(fd) + 1e-6f * kernel.value(0.0f)) << "q=" << q;
            // Radially, ∇²W = W'' + 2W'/r; a wider step keeps float round-off small.
            const float e2 = 5e-3f * h;
            const float plus = kernel.value(r + e2), mid = kernel.value(r), minus = kernel.value(r - e2);
            const float lap = (plus - 2.0f * mid + minus) / (e2 * e2) + 2.0f * (plus - minus) / (2.0f * e2) / r;
            EXPECT_NEAR(kernel.laplacian(r), lap, 2e-2f * std::abs(lap) + 2e-3f * lapScale) << "q=" << q;
        }
    }
}

TEST(KernelDerivatives, MatchFiniteDifferences) {
    for (float h : {1.0f, 0.05f}) {
        expectDerivativesMatchFiniteDifferences(Poly6(h), h);
        expectDerivativesMatchFiniteDifferences(Spiky(h), h);
        expectDerivativesMatchFiniteDifferences(Viscosity(h), h);
        expectDerivativesMatchFiniteDifferences(cubicSpline(h), h);
        expectDerivativesMatchFiniteDifferences(wendland(h), h);
    }
}

/// In 2D: the Laplacian against W'' + W'/r by central differences of the value.
template <class K>
void expectPlanarLaplacianMatchesFiniteDifferences(const K& kernel, float h) {
    float lapScale = 0.0f;
    for (float q : {0.2f, 0.35f, 0.5f, 0.7f, 0.9f}) lapScale = std::max(lapScale, std::abs(kernel.laplacian(q * h)));
    for (float q : {0.2f, 0.35f, 0.5f, 0.7f, 0.9f}) {
        const float r = q * h, e2 = 5e-3f * h;
        const float plus = kernel.value(r + e2), mid = kernel.value(r), minus = kernel.value(r - e2);
        const float lap = (plus - 2.0f * mid + minus) / (e2 * e2) + (plus - minus) / (2.0f * e2) / r;
        EXPECT_NEAR(kernel.laplacian(r), lap, 2e-2f * std::abs(lap) + 2e-3f * lapScale) << "q=" << q;
    }
}

TEST(KernelDerivatives, PlanarLaplaciansMatchFiniteDifferences) {
    for (float h : {1.0f, 0.05f}) {
        expectPlanarLaplacianMatchesFiniteDifferences(Poly6(h, 2), h);
        expectPlanarLaplacianMatchesFiniteDifferences(Spiky(h, 2), h);
        expectPlanarLaplacianMatchesFiniteDifferences(SmoothingKernel(h, KernelShape::CubicSpline, 2), h);
        expectPlanarLaplacianMatchesFiniteDifferences(SmoothingKernel(h, KernelShape::WendlandC2, 2), h);
    }
}

TEST(KernelDerivatives, ViscosityLaplacianIsMuellersForm) {
    const float h = 0.1f;
    for (float r : {0.01f, 0.05f, 0.09f})
        EXPECT_FLOAT_EQ(Viscosity(h).laplacian(r), 45.0f / (pi * std::pow(h, 6.0f)) * (h - r));
}

TEST(KernelDerivatives, SpikyGradientDoesNotVanishAtZero) {
    const float h = 0.1f;
    const float limit = 45.0f / (pi * std::pow(h, 6.0f)) * h * h;
    const glm::vec3 x(1e-6f * h, 0.0f, 0.0f);
    EXPECT_GT(glm::length(Spiky(h).gradient(x, glm::length(x))), 0.99f * limit);
    // Poly6's gradient does vanish there: that is why Müller uses Spiky for pressure.
    EXPECT_LT(glm::length(Poly6(h).gradient(x, glm::length(x))), 1e-3f * limit);
}

TEST(KernelSupport, ZeroAtAndBeyondSupport) {
    const float h = 0.3f;
    for (float r : {h, 1.5f * h}) {
        EXPECT_EQ(Poly6(h).value(r), 0.0f);
        EXPECT_EQ(Spiky(h).value(r), 0.0f);
        EXPECT_EQ(Viscosity(h).value(r), 0.0f);
        EXPECT_EQ(cubicSpline(h).value(r), 0.0f);
        EXPECT_EQ(wendland(h).value(r), 0.0f);
        EXPECT_EQ(wendland(h).derivative(r), 0.0f);
        EXPECT_EQ(Viscosity(h).laplacian(r), 0.0f);
    }
}

// The pressure solves read W'(r)/r per pair from 16-bit codes: every code is within half its
// mantissa's step (2⁻¹², 2.4e-4) of the exact factor, from near 0 to the edge of the support,
// where it is 0, for both kernels.
TEST(PairKernels, CodedGradientFactorIsWithinItsPrecision) {
    const float h = 0.04f;
    // |W'(r)/r| as r → 0, the largest: 12σ/h² for the cubic spline, 20σ/h² for Wendland C2
    for (const auto& [w, largest] : {std::pair{cubicSpline(h), 12.0f}, std::pair{wendland(h), 20.0f}}) {
        tide::PairKernels factors;
        factors.resize(tide::NeighborList{}, w);
        const float bound = largest * w.sigma / (h * h);
        EXPECT_NEAR(factors.unit(), -bound, 1e-6f * bound);
        float worst = 0.0f;
        for (int k = 1; k < 4000; ++k) {
            const float r = h * static_cast<float>(k) / 4000.0f;
            const float exact = w.derivative(r) / r, coded = factors.factor(factors.encode(w, r));
            // Below 2⁻³¹ of the unit a factor codes as 0 (Wendland's (1 − q)³ in the last 0.1 % of the support)
            if (exact / factors.unit() < tide::PairKernels::kSmallest) {
                EXPECT_LE(std::abs(coded - exact), tide::PairKernels::kSmallest * bound) << r;
                continue;
            }
            worst = std::max(worst, std::abs(coded / exact - 1.0f));
        }
        EXPECT_LE(worst, 2.45e-4f) << largest;
        EXPECT_EQ(factors.factor(factors.encode(w, h)), 0.0f);
        EXPECT_EQ(factors.factor(factors.encode(w, 0.0f)), 0.0f);
    }
}

// Wendland's C2 in 3D as Dehnen & Aly 2012 give it (table 1, with their H the support):
// W(0) = 21/(2π H³), and W at H/2 is (1/2)⁴ · 3 of that.
TEST(KernelValues, WendlandC2MatchesDehnenAndAly) {
    const float h = 0.05f;
    const float peak = 21.0f / (2.0f * pi * h * h * h);
    EXPECT_FLOAT_EQ(wendland(h).value(0.0f), peak);
    EXPECT_FLOAT_EQ(wendland(h).value(0.5f * h), peak * 0.0625f * 3.0f);
}

}  // namespace
