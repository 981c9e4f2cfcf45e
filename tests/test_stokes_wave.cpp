// A regular far field of finite height: Stokes' theory to fifth order (Fenton 1985,
// src/ocean/stokes_wave_fenton1985.hpp) as the bound harmonics of an ocean::Sea.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <tide/ocean.hpp>

#include "ocean/dispersion.hpp"
#include "ocean/sea.hpp"
#include "ocean/sea_grid_tessendorf2001.hpp"
#include "ocean/sea_lattice.hpp"
#include "ocean/stokes_wave_fenton1985.hpp"

namespace {

using namespace tide;
using namespace tide::ocean;

constexpr double kPi = std::numbers::pi;
constexpr double g = kGravity;

OceanDef stokesOcean(double height, double period, double depth, int order, double direction = 0.0,
                     OceanWavesDef::MeanCurrent current = OceanWavesDef::MeanCurrent::None) {
    OceanDef o;
    o.depth = depth;
    o.waves.type = OceanWavesDef::Type::Regular;
    o.waves.height = height;
    o.waves.period = period;
    o.waves.order = order;
    o.waves.direction = direction;
    o.waves.meanCurrent = current;
    return o;
}

// How far a wave's surface is from satisfying the exact (nonlinear) surface conditions, in the
// frame moving with it at c = ω/k (where it is steady): the dynamic condition, Bernoulli's
// ½|u − c|² + g η constant along the surface (its range over a wavelength, over g/k), and the
// kinematic one, (u − c) ∂η/∂x = v (its largest residual, over c).
struct SurfaceResidual {
    double dynamic, kinematic;
};

SurfaceResidual surfaceResidual(const Sea& sea) {
    const WaveComponent& first = sea.components().front();
    const double k = first.kx, c = first.omega / k, t = 0.37;
    double lo = 1e300, hi = -1e300, kinematic = 0.0;
    constexpr int kPoints = 200;
    for (int i = 0; i < kPoints; ++i) {
        const double x = (i + 0.5) * (2.0 * kPi / k) / kPoints;
        const double eta = sea.elevation(x, 0.0, t);
        const WaterSample w = sea.sample({x, eta, 0.0}, t);
        const double h = 1e-6 / k;
        const double slope = (sea.elevation(x + h, 0.0, t) - sea.elevation(x - h, 0.0, t)) / (2.0 * h);
        const double u = w.velocity.x - c, v = w.velocity.y;
        const double bernoulli = 0.5 * (u * u + v * v) + g * eta;
        lo = std::min(lo, bernoulli);
        hi = std::max(hi, bernoulli);
        kinematic = std::max(kinematic, std::abs(u * slope - v) / c);
    }
    return {(hi - lo) * k / g, kinematic};
}

TEST(StokesWave, OrderOneIsAirysWave) {
    const StokesWave w = stokesWave(0.16, 2.0, 0.7, g, 1);
    const double omega = kPi;
    EXPECT_NEAR(w.k, waveNumber(omega, 0.7), 1e-12 * w.k);
    EXPECT_NEAR(w.elevation[0], 0.08, 1e-15);
    EXPECT_NEAR(w.velocity[0], 0.08 * omega, 1e-12);
    for (int j = 1; j < 5; ++j) EXPECT_EQ(w.elevation[j], 0.0);
}

TEST(StokesWave, DeepWaterCelerityIsStokesClassicalOne) {
    // Third order in deep water: c = c0 (1 + ε²/2), ε = ka (Stokes 1847; Fenton's C2/C0 → 1/2).
    const double period = 1.0, height = 0.1, depth = 50.0;
    const StokesWave w = stokesWave(height, period, depth, g, 3, OceanWavesDef::MeanCurrent::None);
    const double e = 0.5 * w.k * height;
    const double c0 = std::sqrt(g / w.k), c = w.omega / w.k;
    EXPECT_NEAR(c / c0, 1.0 + 0.5 * e * e, 1e-12);
    // and the wave is longer than Airy's: k below ω²/g by 2ε² to first order.
    EXPECT_LT(w.k, w.omega * w.omega / g);
}

TEST(StokesWave, TheFifthOrderSurfaceSatisfiesTheExactConditionsToTheSixthPower) {
    // Issue 43's flume wave (H 0.16 m, T 2 s, d 0.7 m: ε = 0.107, kd = 0.93): the surface
    // conditions' residuals of a Stokes wave of order n fall as ε^(n+1), so halving H at fifth
    // order divides them by ~64 (a coefficient wrong at order m would leave ε^m: 32 or less;
    // measured 66.9 (kinematic) and 67.7 (dynamic) from 0.16 to 0.08 m, 64.2 and 64.4 from
    // 0.04 to 0.02 m);
    // Airy's (order 1) leave residuals of order ε², 24 and 26 times larger at H 0.16 m.
    for (const auto current : {OceanWavesDef::MeanCurrent::Return, OceanWavesDef::MeanCurrent::None}) {
        double previousDynamic = 0.0, previousKinematic = 0.0;
        for (const double height : {0.16, 0.08}) {
            const Sea fifth = Sea::fromDef(stokesOcean(height, 2.0, 0.7, 5, 0.0, current));
            const Sea airy = Sea::fromDef(stokesOcean(height, 2.0, 0.7, 1));
            ASSERT_EQ(fifth.kinematics(), Stretching::Truncated);
            ASSERT_EQ(fifth.components().size(), 5u);
            const SurfaceResidual r5 = surfaceResidual(fifth);
            const SurfaceResidual r1 = surfaceResidual(airy);  // Wheeler-stretched
            std::printf("H %.2f m: fifth order dynamic %.3e kinematic %.3e; Airy dynamic %.3e kinematic %.3e\n", height,
                        r5.dynamic, r5.kinematic, r1.dynamic, r1.kinematic);
            EXPECT_LT(r5.dynamic, 0.1 * r1.dynamic);
            EXPECT_LT(r5.kinematic, 0.1 * r1.kinematic);
            if (previousDynamic > 0.0) {
                EXPECT_GT(previousDynamic / r5.dynamic, 40.0);
                EXPECT_GT(previousKinematic / r5.kinematic, 40.0);
            }
            previousDynamic = r5.dynamic;
            previousKinematic = r5.kinematic;
        }
    }
}

TEST(StokesWave, WithTheReturnCurrentNoWaterIsCarried) {
    // The volume flux through a fixed section, averaged over a period: 0 with the return
    // current (Fenton's c_S = 0), the waves' Stokes transport without it (second order:
    // g H²/(8 c) per unit width; Dean & Dalrymple 1991, ch. 7), which the return current
    // carries back as c_E d.
    const auto flux = [](const Sea& sea) {
        const double omega = sea.components().front().omega, d = sea.depth();
        double sum = 0.0;
        constexpr int kTimes = 64, kLevels = 400;
        for (int n = 0; n < kTimes; ++n) {
            const double t = (n + 0.5) * 2.0 * kPi / omega / kTimes, eta = sea.elevation(0.0, 0.0, t);
            const double dy = (d + eta) / kLevels;
            for (int l = 0; l < kLevels; ++l) sum += sea.sample({0.0, -d + (l + 0.5) * dy, 0.0}, t).velocity.x * dy;
        }
        return sum / kTimes;
    };
    const Sea carried = Sea::fromDef(stokesOcean(0.16, 2.0, 0.7, 5, 0.0, OceanWavesDef::MeanCurrent::None));
    const Sea returned = Sea::fromDef(stokesOcean(0.16, 2.0, 0.7, 5, 0.0, OceanWavesDef::MeanCurrent::Return));
    const double c = carried.components().front().omega / carried.components().front().kx;
    const double transport = g * 0.16 * 0.16 / (8.0 * c);
    std::printf("flux without the current %.5f m2/s (g H^2/8c %.5f), with it %.2e; current %.4f m/s\n", flux(carried),
                transport, flux(returned), returned.current().x);
    EXPECT_NEAR(flux(carried), transport, 0.1 * transport);  // higher orders add ~ε²
    EXPECT_NEAR(flux(returned), 0.0, 0.01 * transport);
    EXPECT_LT(returned.current().x, 0.0);
    EXPECT_NEAR(returned.current().x * 0.7, -transport, 0.1 * transport);
    EXPECT_EQ(carried.current().x, 0.0);
}

TEST(StokesWave, HeightIsCrestToTroughAndTheCrestStandsHigh) {
    const Sea sea = Sea::fromDef(stokesOcean(0.16, 2.0, 0.7, 5));
    const double k = sea.components().front().kx;
    const double crest = sea.elevation(0.0, 0.0, 0.0), trough = sea.elevation(kPi / k, 0.0, 0.0);
    EXPECT_NEAR(crest - trough, 0.16, 1e-12);
    EXPECT_GT(crest, 0.55 * 0.16);  // Stokes' crests are sharp, its troughs flat
    double mean = 0.0;
    for (int i = 0; i < 64; ++i) mean += sea.elevation((i + 0.5) * 2.0 * kPi / k / 64.0, 0.0, 0.0) / 64.0;
    EXPECT_NEAR(mean, 0.0, 1e-12);
}

TEST(StokesWave, AWaveAtAnAngleIsTheSameWaveTurned) {
    const Sea along = Sea::fromDef(stokesOcean(0.1, 1.0, 0.3, 5, 0.0));
    const Sea turned = Sea::fromDef(stokesOcean(0.1, 1.0, 0.3, 5, 30.0));
    const double c = std::cos(kPi / 6.0), s = std::sin(kPi / 6.0);
    for (const double r : {0.1, 0.4, 0.77}) {
        const WaterSample a = along.sample({r, -0.05, 0.0}, 0.3);
        const WaterSample b = turned.sample({r * c, -0.05, r * s}, 0.3);
        EXPECT_NEAR(a.elevation, b.elevation, 1e-12);
        EXPECT_NEAR(a.velocity.x * c, b.velocity.x, 1e-12);
        EXPECT_NEAR(a.velocity.x * s, b.velocity.z, 1e-12);
        EXPECT_NEAR(a.velocity.y, b.velocity.y, 1e-12);
    }
}

TEST(StokesWave, TheLatticeHoldsTheStokesWaveUpToItsCrests) {
    // The zones read a Stokes sea unstretched, on levels up to its crests: against the direct
    // sum at points across the column, crests and troughs, at 2 cm.
    const Sea sea = Sea::fromDef(stokesOcean(0.16, 2.0, 0.7, 5));
    LatticeSpec spec;
    spec.step = 0.02;
    spec.columnsX = 300;
    spec.columnsZ = 4;
    spec.origin = {-0.1, -0.03};
    spec.levels = 2 * 48;
    SeaLattice lattice(sea, spec);
    const double t = 1.3;
    lattice.update(t);
    double err = 0.0, scale = 0.0;
    for (double x = 0.0; x < 5.0; x += 0.0371) {
        const double eta = sea.elevation(x, 0.0, t);
        EXPECT_NEAR(lattice.elevation(x, 0.0), eta, 2e-3 * 0.16);
        for (const double y : {-0.69, -0.4, -0.1, 0.0, eta - 0.005, eta + 0.03}) {
            const glm::dvec3 exact = sea.sample({x, y, 0.0}, t).velocity, read = lattice.velocity({x, y, 0.0});
            err += glm::dot(read - exact, read - exact);
            scale += glm::dot(exact, exact);
        }
    }
    EXPECT_LT(std::sqrt(err / scale), 5e-3);
}

TEST(StokesWave, OnTheFftGridItsHarmonicsStayLockedToTheFirst) {
    // The renderer's grid (Tessendorf 2001) holds a Stokes sea as the direct sum of its snapped
    // components: the harmonics at j times the first's grid vector, with their own ω and V.
    const Sea sea = Sea::fromDef(stokesOcean(0.16, 2.0, 0.7, 5, 20.0));
    GridSpec grid;
    grid.lengthX = 41.0;
    grid.lengthZ = 37.0;
    grid.pointsX = 128;
    grid.pointsZ = 128;
    const Sea snapped = snapToGrid(sea, grid);
    ASSERT_EQ(snapped.components().size(), 5u);
    const WaveComponent& first = snapped.components()[0];
    for (std::size_t j = 1; j < 5; ++j) {
        EXPECT_NEAR(snapped.components()[j].kx, (j + 1) * first.kx, 1e-12);
        EXPECT_NEAR(snapped.components()[j].kz, (j + 1) * first.kz, 1e-12);
        EXPECT_EQ(snapped.components()[j].omega, sea.components()[j].omega);
    }
    SeaGrid fft(snapped, grid);
    fft.update(0.7);
    double worst = 0.0;
    for (int j = 0; j < 128; j += 9)
        for (int i = 0; i < 128; i += 7) {
            const glm::dvec2 x = fft.position(i, j);
            const WaterSample w = snapped.sample({x.x, 0.0, x.y}, 0.7, Stretching::None);
            worst = std::max({worst, std::abs(fft.elevation()[j * 128 + i] - w.elevation),
                              std::abs(fft.velocityX()[j * 128 + i] - w.velocity.x)});
        }
    EXPECT_LT(worst, 1e-9);
}

TEST(StokesWave, TheDefaultOrderIsFiveWhereTheSeriesConverges) {
    EXPECT_EQ(oceanWaveOrder(stokesOcean(0.16, 2.0, 0.7, 0)), 5);  // issue 43's flume: Ursell 10
    EXPECT_EQ(Sea::fromDef(stokesOcean(0.16, 2.0, 0.7, 0)).components().size(), 5u);
    EXPECT_EQ(oceanWaveOrder(stokesOcean(0.1, 4.0, 0.3, 0)), 1);   // L/d 22: cnoidal waters, Airy
    EXPECT_EQ(oceanWaveOrder(stokesOcean(0.08, 0.5, 0.3, 0)), 1);  // H/L 0.2: beyond breaking
    EXPECT_EQ(oceanWaveOrder(stokesOcean(0.16, 2.0, 0.7, 1)), 1);  // asked for
    EXPECT_EQ(oceanWaveOrder(stokesOcean(0.16, 2.0, 0.7, 3)), 3);
    OceanDef spectrum = stokesOcean(0.1, 2.0, 0.7, 0);
    spectrum.waves.type = OceanWavesDef::Type::Jonswap;
    spectrum.waves.hs = 0.1;
    spectrum.waves.tp = 2.0;
    EXPECT_EQ(oceanWaveOrder(spectrum), 1);
}

TEST(StokesWave, WavesBeyondTheTheoryAreRefusedNamingTheOrder) {
    const auto refusal = [](const OceanDef& o) {
        try {
            validateOcean(o);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    // Steeper than breaking: H/L = 0.16 at kd ~ 3.
    EXPECT_NE(refusal(stokesOcean(0.25, 1.0, 0.5, 5)).find("ocean.waves.order: 5"), std::string::npos);
    EXPECT_NE(refusal(stokesOcean(0.25, 1.0, 0.5, 5)).find("break"), std::string::npos);
    // Shallow water (d 0.3 m, T 4 s: L/d ~ 22): the series does not fall off.
    EXPECT_NE(refusal(stokesOcean(0.1, 4.0, 0.3, 5)).find("Ursell"), std::string::npos);
    EXPECT_NE(refusal(stokesOcean(0.1, 2.0, 0.7, 6)).find("ocean.waves.order"), std::string::npos);
    OceanDef spectrum = stokesOcean(0.1, 2.0, 0.7, 2);
    spectrum.waves.type = OceanWavesDef::Type::Jonswap;
    spectrum.waves.hs = 0.1;
    spectrum.waves.tp = 2.0;
    EXPECT_NE(refusal(spectrum).find("ocean.waves.order"), std::string::npos);
    EXPECT_EQ(refusal(stokesOcean(0.16, 2.0, 0.7, 5)), "accepted");
    // The zone width's default is the Stokes wave's own length (k 1.9 % under Airy's here, 0.9 %
    // with the return current).
    const double airy = 2.0 * kPi / waveNumber(kPi, 0.7);
    EXPECT_NEAR(oceanPeakWavelength(stokesOcean(0.16, 2.0, 0.7, 5)), 2.0 * kPi / stokesWave(0.16, 2.0, 0.7, g, 5).k, 1e-12);
    EXPECT_GT(oceanPeakWavelength(stokesOcean(0.16, 2.0, 0.7, 5)), 1.015 * airy);
    EXPECT_GT(oceanPeakWavelength(stokesOcean(0.16, 2.0, 0.7, 5, 0.0, OceanWavesDef::MeanCurrent::Return)), 1.005 * airy);
}

}  // namespace
