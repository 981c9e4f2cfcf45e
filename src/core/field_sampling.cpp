#include "core/field_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "core/kernels.hpp"

namespace tide {

float freeSurfaceHeight(const ParticleStore& particles, std::span<const MaterialDef> materials, const PeriodicBox& box,
                        const kernels::SmoothingKernel& w, float x, float z) {
    const float h = w.h;
    struct Near {
        float y, horizontal2, volume;
    };
    std::vector<Near> near;
    float top = -std::numeric_limits<float>::infinity(), bottom = std::numeric_limits<float>::infinity();
    for (std::uint32_t j = 0; j < particles.size(); ++j) {
        const glm::vec3 d = box.delta(particles.position[j], glm::vec3(x, particles.position[j].y, z));
        const float horizontal2 = d.x * d.x + d.z * d.z;
        if (horizontal2 >= h * h) continue;
        near.push_back({particles.position[j].y, horizontal2, particles.mass[j] / materials[particles.material[j]].restDensity});
        top = std::max(top, particles.position[j].y);
        bottom = std::min(bottom, particles.position[j].y);
    }
    if (near.empty()) return std::numeric_limits<float>::quiet_NaN();
    const auto colour = [&](float y) {
        double c = 0.0;
        for (const Near& n : near) c += n.volume * w.value(std::sqrt(n.horizontal2 + (y - n.y) * (y - n.y)));
        return c;
    };
    const float step = h / 8.0f;
    float above = top + h;
    for (float y = above - step; y >= bottom - h; y -= step) {
        if (colour(y) >= 0.5) {
            float lo = y, hi = above;  // c(lo) ≥ ½ > c(hi)
            for (int k = 0; k < 24; ++k) {
                const float mid = 0.5f * (lo + hi);
                (colour(mid) >= 0.5 ? lo : hi) = mid;
            }
            return 0.5f * (lo + hi);
        }
        above = y;
    }
    return std::numeric_limits<float>::quiet_NaN();
}

FieldSample sampleField(const ParticleStore& particles, std::span<const MaterialDef> materials, const PeriodicBox& box,
                        const kernels::SmoothingKernel& w, const glm::vec3& point) {
    double weight = 0.0, density = 0.0, pressure = 0.0;
    glm::dvec3 velocity(0.0);
    for (std::uint32_t j = 0; j < particles.size(); ++j) {
        const float r = glm::length(box.delta(point, particles.position[j]));
        if (r >= w.h) continue;
        const double vw = particles.mass[j] / materials[particles.material[j]].restDensity * w.value(r);
        weight += vw;
        density += vw * particles.density[j];
        pressure += vw * particles.pressure[j];
        velocity += vw * glm::dvec3(particles.velocity[j]);
    }
    if (!(weight > 0.0)) {
        const float nan = std::numeric_limits<float>::quiet_NaN();
        return {nan, nan, glm::vec3(nan)};
    }
    return {static_cast<float>(density / weight), static_cast<float>(pressure / weight), glm::vec3(velocity / weight)};
}

}  // namespace tide
