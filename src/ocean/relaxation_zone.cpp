#include "ocean/relaxation_zone.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "core/parallel.hpp"

namespace tide::ocean {

namespace {

/// The inflow strip along an open face, in spacings: deep enough that the particles pushed out
/// by the pressure at the open edge leave a hole the refill sees.
constexpr double kStripSpacings = 2.0;

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
    // A Stokes wave's levels reach up to its crests (SeaLattice): as many more.
    spec.levels = std::max(2, static_cast<int>(std::ceil(2.0 * (def.depth + sea_.kinematicTop()) / spec.step)));
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
    knotStep_ = knotStep(sea_);
    knots_.emplace_back(sea_, spec);
    knots_.emplace_back(sea_, spec);
    lattice_.emplace(sea_, std::move(spec));
}

double knotStep(const Sea& sea) {
    double largest = 0.0;
    for (const WaveComponent& c : sea.components()) largest = std::max(largest, c.amplitude);
    // a (ω Δ)⁴ ≤ a_max (2π/kKnotsPerPeriod)⁴ for every component.
    const double reach = 2.0 * std::numbers::pi / kKnotsPerPeriod;
    double step = std::numeric_limits<double>::infinity();
    for (const WaveComponent& c : sea.components())
        if (c.amplitude > 0.0 && c.omega > 0.0) step = std::min(step, reach * std::pow(largest / c.amplitude, 0.25) / c.omega);
    return std::isfinite(step) ? step : 1.0;
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
    // 1 − α_R(χ) of Jacobsen et al. 2012, eq. 11: 0 at the inner edge, 1 at the outer.
    const double weight = std::expm1(std::pow(chi, kRelaxationExponent)) / (std::numbers::e - 1.0);
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
    return removed;
}

double RelaxationZones::levelError(std::int64_t exchanged, double t) const {
    const bool planar = !(near_.max.z > near_.min.z);
    const double s = near_.spacing;
    const double cell = planar ? s * near_.layer : s * near_.layer * s;  // m² in 2D, m³ in 3D
    const double area = (near_.max.x - near_.min.x) * (planar ? 1.0 : near_.max.z - near_.min.z);
    const double far = ramp(t) * sea_.meanElevation({near_.min.x, near_.min.z}, {near_.max.x, near_.max.z}, t);
    return static_cast<double>(exchanged) * cell / area - far;
}

double RelaxationZones::refillRoom(double levelError) const {
    return kRefillRoomSpacings +
           std::clamp(kRefillRoomPerSpacing * levelError / near_.spacing, -kRefillRoomSwing, kRefillRoomSwing);
}

std::uint32_t RelaxationZones::refill(ParticleStore& particles, double t, double levelError, float mass,
                                      MaterialIndex material, float restDensity, std::uint32_t capacity,
                                      const std::function<bool(const glm::vec3&)>& room, int threads,
                                      std::vector<std::uint64_t>* visits) {
    const double r = ramp(t);
    const SeaLattice* field = r == 0.0 ? nullptr : &lattice(t, threads);
    const double s = near_.spacing;
    const double strip = kStripSpacings * s;
    // The still water's lattice: a spacing apart across, a layer apart up (NearField::layer).
    const glm::dvec3 step(s, near_.layer, s);
    // Lattice indices k with origin + (k + ½)step in [lo, hi].
    const auto range = [&](int axis, double lo, double hi) {
        const double o = near_.latticeOrigin[axis];
        return std::pair<long, long>{static_cast<long>(std::ceil((lo - o) / step[axis] - 0.5 - 1e-6)),
                                     static_cast<long>(std::floor((hi - o) / step[axis] - 0.5 + 1e-6))};
    };
    // Each side's strip of lattice points (along its axis, across it, up) and which of them
    // have a particle within the room's distance: every particle near a strip marks the few points
    // within reach (a sort of those particles by cell each step was 2 % of an ocean's step).
    // The points added below are a spacing apart, so they never take one another's room;
    // where two strips meet (a corner) a point added by one is marked taken in the other.
    struct Strip {
        int axis, other;
        std::pair<long, long> along, across, up;
        [[nodiscard]] std::size_t count() const {
            return static_cast<std::size_t>(std::max(0L, along.second - along.first + 1)) *
                   static_cast<std::size_t>(std::max(0L, across.second - across.first + 1)) *
                   static_cast<std::size_t>(std::max(0L, up.second - up.first + 1));
        }
        [[nodiscard]] std::size_t index(long a, long c, long k) const {
            return (static_cast<std::size_t>(a - along.first) * static_cast<std::size_t>(across.second - across.first + 1) +
                    static_cast<std::size_t>(c - across.first)) *
                       static_cast<std::size_t>(up.second - up.first + 1) +
                   static_cast<std::size_t>(k - up.first);
        }
    };
    std::vector<Strip> strips;
    for (const OceanSide side : sides_) {
        const int axis = axisOf(side), other = 2 - axis;
        const double face = maxSide(side) ? near_.max[axis] : near_.min[axis];
        strips.push_back({axis, other, maxSide(side) ? range(axis, face - strip, face) : range(axis, face, face + strip),
                          range(other, near_.min[other], near_.max[other]), range(1, near_.min.y, near_.max.y)});
    }
    taken_.resize(strips.size());
    for (std::size_t n = 0; n < strips.size(); ++n) taken_[n].assign(strips[n].count(), 0);
    const double roomSpacings = refillRoom(levelError);
    const double r2 = roomSpacings * roomSpacings * s * s;
    const glm::dvec3 origin(near_.latticeOrigin);
    // The lattice indices along `axis` whose points lie within the room's reach of coordinate
    // p along it (a necessary condition of the distance test: at most two).
    const auto reach = [&](double p, int axis, std::pair<long, long> limits, long out[3]) {
        const double u = (p - origin[axis]) / step[axis] - 0.5;
        if (!(std::abs(u) < 1e9)) return 0;  // a stray far outside (or not finite): no index to cast
        int n = 0;
        for (long k = static_cast<long>(std::floor(u)) - 1; k <= static_cast<long>(std::floor(u)) + 2; ++k) {
            const double d = origin[axis] + (static_cast<double>(k) + 0.5) * step[axis] - p;
            if (k >= limits.first && k <= limits.second && d * d < r2 && n < 3) out[n++] = k;
        }
        return n;
    };
    for (std::uint32_t i = 0; i < particles.size(); ++i) {
        if (!(distanceToOpenFace(particles.position[i]) < strip + 2.0 * s)) continue;
        const glm::dvec3 p(particles.position[i]);
        for (std::size_t n = 0; n < strips.size(); ++n) {
            const Strip& st = strips[n];
            long as[3], cs[3], ks[3];
            const int na = reach(p[st.axis], st.axis, st.along, as);
            if (na == 0) continue;
            const int nc = reach(p[st.other], st.other, st.across, cs), nk = reach(p.y, 1, st.up, ks);
            for (int ia = 0; ia < na; ++ia)
                for (int ic = 0; ic < nc; ++ic)
                    for (int ik = 0; ik < nk; ++ik) {
                        glm::dvec3 x;
                        x[st.axis] = origin[st.axis] + (static_cast<double>(as[ia]) + 0.5) * s;
                        x[st.other] = origin[st.other] + (static_cast<double>(cs[ic]) + 0.5) * s;
                        x.y = origin.y + (static_cast<double>(ks[ik]) + 0.5) * step.y;
                        const glm::dvec3 d = p - x;
                        if (glm::dot(d, d) < r2) taken_[n][st.index(as[ia], cs[ic], ks[ik])] = 1;
                    }
        }
    }
    std::uint32_t added = 0;
    std::uint64_t visited = 0;  // lattice points under the surface so far, on every rank alike
    for (std::size_t n = 0; n < strips.size(); ++n) {
        const Strip& st = strips[n];
        const int axis = st.axis, other = st.other;
        for (long a = st.along.first; a <= st.along.second; ++a)
            for (long c = st.across.first; c <= st.across.second; ++c) {
                glm::dvec3 x;
                x[axis] = near_.latticeOrigin[axis] + (static_cast<double>(a) + 0.5) * s;
                x[other] = near_.latticeOrigin[other] + (static_cast<double>(c) + 0.5) * s;
                const double surface = near_.stillWaterY + (field ? r * field->elevation(x.x, x.z) : 0.0);
                for (long k = st.up.first; k <= st.up.second; ++k) {
                    x.y = near_.latticeOrigin.y + (static_cast<double>(k) + 0.5) * step.y;
                    // A cell wholly under the far field's surface.
                    if (x.y + 0.5 * step.y > surface) break;
                    const std::uint64_t visit = visited++;
                    const glm::vec3 p(x);
                    if (outside(p) || taken_[n][st.index(a, c, k)] || !room(p)) continue;
                    if (particles.size() >= capacity) return added;
                    particles.append(p, field ? glm::vec3(velocityFrom(*field, p, r)) : glm::vec3(0.0f), mass, material,
                                     restDensity);
                    for (std::size_t m = n + 1; m < strips.size(); ++m) {
                        const Strip& o = strips[m];
                        long index[3];
                        index[axis] = a, index[other] = c, index[1] = k;
                        const long oa = index[o.axis], oc = index[o.other];
                        if (oa >= o.along.first && oa <= o.along.second && oc >= o.across.first && oc <= o.across.second)
                            taken_[m][o.index(oa, oc, k)] = 1;
                    }
                    if (visits) visits->push_back(visit);
                    ++added;
                }
            }
    }
    return added;
}

}  // namespace tide::ocean
