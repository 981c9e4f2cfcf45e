// The pressure solves' SIMD pair sums (solvers/pair_sums.hpp) against the same sums in
// double precision, for lists of every length around the lane count (the lanes past a list's
// end must add nothing, whatever indices and codes follow it), and across a periodic axis;
// and the codes the density pass writes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/kernels.hpp"
#include "core/periodic_box.hpp"
#include "neighbors/neighbor_list.hpp"
#include "solvers/pair_kernels.hpp"
#include "solvers/pair_sums.hpp"

namespace {

using namespace tide;

struct Cloud {
    std::vector<glm::vec4> points;  ///< (x, w)
    std::vector<glm::vec4> velocities;  ///< (v, u): u a second weight (1/ρ in the viscosity)
};

Cloud randomCloud(std::size_t n, float size, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> position(0.0f, size), weight(0.5f, 2.0f), speed(-1.0f, 1.0f);
    Cloud cloud;
    for (std::size_t i = 0; i < n; ++i) {
        cloud.points.emplace_back(position(random), position(random), position(random), weight(random));
        cloud.velocities.emplace_back(speed(random), speed(random), speed(random), weight(random));
    }
    return cloud;
}

/// Checks the three sums for particle i over the first `count` of `candidates` (the same for
/// every count, so each length 0 … candidates.size() is covered).
void expectSumsMatch(const Cloud& cloud, std::uint32_t i, const std::vector<std::uint32_t>& candidates,
                     const kernels::SmoothingKernel& w, const PeriodicBox& box) {
    const double h = w.h;
    const glm::vec3 xi(cloud.points[i]);
    const glm::vec3 vi(cloud.velocities[i]);
    PairKernels factors;
    factors.resize(NeighborList{}, w);  // the kernel's unit
    std::vector<PairKernels::Code> codes;
    for (const std::uint32_t j : candidates) {
        const glm::vec3 r = box.delta(xi, glm::vec3(cloud.points[j]));
        codes.push_back(factors.encode(w, glm::length(r)));
    }
    // Read past the end (they must not count): near neighbours' indices with codes of the
    // largest factor.
    std::vector<std::uint32_t> indices = candidates;
    indices.resize(indices.size() + pair_sums::kPadding, candidates.front());
    codes.resize(codes.size() + pair_sums::kPadding, 0xFFFF);
    // The same neighbours as 16-bit offsets from i (NeighborList::build's form). Each count
    // below reads them as a list padded to a whole block: the offsets past it are i's own (0)
    // only from the next block on, so the lanes past the count must add nothing either way.
    std::vector<std::int16_t> offsets;
    for (const std::uint32_t j : candidates) offsets.push_back(static_cast<std::int16_t>(std::int64_t{j} - i));
    offsets.resize((offsets.size() / NeighborList::kOffsetBlock + 1) * NeighborList::kOffsetBlock, 0);
    for (const bool asOffsets : {false, true})
    for (std::size_t count = 0; count <= candidates.size(); ++count) {
        SCOPED_TRACE(asOffsets ? "as offsets" : "as indices");
        const auto n = static_cast<std::uint32_t>(count);
        const pair_sums::Neighbors neighbors(asOffsets ? NeighborSpan(offsets.data(), i, n) : NeighborSpan(indices.data(), n),
                                             codes.data());
        double kernel = 0.0, kernelScale = 0.0, divergence = 0.0, divergenceScale = 0.0;
        glm::dvec3 gradient(0.0), gradientScale(0.0), viscous(0.0), viscousScale(0.0), harmonic(0.0), harmonicScale(0.0);
        const double mui = cloud.points[i].w;  // the harmonic sum reads the points' weights as viscosities
        double squares = 0.0, cappedSquares = 0.0;
        glm::dvec3 plainGradient(0.0), plainGradientScale(0.0);
        glm::dvec3 xsph(0.0), xsphScale(0.0);
        const kernels::Poly6 poly6(w.h);
        const double epsilon = 0.01 * 0.25 * h * h;
        for (std::size_t k = 0; k < count; ++k) {
            const std::uint32_t j = candidates[k];
            const glm::dvec3 r(box.delta(xi, glm::vec3(cloud.points[j])));
            const double wj = cloud.points[j].w, m = PairKernels::magnitude(codes[k]);
            const double value = wj * w.value(static_cast<float>(glm::length(r)));
            kernel += value;
            kernelScale += std::abs(value);
            gradient += wj * m * r;
            gradientScale += glm::abs(wj * m * r);
            squares += glm::dot(wj * m * r, wj * m * r);
            plainGradient += m * r;
            plainGradientScale += glm::abs(m * r);
            cappedSquares += std::max(mui / wj, 1.0) * glm::dot(m * r, m * r);
            const double rate = wj * m * glm::dot(glm::dvec3(vi - glm::vec3(cloud.velocities[j])), r);
            divergence += rate;
            divergenceScale += std::abs(rate);
            const double length = glm::length(r);
            const glm::dvec3 shear = (wj * cloud.velocities[j].w * length * w.derivative(static_cast<float>(length)) /
                                      (length * length + epsilon)) *
                                     glm::dvec3(vi - glm::vec3(cloud.velocities[j]));
            viscous += shear;
            viscousScale += glm::abs(shear);
            const double muj = cloud.points[j].w;
            const glm::dvec3 mixed = (4.0 * mui * muj / (mui + muj) / wj) * shear;  // μ̄_ij in place of w_j
            harmonic += mixed;
            harmonicScale += glm::abs(mixed);
            const double reach = std::max(double{poly6.h2} - glm::dot(r, r), 0.0);
            const glm::dvec3 smoothing = (2.0 * wj / (double{cloud.velocities[i].w} + cloud.velocities[j].w) * reach * reach * reach) *
                                         glm::dvec3(glm::vec3(cloud.velocities[j]) - vi);
            xsph += smoothing;
            xsphScale += glm::abs(smoothing);
        }
        ASSERT_TRUE(count == 0 || gradientScale.x + gradientScale.y + gradientScale.z > 0.0);  // codes that count
        const glm::vec3 v = pair_sums::viscousSum(neighbors, cloud.points.data(), cloud.velocities.data(), xi, vi, w,
                                                  static_cast<float>(epsilon), box);
        for (int axis = 0; axis < 3; ++axis)
            EXPECT_NEAR(v[axis], viscous[axis], 1e-5 * viscousScale[axis] + 1e-12) << count << " neighbours";
        // α's sums with other masses: the points' weights as masses, i's own as m_i.
        const glm::vec4 capped =
            pair_sums::cappedGradientSquares(neighbors, cloud.points.data(), xi, static_cast<float>(mui), box);
        for (int axis = 0; axis < 3; ++axis)
            EXPECT_NEAR(capped[axis], plainGradient[axis], 1e-5 * plainGradientScale[axis] + 1e-12) << count << " neighbours";
        EXPECT_NEAR(capped.w, cappedSquares, 1e-5 * cappedSquares + 1e-12) << count << " neighbours";
        const glm::vec3 mixed = pair_sums::viscousSumHarmonic(neighbors, cloud.points.data(), cloud.velocities.data(), xi, vi,
                                                              static_cast<float>(mui), w, static_cast<float>(epsilon), box);
        for (int axis = 0; axis < 3; ++axis)
            EXPECT_NEAR(mixed[axis], harmonic[axis], 1e-5 * harmonicScale[axis] + 1e-12) << count << " neighbours";
        // An inviscid particle feels no viscous pair (μ̄_ij = 0), and among inviscid ones 0/0 adds nothing (no NaN).
        EXPECT_EQ(pair_sums::viscousSumHarmonic(neighbors, cloud.points.data(), cloud.velocities.data(), xi, vi, 0.0f, w,
                                                static_cast<float>(epsilon), box),
                  glm::vec3(0.0f))
            << count << " neighbours";
        std::vector<glm::vec4> inviscid = cloud.points;
        for (glm::vec4& point : inviscid) point.w = 0.0f;
        EXPECT_EQ(pair_sums::viscousSumHarmonic(neighbors, inviscid.data(), cloud.velocities.data(), xi, vi, 0.0f, w,
                                                static_cast<float>(epsilon), box),
                  glm::vec3(0.0f))
            << count << " neighbours";
        glm::dvec3 plain(0.0), weighted(0.0), plainScale(0.0), weightedScale(0.0);
        for (std::size_t k = 0; k < count; ++k) {
            const std::uint32_t j = candidates[k];
            const glm::vec3 r = box.delta(xi, glm::vec3(cloud.points[j]));
            const glm::dvec3 g(w.gradient(r, glm::length(r)));
            plain += g;
            plainScale += glm::abs(g);
            weighted += double{cloud.points[j].w} * g;
            weightedScale += glm::abs(double{cloud.points[j].w} * g);
        }
        const pair_sums::GradientSums gradients = pair_sums::kernelGradientSums(neighbors, cloud.points.data(), xi, w, box);
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_NEAR(gradients.plain[axis], plain[axis], 1e-5 * plainScale[axis] + 1e-12) << count << " neighbours";
            EXPECT_NEAR(gradients.weighted[axis], weighted[axis], 1e-5 * weightedScale[axis] + 1e-12) << count << " neighbours";
        }
        const glm::vec3 x = pair_sums::xsphSum(neighbors, cloud.points.data(), cloud.velocities.data(), xi,
                                               cloud.velocities[i], poly6, box);
        for (int axis = 0; axis < 3; ++axis)
            EXPECT_NEAR(x[axis], xsph[axis], 1e-5 * xsphScale[axis] + 1e-30) << count << " neighbours";
        for (const auto order : {pair_sums::Order::Lanes, pair_sums::Order::Sequential}) {
            const float initial = 0.25f;
            // The density pass writes each pair's code, bit for bit encode()'s, and nothing past the list.
            constexpr PairKernels::Code untouched = 0xABCD;
            std::vector<PairKernels::Code> written(codes.size(), untouched);
            EXPECT_NEAR(pair_sums::kernelSumAndCodes(neighbors, cloud.points.data(), xi, w, box, initial, factors,
                                                     written.data(), order),
                        initial + kernel, 1e-5 * (kernelScale + initial))
                << count << " neighbours";
            for (std::size_t k = 0; k < written.size(); ++k)
                EXPECT_EQ(written[k], k < count ? codes[k] : untouched) << k << " of " << count << " neighbours";
            // α's sums from the same pass, over the codes it writes (the same codes again).
            glm::vec4 alphaSums(-1.0f);
            std::vector<PairKernels::Code> again(codes.size(), untouched);
            pair_sums::kernelSumAndCodes(neighbors, cloud.points.data(), xi, w, box, initial, factors, again.data(), order,
                                         &alphaSums);
            EXPECT_EQ(again, written);
            for (int axis = 0; axis < 3; ++axis)
                EXPECT_NEAR(alphaSums[axis], gradient[axis], 1e-5 * gradientScale[axis] + 1e-12) << count << " neighbours";
            EXPECT_NEAR(alphaSums.w, squares, 1e-5 * squares + 1e-12) << count << " neighbours";
            EXPECT_NEAR(pair_sums::kernelSum(neighbors, cloud.points.data(), xi, w, box, initial, order), initial + kernel,
                        1e-5 * (kernelScale + initial))
                << count << " neighbours";
            const glm::vec3 g = pair_sums::gradientSum(neighbors, cloud.points.data(), xi, box, order);
            for (int axis = 0; axis < 3; ++axis)
                EXPECT_NEAR(g[axis], gradient[axis], 1e-5 * gradientScale[axis] + 1e-12) << count << " neighbours";
            EXPECT_NEAR(pair_sums::divergenceSum(neighbors, cloud.points.data(), cloud.velocities.data(), xi, vi, box, order),
                        divergence, 1e-5 * divergenceScale + 1e-12)
                << count << " neighbours";
        }
    }
}

TEST(PairSums, MatchTheSumsInDoubleForEveryListLength) {
    std::printf("pair sums run on %s\n", pair_sums::instructionSet());
    const float h = 0.04f;
    const Cloud cloud = randomCloud(400, 2.0f * h, 7);
    const PeriodicBox none;
    // 21 of particle 0's neighbours within the support.
    std::vector<std::uint32_t> candidates;
    for (std::uint32_t j = 1; j < cloud.points.size() && candidates.size() < 21; ++j)
        if (glm::length(glm::vec3(cloud.points[j]) - glm::vec3(cloud.points[0])) < h) candidates.push_back(j);
    ASSERT_EQ(candidates.size(), 21u);
    for (const KernelShape shape : {KernelShape::CubicSpline, KernelShape::WendlandC2})
        expectSumsMatch(cloud, 0, candidates, kernels::SmoothingKernel(h, shape), none);
}

TEST(PairSums, TakeTheNearestImageAcrossAPeriodicAxis) {
    const float h = 0.04f, size = 0.2f;
    Cloud cloud = randomCloud(300, size, 11);
    const PeriodicBox box = PeriodicBox::make({0, 0, 0}, {size, size, size}, {true, false, true});
    cloud.points[0] = glm::vec4(0.005f, 0.1f, 0.195f, 1.0f);  // at a corner of the periodic faces
    std::vector<std::uint32_t> candidates;
    for (std::uint32_t j = 1; j < cloud.points.size(); ++j)
        if (glm::length(box.delta(glm::vec3(cloud.points[0]), glm::vec3(cloud.points[j]))) < h) candidates.push_back(j);
    std::size_t across = 0;  // neighbours that are only near through the periodic faces
    for (const std::uint32_t j : candidates)
        across += glm::length(glm::vec3(cloud.points[0]) - glm::vec3(cloud.points[j])) >= h;
    ASSERT_GE(across, 3u);
    for (const KernelShape shape : {KernelShape::CubicSpline, KernelShape::WendlandC2})
        expectSumsMatch(cloud, 0, candidates, kernels::SmoothingKernel(h, shape), box);
}

}  // namespace
