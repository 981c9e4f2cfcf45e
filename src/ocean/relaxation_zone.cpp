#include "ocean/relaxation_zone.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "core/parallel.hpp"

namespace tide::ocean {

namespace {

/// The inflow strip along an open face, in spacings: deep enough that the particles pushed out
/// by the pressure at the open edge leave a hole the refill sees.
constexpr double kStripSpacings = 2.0;
/// A lattice point nearer than this (in spacings) to a particle has no room (World's blocks
/// keep the same distance to solids).
constexpr double kRoomSpacings = 0.9;

int axisOf(OceanSide side) { return side == OceanSide::MinusX || side == OceanSide::PlusX ? 0 : 2; }
bool maxSide(OceanSide side) { return side == OceanSide::PlusX || side == OceanSide::PlusZ; }

}  // namespace

RelaxationZones::RelaxationZones(const OceanDef& def, const NearField& near, double g)
    : sea_(Sea::fromDef(def, g)), near_(near), sides_(def.openSides), width_(oceanZoneWidth(def, g)) {
    const double period = def.waves.type == OceanWavesDef::Type::Regular ? def.waves.period : def.waves.tp;
    rampTime_ = period;
    tau0_ = period / kRelaxationSteps;
    for (const OceanSide side : sides_) openFaces_ |= 1u << (2 * axisOf(side) + (maxSide(side) ? 1 : 0));
    for (const int axis : {0, 2}) {
        const int open = ((openFaces_ >> (2 * axis)) & 1u) + ((openFaces_ >> (2 * axis + 1)) & 1u);
        const double extent = near.max[axis] - near.min[axis];
        if (open * width_ > extent) {
            std::ostringstream msg;
            msg << "ocean.zone_width: " << open << " zone(s) of " << width_ << " m do not fit in the near field's "
                << extent << " m along " << (axis == 0 ? "x" : "z") << ", got " << def.zoneWidth;
            throw std::invalid_argument(msg.str());
        }
    }
}

double RelaxationZones::ramp(double t) const {
    if (t >= rampTime_) return 1.0;
    if (t <= 0.0) return 0.0;
    return 0.5 * (1.0 - std::cos(std::numbers::pi * t / rampTime_));
}

double RelaxationZones::distanceToOpenFace(const glm::vec3& x) const {
    double nearest = std::numeric_limits<double>::infinity();
    for (const OceanSide side : sides_) {
        const int axis = axisOf(side);
        const double s = maxSide(side) ? double{near_.max[axis]} - x[axis] : double{x[axis]} - near_.min[axis];
        nearest = std::min(nearest, s);
    }
    return nearest;
}

double RelaxationZones::rate(const glm::vec3& x) const {
    const double s = distanceToOpenFace(x);
    if (!(s < width_)) return 0.0;
    const double chi = std::clamp(1.0 - s / width_, 0.0, 1.0);
    // 1 − α_R(χ) of Jacobsen et al. 2012, eq. 11: 0 at the inner edge, 1 at the outer.
    const double weight = (std::exp(std::pow(chi, 3.5)) - 1.0) / (std::numbers::e - 1.0);
    return weight / tau0_;
}

double RelaxationZones::surfaceY(double x, double z, double t) const {
    return near_.stillWaterY + ramp(t) * sea_.elevation(x, z, t);
}

glm::dvec3 RelaxationZones::velocity(const glm::vec3& x, double t) const {
    const double r = ramp(t);
    if (r == 0.0) return glm::dvec3(0.0);
    const glm::dvec3 p(x.x, x.y - near_.stillWaterY, x.z);
    return r * sea_.sample(p, t).velocity;
}

bool RelaxationZones::outside(const glm::vec3& x) const { return distanceToOpenFace(x) < 0.0; }

void RelaxationZones::holdBegin(const ParticleStore& particles) {
    held_.clear();
    heldFrom_.clear();
    const double buffer = kBufferSpacings * near_.spacing;
    for (std::uint32_t i = 0; i < particles.size(); ++i)
        if (distanceToOpenFace(particles.position[i]) < buffer) {
            held_.push_back(i);
            heldFrom_.push_back(particles.position[i]);
        }
}

void RelaxationZones::holdEnd(ParticleStore& particles, double t0, double dt, bool clockHeld, int threads) {
    const double mid = clockHeld ? t0 : t0 + 0.5 * dt, end = clockHeld ? t0 : t0 + dt;
    parallelFor(static_cast<std::uint32_t>(held_.size()), threads, [&](std::uint32_t k) {
        const std::uint32_t i = held_[k];
        const glm::vec3 x = heldFrom_[k] + static_cast<float>(dt) * glm::vec3(velocity(heldFrom_[k], mid));
        particles.position[i] = x;
        particles.velocity[i] = glm::vec3(velocity(x, end));
    });
}

void RelaxationZones::relax(ParticleStore& particles, double t, double dt, int threads) const {
    parallelFor(particles.size(), threads, [&](std::uint32_t i) {
        const double r = rate(particles.position[i]);
        if (r == 0.0) return;
        const glm::dvec3 target = velocity(particles.position[i], t);
        const double keep = std::exp(-dt * r);
        const glm::dvec3 v(particles.velocity[i]);
        particles.velocity[i] = glm::vec3(target + (v - target) * keep);
    });
}

std::uint32_t RelaxationZones::removeOutflow(ParticleStore& particles) {
    keep_.assign(particles.size(), 1);
    std::uint32_t removed = 0;
    for (std::uint32_t i = 0; i < particles.size(); ++i)
        if (outside(particles.position[i])) {
            keep_[i] = 0;
            ++removed;
        }
    if (removed > 0) particles.retain(keep_);
    totals_.removed += removed;
    return removed;
}

std::uint32_t RelaxationZones::refill(ParticleStore& particles, double t, float mass, MaterialIndex material,
                                      float restDensity, std::uint32_t capacity,
                                      const std::function<bool(const glm::vec3&)>& room) {
    const double s = near_.spacing;
    const double strip = kStripSpacings * s;
    // The particles near the strips, binned in cells of one spacing.
    const auto cellOf = [&](const glm::dvec3& x) {
        const auto c = glm::floor(x / s);
        return (static_cast<std::int64_t>(c.x) & 0x1fffff) | (static_cast<std::int64_t>(c.y) & 0x1fffff) << 21 |
               (static_cast<std::int64_t>(c.z) & 0x1fffff) << 42;
    };
    std::unordered_map<std::int64_t, std::vector<glm::vec3>> cells;
    for (std::uint32_t i = 0; i < particles.size(); ++i)
        if (distanceToOpenFace(particles.position[i]) < strip + 2.0 * s)
            cells[cellOf(glm::dvec3(particles.position[i]))].push_back(particles.position[i]);
    const auto occupied = [&](const glm::dvec3& x) {
        const double r2 = kRoomSpacings * kRoomSpacings * s * s;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const auto found = cells.find(cellOf(x + s * glm::dvec3(dx, dy, dz)));
                    if (found == cells.end()) continue;
                    for (const glm::vec3& p : found->second) {
                        const glm::dvec3 d = glm::dvec3(p) - x;
                        if (glm::dot(d, d) < r2) return true;
                    }
                }
        return false;
    };
    // Lattice indices k with origin + (k + ½)s in [lo, hi].
    const auto range = [&](int axis, double lo, double hi) {
        const double o = near_.latticeOrigin[axis];
        return std::pair<long, long>{static_cast<long>(std::ceil((lo - o) / s - 0.5 - 1e-6)),
                                     static_cast<long>(std::floor((hi - o) / s - 0.5 + 1e-6))};
    };
    std::uint32_t added = 0;
    for (const OceanSide side : sides_) {
        const int axis = axisOf(side), other = 2 - axis;
        const double face = maxSide(side) ? near_.max[axis] : near_.min[axis];
        const auto along = maxSide(side) ? range(axis, face - strip, face) : range(axis, face, face + strip);
        const auto across = range(other, near_.min[other], near_.max[other]);
        const auto up = range(1, near_.min.y, near_.max.y);
        for (long a = along.first; a <= along.second; ++a)
            for (long c = across.first; c <= across.second; ++c) {
                glm::dvec3 x;
                x[axis] = near_.latticeOrigin[axis] + (static_cast<double>(a) + 0.5) * s;
                x[other] = near_.latticeOrigin[other] + (static_cast<double>(c) + 0.5) * s;
                const double surface = surfaceY(x.x, x.z, t);
                for (long k = up.first; k <= up.second; ++k) {
                    x.y = near_.latticeOrigin.y + (static_cast<double>(k) + 0.5) * s;
                    // A cell wholly under the far field's surface.
                    if (x.y + 0.5 * s > surface) break;
                    const glm::vec3 p(x);
                    if (outside(p) || occupied(x) || !room(p)) continue;
                    if (particles.size() >= capacity) return added;
                    particles.append(p, glm::vec3(velocity(p, t)), mass, material, restDensity);
                    cells[cellOf(x)].push_back(p);
                    ++added;
                    ++totals_.added;
                }
            }
    }
    return added;
}

}  // namespace tide::ocean
