#include "ocean/stokes_wave_fenton1985.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "ocean/dispersion.hpp"

namespace tide::ocean {

namespace {

// Fenton 1985, Table 1 (as in Fenton 1990), in S = sech 2kd. kd is capped at 15, where
// tanh kd = 1 − 2e-13: deeper water is deep water, and cosh does not overflow.
struct Coefficients {
    double a11, a22, a31, a33, a42, a44, a51, a53, a55;
    double b22, b31, b42, b44, b53, b55;
    double c0, c2, c4, d2, d4;
};

Coefficients coefficients(double kd) {
    kd = std::min(kd, 15.0);
    const double s = 1.0 / std::cosh(2.0 * kd), sh = std::sinh(kd), th = std::tanh(kd), coth = 1.0 / th;
    const double s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s, s6 = s5 * s, s7 = s6 * s, s8 = s7 * s;
    const double m = 1.0 - s, m2 = m * m, m3 = m2 * m, m4 = m3 * m, m5 = m4 * m, m6 = m5 * m;
    const double p = 3.0 + 2.0 * s, q = 4.0 + s;
    Coefficients c{};
    c.a11 = 1.0 / sh;
    c.a22 = 3.0 * s2 / (2.0 * m2);
    c.a31 = (-4.0 - 20.0 * s + 10.0 * s2 - 13.0 * s3) / (8.0 * sh * m3);
    c.a33 = (-2.0 * s2 + 11.0 * s3) / (8.0 * sh * m3);
    c.a42 = (12.0 * s - 14.0 * s2 - 264.0 * s3 - 45.0 * s4 - 13.0 * s5) / (24.0 * m5);
    c.a44 = (10.0 * s3 - 174.0 * s4 + 291.0 * s5 + 278.0 * s6) / (48.0 * p * m5);
    c.a51 = (-1184.0 + 32.0 * s + 13232.0 * s2 + 21712.0 * s3 + 20940.0 * s4 + 12554.0 * s5 - 500.0 * s6 -
             3341.0 * s7 - 670.0 * s8) /
            (64.0 * sh * p * q * m6);
    c.a53 = (4.0 * s + 105.0 * s2 + 198.0 * s3 - 1376.0 * s4 - 1302.0 * s5 - 117.0 * s6 + 58.0 * s7) / (32.0 * sh * p * m6);
    c.a55 = (-6.0 * s3 + 272.0 * s4 - 1552.0 * s5 + 852.0 * s6 + 2029.0 * s7 + 430.0 * s8) / (64.0 * sh * p * q * m6);
    c.b22 = coth * (1.0 + 2.0 * s) / (2.0 * m);
    c.b31 = -3.0 * (1.0 + 3.0 * s + 3.0 * s2 + 2.0 * s3) / (8.0 * m3);
    c.b42 = coth * (6.0 - 26.0 * s - 182.0 * s2 - 204.0 * s3 - 25.0 * s4 + 26.0 * s5) / (6.0 * p * m4);
    c.b44 = coth * (24.0 + 92.0 * s + 122.0 * s2 + 66.0 * s3 + 67.0 * s4 + 34.0 * s5) / (24.0 * p * m4);
    c.b53 = 9.0 * (132.0 + 17.0 * s - 2216.0 * s2 - 5897.0 * s3 - 6292.0 * s4 - 2687.0 * s5 + 194.0 * s6 + 467.0 * s7 + 82.0 * s8) /
            (128.0 * p * q * m6);
    c.b55 = 5.0 * (300.0 + 1579.0 * s + 3176.0 * s2 + 2949.0 * s3 + 1188.0 * s4 + 675.0 * s5 + 1326.0 * s6 + 827.0 * s7 + 130.0 * s8) /
            (384.0 * p * q * m6);
    c.c0 = std::sqrt(th);
    c.c2 = c.c0 * (2.0 + 7.0 * s2) / (4.0 * m2);
    c.c4 = c.c0 * (4.0 + 32.0 * s - 116.0 * s2 - 400.0 * s3 - 71.0 * s4 + 146.0 * s5) / (32.0 * m5);
    c.d2 = -0.5 * std::sqrt(coth);
    c.d4 = std::sqrt(coth) * (2.0 + 4.0 * s + s2 + 2.0 * s3) / (8.0 * m3);
    return c;
}

// ū √(k/g) (eq. 15) and, with the mass flux, Q/d √(k/g) (eq. 16), truncated at ε^order.
double meanSpeed(const Coefficients& c, double e, int order) {
    const double e2 = e * e;
    return c.c0 + (order >= 3 ? e2 * c.c2 : 0.0) + (order >= 5 ? e2 * e2 * c.c4 : 0.0);
}
double fluxSpeed(const Coefficients& c, double e, double kd, int order) {
    const double e2 = e * e;
    return meanSpeed(c, e, order) + (order >= 3 ? e2 * c.d2 / kd : 0.0) + (order >= 5 ? e2 * e2 * c.d4 / kd : 0.0);
}

// c √(k/g) less the theory's for the chosen current.
double celerityMismatch(double k, double height, double omega, double depth, double g, int order, bool noMassFlux) {
    const Coefficients c = coefficients(k * depth);
    const double e = 0.5 * k * height;
    const double series = noMassFlux ? fluxSpeed(c, e, k * depth, order) : meanSpeed(c, e, order);
    return omega / std::sqrt(g * k) - series;
}

[[noreturn]] void refuse(const char* field, int order, const std::string& why) {
    std::ostringstream message;
    message << field << ": " << order << " (Stokes' theory, Fenton 1985) " << why;
    throw std::invalid_argument(message.str());
}

}  // namespace

StokesWave stokesWave(double height, double period, double depth, double g, int order, OceanWavesDef::MeanCurrent current,
                      const char* field) {
    const bool noMassFlux = current == OceanWavesDef::MeanCurrent::Return;
    if (!(order >= 1 && order <= 5)) refuse(field, order, "must be 1 to 5");
    if (!(height > 0.0 && period > 0.0 && depth > 0.0 && g > 0.0) || !std::isfinite(height + period + depth + g))
        refuse(field, order, "needs a height, period, depth and g > 0");
    StokesWave w;
    w.order = order;
    w.omega = 2.0 * std::numbers::pi / period;
    // The mismatch falls with k (the celerity term ω/√(gk) does, the series barely moves):
    // bisect between half and twice Airy's k, where it changes sign for any wave the theory holds.
    const double linear = waveNumber(w.omega, depth, g);
    double lo = 0.5 * linear, hi = 2.0 * linear;
    const double fLo = celerityMismatch(lo, height, w.omega, depth, g, order, noMassFlux);
    const double fHi = celerityMismatch(hi, height, w.omega, depth, g, order, noMassFlux);
    if (!(fLo > 0.0 && fHi < 0.0)) refuse(field, order, "has no wave number for this height, period and depth");
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (celerityMismatch(mid, height, w.omega, depth, g, order, noMassFlux) > 0.0 ? lo : hi) = mid;
    }
    w.k = 0.5 * (lo + hi);
    const double kd = w.k * depth, e = 0.5 * w.k * height;
    const double steepness = height * w.k / (2.0 * std::numbers::pi), limit = 0.142 * std::tanh(kd);
    if (steepness > limit) {
        std::ostringstream why;
        why << "cannot hold H/L = " << steepness << ": waves break above 0.142 tanh kd = " << limit << " (Miche 1944)";
        refuse(field, order, why.str());
    }
    const Coefficients c = coefficients(kd);
    // c_E = c − ū: 0 by definition without a current; with no mass flux, the return current.
    w.current = noMassFlux ? w.omega / w.k - std::sqrt(g / w.k) * meanSpeed(c, e, order) : 0.0;
    // ε^i, zero above the order.
    double powers[6] = {1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    for (int i = 1; i <= 5; ++i) powers[i] = i <= order ? powers[i - 1] * e : 0.0;
    const double k = w.k;
    w.elevation = {(powers[1] + powers[3] * c.b31 - powers[5] * (c.b53 + c.b55)) / k, (powers[2] * c.b22 + powers[4] * c.b42) / k,
                   (-powers[3] * c.b31 + powers[5] * c.b53) / k, powers[4] * c.b44 / k, powers[5] * c.b55 / k};
    // u = ∂φ/∂x = C0 √(g/k) Σ_i ε^i Σ_j j A_ij cosh(jk(y+d)) cos jθ, so V_j = C0 √(g/k) j sinh(jkd) Σ_i ε^i A_ij.
    const double sums[5] = {powers[1] * c.a11 + powers[3] * c.a31 + powers[5] * c.a51, powers[2] * c.a22 + powers[4] * c.a42,
                            powers[3] * c.a33 + powers[5] * c.a53, powers[4] * c.a44, powers[5] * c.a55};
    const double scale = c.c0 * std::sqrt(g / k), cappedKd = std::min(kd, 15.0);
    for (int j = 0; j < 5; ++j) w.velocity[j] = scale * (j + 1) * std::sinh((j + 1) * cappedKd) * sums[j];
    for (int j = 1; j < order; ++j)
        if (std::abs(w.elevation[j]) > std::abs(w.elevation[j - 1])) {
            std::ostringstream why;
            why << "does not converge for this wave: harmonic " << j + 1 << " of the elevation (" << w.elevation[j]
                << " m) exceeds harmonic " << j << " (" << w.elevation[j - 1] << " m), Ursell number H L^2/d^3 = "
                << height * std::pow(2.0 * std::numbers::pi / k, 2.0) / (depth * depth * depth)
                << " (shallow water: use order 1)";
            refuse(field, order, why.str());
        }
    return w;
}

}  // namespace tide::ocean
