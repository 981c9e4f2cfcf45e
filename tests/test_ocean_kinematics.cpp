// The far-field sea's kinematics (issue 43, acceptance item 2): dispersion, the FFT grid
// against the direct sum, continuity and the linear surface conditions.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include <tide/ocean.hpp>

#include "ocean/dispersion.hpp"
#include "ocean/sea.hpp"
#include "ocean/sea_grid_tessendorf2001.hpp"
#include "ocean/spectrum.hpp"

namespace {

using namespace tide;
using namespace tide::ocean;

constexpr double kPi = std::numbers::pi;
constexpr double g = kGravity;

// The acceptance sea: JONSWAP Hs 2.5 m, Tp 7 s, short-crested (s = 10) about 30°, on 30 m.
OceanDef acceptanceSea() {
    OceanDef def;
    def.depth = 30.0;
    def.waves.type = OceanWavesDef::Type::Jonswap;
    def.waves.hs = 2.5;
    def.waves.tp = 7.0;
    def.waves.gamma = 1.932;
    def.waves.spreading = 10.0;
    def.waves.direction = 30.0;
    def.waves.components = 24;
    def.waves.directions = 8;
    def.waves.seed = 43;
    return def;
}

// Scaled units: lengths by 1/kp, times by 1/ωp, elevations by Hs, velocities by Hs ωp.
struct Scales {
    double kp, wp, hs;
};
Scales scalesOf(const OceanDef& def) {
    const double wp = 2.0 * kPi / def.waves.tp;
    return {waveNumber(wp, def.depth), wp, def.waves.hs};
}

TEST(OceanDispersion, SolvesTheRelationToTenDigits) {
    // Acceptance 2: k solves ω² = g k tanh(kd) within 1e-10 relative, from very shallow to
    // very deep water (kd from ~1e-4 to ~1e5).
    double worst = 0.0;
    for (const double depth : {0.01, 0.7, 30.0, 5000.0}) {
        for (double period = 0.2; period < 400.0; period *= 1.37) {
            const double omega = 2.0 * kPi / period;
            const double k = waveNumber(omega, depth);
            const double residual = std::abs(g * k * std::tanh(k * depth) - omega * omega) / (omega * omega);
            worst = std::max(worst, residual);
            EXPECT_LE(residual, 1e-10) << "d " << depth << " T " << period;
        }
    }
    std::printf("dispersion: worst relative residual %.2e\n", worst);
    // The limits: deep water ω² = g k, shallow ω = k √(g d) to O((kd)²).
    EXPECT_NEAR(waveNumber(2.0 * kPi, 1000.0), 4.0 * kPi * kPi / g, 1e-12 * 4.0 * kPi * kPi / g);
    const double slow = 2.0 * kPi / 200.0, kShallow = slow / std::sqrt(g * 0.5);
    EXPECT_NEAR(waveNumber(slow, 0.5), kShallow, 1e-4 * kShallow);
    EXPECT_THROW(waveNumber(0.0, 1.0), std::invalid_argument);
    EXPECT_THROW(waveNumber(1.0, -1.0), std::invalid_argument);
}

TEST(OceanGrid, FftAgreesWithTheDirectSum) {
    // Acceptance 2: on a grid whose wave vectors carry the components, the FFT and the direct
    // sum agree within 1e-5 Hs (η, displacement) and 1e-5 Hs ωp (velocities).
    const OceanDef def = acceptanceSea();
    const Scales s = scalesOf(def);
    GridSpec grid;
    grid.lengthX = 600.0;  // unequal sides and counts catch a swapped axis
    grid.lengthZ = 450.0;
    grid.pointsX = 128;
    grid.pointsZ = 96;
    grid.origin = {-123.0, 45.5};
    const Sea sea = snapToGrid(Sea::fromDef(def), grid);
    // The grid (Nyquist k = π/4.7 m) keeps what lies below ~3 ωp: nearly all of the variance.
    EXPECT_GT(sea.variance(), 0.97 * Sea::fromDef(def).variance());
    SeaGrid fft(sea, grid);
    for (const double t : {0.0, 13.7}) {
        fft.update(t);
        double worstEta = 0.0, worstDisplacement = 0.0, worstVelocity = 0.0;
        for (int j = 0; j < grid.pointsZ; j += 3) {
            for (int i = 0; i < grid.pointsX; i += 3) {
                const glm::dvec2 p = fft.position(i, j);
                const std::size_t n = static_cast<std::size_t>(j) * grid.pointsX + i;
                const WaterSample w = sea.sample({p.x, 0.0, p.y}, t, Stretching::None);
                const glm::dvec2 d = sea.horizontalDisplacement(p.x, p.y, t);
                worstEta = std::max(worstEta, std::abs(fft.elevation()[n] - sea.elevation(p.x, p.y, t)));
                worstDisplacement = std::max({worstDisplacement, std::abs(fft.displacementX()[n] - d.x),
                                              std::abs(fft.displacementZ()[n] - d.y)});
                worstVelocity = std::max({worstVelocity, std::abs(fft.velocityX()[n] - w.velocity.x),
                                          std::abs(fft.velocityY()[n] - w.velocity.y),
                                          std::abs(fft.velocityZ()[n] - w.velocity.z)});
            }
        }
        EXPECT_LE(worstEta, 1e-5 * s.hs) << "t " << t;
        EXPECT_LE(worstDisplacement, 1e-5 * s.hs) << "t " << t;
        EXPECT_LE(worstVelocity, 1e-5 * s.hs * s.wp) << "t " << t;
        std::printf("t %.1f s: FFT - direct, max over grid: eta %.2e Hs, displacement %.2e Hs, velocity %.2e Hs wp\n", t,
                    worstEta / s.hs, worstDisplacement / s.hs, worstVelocity / (s.hs * s.wp));
    }
    // The fields are not trivially small: η's variance over the grid is near the sea's (not
    // equal: components snapped into one bin interfere).
    double square = 0.0;
    for (const double eta : fft.elevation()) square += eta * eta / static_cast<double>(fft.elevation().size());
    EXPECT_GT(square, 0.5 * sea.variance());
}

TEST(OceanGrid, GridSeaHoldsTheSpectrumsVarianceAndDirection) {
    // Tessendorf's sampling of the directional wave-number spectrum at every grid wave vector:
    // a 16 λp square at 256² reaches k = 8 kp (ω = 2.83 ωp in deep water) along the axes and
    // √2 more in the corners, so Σ a²/2 lies between the spectrum's m0 up to those two
    // frequencies (each from 0.2 ωp), less the quadrature's error on the peak (2 %).
    OceanDef def = acceptanceSea();
    def.depth = 400.0;  // deep: ω = √(g k)
    def.waves.gamma = 3.3;
    const double wp = 2.0 * kPi / def.waves.tp, kp = wp * wp / g;
    GridSpec grid{16.0 * 2.0 * kPi / kp, 16.0 * 2.0 * kPi / kp, 256, 256, {0.0, 0.0}};
    const Sea sea = gridSea(def, grid);
    const auto m0 = [&](double highest) {
        const int n = 20000;
        const double a = 0.2 * wp, h = (highest - a) / n;
        double sum = 0.0;
        for (int i = 0; i <= n; ++i)
            sum += (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0)) * jonswap(a + i * h, 2.5, 7.0, 3.3);
        return sum * h / 3.0;
    };
    const double lower = m0(std::sqrt(g * 8.0 * kp)), upper = m0(std::sqrt(g * 8.0 * std::sqrt(2.0) * kp));
    std::printf("grid sea: sum a^2/2 = %.4f m^2, m0 up to the axes' and the corners' k: %.4f, %.4f\n", sea.variance(), lower, upper);
    EXPECT_GT(sea.variance(), 0.98 * lower);
    EXPECT_LT(sea.variance(), 1.02 * upper);
    double sx = 0.0, sz = 0.0;
    for (const WaveComponent& c : sea.components()) {
        const double k = std::hypot(c.kx, c.kz);
        sx += c.amplitude * c.amplitude * c.kx / k;
        sz += c.amplitude * c.amplitude * c.kz / k;
    }
    EXPECT_NEAR(std::atan2(sz, sx) * 180.0 / kPi, 30.0, 0.5);
    // It lives on the grid: SeaGrid takes it as it is.
    SeaGrid fft(sea, grid);
    fft.update(1.0);
    const glm::dvec2 p = fft.position(17, 201);
    EXPECT_NEAR(fft.elevation()[201 * 256 + 17], sea.elevation(p.x, p.y, 1.0), 1e-5 * def.waves.hs);
}

TEST(OceanGrid, RefusesComponentsOffItsWaveVectors) {
    GridSpec grid{100.0, 100.0, 32, 32, {0.0, 0.0}};
    const double k = 2.0 * kPi * 3.5 / 100.0;  // half-way between two grid wave numbers
    const Sea off({WaveComponent{1.0, angularFrequency(k, 20.0), k, 0.0, 0.0}}, 20.0);
    EXPECT_THROW(SeaGrid(off, grid), std::invalid_argument);
    const double nyquist = 2.0 * kPi * 16.0 / 100.0;
    const Sea edge({WaveComponent{1.0, angularFrequency(nyquist, 20.0), nyquist, 0.0, 0.0}}, 20.0);
    EXPECT_THROW(SeaGrid(edge, grid), std::invalid_argument);
    EXPECT_EQ(snapToGrid(edge, grid).components().size(), 0u);
    EXPECT_EQ(snapToGrid(off, grid).components().size(), 1u);
}

TEST(OceanKinematics, VelocityIsDivergenceFree) {
    // Acceptance 2: ∂u/∂x + ∂v/∂y + ∂w/∂z = 0 within 1e-6 in scaled units (fourth-order central
    // differences, step 1e-3/kp), through the whole column of the linear field.
    const OceanDef def = acceptanceSea();
    const Scales s = scalesOf(def);
    const Sea sea = Sea::fromDef(def);
    const double h = 1e-3 / s.kp;
    const auto velocity = [&](glm::dvec3 p) { return sea.sample(p, 5.3, Stretching::None).velocity; };
    const auto derivative = [&](glm::dvec3 p, int axis) {
        glm::dvec3 e(0.0);
        e[axis] = h;
        const auto f = [&](double m) { return velocity(p + m * e)[axis]; };
        return (-f(2.0) + 8.0 * f(1.0) - 8.0 * f(-1.0) + f(-2.0)) / (12.0 * h);
    };
    double worst = 0.0, scale = 0.0;
    for (const double y : {-29.9, -15.0, -3.0, -0.5, 0.0}) {
        for (const double x : {0.0, 17.3, -41.0}) {
            const glm::dvec3 p(x, y, 0.37 * x + 5.0);
            double divergence = 0.0;
            for (int axis = 0; axis < 3; ++axis) {
                divergence += derivative(p, axis);
                scale = std::max(scale, std::abs(derivative(p, axis)) / (s.hs * s.wp * s.kp));
            }
            worst = std::max(worst, std::abs(divergence) / (s.hs * s.wp * s.kp));
        }
    }
    EXPECT_LE(worst, 1e-6);
    EXPECT_GT(scale, 0.05);  // the terms themselves are not small
    std::printf("divergence: worst %.2e (scaled by Hs wp kp)\n", worst);
}

TEST(OceanKinematics, LinearSurfaceConditionsHold) {
    // Acceptance 2: ∂η/∂t = v at y = 0 within 1e-6 in scaled units (∂η/∂t by fourth-order
    // central differences in time), and the dynamic condition p = ρ g η at y = 0.
    const OceanDef def = acceptanceSea();
    const Scales s = scalesOf(def);
    const Sea sea = Sea::fromDef(def);
    const double dt = 1e-3 / s.wp;
    double worst = 0.0;
    for (const double t : {0.0, 2.2, 31.0}) {
        for (const double x : {0.0, 12.5, -60.0}) {
            const double z = 3.0 - 0.8 * x;
            const auto eta = [&](double m) { return sea.elevation(x, z, t + m * dt); };
            const double rate = (-eta(2.0) + 8.0 * eta(1.0) - 8.0 * eta(-1.0) + eta(-2.0)) / (12.0 * dt);
            const WaterSample w = sea.sample({x, 0.0, z}, t, Stretching::None);
            worst = std::max(worst, std::abs(rate - w.velocity.y) / (s.hs * s.wp));
            EXPECT_NEAR(sea.elevationRate(x, z, t), w.velocity.y, 1e-12 * s.hs * s.wp);
            EXPECT_NEAR(w.pressure, sea.density() * g * sea.elevation(x, z, t), 1e-12 * sea.density() * g * s.hs);
        }
    }
    EXPECT_LE(worst, 1e-6);
    std::printf("kinematic surface condition: worst |deta/dt - v| %.2e Hs wp\n", worst);
}

TEST(OceanKinematics, MeanElevationOverARectangleIsTheAverageOfTheSurface) {
    // Sea::meanElevation (the near field's water, RelaxationZones::levelError) against the
    // midpoint rule on n and 2n cells a side extrapolated (Richardson: its error falls as h⁴),
    // over a rectangle of a few wavelengths, a line (2D), a point, and a square smaller than a wave.
    const OceanDef def = acceptanceSea();
    const Sea sea = Sea::fromDef(def);
    const double lp = 2.0 * kPi / scalesOf(def).kp;
    const auto midpointOn = [&](glm::dvec2 lo, glm::dvec2 hi, double t, int n) {
        const int nx = hi.x > lo.x ? n : 1, nz = hi.y > lo.y ? n : 1;
        double sum = 0.0;
        for (int i = 0; i < nx; ++i)
            for (int j = 0; j < nz; ++j)
                sum += sea.elevation(lo.x + (i + 0.5) * (hi.x - lo.x) / nx, lo.y + (j + 0.5) * (hi.y - lo.y) / nz, t);
        return sum / (nx * nz);
    };
    const auto midpoint = [&](glm::dvec2 lo, glm::dvec2 hi, double t) {
        return (4.0 * midpointOn(lo, hi, t, 400) - midpointOn(lo, hi, t, 200)) / 3.0;
    };
    const struct {
        glm::dvec2 lo, hi;
    } cases[] = {{{-10.0, 5.0}, {-10.0 + 2.3 * lp, 5.0 + 1.7 * lp}},
                 {{3.0, 7.0}, {3.0 + 4.1 * lp, 7.0}},
                 {{3.0, 7.0}, {3.0, 7.0}},
                 {{0.0, 0.0}, {0.3 * lp, 0.3 * lp}}};
    for (const auto& c : cases)
        for (const double t : {0.0, 13.7}) {
            const double exact = sea.meanElevation(c.lo, c.hi, t), summed = midpoint(c.lo, c.hi, t);
            std::printf("mean elevation over %.1f x %.1f m at %.1f s: %.8f m, summed %.8f m\n", c.hi.x - c.lo.x,
                        c.hi.y - c.lo.y, t, exact, summed);
            EXPECT_NEAR(exact, summed, 1e-6 * def.waves.hs) << c.hi.x - c.lo.x << " x " << c.hi.y - c.lo.y << " m";
        }
    EXPECT_EQ(sea.meanElevation({3.0, 7.0}, {3.0, 7.0}, 13.7), sea.elevation(3.0, 7.0, 13.7));
    // Over a large sea the mean tends to zero (a per cent of Hs over 2.3 x 1.7 wavelengths).
    EXPECT_LT(std::abs(sea.meanElevation({-10.0, 5.0}, {-10.0 + 2.3 * lp, 5.0 + 1.7 * lp}, 0.0)), 0.05 * def.waves.hs);
}

TEST(OceanKinematics, FloorIsImpermeableAndPressureHydrostaticAtRest) {
    const Sea sea = Sea::fromDef(acceptanceSea());
    const WaterSample floor = sea.sample({10.0, -30.0, -4.0}, 1.0, Stretching::None);
    EXPECT_NEAR(floor.velocity.y, 0.0, 1e-14);
    const Sea calm({}, 30.0);
    EXPECT_NEAR(calm.sample({0.0, -12.0, 0.0}, 0.0).pressure, 1000.0 * g * 12.0, 1e-9);
}

TEST(OceanKinematics, RegularWaveLimitsOfAiryTheory) {
    // Shallow water (kd = 0.05): u ≈ η √(g/d), uniform over depth, to O((kd)²).
    const double depth = 0.5, k = 0.1;
    const Sea shallow({WaveComponent{0.01, angularFrequency(k, depth), k, 0.0, 0.0}}, depth);
    const double uSurface = shallow.sample({0.0, 0.0, 0.0}, 0.0, Stretching::None).velocity.x;
    const double uFloor = shallow.sample({0.0, -depth, 0.0}, 0.0, Stretching::None).velocity.x;
    EXPECT_NEAR(uSurface, 0.01 * std::sqrt(g / depth), 2e-3 * uSurface);
    EXPECT_NEAR(uFloor, uSurface, 3e-3 * uSurface);
    // Deep water (kd = 100): surface speed a ω, decaying as e^{ky}, here along −z (direction 270°).
    const double kd = 1.0;
    const Sea deep({WaveComponent{0.5, angularFrequency(kd, 100.0), 0.0, -kd, 0.0}}, 100.0);
    const double omega = std::sqrt(g * kd);
    EXPECT_NEAR(deep.sample({0.0, 0.0, 0.0}, 0.0, Stretching::None).velocity.z, -0.5 * omega, 1e-12);
    EXPECT_NEAR(deep.sample({0.0, -2.0, 0.0}, 0.0, Stretching::None).velocity.z, -0.5 * omega * std::exp(-2.0), 1e-12);
}

TEST(OceanKinematics, WheelerStretchingMapsTheColumnOntoStillWater) {
    // Wheeler 1970: the surface gets the linear field's still-water values and zero pressure,
    // the floor keeps its own; above the surface the point is dry.
    const Sea sea = Sea::fromDef(acceptanceSea());
    for (const double x : {0.0, 9.0, 33.0, -70.0}) {
        const double z = 0.5 * x, t = 4.0;
        const double eta = sea.elevation(x, z, t);
        const WaterSample surface = sea.sample({x, eta, z}, t);
        const WaterSample linear = sea.sample({x, 0.0, z}, t, Stretching::None);
        EXPECT_TRUE(surface.wet);
        EXPECT_NEAR(surface.pressure, 0.0, 1e-9 * 1000.0 * g * 2.5);
        for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(surface.velocity[axis], linear.velocity[axis], 1e-12);
        const WaterSample floor = sea.sample({x, -30.0, z}, t);
        const WaterSample linearFloor = sea.sample({x, -30.0, z}, t, Stretching::None);
        EXPECT_NEAR(floor.velocity.x, linearFloor.velocity.x, 1e-12);
        EXPECT_NEAR(floor.pressure, linearFloor.pressure, 1e-6);
        const WaterSample air = sea.sample({x, eta + 0.1, z}, t);
        EXPECT_FALSE(air.wet);
        EXPECT_EQ(air.pressure, 0.0);
    }
}

TEST(OceanKinematics, BatchSamplingIsTheSameOnAnyThreadCount) {
    const Sea sea = Sea::fromDef(acceptanceSea());
    std::vector<glm::dvec3> points;
    for (int i = 0; i < 600; ++i) points.emplace_back(0.7 * i - 200.0, -0.05 * i + 1.0, 0.3 * i);
    std::vector<WaterSample> one(points.size()), two(points.size());
    sea.sample(points, 2.5, one, 1);
    sea.sample(points, 2.5, two, 2);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const WaterSample single = sea.sample(points[i], 2.5);
        for (const WaterSample* w : {&one[i], &two[i]}) {
            EXPECT_EQ(w->elevation, single.elevation);
            EXPECT_EQ(w->pressure, single.pressure);
            EXPECT_EQ(w->wet, single.wet);
            for (int axis = 0; axis < 3; ++axis) EXPECT_EQ(w->velocity[axis], single.velocity[axis]);
        }
    }
    std::vector<WaterSample> wrong(3);
    EXPECT_THROW(sea.sample(points, 0.0, wrong), std::invalid_argument);
}

}  // namespace
