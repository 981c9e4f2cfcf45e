#include "ocean/sea_surface.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

#include "core/parallel.hpp"

namespace tide::ocean {

namespace {
/// A component's weight on a mesh of spacing Δ: 1 up to kΔ = π/2 (four samples a wavelength),
/// smoothly to 0 at kΔ = π (two: the mesh's Nyquist limit).
double detailWeight(double k, double spacing) {
    const double s = std::clamp((k * spacing - 0.5 * std::numbers::pi) / (0.5 * std::numbers::pi), 0.0, 1.0);
    return 1.0 - s * s * (3.0 - 2.0 * s);
}
}  // namespace

void sampleSurface(const Sea& sea, std::span<const glm::dvec2> rest, std::span<const float> spacing,
                   const SurfaceSampling& sampling, std::span<SurfacePoint> out, int threads) {
    if (spacing.size() != rest.size() || out.size() != rest.size())
        throw std::invalid_argument("sampleSurface: rest, spacing and out must have the same size");
    const auto& components = sea.components();
    const double d = sea.depth();
    // The displacement's amplitude V/ω per component (a for a free wave).
    std::vector<double> moving(components.size());
    for (std::size_t n = 0; n < components.size(); ++n) moving[n] = sea.velocityAmplitude(n) / components[n].omega;
    parallelFor(static_cast<std::uint32_t>(rest.size()), threads, [&](std::uint32_t i) {
        const glm::dvec2 x = rest[i];
        double eta = 0.0, slopeX = 0.0, slopeZ = 0.0;
        glm::dvec2 shift(0.0);
        for (std::size_t n = 0; n < components.size(); ++n) {
            const WaveComponent& c = components[n];
            const double k = std::hypot(c.kx, c.kz);
            const double weight = detailWeight(k, spacing[i]), a = c.amplitude * weight;
            if (a == 0.0 || k == 0.0) continue;
            const double theta = c.kx * x.x + c.kz * x.y - c.omega * sampling.time + c.phase;
            const double cosTheta = std::cos(theta), sinTheta = std::sin(theta);
            eta += a * cosTheta;  // Sea::elevation
            slopeX -= a * c.kx * sinTheta;
            slopeZ -= a * c.kz * sinTheta;
            // Sea::horizontalDisplacement: −(V/ω) coth(kd) sin θ k/|k|
            const double coth = 1.0 / std::tanh(k * d);
            shift -= (moving[n] * weight * coth * sinTheta / k) * glm::dvec2(c.kx, c.kz);
        }
        const double r = sampling.ramp;
        const glm::dvec2 moved = sampling.choppy ? x + r * shift : x;
        out[i].position = glm::vec3(moved.x, sampling.stillWaterY + r * eta, moved.y);
        out[i].normal = glm::vec3(glm::normalize(glm::dvec3(-r * slopeX, 1.0, -r * slopeZ)));
    });
}

}  // namespace tide::ocean
