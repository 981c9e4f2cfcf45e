#include "ocean/spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tide::ocean {

double piersonMoskowitz(double omega, double hs, double tp) {
    if (!(omega > 0.0)) return 0.0;
    const double wp = 2.0 * std::numbers::pi / tp;
    const double r = wp / omega;  // (ω/ωp)⁻¹
    const double r4 = r * r * r * r;
    return 5.0 / 16.0 * hs * hs * r4 / omega * std::exp(-1.25 * r4);
}

double jonswap(double omega, double hs, double tp, double gamma) {
    if (!(omega > 0.0)) return 0.0;
    const double wp = 2.0 * std::numbers::pi / tp;
    const double sigma = omega <= wp ? 0.07 : 0.09;
    const double x = (omega - wp) / (sigma * wp);
    const double enhancement = std::pow(gamma, std::exp(-0.5 * x * x));
    return (1.0 - 0.287 * std::log(gamma)) * piersonMoskowitz(omega, hs, tp) * enhancement;
}

double dnvGamma(double hs, double tp) {
    const double ratio = tp / std::sqrt(hs);
    if (ratio <= 3.6) return 5.0;
    if (ratio < 5.0) return std::exp(5.75 - 1.15 * ratio);
    return 1.0;
}

Cos2sSpreading::Cos2sSpreading(double s)
    : s_(s),
      // log G(s), through lgamma so large s does not overflow
      logNorm_((2.0 * s - 1.0) * std::numbers::ln2 + 2.0 * std::lgamma(s + 1.0) - std::log(std::numbers::pi) -
               std::lgamma(2.0 * s + 1.0)) {}

double Cos2sSpreading::operator()(double relative) const {
    const double wrapped = std::remainder(relative, 2.0 * std::numbers::pi);
    const double c = std::cos(0.5 * wrapped);
    if (c <= 0.0) return 0.0;
    return std::exp(logNorm_ + 2.0 * s_ * std::log(c));
}

std::vector<double> Cos2sSpreading::equalEnergyDirections(int count) const {
    // The cumulative ∫ D on a fine table (Simpson per cell), inverted by linear interpolation.
    constexpr int kCells = 16384;
    const double pi = std::numbers::pi;
    const double h = 2.0 * pi / kCells;
    std::vector<double> cumulative(kCells + 1, 0.0);
    for (int i = 0; i < kCells; ++i) {
        const double a = -pi + i * h;
        cumulative[i + 1] = cumulative[i] + h / 6.0 * ((*this)(a) + 4.0 * (*this)(a + 0.5 * h) + (*this)(a + h));
    }
    const double total = cumulative.back();
    std::vector<double> angles;
    angles.reserve(static_cast<std::size_t>(count));
    for (int j = 0; j < count; ++j) {
        const double target = total * (j + 0.5) / count;
        const auto it = std::lower_bound(cumulative.begin(), cumulative.end(), target);
        const auto i = static_cast<int>(std::clamp<std::ptrdiff_t>(it - cumulative.begin(), 1, kCells));
        const double f0 = cumulative[i - 1], f1 = cumulative[i];
        const double fraction = f1 > f0 ? (target - f0) / (f1 - f0) : 0.5;
        angles.push_back(-pi + (i - 1 + fraction) * h);
    }
    return angles;
}

}  // namespace tide::ocean
