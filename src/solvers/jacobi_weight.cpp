#include "solvers/jacobi_weight.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/kernels.hpp"

namespace tide {

float latticeJacobiGain(float supportRatio, KernelShape shape, int dimensions) {
    const kernels::SmoothingKernel w(supportRatio, shape, dimensions);
    const int reach = static_cast<int>(std::ceil(supportRatio));
    const int reachZ = dimensions == 2 ? 0 : reach;
    std::vector<glm::vec3> sites, gradients;
    double squares = 0.0;
    for (int x = -reach; x <= reach; ++x)
        for (int y = -reach; y <= reach; ++y)
            for (int z = -reachZ; z <= reachZ; ++z) {
                const glm::vec3 r(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
                const float length = glm::length(r);
                if (length <= 0.0f || length >= supportRatio) continue;
                const glm::vec3 g = w.gradient(r, length);
                sites.push_back(r);
                gradients.push_back(g);
                squares += glm::dot(g, g);
            }
    if (squares <= 0.0) return 0.0f;
    // G(k) is even in each component of k (the lattice's mirror symmetries): [0, π]³ covers the zone.
    constexpr int kSamples = 12;
    const int samplesZ = dimensions == 2 ? 0 : kSamples;
    double largest = 0.0;
    for (int a = 0; a <= kSamples; ++a)
        for (int b = 0; b <= kSamples; ++b)
            for (int c = 0; c <= samplesZ; ++c) {
                const glm::dvec3 k = std::numbers::pi * glm::dvec3(a, b, c) / static_cast<double>(kSamples);
                glm::dvec3 sum(0.0);
                for (std::size_t s = 0; s < sites.size(); ++s)
                    sum += std::sin(glm::dot(k, glm::dvec3(sites[s]))) * glm::dvec3(gradients[s]);
                largest = std::max(largest, glm::dot(sum, sum));
            }
    return static_cast<float>(largest / squares);
}

float jacobiWeightScale(float supportRatio, KernelShape shape, int dimensions) {
    constexpr float kTunedSupport = 2.0f;
    // 0.04 m / 0.02 m may round above 2
    if (shape == KernelShape::CubicSpline && supportRatio <= kTunedSupport + 1e-4f) return 1.0f;
    static const float tuned = latticeJacobiGain(kTunedSupport);
    static const float tuned2D = latticeJacobiGain(kTunedSupport, KernelShape::CubicSpline, 2);
    return std::min(1.0f, (dimensions == 2 ? tuned2D : tuned) / latticeJacobiGain(supportRatio, shape, dimensions));
}

}  // namespace tide
