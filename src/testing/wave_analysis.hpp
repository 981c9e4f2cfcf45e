#pragma once
/// \file
/// Analysis of wave-gauge records (free-surface height sampled at a fixed interval), shared
/// by the wave tests and benchmarks: zero up-crossing periods and heights, the complex
/// amplitude at one frequency, and the incident/reflected split of two gauges.

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

namespace tide::waves {

/// A gauge record: heights η[k] at times t0 + k·dt.
struct Record {
    double t0 = 0.0, dt = 0.01;
    std::vector<double> eta;
    [[nodiscard]] double time(std::size_t k) const { return t0 + dt * static_cast<double>(k); }
};

/// The part of a record with from ≤ t < to.
inline Record window(const Record& r, double from, double to) {
    Record out{0.0, r.dt, {}};
    bool first = true;
    for (std::size_t k = 0; k < r.eta.size(); ++k)
        if (r.time(k) >= from - 1e-9 && r.time(k) < to - 1e-9) {
            if (first) out.t0 = r.time(k), first = false;
            out.eta.push_back(r.eta[k]);
        }
    return out;
}

/// A single crest's passage at a gauge (a solitary wave's): its height, the highest sample
/// before `last`, and its time, the centroid in time of η² over the samples around it above
/// half that height (less noisy than the highest sample's time).
struct CrestPassage {
    double height = 0.0, time = 0.0;
};
inline CrestPassage crestPassage(const Record& r, std::size_t last) {
    last = std::min(last, r.eta.size());
    if (last == 0) return {};
    const auto top = static_cast<std::size_t>(std::max_element(r.eta.begin(), r.eta.begin() + static_cast<std::ptrdiff_t>(last)) -
                                              r.eta.begin());
    const double crest = r.eta[top];
    std::size_t a = top, b = top;
    while (a > 0 && r.eta[a - 1] > 0.5 * crest) --a;
    while (b + 1 < last && r.eta[b + 1] > 0.5 * crest) ++b;
    double w = 0.0, wt = 0.0;
    for (std::size_t k = a; k <= b; ++k) w += r.eta[k] * r.eta[k], wt += r.eta[k] * r.eta[k] * r.time(k);
    return {crest, w > 0.0 ? wt / w : r.time(top)};
}

/// The least-squares slope of x against t: a celerity from arrival times at gauges.
inline double celerity(const std::vector<double>& x, const std::vector<double>& t) {
    double st = 0.0, sx = 0.0, stt = 0.0, stx = 0.0;
    const auto n = static_cast<double>(x.size());
    for (std::size_t k = 0; k < x.size(); ++k) st += t[k], sx += x[k], stt += t[k] * t[k], stx += t[k] * x[k];
    return (n * stx - st * sx) / (n * stt - st * st);
}

inline double mean(const Record& r) {
    double sum = 0.0;
    for (const double e : r.eta) sum += e;
    return r.eta.empty() ? 0.0 : sum / static_cast<double>(r.eta.size());
}

/// The wave-height envelope over periods [first, last) of length T (periods counted from
/// t = 0): the mean over those periods of each period's highest minus lowest η. A standing
/// or partly standing wave's local height, which a growing seiche makes grow.
inline double envelope(const Record& r, double period, int first, int last) {
    double sum = 0.0;
    int count = 0;
    for (int n = first; n < last; ++n) {
        const Record w = window(r, n * period, (n + 1) * period);
        if (w.eta.empty()) continue;
        const auto [lo, hi] = std::minmax_element(w.eta.begin(), w.eta.end());
        sum += *hi - *lo;
        ++count;
    }
    return count > 0 ? sum / count : 0.0;
}

/// Zero up-crossing analysis about the record's mean (the standard wave-by-wave definition,
/// e.g. Goda, "Random seas and design of maritime structures", §2.1): the times of up-crossings
/// (linearly interpolated), and the crest-to-trough height of each wave between two of them.
struct Crossings {
    std::vector<double> times;
    std::vector<double> heights;
    [[nodiscard]] double meanPeriod() const {
        return times.size() < 2 ? 0.0 : (times.back() - times.front()) / static_cast<double>(times.size() - 1);
    }
    [[nodiscard]] double meanHeight() const {
        double sum = 0.0;
        for (const double h : heights) sum += h;
        return heights.empty() ? 0.0 : sum / static_cast<double>(heights.size());
    }
};

inline Crossings upCrossings(const Record& r) {
    Crossings c;
    const double m = mean(r);
    std::size_t last = 0;
    for (std::size_t k = 1; k < r.eta.size(); ++k) {
        const double a = r.eta[k - 1] - m, b = r.eta[k] - m;
        if (a < 0.0 && b >= 0.0) {
            c.times.push_back(r.time(k - 1) + r.dt * (-a / (b - a)));
            if (c.times.size() >= 2) {
                double hi = -1e30, lo = 1e30;
                for (std::size_t j = last; j <= k; ++j) hi = std::max(hi, r.eta[j]), lo = std::min(lo, r.eta[j]);
                c.heights.push_back(hi - lo);
            }
            last = k;
        }
    }
    return c;
}

/// Complex amplitude A at angular frequency ω, η ≈ Re(A e^{iωt}) (A = (2/N) Σ η_k e^{−iωt_k};
/// exact for a record of whole periods).
inline std::complex<double> amplitudeAt(const Record& r, double omega) {
    std::complex<double> sum = 0.0;
    const double m = mean(r);
    for (std::size_t k = 0; k < r.eta.size(); ++k)
        sum += (r.eta[k] - m) * std::exp(std::complex<double>(0.0, -omega * r.time(k)));
    return 2.0 * sum / static_cast<double>(r.eta.size());
}

/// Incident and reflected wave amplitudes from two gauges Δx apart (x2 > x1, waves coming
/// from −x) by the two-gauge method of Goda & Suzuki 1976 ("Estimation of incident and
/// reflected waves in random wave experiments", Proc. 15th ICCE): with η = a_I cos(ωt − kx + φ_I)
/// + a_R cos(ωt + kx + φ_R), A1 = I + R, A2 = I e^{−ikΔx} + R e^{ikΔx}.
struct Split {
    double incident, reflected;
    [[nodiscard]] double coefficient() const { return reflected / incident; }
};
inline Split incidentReflected(std::complex<double> a1, std::complex<double> a2, double k, double dx) {
    const std::complex<double> e(std::cos(k * dx), std::sin(k * dx));  // e^{ikΔx}
    const std::complex<double> det = e - std::conj(e);                 // 2i sin kΔx
    const std::complex<double> incident = (a1 * e - a2) / det;
    const std::complex<double> reflected = (a2 - a1 * std::conj(e)) / det;
    return {std::abs(incident), std::abs(reflected)};
}

namespace detail {
/// The fit(p, q) with the least rmsResidual over [pLo, pHi] × [qLo, qHi]: a scan of
/// (pSteps + 1) × (qSteps + 1) points (qSteps 0: q stays qLo), then coordinate steps halved
/// whenever none improves (60 rounds), q kept ≥ qMin.
template <class Fit>
auto scanThenRefine(Fit fit, double pLo, double pHi, int pSteps, double qLo, double qHi, int qSteps, double qMin) {
    auto best = fit(pLo, qLo);
    double bestP = pLo, bestQ = qLo;
    for (int iq = 0; iq <= qSteps; ++iq)
        for (int ip = 0; ip <= pSteps; ++ip) {
            const double p = pLo + (pHi - pLo) * ip / pSteps, q = qSteps > 0 ? qLo + (qHi - qLo) * iq / qSteps : qLo;
            const auto f = fit(p, q);
            if (f.rmsResidual < best.rmsResidual) best = f, bestP = p, bestQ = q;
        }
    double dp = (pHi - pLo) / pSteps, dq = qSteps > 0 ? (qHi - qLo) / qSteps : 0.0;
    for (int round = 0; round < 60; ++round) {
        bool moved = false;
        for (const auto& [sp, sq] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
            if (sq != 0 && qSteps == 0) continue;
            const double p = bestP + sp * dp, q = std::max(qMin, bestQ + sq * dq);
            const auto f = fit(p, q);
            if (f.rmsResidual < best.rmsResidual) best = f, bestP = p, bestQ = q, moved = true;
        }
        if (!moved) dp *= 0.5, dq *= 0.5;
    }
    return best;
}
}  // namespace detail

/// Incident and reflected waves and the wave number itself, from N ≥ 3 gauges at x_j along
/// the flume: the least-squares fit of A_j = I e^{−κ x_j} + R e^{κ x_j}, κ = α + ik, over all
/// gauges — the method of Mansard & Funke 1980 ("The measurement of incident and reflected
/// spectra using a least squares method", Proc. 17th ICCE, eq. 5–9) with k an unknown as
/// well, and α, the waves' spatial decay rate (1/m), an optional one. For given κ the fit is
/// linear in I and R (2 × 2 normal equations); κ minimising the residual is found by a scan
/// of [kLo, kHi] × [αLo, αHi] refined by shrinking coordinate steps. A two-gauge phase lag reads k with an error of up
/// to ~ Kr rad at each gauge from the reflected wave; the fit separates the two.
struct FlumeFit {
    double k = 0.0;      ///< wave number, 1/m
    double alpha = 0.0;  ///< spatial decay rate of the incident wave, 1/m (0 unless fitted)
    std::complex<double> incident, reflected;  ///< amplitudes at x = 0 (η = Re(I e^{iωt − κx} + R e^{iωt + κx}))
    double rmsResidual = 0.0;  ///< of the fit, m (complex amplitude)
    [[nodiscard]] double coefficient() const { return std::abs(reflected) / std::abs(incident); }
};
namespace detail {
inline FlumeFit fitAt(const std::vector<double>& x, const std::vector<std::complex<double>>& a, double k, double alpha) {
    using C = std::complex<double>;
    const C kappa(alpha, k);
    C a11 = 0.0, a12 = 0.0, a22 = 0.0, b1 = 0.0, b2 = 0.0;
    for (std::size_t j = 0; j < x.size(); ++j) {
        const C e1 = std::exp(-kappa * x[j]), e2 = std::exp(kappa * x[j]);
        a11 += std::norm(e1), a12 += std::conj(e1) * e2, a22 += std::norm(e2);
        b1 += std::conj(e1) * a[j], b2 += std::conj(e2) * a[j];
    }
    const C det = a11 * a22 - a12 * std::conj(a12);
    FlumeFit f;
    f.k = k, f.alpha = alpha;
    f.incident = (b1 * a22 - a12 * b2) / det;
    f.reflected = (a11 * b2 - std::conj(a12) * b1) / det;
    double sum = 0.0;
    for (std::size_t j = 0; j < x.size(); ++j)
        sum += std::norm(a[j] - f.incident * std::exp(-kappa * x[j]) - f.reflected * std::exp(kappa * x[j]));
    f.rmsResidual = std::sqrt(sum / static_cast<double>(x.size()));
    return f;
}
}  // namespace detail
inline FlumeFit fitIncidentReflected(const std::vector<double>& x, const std::vector<std::complex<double>>& a, double kLo,
                                     double kHi, double alphaLo = 0.0, double alphaHi = 0.0) {
    return detail::scanThenRefine([&](double k, double alpha) { return detail::fitAt(x, a, k, alpha); }, kLo, kHi, 400,
                                  alphaLo, alphaHi, alphaHi > alphaLo ? 40 : 0, -std::numeric_limits<double>::infinity());
}

/// A damped oscillation η(t) ≈ e^(−βt)(A sin ωt + B cos ωt) + C fitted by least squares
/// (A, B, C linear for each ω, β; ω and β searched on a grid in [omegaLo, omegaHi] × [0,
/// betaHi], then refined): a frequency that uses the whole record, less sensitive to particle
/// noise than counting crossings.
struct DampedFit {
    double omega = 0.0;        ///< rad/s
    double beta = 0.0;         ///< decay rate, 1/s
    double amplitude = 0.0;    ///< √(A² + B²) at t = 0
    double rmsResidual = 0.0;
};
namespace detail {
inline DampedFit fitDampedAt(const Record& r, double omega, double beta) {
    double s[3][3] = {}, rhs[3] = {};
    for (std::size_t k = 0; k < r.eta.size(); ++k) {
        const double t = r.time(k), e = std::exp(-beta * t);
        const double f[3] = {e * std::sin(omega * t), e * std::cos(omega * t), 1.0};
        for (int i = 0; i < 3; ++i) {
            rhs[i] += f[i] * r.eta[k];
            for (int j = 0; j < 3; ++j) s[i][j] += f[i] * f[j];
        }
    }
    // Gaussian elimination of the 3×3 normal equations (symmetric positive definite).
    for (int c = 0; c < 3; ++c)
        for (int i = c + 1; i < 3; ++i) {
            const double m = s[i][c] / s[c][c];
            for (int j = c; j < 3; ++j) s[i][j] -= m * s[c][j];
            rhs[i] -= m * rhs[c];
        }
    double x[3];
    for (int i = 2; i >= 0; --i) {
        x[i] = rhs[i];
        for (int j = i + 1; j < 3; ++j) x[i] -= s[i][j] * x[j];
        x[i] /= s[i][i];
    }
    double sum = 0.0;
    for (std::size_t k = 0; k < r.eta.size(); ++k) {
        const double t = r.time(k), e = std::exp(-beta * t);
        const double fit = e * (x[0] * std::sin(omega * t) + x[1] * std::cos(omega * t)) + x[2];
        sum += (r.eta[k] - fit) * (r.eta[k] - fit);
    }
    return {omega, beta, std::hypot(x[0], x[1]), std::sqrt(sum / static_cast<double>(std::max<std::size_t>(1, r.eta.size())))};
}
}  // namespace detail
inline DampedFit fitDampedOscillation(const Record& r, double omegaLo, double omegaHi, double betaHi = 1.0) {
    return detail::scanThenRefine([&](double omega, double beta) { return detail::fitDampedAt(r, omega, beta); }, omegaLo,
                                  omegaHi, 300, 0.0, betaHi, 20, 0.0);
}

}  // namespace tide::waves
