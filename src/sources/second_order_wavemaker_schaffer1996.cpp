#include "sources/second_order_wavemaker_schaffer1996.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "sources/wave_theory.hpp"

namespace tide::waves {

namespace {

using Complex = std::complex<double>;

/// κ_j d of the j-th evanescent mode (j ≥ 1): ω² = −g κ tan κd, i.e. y sin y + ν cos y = 0 with
/// y = κd, ν = ω²d/g, whose one root in ((j − ½)π, jπ) bisection finds to the last bit.
double evanescentRoot(int j, double nu) {
    double lo = (j - 0.5) * std::numbers::pi, hi = j * std::numbers::pi;
    const auto f = [nu](double y) { return y * std::sin(y) + nu * std::cos(y); };
    const bool lowPositive = f(lo) > 0.0;
    for (int step = 0; step < 64 && hi - lo > 1e-15 * hi; ++step) {
        const double mid = 0.5 * (lo + hi);
        ((f(mid) > 0.0) == lowPositive ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

/// C of pistonSecondOrderStroke with the progressive mode and `modes` evanescent ones.
Complex strokeWithModes(double a, double omega, double d, double g, int modes) {
    const double k = waveNumber(omega, d, g), bigK = waveNumber(2.0 * omega, d, g);
    const double nu = omega * omega * d / g;
    std::vector<Complex> kj(static_cast<std::size_t>(modes) + 1), cj(kj.size());
    kj[0] = k;
    for (int j = 1; j <= modes; ++j) kj[static_cast<std::size_t>(j)] = Complex(0.0, -evanescentRoot(j, nu) / d);
    // Each mode's surface amplitude per unit of paddle displacement (Schäffer eq. 20–21).
    for (std::size_t j = 0; j < kj.size(); ++j) {
        const Complex kd = kj[j] * d;
        const Complex norm = 0.5 * d + std::sinh(2.0 * kd) / (4.0 * kj[j]);
        cj[j] = omega * omega * std::sinh(kd) * std::cosh(kd) / (g * kj[j] * kj[j] * norm);
    }
    const double K2 = bigK * bigK;
    Complex s1 = 0.0, s3 = 0.0;
    for (std::size_t j = 0; j < kj.size(); ++j) {
        s1 += cj[j] * kj[j] * kj[j] / (kj[j] * kj[j] - K2);
        for (std::size_t l = 0; l < kj.size(); ++l) {
            const Complex sum = kj[j] + kj[l];
            // Schäffer eq. 25d with n = m.
            const Complex h = 3.0 * omega * omega * omega -
                              (g * g / omega) * (2.0 * kj[j] * kj[l] + 0.5 * (kj[j] * kj[j] + kj[l] * kj[l]));
            s3 += cj[j] * cj[l] * sum * h / (sum * sum - K2);
        }
    }
    const double c0 = cj[0].real();  // H/S
    return a * a * K2 * (3.0 * g * omega * s1 + s3) / (16.0 * omega * omega * omega * c0 * c0);
}

}  // namespace

Complex pistonSecondOrderStroke(double waveHeight, double omega, double depth, double g, int modes) {
    if (!(waveHeight > 0.0) || !(omega > 0.0) || !(depth > 0.0) || !(g > 0.0) || modes <= 0)
        throw std::invalid_argument("pistonSecondOrderStroke: H, ω, depth, g and modes must be > 0, got " +
                                    std::to_string(waveHeight) + ", " + std::to_string(omega) + ", " +
                                    std::to_string(depth) + ", " + std::to_string(g) + ", " + std::to_string(modes));
    const double a = 0.5 * waveHeight;
    // The evanescent sums' error falls as 1/N: C(∞) ≈ 2 C(2N) − C(N).
    return 2.0 * strokeWithModes(a, omega, depth, g, 2 * modes) - strokeWithModes(a, omega, depth, g, modes);
}

double freeSecondHarmonic(Complex stroke, double omega, double depth, double g) {
    return pistonHeightToStroke(waveNumber(2.0 * omega, depth, g) * depth) * std::abs(stroke);
}

}  // namespace tide::waves
