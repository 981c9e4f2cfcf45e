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
    const double inf = std::numeric_limits<double>::infinity();
    faceLow_ = {openFaces_ & 1u ? double{near.min.x} : -inf, openFaces_ & 16u ? double{near.min.z} : -inf};
    faceHigh_ = {openFaces_ & 2u ? double{near.max.x} : inf, openFaces_ & 32u ? double{near.max.z} : inf};
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
    // The lattice covers the near field and three steps beyond its faces; only the columns
    // within reach of a band (a cubic stencil: two steps) are evaluated.
    LatticeSpec spec;
    spec.step = kLatticeSpacings * near.spacing;
    constexpr int kMargin = 3;
    spec.origin = glm::dvec2(near.min.x, near.min.z) - static_cast<double>(kMargin) * spec.step;
    spec.columnsX = static_cast<int>(std::ceil((near.max.x - near.min.x) / spec.step)) + 2 * kMargin + 1;
    spec.columnsZ = static_cast<int>(std::ceil((near.max.z - near.min.z) / spec.step)) + 2 * kMargin + 1;
    // Levels half a step apart: the short waves' profiles grow fast towards the surface
    // (ocean_pile's sea: velocity error 4.4 % with levels a step apart, 1.9 % at half a step).
    spec.levels = std::max(2, static_cast<int>(std::ceil(2.0 * def.depth / spec.step)));
    spec.used.assign(static_cast<std::size_t>(spec.columnsX) * static_cast<std::size_t>(spec.columnsZ), 0);
    // In 2D the particles lie on the plane z = min.z, on the row of columns kMargin steps in,
    // where the stencil's weights across are (0, 1, 0, 0): only that row is evaluated (the
    // others read as still water with weight 0), a seventh of the sums and a quarter of each
    // particle's stencil (a 2D flume's coupling was 13 % of its step, SeaLattice::velocity 7 %).
    const bool planar = !(near.max.z > near.min.z);
    for (int j = 0; j < spec.columnsZ; ++j)
        for (int i = 0; i < spec.columnsX; ++i) {
            const glm::vec3 x(spec.origin.x + i * spec.step, near.min.y, spec.origin.y + j * spec.step);
            const bool reached = !planar || j == kMargin;
            spec.used[static_cast<std::size_t>(j) * static_cast<std::size_t>(spec.columnsX) + static_cast<std::size_t>(i)] =
                reached && distanceToOpenFace(x) < width_ + kMargin * spec.step ? 1 : 0;
        }
    // Knots of the lattice in time an eighth of the shortest component's period apart: the
    // Hermite blend's error is (ω Δt)⁴/384 ≈ 1e-3 of that component (far less at the peak).
    double fastest = 0.0;
    for (const WaveComponent& c : sea_.components()) fastest = std::max(fastest, c.omega);
    knotStep_ = fastest > 0.0 ? 2.0 * std::numbers::pi / fastest / kKnotsPerPeriod : 1.0;
    knots_.emplace_back(sea_, spec);
    knots_.emplace_back(sea_, spec);
    lattice_.emplace(sea_, std::move(spec));
}

double RelaxationZones::ramp(double t) const {
    if (t >= rampTime_) return 1.0;
    if (t <= 0.0) return 0.0;
    return 0.5 * (1.0 - std::cos(std::numbers::pi * t / rampTime_));
}

double RelaxationZones::distanceToOpenFace(const glm::vec3& x) const {
    // A closed face stands at ∓infinity: four subtractions and a min, no branch per side.
    return std::min(std::min(double{x.x} - faceLow_.x, faceHigh_.x - double{x.x}),
                    std::min(double{x.z} - faceLow_.y, faceHigh_.y - double{x.z}));
}

double RelaxationZones::rate(const glm::vec3& x) const { return rateAt(distanceToOpenFace(x)); }

double RelaxationZones::rateAt(double s) const {
    if (!(s < width_)) return 0.0;
    const double chi = std::clamp(1.0 - s / width_, 0.0, 1.0);
    // 1 − α_R(χ) of Jacobsen et al. 2012, eq. 11: 0 at the inner edge, 1 at the outer
    // (χ^3.5 as χ³ √χ).
    const double weight = std::expm1(chi * chi * chi * std::sqrt(chi)) / (std::numbers::e - 1.0);
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

const SeaLattice& RelaxationZones::lattice(double t, int threads) {
    if (lattice_->time() == t) return *lattice_;
    // The knots around t, at multiples of knotStep_ (so a resumed run meets the same ones).
    const double ta = std::floor(t / knotStep_) * knotStep_, tb = ta + knotStep_;
    if (knots_[0].time() != ta) {
        if (knots_[1].time() == ta)
            std::swap(knots_[0], knots_[1]);
        else
            knots_[0].update(ta, threads, true);
    }
    if (knots_[1].time() != tb) knots_[1].update(tb, threads, true);
    lattice_->blend(knots_[0], knots_[1], std::clamp(t, ta, tb), threads);
    return *lattice_;
}

glm::dvec3 RelaxationZones::velocityFrom(const SeaLattice& lattice, const glm::vec3& x, double r) const {
    return r * lattice.velocity(glm::dvec3(x.x, x.y - near_.stillWaterY, x.z));
}

glm::dvec3 RelaxationZones::latticeVelocity(const glm::vec3& x, double t, int threads) {
    const double r = ramp(t);
    if (r == 0.0) return glm::dvec3(0.0);
    return velocityFrom(lattice(t, threads), x, r);
}

void RelaxationZones::holdBegin(const ParticleStore& particles) {
    held_.clear();
    heldFrom_.clear();
    heldVelocity_.clear();
    const double buffer = kBufferSpacings * near_.spacing;
    for (std::uint32_t i = 0; i < particles.size(); ++i)
        if (distanceToOpenFace(particles.position[i]) < buffer) {
            held_.push_back(i);
            heldFrom_.push_back(particles.position[i]);
            heldVelocity_.push_back(particles.velocity[i]);
        }
}

void RelaxationZones::holdEnd(ParticleStore& particles, double t0, double dt, bool clockHeld, int threads) {
    if (held_.empty()) return;
    const double end = clockHeld ? t0 : t0 + dt;
    const double r1 = ramp(end);
    if (r1 == 0.0) {
        parallelFor(static_cast<std::uint32_t>(held_.size()), threads, [&](std::uint32_t k) {
            particles.position[held_[k]] = heldFrom_[k];
            particles.velocity[held_[k]] = glm::vec3(0.0f);
        });
        return;
    }
    // The trapezoid of the velocity at the step's start (the far field's there for a particle
    // held the step before) and the far field's at its end; the end's velocity is taken where
    // the particle started (it moves a fraction of a spacing: u dt).
    const SeaLattice& to = lattice(end, threads);
    parallelFor(static_cast<std::uint32_t>(held_.size()), threads, [&](std::uint32_t k) {
        const std::uint32_t i = held_[k];
        const glm::vec3 u(velocityFrom(to, heldFrom_[k], r1));
        particles.position[i] = heldFrom_[k] + static_cast<float>(0.5 * dt) * (heldVelocity_[k] + u);
        particles.velocity[i] = u;
    });
}

void RelaxationZones::relax(ParticleStore& particles, double t, double dt, int threads) {
    const double r = ramp(t);
    const SeaLattice* field = r == 0.0 ? nullptr : &lattice(t, threads);
    const double buffer = kBufferSpacings * near_.spacing;
    parallelFor(particles.size(), threads, [&](std::uint32_t i) {
        const double s = distanceToOpenFace(particles.position[i]);
        // Outside the bands nothing; in the buffers the particles move with the far field.
        if (!(s < width_) || s < buffer) return;
        const double rate = rateAt(s);
        const glm::dvec3 target = field ? velocityFrom(*field, particles.position[i], r) : glm::dvec3(0.0);
        const double keep = std::exp(-dt * rate);
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
                                      const std::function<bool(const glm::vec3&)>& room, int threads,
                                      std::vector<std::uint64_t>* visits) {
    const double r = ramp(t);
    const SeaLattice* field = r == 0.0 ? nullptr : &lattice(t, threads);
    const double s = near_.spacing;
    const double strip = kStripSpacings * s;
    // The particles near the strips, binned in cells of one spacing.
    const auto cellOf = [&](const glm::dvec3& x) {
        const auto c = glm::floor(x / s);
        return (static_cast<std::int64_t>(c.x) & 0x1fffff) | (static_cast<std::int64_t>(c.y) & 0x1fffff) << 21 |
               (static_cast<std::int64_t>(c.z) & 0x1fffff) << 42;
    };
    // Sorted by cell (a vector, not a map of vectors: this runs every step); the particles
    // added here go to a map, few after the ramp.
    binned_.clear();
    for (std::uint32_t i = 0; i < particles.size(); ++i)
        if (distanceToOpenFace(particles.position[i]) < strip + 2.0 * s)
            binned_.emplace_back(cellOf(glm::dvec3(particles.position[i])), particles.position[i]);
    std::sort(binned_.begin(), binned_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::unordered_map<std::int64_t, std::vector<glm::vec3>> addedCells;
    const auto occupied = [&](const glm::dvec3& x) {
        const double r2 = kRoomSpacings * kRoomSpacings * s * s;
        const auto near = [&](const glm::vec3& p) {
            const glm::dvec3 d = glm::dvec3(p) - x;
            return glm::dot(d, d) < r2;
        };
        // The point's own cell first: where water is, its particle is usually there.
        for (int n = 0; n < 27; ++n) {
            const int m = (n + 13) % 27;  // 13: the middle cell
            const std::int64_t key = cellOf(x + s * glm::dvec3(m % 3 - 1, m / 3 % 3 - 1, m / 9 - 1));
            auto at = std::lower_bound(binned_.begin(), binned_.end(), key,
                                       [](const auto& entry, std::int64_t k) { return entry.first < k; });
            for (; at != binned_.end() && at->first == key; ++at)
                if (near(at->second)) return true;
            if (addedCells.empty()) continue;
            const auto found = addedCells.find(key);
            if (found != addedCells.end())
                for (const glm::vec3& p : found->second)
                    if (near(p)) return true;
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
    std::uint64_t visited = 0;  // lattice points under the surface so far, on every rank alike
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
                const double surface = near_.stillWaterY + (field ? r * field->elevation(x.x, x.z) : 0.0);
                for (long k = up.first; k <= up.second; ++k) {
                    x.y = near_.latticeOrigin.y + (static_cast<double>(k) + 0.5) * s;
                    // A cell wholly under the far field's surface.
                    if (x.y + 0.5 * s > surface) break;
                    const std::uint64_t visit = visited++;
                    const glm::vec3 p(x);
                    if (outside(p) || occupied(x) || !room(p)) continue;
                    if (particles.size() >= capacity) return added;
                    particles.append(p, field ? glm::vec3(velocityFrom(*field, p, r)) : glm::vec3(0.0f), mass, material,
                                     restDensity);
                    addedCells[cellOf(x)].push_back(p);
                    if (visits) visits->push_back(visit);
                    ++added;
                    ++totals_.added;
                }
            }
    }
    return added;
}

}  // namespace tide::ocean
