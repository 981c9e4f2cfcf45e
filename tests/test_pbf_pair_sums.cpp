// pbf's SIMD pair loops (solvers/pbf_pair_sums.hpp) against the same sums in double precision
// (Macklin & Müller 2013, eq. 1, 11, 13 and 14), for lists of every length around the lane
// count, as indices and as offsets, with neighbours beyond the support among them (they must
// count for nothing), and across a periodic axis; and the per-pair factors the λ pass writes,
// nowhere past a list of indices.
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/kernels.hpp"
#include "core/periodic_box.hpp"
#include "neighbors/neighbor_list.hpp"
#include "solvers/pair_sums.hpp"
#include "solvers/pbf_pair_sums.hpp"

namespace {

using namespace tide;

std::vector<glm::vec4> randomRows(std::size_t n, float size, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> position(0.0f, size), weight(0.5f, 2.0f);
    std::vector<glm::vec4> rows;
    for (std::size_t i = 0; i < n; ++i) rows.emplace_back(position(random), position(random), position(random), weight(random));
    return rows;
}

pbf_sums::LambdaKernel kernelFor(float h, KernelShape shape, float spacing) {
    pbf_sums::LambdaKernel k{kernels::SmoothingKernel(h, shape)};
    const kernels::Spiky spiky(h);
    k.h = h;
    k.h2 = h * h;
    k.spikyGradient = spiky.gradNorm;
    k.invWdq = 1.0f / k.density.value(0.2f * h);
    const float rest = k.density.value(spacing) * k.invWdq;
    k.restTensile = rest * rest * rest * rest;
    k.tensileScale = -0.1f * h * h;
    return k;
}

/// Checks the three loops for particle i over the first `count` of `candidates`, every count.
void expectLoopsMatch(const std::vector<glm::vec4>& rows, std::uint32_t i, const std::vector<std::uint32_t>& candidates,
                      const pbf_sums::LambdaKernel& kernel, const PeriodicBox& box) {
    const glm::vec3 xi(rows[i]);
    const float vi = rows[i].w;
    std::vector<float> weighted(rows.size());  // w_j V_j², another weight per particle
    for (std::size_t j = 0; j < rows.size(); ++j) weighted[j] = 0.5f + 0.25f * static_cast<float>(j % 7);
    // Past the end (ignored): a near neighbour's index, as NeighborList's next lists.
    std::vector<std::uint32_t> indices = candidates;
    indices.resize(indices.size() + pair_sums::kPadding, candidates.front());
    std::vector<std::int16_t> offsets;
    for (const std::uint32_t j : candidates) offsets.push_back(static_cast<std::int16_t>(std::int64_t{j} - i));
    const std::size_t padded = (offsets.size() / NeighborList::kOffsetBlock + 1) * NeighborList::kOffsetBlock;
    offsets.resize(padded, 0);
    constexpr float kUnwritten = 12345.0f;
    for (const bool asOffsets : {false, true})
        for (std::size_t count = 0; count <= candidates.size(); ++count) {
            SCOPED_TRACE(asOffsets ? "as offsets" : "as indices");
            const auto n = static_cast<std::uint32_t>(count);
            const pair_sums::Neighbors neighbors(asOffsets ? NeighborSpan(offsets.data(), i, n)
                                                           : NeighborSpan(indices.data(), n));
            std::vector<float> factor(padded + pair_sums::kPadding, kUnwritten), tensile(factor);
            const pbf_sums::LambdaSums sums = pbf_sums::lambdaSums(neighbors, rows.data(), weighted.data(), xi, vi, kernel,
                                                                   box, factor.data(), tensile.data());
            double sumW = 0.0, squares = 0.0;
            glm::dvec3 gradient(0.0), gradientScale(0.0);
            std::size_t near = 0;
            for (std::size_t k = 0; k < count; ++k) {
                const std::uint32_t j = candidates[k];
                const glm::dvec3 d(box.delta(xi, glm::vec3(rows[j])));
                const double r = glm::length(d);
                double f = 0.0, s = 0.0;
                if (r < kernel.h) {
                    ++near;
                    const double wij = kernel.density.value(static_cast<float>(r));
                    sumW += wij;
                    f = kernel.spikyGradient * (kernel.h - r) * (kernel.h - r) / r;
                    gradient += f * d;
                    gradientScale += glm::abs(f * d);
                    squares += weighted[j] * f * f * glm::dot(d, d);
                    const double ratio = wij * kernel.invWdq;
                    s = 0.5 * (vi + rows[j].w) * kernel.tensileScale * std::max(std::pow(ratio, 4) - kernel.restTensile, 0.0);
                }
                // h − r in single precision near the support's edge: r's rounding (~1e-7 r) relative
                // to h − r, twice over in (h − r)², three times in W ∝ (h − r)³
                const double edge = 4e-7 * kernel.h / std::max(kernel.h - r, 1e-12);
                EXPECT_NEAR(factor[k], f, (1e-5 + edge) * std::abs(f) + 1e-9) << count << " neighbours, pair " << k;
                EXPECT_NEAR(tensile[k], s, (1e-5 + 4.0 * edge) * std::abs(s) + 1e-15) << count << " neighbours, pair " << k;
            }
            if (count == candidates.size()) {  // pairs within the support, and some beyond it
                ASSERT_GT(near, 4u);
                ASSERT_LT(near, count);
            }
            if (!asOffsets)  // nothing past a list of indices: the next list's slots are another thread's
                for (std::size_t k = count; k < factor.size(); ++k) {
                    EXPECT_EQ(factor[k], kUnwritten) << count << " neighbours, slot " << k;
                    EXPECT_EQ(tensile[k], kUnwritten) << count << " neighbours, slot " << k;
                }
            EXPECT_NEAR(sums.kernelSum, sumW, 1e-5 * sumW + 1e-9) << count << " neighbours";
            EXPECT_NEAR(sums.weightedSquares, squares, 1e-5 * squares + 1e-9) << count << " neighbours";
            for (int axis = 0; axis < 3; ++axis)
                EXPECT_NEAR(sums.gradient[axis], gradient[axis], 1e-5 * gradientScale[axis] + 1e-9) << count << " neighbours";
            // The boundary's sums (Σ ∇W, Σ W) over the same points as a list of indices.
            if (!asOffsets) {
                const glm::vec4 wall = pbf_sums::wallSums(neighbors, rows.data(), xi, kernel, box);
                EXPECT_NEAR(wall.w, sumW, 1e-5 * sumW + 1e-9) << count << " neighbours";
                for (int axis = 0; axis < 3; ++axis)
                    EXPECT_NEAR(wall[axis], gradient[axis], 1e-5 * gradientScale[axis] + 1e-9) << count << " neighbours";
            }
            // eq. 14 over the factors just written, with rows' w as λ_j V_j; what lies past the
            // list in the factors (the next list's, or the padding's) must add nothing.
            std::fill(factor.begin() + static_cast<std::ptrdiff_t>(count), factor.end(), 1e6f);
            const float li = -0.3f;
            const glm::vec3 dx = pbf_sums::correctionSum(neighbors, rows.data(), xi, li, factor.data(), tensile.data(), box);
            glm::dvec3 expected(0.0), scale(0.0);
            for (std::size_t k = 0; k < count; ++k) {
                const glm::dvec3 term = (double{li} + rows[candidates[k]].w + tensile[k]) * double{factor[k]} *
                                        glm::dvec3(box.delta(xi, glm::vec3(rows[candidates[k]])));
                expected += term;
                scale += glm::abs(term);
            }
            for (int axis = 0; axis < 3; ++axis)
                EXPECT_NEAR(dx[axis], expected[axis], 1e-5 * scale[axis] + 1e-9) << count << " neighbours";
        }
}

TEST(PbfPairSums, MatchTheSumsInDoubleForEveryListLength) {
    std::printf("pbf pair sums run on %s\n", pair_sums::instructionSet());
    const float h = 0.04f;
    const std::vector<glm::vec4> rows = randomRows(400, 2.0f * h, 7);
    const PeriodicBox none;
    // 23 of particle 0's candidates within 1.3 h: some beyond the support, as a list found
    // at the step's start holds once particles have moved.
    std::vector<std::uint32_t> candidates;
    for (std::uint32_t j = 1; j < rows.size() && candidates.size() < 23; ++j)
        if (glm::length(glm::vec3(rows[j]) - glm::vec3(rows[0])) < 1.3f * h) candidates.push_back(j);
    ASSERT_EQ(candidates.size(), 23u);
    for (const KernelShape shape : {KernelShape::CubicSpline, KernelShape::WendlandC2})
        expectLoopsMatch(rows, 0, candidates, kernelFor(h, shape, 0.5f * h), none);
}

TEST(PbfPairSums, TakeTheNearestImageAcrossAPeriodicAxis) {
    const float h = 0.04f, size = 0.2f;
    std::vector<glm::vec4> rows = randomRows(300, size, 11);
    const PeriodicBox box = PeriodicBox::make({0, 0, 0}, {size, size, size}, {true, false, true});
    rows[0] = glm::vec4(0.005f, 0.1f, 0.195f, 1.0f);  // at a corner of the periodic faces
    std::vector<std::uint32_t> candidates;
    for (std::uint32_t j = 1; j < rows.size(); ++j)
        if (glm::length(box.delta(glm::vec3(rows[0]), glm::vec3(rows[j]))) < 1.3f * h) candidates.push_back(j);
    std::size_t across = 0;  // neighbours near only through the periodic faces
    for (const std::uint32_t j : candidates) across += glm::length(glm::vec3(rows[0]) - glm::vec3(rows[j])) >= h;
    ASSERT_GE(across, 3u);
    expectLoopsMatch(rows, 0, candidates, kernelFor(h, KernelShape::CubicSpline, 0.5f * h), box);
}

}  // namespace
