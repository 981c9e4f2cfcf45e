#include "ocean/sea_lattice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/parallel.hpp"

namespace tide::ocean {

namespace {

// Catmull & Rom 1974's cubic through four equally spaced nodes, at t in [0, 1] between the
// middle two.
void catmullRom(double t, double w[4]) {
    const double t2 = t * t, t3 = t2 * t;
    w[0] = 0.5 * (-t3 + 2.0 * t2 - t);
    w[1] = 0.5 * (3.0 * t3 - 5.0 * t2 + 2.0);
    w[2] = 0.5 * (-3.0 * t3 + 4.0 * t2 + t);
    w[3] = 0.5 * (t3 - t2);
}

// sum += profile · factor over n entries (a plain loop GCC vectorises: no aliasing).
void accumulate(float* __restrict sum, const float* __restrict profile, float factor, std::size_t n) {
    for (std::size_t l = 0; l < n; ++l) sum[l] += profile[l] * factor;
}

}  // namespace

SeaLattice::SeaLattice(const Sea& sea, LatticeSpec spec)
    : spec_(std::move(spec)), depth_(sea.depth()), kinematics_(sea.kinematics()), current_(sea.current()),
      time_(std::numeric_limits<double>::quiet_NaN()) {
    const auto columns = static_cast<std::size_t>(std::max(spec_.columnsX, 0)) * static_cast<std::size_t>(std::max(spec_.columnsZ, 0));
    if (!(spec_.step > 0.0 && std::isfinite(spec_.step)) || spec_.columnsX < 4 || spec_.columnsZ < 4 ||
        spec_.levels < 2 || !(spec_.used.empty() || spec_.used.size() == columns)) {
        std::ostringstream message;
        message << "ocean::SeaLattice: needs step > 0, >= 4 x 4 columns, >= 2 levels and a mask per column, got step "
                << spec_.step << ", " << spec_.columnsX << " x " << spec_.columnsZ << " columns, " << spec_.levels
                << " levels, " << spec_.used.size() << " mask entries";
        throw std::invalid_argument(message.str());
    }
    if (spec_.used.empty()) spec_.used.assign(columns, 1);
    levelCount_ = spec_.levels + 3;
    components_ = sea.components().size();
    const std::size_t n = components_;
    // Wheeler: levels over the stretched column −d … 0. Truncated (a Stokes wave): over the
    // column itself, from the floor to the highest crest the components can make.
    top_ = sea.kinematicTop();
    levelStep_ = (depth_ + top_) / spec_.levels;
    const double dy = levelStep_;
    cosX_.resize(static_cast<std::size_t>(spec_.columnsX) * n);
    sinX_.resize(cosX_.size());
    cosZ_.resize(static_cast<std::size_t>(spec_.columnsZ) * n);
    sinZ_.resize(cosZ_.size());
    profileX_.resize(n * static_cast<std::size_t>(levelCount_));
    profileY_.resize(profileX_.size());
    profileZ_.resize(profileX_.size());
    for (std::size_t c = 0; c < n; ++c) {
        const WaveComponent& w = sea.components()[c];
        amplitude_.push_back(w.amplitude);
        omega_.push_back(w.omega);
        phase_.push_back(w.phase);
        for (int i = 0; i < spec_.columnsX; ++i) {
            const double x = spec_.origin.x + i * spec_.step;
            cosX_[static_cast<std::size_t>(i) * n + c] = std::cos(w.kx * x);
            sinX_[static_cast<std::size_t>(i) * n + c] = std::sin(w.kx * x);
        }
        for (int j = 0; j < spec_.columnsZ; ++j) {
            const double z = spec_.origin.y + j * spec_.step;
            cosZ_[static_cast<std::size_t>(j) * n + c] = std::cos(w.kz * z);
            sinZ_[static_cast<std::size_t>(j) * n + c] = std::sin(w.kz * z);
        }
        // The profiles of Sea::sample: cosh(k(y'+d))/sinh(kd) and sinh(k(y'+d))/sinh(kd) as
        // (e^{ky'} ± e^{−k(y'+2d)}) / (1 − e^{−2kd}).
        const double k = std::hypot(w.kx, w.kz);
        const double decay = std::exp(-2.0 * k * depth_), overSinh = 1.0 / -std::expm1(-2.0 * k * depth_);
        for (int l = 0; l < levelCount_; ++l) {
            const double y = -depth_ + (l - 1) * dy;
            const double up = std::exp(k * y), down = decay / up;
            const double horizontal = sea.velocityAmplitude(c) * (up + down) * overSinh;
            const std::size_t at = c * static_cast<std::size_t>(levelCount_) + static_cast<std::size_t>(l);
            profileX_[at] = static_cast<float>(horizontal * w.kx / k);
            profileZ_[at] = static_cast<float>(horizontal * w.kz / k);
            profileY_[at] = static_cast<float>(sea.velocityAmplitude(c) * (up - down) * overSinh);
        }
    }
    slot_.assign(columns, -1);
    for (std::size_t k = 0; k < columns; ++k)
        if (spec_.used[k]) {
            slot_[k] = static_cast<std::int32_t>(active_.size());
            active_.push_back(static_cast<std::uint32_t>(k));
        }
    elevation_.assign(active_.size(), 0.0f);
    velocity_.assign(active_.size() * static_cast<std::size_t>(levelCount_) * 3, 0.0f);
}

void SeaLattice::update(double t, int threads, bool rates) {
    const std::size_t n = components_, levels = static_cast<std::size_t>(levelCount_);
    // e^{i(φ − ωt)} once per component.
    std::vector<double> turnCos(n), turnSin(n);
    for (std::size_t c = 0; c < n; ++c) {
        turnCos[c] = std::cos(phase_[c] - omega_[c] * t);
        turnSin[c] = std::sin(phase_[c] - omega_[c] * t);
    }
    if (rates && elevationRate_.size() != elevation_.size()) {
        elevationRate_.assign(elevation_.size(), 0.0f);
        velocityRate_.assign(velocity_.size(), 0.0f);
    }
    const auto currentX = static_cast<float>(current_.x), currentZ = static_cast<float>(current_.y);
    parallelFor(static_cast<std::uint32_t>(active_.size()), threads, [&](std::uint32_t a) {
        const std::size_t column = active_[a];
        const std::size_t i = column % static_cast<std::size_t>(spec_.columnsX), j = column / static_cast<std::size_t>(spec_.columnsX);
        // In float (as stored; four lanes of SSE): 48 terms of a sum lose ~1e-6 of it.
        thread_local std::vector<float> sums;
        sums.assign(6 * levels, 0.0f);
        float* ux = sums.data();
        float* uy = ux + levels;
        float* uz = uy + levels;
        float* rx = uz + levels;  // ∂/∂t: d cos θ/dt = ω sin θ, d sin θ/dt = −ω cos θ
        float* ry = rx + levels;
        float* rz = ry + levels;
        double eta = 0.0, etaRate = 0.0;
        for (std::size_t c = 0; c < n; ++c) {
            // e^{iθ} = e^{i kx x} e^{i kz z} e^{i(φ − ωt)}.
            const double xc = cosX_[i * n + c], xs = sinX_[i * n + c], zc = cosZ_[j * n + c], zs = sinZ_[j * n + c];
            const double sc = xc * zc - xs * zs, ss = xs * zc + xc * zs;
            const double cosTheta = sc * turnCos[c] - ss * turnSin[c], sinTheta = ss * turnCos[c] + sc * turnSin[c];
            eta += amplitude_[c] * cosTheta;
            const auto cf = static_cast<float>(cosTheta), sf = static_cast<float>(sinTheta);
            accumulate(ux, &profileX_[c * levels], cf, levels);
            accumulate(uz, &profileZ_[c * levels], cf, levels);
            accumulate(uy, &profileY_[c * levels], sf, levels);
            if (rates) {
                const auto wc = static_cast<float>(omega_[c] * cosTheta), ws = static_cast<float>(omega_[c] * sinTheta);
                etaRate += amplitude_[c] * omega_[c] * sinTheta;
                accumulate(rx, &profileX_[c * levels], ws, levels);
                accumulate(rz, &profileZ_[c * levels], ws, levels);
                accumulate(ry, &profileY_[c * levels], -wc, levels);
            }
        }
        elevation_[a] = static_cast<float>(eta);
        float* out = &velocity_[a * levels * 3];
        for (std::size_t l = 0; l < levels; ++l) {
            out[3 * l] = ux[l] + currentX;
            out[3 * l + 1] = uy[l];
            out[3 * l + 2] = uz[l] + currentZ;
        }
        if (!rates) return;
        elevationRate_[a] = static_cast<float>(etaRate);
        float* outRate = &velocityRate_[a * levels * 3];
        for (std::size_t l = 0; l < levels; ++l) {
            outRate[3 * l] = rx[l];
            outRate[3 * l + 1] = ry[l];
            outRate[3 * l + 2] = rz[l];
        }
    });
    time_ = t;
}

void SeaLattice::blend(const SeaLattice& a, const SeaLattice& b, double t, int threads) {
    const double span = b.time_ - a.time_;
    if (!(span > 0.0) || a.elevationRate_.size() != elevation_.size() || b.elevationRate_.size() != elevation_.size() ||
        a.velocity_.size() != velocity_.size() || b.velocity_.size() != velocity_.size() ||
        !(t >= a.time_ && t <= b.time_))
        throw std::invalid_argument("ocean::SeaLattice::blend: needs two lattices of this spec updated with rates at ta < tb, "
                                    "and ta <= t <= tb");
    // Cubic Hermite basis at s = (t − ta)/(tb − ta).
    const double s = (t - a.time_) / span, s2 = s * s, s3 = s2 * s;
    const auto h00 = static_cast<float>(2.0 * s3 - 3.0 * s2 + 1.0), h01 = static_cast<float>(-2.0 * s3 + 3.0 * s2);
    const auto h10 = static_cast<float>((s3 - 2.0 * s2 + s) * span), h11 = static_cast<float>((s3 - s2) * span);
    const auto mix = [&](std::vector<float>& out, const std::vector<float>& fa, const std::vector<float>& ra,
                         const std::vector<float>& fb, const std::vector<float>& rb) {
        parallelFor(static_cast<std::uint32_t>(out.size()), threads,
                    [&](std::uint32_t i) { out[i] = h00 * fa[i] + h10 * ra[i] + h01 * fb[i] + h11 * rb[i]; });
    };
    mix(elevation_, a.elevation_, a.elevationRate_, b.elevation_, b.elevationRate_);
    mix(velocity_, a.velocity_, a.velocityRate_, b.velocity_, b.velocityRate_);
    time_ = t;
}

SeaLattice::Stencil SeaLattice::horizontal(double coordinate, double origin, int count) const {
    // Clamped so that the four nodes exist: points beyond take the edge's cubic.
    const double u = std::clamp((coordinate - origin) / spec_.step, 1.0, static_cast<double>(count - 2));
    const int cell = std::min(static_cast<int>(u), count - 3);  // u ≥ 1: truncation is floor
    Stencil s{cell - 1, {}};
    catmullRom(u - cell, s.w);
    return s;
}

double SeaLattice::elevation(double x, double z) const {
    const Stencil sx = horizontal(x, spec_.origin.x, spec_.columnsX), sz = horizontal(z, spec_.origin.y, spec_.columnsZ);
    double eta = 0.0;
    for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a) {
            const std::int32_t slot = slotAt(sx.first + a, sz.first + b);
            if (slot >= 0) eta += sz.w[b] * sx.w[a] * elevation_[static_cast<std::size_t>(slot)];
        }
    return eta;
}

glm::dvec3 SeaLattice::velocity(const glm::dvec3& point) const {
    const Stencil sx = horizontal(point.x, spec_.origin.x, spec_.columnsX), sz = horizontal(point.z, spec_.origin.y, spec_.columnsZ);
    std::int32_t slots[4][4];
    double eta = 0.0;
    for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a) {
            slots[b][a] = slotAt(sx.first + a, sz.first + b);
            if (slots[b][a] >= 0) eta += sz.w[b] * sx.w[a] * elevation_[static_cast<std::size_t>(slots[b][a])];
        }
    // As Sea::sample: Wheeler 1970 maps the column floor..η onto floor..0; Truncated reads the
    // point itself up to η. Dry points take the surface's velocity.
    double y = std::clamp(std::min(point.y, eta), -depth_, top_);
    if (kinematics_ != Stretching::Truncated) {
        const double column = depth_ + eta;
        const bool wet = point.y <= eta && column > 0.0;
        y = wet ? std::max(depth_ * (point.y + depth_) / column - depth_, -depth_) : 0.0;
    }
    const double u = (y + depth_) / levelStep_ + 1.0;  // level index (level −1 at 0)
    const int cell = std::min(static_cast<int>(u), spec_.levels);  // u ≥ 1
    double wy[4];
    catmullRom(u - cell, wy);
    const std::size_t levels = static_cast<std::size_t>(levelCount_);
    // The 4 levels × 3 components of a column are 12 consecutive floats: the horizontal
    // weighted sum of those 12-vectors (in float, as stored), then the vertical weights.
    float sum[12] = {};
    for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a) {
            if (slots[b][a] < 0) continue;
            const auto w = static_cast<float>(sz.w[b] * sx.w[a]);
            const float* node = &velocity_[(static_cast<std::size_t>(slots[b][a]) * levels + static_cast<std::size_t>(cell - 1)) * 3];
            for (int e = 0; e < 12; ++e) sum[e] += w * node[e];
        }
    glm::dvec3 v(0.0);
    for (int l = 0; l < 4; ++l) v += wy[l] * glm::dvec3(sum[3 * l], sum[3 * l + 1], sum[3 * l + 2]);
    return v;
}

}  // namespace tide::ocean
