#include "sources/second_order_wavemaker_schaffer1996.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
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

/// A first-order component's modes for the pair sums, at a signed frequency ω (ω < 0: the
/// conjugate of the component at −ω). The progressive mode k₀ (sign of ω) with its c₀; the
/// evanescent k_j = −iκ_j, whose c_j = i·ĉ_j is imaginary, kept as reals (the same for ±ω).
struct SignedModes {
    double omega = 0.0, k0 = 0.0, c0 = 0.0;
    std::vector<double> kappa, cHat;  ///< j = 1 … 2·modes
};

SignedModes signedModes(double omega, double d, double g, int modes) {
    SignedModes m;
    m.omega = omega;
    const double w2 = omega * omega, k = waveNumber(std::abs(omega), d, g);
    m.k0 = omega > 0.0 ? k : -k;
    // c₀ = ω² sinh kd cosh kd/(g k² N₀), N₀ = d/2 + sinh 2kd/(4k): odd in k (eq. 20–21).
    m.c0 = w2 * std::sinh(m.k0 * d) * std::cosh(m.k0 * d) /
           (g * m.k0 * m.k0 * (0.5 * d + std::sinh(2.0 * m.k0 * d) / (4.0 * m.k0)));
    const double nu = w2 * d / g;
    m.kappa.resize(static_cast<std::size_t>(2 * modes));
    m.cHat.resize(m.kappa.size());
    for (std::size_t j = 0; j < m.kappa.size(); ++j) {
        const double y = evanescentRoot(static_cast<int>(j) + 1, nu), kappa = y / d;
        // k = −iκ: sinh kd cosh kd = −i sin y cos y, k² = −κ², N = d/2 + sin 2y/(4κ).
        m.kappa[j] = kappa;
        m.cHat[j] = w2 * std::sin(y) * std::cos(y) / (g * kappa * kappa * (0.5 * d + std::sin(2.0 * y) / (4.0 * kappa)));
    }
    return m;
}

/// (ω_x² − Ω²)/(k_x² − K²) for a progressive k_x: both vanish together where |k_x| = K (a
/// subharmonic with ω_n = 2ω_m); there the derivative d(ω²)/d(k²) = g(tanh kd + kd sech² kd)/(2k).
double progressiveRatio(double omegaX, double kX, double Omega, double K, double d, double g) {
    const double k = std::abs(kX);
    if (std::abs(k - K) > 1e-4 * K) return (omegaX * omegaX - Omega * Omega) / (kX * kX - K * K);
    const double mid = 0.5 * (k + K), t = std::tanh(mid * d);
    return g * (t + mid * d * (1.0 - t * t)) / (2.0 * mid);
}

/// B of pistonSecondOrderPair for the signed components a, b, with the first `modes`
/// evanescent modes and with 2·`modes`, extrapolated: B(∞) ≈ 2 B(2N) − B(N).
Complex pairBracket(const SignedModes& a, const SignedModes& b, double d, double g, int modes) {
    const double W = a.omega + b.omega, K = waveNumber(std::abs(W), d, g), K2 = K * K;
    const auto n = static_cast<std::size_t>(modes), all = 2 * n;
    const double wa = a.omega, wb = b.omega, wab = wa * wb, g2 = g * g;
    // H_jl = α + Ω (−g²/(ω_a ω_b)) k_j k_l − (g²/2)(k_j²/ω_a + k_l²/ω_b)   (eq. 25d)
    const double alpha = W * wab + 0.5 * (wa * wa * wa + wb * wb * wb), beta = -W * g2 / wab;
    const auto h = [&](Complex kj, Complex kl) {
        return alpha + beta * kj * kl - 0.5 * g2 * (kj * kj / wa + kl * kl / wb);
    };
    // The paddle's displacement terms (the two single sums) and the progressive rows of the
    // double sum: few terms, in complex arithmetic.
    Complex small = 0.0, large = 0.0;
    const auto both = [&](std::size_t j, Complex term) {
        large += term;
        if (j < n) small += term;
    };
    const Complex single0 = -(g / (2.0 * wa)) * a.c0 * a.k0 * a.k0 * progressiveRatio(wa, a.k0, W, K, d, g) -
                            (g / (2.0 * wb)) * b.c0 * b.k0 * b.k0 * progressiveRatio(wb, b.k0, W, K, d, g);
    const double lambda00 = a.k0 + b.k0;
    const Complex double00 = a.c0 * b.c0 * lambda00 * h(a.k0, b.k0) / (lambda00 * lambda00 - K2);
    small += single0 + double00;
    large += single0 + double00;
    for (std::size_t j = 0; j < all; ++j) {
        const double ka = a.kappa[j], kb = b.kappa[j];
        // k² = −κ², c = iĉ: c k² (ω² − Ω²)/(k² − K²) = i ĉ κ² (ω² − Ω²)/(κ² + K²).
        both(j, Complex(0.0, -(g / (2.0 * wa)) * a.cHat[j] * ka * ka * (wa * wa - W * W) / (ka * ka + K2) -
                                 (g / (2.0 * wb)) * b.cHat[j] * kb * kb * (wb * wb - W * W) / (kb * kb + K2)));
        const Complex kaj(0.0, -ka), kbj(0.0, -kb);
        const Complex la = a.k0 + kbj, lb = kaj + b.k0;  // (0, j) and (j, 0)
        both(j, a.c0 * Complex(0.0, b.cHat[j]) * la * h(a.k0, kbj) / (la * la - K2) +
                    Complex(0.0, a.cHat[j]) * b.c0 * lb * h(kaj, b.k0) / (lb * lb - K2));
    }
    // Evanescent with evanescent, in real arithmetic: k_j k_l = −κ_j κ_l, λ = −iσ (σ = κ_j + κ_l),
    // c_j c_l = −ĉ_j ĉ_l, so each term is −i ĉ_j ĉ_l σ H/(σ² + K²) with H real.
    double smallImag = 0.0, largeImag = 0.0;
    for (std::size_t j = 0; j < all; ++j) {
        const double kj = a.kappa[j], cj = a.cHat[j], hj = alpha + 0.5 * g2 * kj * kj / wa;
        double row = 0.0, rowSmall = 0.0;
        for (std::size_t l = 0; l < all; ++l) {
            const double kl = b.kappa[l], sigma = kj + kl;
            const double hjl = hj - beta * kj * kl + 0.5 * g2 * kl * kl / wb;
            const double term = b.cHat[l] * sigma * hjl / (sigma * sigma + K2);
            row += term;
            if (l < n) rowSmall += term;
        }
        largeImag -= cj * row;
        if (j < n) smallImag -= cj * rowSmall;
    }
    small += Complex(0.0, smallImag);
    large += Complex(0.0, largeImag);
    return 2.0 * large - small;
}

}  // namespace

Complex pistonSecondOrderStroke(double waveHeight, double omega, double depth, double g, int modes) {
    if (!(waveHeight > 0.0) || !(omega > 0.0) || !(depth > 0.0) || !(g > 0.0) || modes <= 0)
        throw std::invalid_argument("pistonSecondOrderStroke: H, ω, depth, g and modes must be > 0, got " +
                                    std::to_string(waveHeight) + ", " + std::to_string(omega) + ", " +
                                    std::to_string(depth) + ", " + std::to_string(g) + ", " + std::to_string(modes));
    // A component with itself: half the superharmonic of a pair at the same ω (δ = ½).
    const double stroke = 0.5 * waveHeight / pistonHeightToStroke(waveNumber(omega, depth, g) * depth);
    return 0.5 * pistonSecondOrderPair(stroke, omega, stroke, omega, depth, g, modes).sum;
}

double freeSecondHarmonic(Complex stroke, double omega, double depth, double g) {
    return pistonHeightToStroke(waveNumber(2.0 * omega, depth, g) * depth) * std::abs(stroke);
}

SecondOrderPair pistonSecondOrderPair(double strokeN, double omegaN, double strokeM, double omegaM, double depth,
                                      double g, int modes) {
    if (!(omegaN > 0.0) || !(omegaM > 0.0) || !(depth > 0.0) || !(g > 0.0) || modes <= 0)
        throw std::invalid_argument("pistonSecondOrderPair: ω_n, ω_m, depth, g and modes must be > 0, got " +
                                    std::to_string(omegaN) + ", " + std::to_string(omegaM) + ", " +
                                    std::to_string(depth) + ", " + std::to_string(g) + ", " + std::to_string(modes));
    const SignedModes n = signedModes(omegaN, depth, g, modes), m = signedModes(omegaM, depth, g, modes);
    SecondOrderPair out;
    const double sum = omegaN + omegaM, kSum = waveNumber(sum, depth, g);
    out.sum = strokeN * strokeM * kSum * kSum * pairBracket(n, m, depth, g, modes) / (sum * sum * sum);
    const double difference = omegaN - omegaM;
    if (difference != 0.0) {
        const double kDifference = waveNumber(std::abs(difference), depth, g);
        out.difference = -strokeN * strokeM * kDifference * kDifference *
                         pairBracket(n, signedModes(-omegaM, depth, g, modes), depth, g, modes) /
                         (difference * difference * difference);
    }
    return out;
}

std::vector<PaddleComponent> pistonSecondOrderComponents(std::span<const PaddleComponent> first, double depth,
                                                         double g, int modes) {
    std::vector<SignedModes> plus, minus;
    for (const PaddleComponent& c : first) {
        if (!(c.omega > 0.0))
            throw std::invalid_argument("pistonSecondOrderComponents: ω must be > 0, got " + std::to_string(c.omega));
        plus.push_back(signedModes(c.omega, depth, g, modes));
        minus.push_back(signedModes(-c.omega, depth, g, modes));
    }
    // Every term as (Ω, Z): X = Re[−i Z e^{iΩt}] = |Z| sin(Ωt + arg Z), Z = C e^{i(φ_n ± φ_m)}.
    std::vector<std::pair<double, Complex>> terms;
    terms.reserve(first.size() * first.size());
    for (std::size_t i = 0; i < first.size(); ++i)
        for (std::size_t j = i; j < first.size(); ++j) {
            const PaddleComponent &n = first[i], &m = first[j];
            const double product = n.amplitude * m.amplitude;
            const double sum = n.omega + m.omega, kSum = waveNumber(sum, depth, g);
            const double half = i == j ? 0.5 : 1.0;  // δ: a component with itself
            const Complex cSum = half * product * kSum * kSum * pairBracket(plus[i], plus[j], depth, g, modes) /
                                 (sum * sum * sum);
            terms.emplace_back(sum, cSum * std::polar(1.0, n.phase + m.phase));
            if (i == j || n.omega == m.omega) continue;
            // The subharmonic at the positive Ω = ω_high − ω_low.
            const bool nHigh = n.omega > m.omega;
            const std::size_t hi = nHigh ? i : j, lo = nHigh ? j : i;
            const double W = first[hi].omega - first[lo].omega, kW = waveNumber(W, depth, g);
            const Complex cDifference =
                -product * kW * kW * pairBracket(plus[hi], minus[lo], depth, g, modes) / (W * W * W);
            terms.emplace_back(W, cDifference * std::polar(1.0, first[hi].phase - first[lo].phase));
        }
    std::sort(terms.begin(), terms.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<PaddleComponent> out;
    for (std::size_t t = 0; t < terms.size();) {
        const double omega = terms[t].first;
        Complex z = 0.0;
        for (; t < terms.size() && terms[t].first - omega <= 1e-9 * omega; ++t) z += terms[t].second;
        PaddleComponent c;
        c.omega = omega;
        c.amplitude = std::abs(z);
        c.phase = std::arg(z);
        out.push_back(c);
    }
    return out;
}

}  // namespace tide::waves
