#include "ocean/sea_grid_tessendorf2001.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>

#include <kissfft.hh>

#include "ocean/spectrum.hpp"
#include "ocean/uniform_random.hpp"

namespace tide::ocean {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

void checkGrid(const GridSpec& g) {
    if (!(g.lengthX > 0.0 && std::isfinite(g.lengthX)) || !(g.lengthZ > 0.0 && std::isfinite(g.lengthZ)) ||
        g.pointsX < 2 || g.pointsZ < 2 || !std::isfinite(g.origin.x) || !std::isfinite(g.origin.y)) {
        std::ostringstream message;
        message << "ocean::GridSpec: lengths must be > 0 and points >= 2, got " << g.lengthX << " x " << g.lengthZ
                << " m, " << g.pointsX << " x " << g.pointsZ << " points";
        throw std::invalid_argument(message.str());
    }
}

// The grid index m (in (−N/2, N/2)) of wave number k on a period L, or none when it is 0 or
// the Nyquist number.
bool interiorIndex(long m, int points) { return 2 * std::abs(m) < points; }

}  // namespace

Sea snapToGrid(const Sea& sea, const GridSpec& grid) {
    checkGrid(grid);
    std::vector<WaveComponent> snapped;
    // A Stokes wave's harmonics go to j times its first harmonic's grid vector, so they stay
    // locked to it (rounding each alone could put the second at 21 bins when the first is at 10).
    long firstX = 0, firstZ = 0;
    double firstK = 0.0;
    for (WaveComponent c : sea.components()) {
        long mx = std::lround(c.kx * grid.lengthX / kTwoPi);
        long mz = std::lround(c.kz * grid.lengthZ / kTwoPi);
        if (c.bound && firstK == 0.0) {
            firstX = mx, firstZ = mz, firstK = std::hypot(c.kx, c.kz);
        } else if (c.bound) {
            const long j = std::lround(std::hypot(c.kx, c.kz) / firstK);
            mx = j * firstX, mz = j * firstZ;
        }
        if ((mx == 0 && mz == 0) || !interiorIndex(mx, grid.pointsX) || !interiorIndex(mz, grid.pointsZ)) continue;
        c.kx = kTwoPi * static_cast<double>(mx) / grid.lengthX;
        c.kz = kTwoPi * static_cast<double>(mz) / grid.lengthZ;
        // A Stokes wave's bound harmonics keep their ω (j times the first's).
        if (!c.bound) c.omega = angularFrequency(std::hypot(c.kx, c.kz), sea.depth(), sea.gravity());
        snapped.push_back(c);
    }
    return Sea(std::move(snapped), sea.depth(), sea.gravity(), sea.density(), sea.current());
}

Sea gridSea(const OceanDef& def, const GridSpec& grid, double g) {
    validateOcean(def);
    checkGrid(grid);
    const OceanWavesDef& w = def.waves;
    if (!w.spreading) return snapToGrid(Sea(discretise(def, g), def.depth, g), grid);
    const Cos2sSpreading spreading(*w.spreading);
    const double gamma = oceanGamma(w), mean = w.direction * std::numbers::pi / 180.0, d = def.depth;
    const double dkx = kTwoPi / grid.lengthX, dkz = kTwoPi / grid.lengthZ;
    std::mt19937_64 random(w.seed);
    std::vector<WaveComponent> components;
    for (int j = 0; j < grid.pointsZ; ++j) {
        for (int i = 0; i < grid.pointsX; ++i) {
            const double phase = kTwoPi * uniform01(random);  // drawn for every bin: the order is fixed
            const long mx = i < grid.pointsX / 2 ? i : i - grid.pointsX;
            const long mz = j < grid.pointsZ / 2 ? j : j - grid.pointsZ;
            if ((mx == 0 && mz == 0) || !interiorIndex(mx, grid.pointsX) || !interiorIndex(mz, grid.pointsZ)) continue;
            const double kx = dkx * static_cast<double>(mx), kz = dkz * static_cast<double>(mz);
            const double k = std::hypot(kx, kz), kd = k * d;
            const double omega = angularFrequency(k, d, g);
            // c_g = ω/(2k) (1 + 2kd/sinh 2kd); the ratio written to stay finite in deep water.
            const double ratio = kd < 350.0 ? 2.0 * kd / std::sinh(2.0 * kd) : 0.0;
            const double groupSpeed = omega / (2.0 * k) * (1.0 + ratio);
            const double density = jonswap(omega, w.hs, w.tp, gamma) * spreading(std::atan2(kz, kx) - mean) * groupSpeed / k;
            const double amplitude = std::sqrt(2.0 * density * dkx * dkz);
            if (amplitude > 0.0) components.push_back(WaveComponent{amplitude, omega, kx, kz, phase});
        }
    }
    return Sea(std::move(components), d, g);
}

struct SeaGrid::Transforms {
    kissfft<double> x, z;
    Transforms(int nx, int nz) : x(static_cast<std::size_t>(nx), true), z(static_cast<std::size_t>(nz), true) {}
};

SeaGrid::SeaGrid(const Sea& sea, GridSpec grid) : grid_(grid), current_(sea.current()) {
    checkGrid(grid_);
    const int nx = grid_.pointsX, nz = grid_.pointsZ;
    const double d = sea.depth();
    for (std::size_t n = 0; n < sea.components().size(); ++n) {
        const WaveComponent& c = sea.components()[n];
        const double fx = c.kx * grid_.lengthX / kTwoPi, fz = c.kz * grid_.lengthZ / kTwoPi;
        const long mx = std::lround(fx), mz = std::lround(fz);
        const bool onGrid = std::abs(fx - static_cast<double>(mx)) <= 1e-9 * std::max(1.0, std::abs(fx)) &&
                            std::abs(fz - static_cast<double>(mz)) <= 1e-9 * std::max(1.0, std::abs(fz));
        if (!onGrid || (mx == 0 && mz == 0) || !interiorIndex(mx, nx) || !interiorIndex(mz, nz)) {
            std::ostringstream message;
            message << "ocean::SeaGrid: component " << n << " has k = (" << c.kx << ", " << c.kz
                    << ") rad/m, not an interior wave vector of the grid (k L/2pi = (" << fx << ", " << fz
                    << ")): use snapToGrid";
            throw std::invalid_argument(message.str());
        }
        const auto wrap = [](long m, int points) { return static_cast<int>((m % points + points) % points); };
        Mode mode{};
        mode.bin = wrap(mz, nz) * nx + wrap(mx, nx);
        mode.mirror = wrap(-mz, nz) * nx + wrap(-mx, nx);
        mode.omega = c.omega;
        // A real field Σ A cos θ + B sin θ is Σ P e^{iθ} + conj(P) e^{−iθ} with P = (A − iB)/2;
        // a pair F + iG puts (P_F + i P_G) e^{iψ} at k and (conj P_F + i conj P_G) e^{−iψ} at −k,
        // θ = k·(x − origin) + ψ, ψ = φ + k·origin − ωt (Tessendorf 2001 eq. 19 and 29).
        const double k = std::hypot(c.kx, c.kz);
        const double coth = 1.0 / std::tanh(k * d);
        // aw: the velocity amplitude V (a ω for a free wave); ad: the displacement's, V/ω.
        const double a = c.amplitude, aw = sea.velocityAmplitude(n), ad = aw / c.omega;
        const double ux = c.kx / k, uz = c.kz / k;
        using C = std::complex<double>;
        const C pairs[3][2] = {
            {C(a, 0.0) / 2.0, C(0.0, -aw) / 2.0},                            // η (cos), v (sin)
            {C(0.0, ad * coth * ux) / 2.0, C(0.0, ad * coth * uz) / 2.0},   // D = −(V/ω) coth sin θ k̂
            {C(aw * coth * ux, 0.0) / 2.0, C(aw * coth * uz, 0.0) / 2.0},   // u, w (cos)
        };
        const C rotation = std::polar(1.0, c.phase + c.kx * grid_.origin.x + c.kz * grid_.origin.y);
        for (int p = 0; p < 3; ++p) {
            const C pf = pairs[p][0], pg = pairs[p][1];
            mode.plus[p] = (pf + C(0.0, 1.0) * pg) * rotation;
            mode.minus[p] = (std::conj(pf) + C(0.0, 1.0) * std::conj(pg)) * std::conj(rotation);
        }
        modes_.push_back(mode);
    }
    transforms_ = std::make_unique<Transforms>(nx, nz);
    const auto cells = static_cast<std::size_t>(nx) * static_cast<std::size_t>(nz);
    work_.resize(cells);
    line_.resize(static_cast<std::size_t>(std::max(nx, nz)));
    lineOut_.resize(line_.size());
    for (auto* field : {&elevation_, &displacementX_, &displacementZ_, &velocityX_, &velocityY_, &velocityZ_})
        field->assign(cells, 0.0);
}

SeaGrid::~SeaGrid() = default;
SeaGrid::SeaGrid(SeaGrid&&) noexcept = default;
SeaGrid& SeaGrid::operator=(SeaGrid&&) noexcept = default;

glm::dvec2 SeaGrid::position(int i, int j) const {
    return grid_.origin + glm::dvec2(i * grid_.lengthX / grid_.pointsX, j * grid_.lengthZ / grid_.pointsZ);
}

void SeaGrid::inverse2d(std::vector<std::complex<double>>& field) {
    const auto nx = static_cast<std::size_t>(grid_.pointsX), nz = static_cast<std::size_t>(grid_.pointsZ);
    for (std::size_t j = 0; j < nz; ++j) {
        transforms_->x.transform(&field[j * nx], lineOut_.data());
        std::copy(lineOut_.begin(), lineOut_.begin() + static_cast<std::ptrdiff_t>(nx), field.begin() + static_cast<std::ptrdiff_t>(j * nx));
    }
    for (std::size_t i = 0; i < nx; ++i) {
        for (std::size_t j = 0; j < nz; ++j) line_[j] = field[j * nx + i];
        transforms_->z.transform(line_.data(), lineOut_.data());
        for (std::size_t j = 0; j < nz; ++j) field[j * nx + i] = lineOut_[j];
    }
}

void SeaGrid::update(double t) {
    std::vector<double>* outputs[3][2] = {
        {&elevation_, &velocityY_}, {&displacementX_, &displacementZ_}, {&velocityX_, &velocityZ_}};
    for (int p = 0; p < 3; ++p) {
        std::fill(work_.begin(), work_.end(), std::complex<double>(0.0));
        for (const Mode& m : modes_) {
            const std::complex<double> turn = std::polar(1.0, -m.omega * t);
            work_[static_cast<std::size_t>(m.bin)] += m.plus[p] * turn;
            work_[static_cast<std::size_t>(m.mirror)] += m.minus[p] * std::conj(turn);
        }
        inverse2d(work_);
        for (std::size_t n = 0; n < work_.size(); ++n) {
            (*outputs[p][0])[n] = work_[n].real();
            (*outputs[p][1])[n] = work_[n].imag();
        }
    }
    for (std::size_t n = 0; n < velocityX_.size(); ++n) velocityX_[n] += current_.x, velocityZ_[n] += current_.y;
}

}  // namespace tide::ocean
