#pragma once
/// \file
/// Sea-state spectra in angular frequency ω (rad/s) in terms of Hs and Tp, and the cos-2s
/// directional spreading function.
///
/// Pierson–Moskowitz and JONSWAP as DNV-RP-C205 (2010), "Environmental conditions and
/// environmental loads", §3.5.5, writes them (the JONSWAP shape of Hasselmann et al. 1973,
/// "Measurements of wind-wave growth and swell decay during the Joint North Sea Wave Project",
/// Dtsch. Hydrogr. Z. A8(12), normalised to Hs with Goda's factor, Goda 2000, "Random seas and
/// design of maritime structures", ch. 2):
///   S_PM(ω) = 5/16 Hs² ωp⁴ ω⁻⁵ exp(−5/4 (ω/ωp)⁻⁴),                    ωp = 2π/Tp
///   S_J(ω)  = A_γ S_PM(ω) γ^exp(−½ ((ω − ωp)/(σ ωp))²),  A_γ = 1 − 0.287 ln γ,
///   σ = 0.07 for ω ≤ ωp, 0.09 above.
/// A_γ makes m0 = ∫ S dω ≈ Hs²/16: within 0.3 % for 1 ≤ γ ≤ 5, 1.8 % low at γ = 7 (over
/// [0.2, 10] ωp; tests/test_ocean_spectrum.cpp, docs/ocean.md).

#include <vector>

namespace tide::ocean {

/// Pierson–Moskowitz S(ω), m²·s (DNV-RP-C205 §3.5.5).
double piersonMoskowitz(double omega, double hs, double tp);

/// JONSWAP S(ω), m²·s (Hasselmann et al. 1973 in the form of DNV-RP-C205 §3.5.5; γ = 1 is
/// Pierson–Moskowitz).
double jonswap(double omega, double hs, double tp, double gamma);

/// DNV-RP-C205 §3.5.5's γ for a sea of given Hs and Tp when none is known:
/// 5 for Tp/√Hs ≤ 3.6, exp(5.75 − 1.15 Tp/√Hs) below 5, 1 from 5 (Hs in m, Tp in s).
double dnvGamma(double hs, double tp);

/// The cos-2s directional spreading function of Longuet-Higgins, Cartwright & Smith 1963
/// ("Observations of the directional spectrum of sea waves using the motions of a floating
/// buoy"), as in Goda 2000, ch. 2:
///   D(θ) = G(s) cos^{2s}((θ − θ̄)/2),  G(s) = 2^{2s−1} Γ²(s+1) / (π Γ(2s+1)),
/// for θ − θ̄ in [−π, π], so ∫ D dθ = 1 over the circle.
class Cos2sSpreading {
public:
    explicit Cos2sSpreading(double s);
    /// D at an angle `relative` = θ − θ̄ (rad), 1/rad; wrapped into [−π, π].
    [[nodiscard]] double operator()(double relative) const;
    /// The angles (relative to θ̄, rad) of `count` directions of equal energy: the medians of
    /// the bands between the quantiles j/count of ∫ D (each band carries 1/count of it).
    [[nodiscard]] std::vector<double> equalEnergyDirections(int count) const;
    [[nodiscard]] double s() const { return s_; }

private:
    double s_, logNorm_;
};

}  // namespace tide::ocean
