#pragma once
/// \file
/// The energy of water carrying a standing wave, split: the linear mode's velocity field
/// (cosh ky sin kx, sinh ky cos kx and its quarter-period twin, fitted by least squares), a
/// smooth remainder (the residual averaged over 6 cm × 3 cm cells) and the particle-scale rest
/// (tide_standing_wave --energy; docs/waves.md § Where the height goes).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include <tide/particles.hpp>

namespace tide::bench {

struct ModeEnergy {
    double kinetic = 0.0, total = 0.0;  ///< J; total adds g y (from the floor)
    double smoothResidual = 0.0;        ///< kinetic energy of the residual's cell means, J
    double particleScale = 0.0;         ///< kinetic energy of the residual about its cell means, J
    std::vector<double> particleScaleRms;  ///< m/s, by 3 cm layer from the floor
};

inline ModeEnergy modeEnergy(const ParticleStore& q, double k, double g, float length, float height) {
    constexpr float kCellX = 0.06f, kCellY = 0.03f;
    ModeEnergy out;
    auto shape = [&](int m, const glm::vec3& x) {
        const double ch = std::cosh(k * x.y), sh = std::sinh(k * x.y), s = std::sin(k * x.x), c = std::cos(k * x.x);
        return m == 0 ? glm::dvec3(-ch * s, sh * c, 0.0) : glm::dvec3(ch * c, sh * s, 0.0);
    };
    double coefficient[2];
    for (int m = 0; m < 2; ++m) {
        double num = 0.0, den = 0.0;
        for (std::uint32_t i = 0; i < q.size(); ++i) {
            const glm::dvec3 f = shape(m, q.position[i]);
            num += glm::dot(glm::dvec3(q.velocity[i]), f);
            den += glm::dot(f, f);
        }
        coefficient[m] = den > 0.0 ? num / den : 0.0;
    }
    auto residual = [&](std::uint32_t i) {
        return glm::dvec3(q.velocity[i]) - coefficient[0] * shape(0, q.position[i]) - coefficient[1] * shape(1, q.position[i]);
    };
    const int nx = std::max(1, static_cast<int>(std::ceil(length / kCellX)));
    const int ny = std::max(1, static_cast<int>(std::ceil(height / kCellY)));
    auto cellOf = [&](std::uint32_t i) {
        return std::clamp(static_cast<int>(q.position[i].y / kCellY), 0, ny - 1) * nx +
               std::clamp(static_cast<int>(q.position[i].x / kCellX), 0, nx - 1);
    };
    std::vector<glm::dvec3> cellSum(static_cast<std::size_t>(nx * ny), glm::dvec3(0.0));
    std::vector<double> cellCount(cellSum.size(), 0.0), layerSum(static_cast<std::size_t>(ny), 0.0), layerCount(layerSum.size(), 0.0);
    for (std::uint32_t i = 0; i < q.size(); ++i) {
        cellSum[cellOf(i)] += residual(i);
        cellCount[cellOf(i)] += 1.0;
        out.kinetic += 0.5 * q.mass[i] * glm::dot(q.velocity[i], q.velocity[i]);
        out.total += q.mass[i] * g * q.position[i].y;
    }
    out.total += out.kinetic;
    for (std::uint32_t i = 0; i < q.size(); ++i) {
        const int c = cellOf(i);
        const glm::dvec3 mean = cellSum[c] / cellCount[c], dv = residual(i) - mean;
        out.smoothResidual += 0.5 * q.mass[i] * glm::dot(mean, mean);
        out.particleScale += 0.5 * q.mass[i] * glm::dot(dv, dv);
        layerSum[c / nx] += glm::dot(dv, dv);
        layerCount[c / nx] += 1.0;
    }
    for (int l = 0; l < ny; ++l)
        if (layerCount[l] > 0.0) out.particleScaleRms.push_back(std::sqrt(layerSum[l] / layerCount[l]));
    return out;
}

}  // namespace tide::bench
