#include "boundary/boundary_particles.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "core/parallel.hpp"

namespace tide {

namespace {
/// Lattice coordinates along one axis: `layers` beyond each wall, and the interior lattice
/// min + (i + ½)·step stretched to fit the extent exactly.
std::vector<float> axisCoordinates(float lo, float hi, float spacing, int layers, std::vector<bool>& inside) {
    const float extent = hi - lo;
    const int n = std::max(1, static_cast<int>(std::lround(extent / spacing)));
    const float step = extent / static_cast<float>(n);
    std::vector<float> coords;
    inside.clear();
    for (int k = layers - 1; k >= 0; --k) {
        coords.push_back(lo - (static_cast<float>(k) + 0.5f) * spacing);
        inside.push_back(false);
    }
    for (int i = 0; i < n; ++i) {
        coords.push_back(lo + (static_cast<float>(i) + 0.5f) * step);
        inside.push_back(true);
    }
    for (int k = 0; k < layers; ++k) {
        coords.push_back(hi + (static_cast<float>(k) + 0.5f) * spacing);
        inside.push_back(false);
    }
    return coords;
}
}  // namespace

void BoundaryParticles::sampleBoxShell(const glm::vec3& min, const glm::vec3& max, float spacing, int layers,
                                       float particleVolume, float searchRadius, int threads, unsigned openFaces,
                                       int dimensions) {
    std::vector<bool> inX, inY, inZ;
    const auto layersAlong = [&](int axis) { return periodic.periodic(axis) || (axis == 2 && dimensions == 2) ? 0 : layers; };
    const auto xs = axisCoordinates(min.x, max.x, spacing, layersAlong(0), inX);
    const auto ys = axisCoordinates(min.y, max.y, spacing, layersAlong(1), inY);
    const auto zs = axisCoordinates(min.z, max.z, spacing, layersAlong(2), inZ);
    position.clear();
    // Exactly the shell's count: doubling growth left half of it unused (the shell outnumbers
    // the fluid 2.5 to 1 in the 50k benchmark dam break).
    const auto inside = [](const std::vector<bool>& in) { return static_cast<std::size_t>(std::count(in.begin(), in.end(), true)); };
    position.reserve(xs.size() * ys.size() * zs.size() - inside(inX) * inside(inY) * inside(inZ));
    solid.clear();
    solid.reserve(position.capacity());
    for (std::size_t k = 0; k < zs.size(); ++k)
        for (std::size_t j = 0; j < ys.size(); ++j)
            for (std::size_t i = 0; i < xs.size(); ++i)
                if (!(inX[i] && inY[j] && inZ[k])) {
                    const std::size_t at[3] = {i, j, k};
                    const std::vector<bool>* in[3] = {&inX, &inY, &inZ};
                    bool open = false;
                    for (int axis = 0; axis < 3; ++axis)
                        if (!(*in[axis])[at[axis]]) {
                            const bool maxSide = at[axis] >= static_cast<std::size_t>(layersAlong(axis));
                            open = open || (openFaces >> (2 * axis + (maxSide ? 1 : 0)) & 1u) != 0;
                        }
                    if (open) continue;
                    const glm::vec3 x(xs[i], ys[j], zs[k]);
                    position.push_back(x);
                    // Which face: the axis it lies most layers outside along (x, z, y on ties).
                    const std::size_t index[3] = {i, j, k};
                    const std::size_t count[3] = {xs.size(), ys.size(), zs.size()};
                    std::uint16_t face = kWallFace;
                    std::size_t deepest = 0;
                    for (const int axis : {0, 2, 1}) {
                        const std::size_t beyond = static_cast<std::size_t>(layersAlong(axis));
                        const std::size_t n = index[axis];
                        const std::size_t depth = n < beyond ? beyond - n : (n + beyond >= count[axis] ? n + beyond + 1 - count[axis] : 0);
                        if (depth > deepest) {
                            deepest = depth;
                            face = static_cast<std::uint16_t>(kWallFace + 2 * axis + (n >= beyond ? 1 : 0));
                        }
                    }
                    solid.push_back(face);
                }
    volume = particleVolume;
    velocity.assign(moving ? position.size() : 0, glm::vec3(0.0f));
    acceleration.assign(moving ? position.size() : 0, glm::vec3(0.0f));
    movable.assign(position.size(), 0);
    grid.build(position, searchRadius, threads, periodic);
}

std::uint32_t BoundaryParticles::add(std::span<const glm::vec3> points, float particleVolume, float minSeparation,
                                     float searchRadius, int threads, std::uint16_t solidIndex) {
    setVolume(particleVolume);
    // Moving particles are elsewhere soon: fixed points are checked against fixed particles only.
    std::vector<std::uint8_t> keep(points.size(), 1);
    movable.resize(position.size(), 0);  // positions set by hand are fixed
    solid.resize(position.size(), 0);    // and count towards solid 0
    if (!position.empty())
        parallelFor(static_cast<std::uint32_t>(points.size()), threads,
                    [&](std::uint32_t i) { keep[i] = !anyCloserThan(points[i], minSeparation, true); });
    const std::size_t before = position.size();
    for (std::size_t i = 0; i < points.size(); ++i)
        if (keep[i]) position.push_back(points[i]);
    if (moving) {
        velocity.resize(position.size(), glm::vec3(0.0f));
        acceleration.resize(position.size(), glm::vec3(0.0f));
    }
    movable.resize(position.size(), 0);
    solid.resize(position.size(), solidIndex);
    grid.build(position, searchRadius, threads, periodic);
    return static_cast<std::uint32_t>(position.size() - before);
}

void BoundaryParticles::setVolume(float particleVolume) {
    if (!position.empty() && particleVolume != volume)
        throw std::invalid_argument("BoundaryParticles: volume " + std::to_string(particleVolume) +
                                    " m3 differs from the " + std::to_string(volume) +
                                    " m3 of the boundary particles already sampled (all sample one lattice)");
    volume = particleVolume;
}

bool BoundaryParticles::anyCloserThan(const glm::vec3& x, float radius, bool fixedOnly) const {
    if (position.empty()) return false;
    // The grid's cells are at least its search radius wide, so any particle within `radius`
    // of x lies in the 3×3×3 cells around it.
    const auto sorted = grid.sortedParticles();
    const float limit2 = radius * radius;
    bool found = false;
    grid.forEachNeighborRun(grid.cellOf(x), [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t k = begin; k < end && !found; ++k) {
            if (fixedOnly && movable[sorted[k]]) continue;
            const glm::vec3 d = periodic.delta(position[sorted[k]], x);
            found = glm::dot(d, d) < limit2;
        }
    });
    return found;
}

std::uint32_t BoundaryParticles::addMoving(std::span<const glm::vec3> points, float particleVolume,
                                           std::uint16_t solidIndex) {
    setVolume(particleVolume);
    solid.resize(position.size(), 0);
    solid.resize(position.size() + points.size(), solidIndex);
    const auto begin = static_cast<std::uint32_t>(position.size());
    position.insert(position.end(), points.begin(), points.end());
    velocity.resize(position.size(), glm::vec3(0.0f));
    acceleration.resize(position.size(), glm::vec3(0.0f));
    movable.resize(position.size(), 1);
    moving = true;
    return begin;
}

}  // namespace tide
