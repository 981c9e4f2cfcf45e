#pragma once
/// \file
/// Linear (Airy) wave theory for wave makers: the dispersion relation, the wavemaker
/// transfer functions of Biesel & Suquet 1951 as written in Dean & Dalrymple, "Water wave
/// mechanics for engineers and scientists" (1991), §6.2, and sea-state spectra.

#include <cstdint>
#include <vector>

#include <tide/defs.hpp>

namespace tide::waves {

inline constexpr double kGravity = 9.81;  ///< m/s², the g of the formulas below unless given

/// Wave number k (rad/m) with ω² = g k tanh(k d), by Newton's method from the deep- or
/// shallow-water guess (whichever is closer), to relative precision 1e-12.
double waveNumber(double omega, double depth, double g = kGravity);

/// H/S of a piston paddle: 2(cosh 2kd − 1)/(sinh 2kd + 2kd) (Dean & Dalrymple eq. 6.20).
double pistonHeightToStroke(double kd);
/// H/S of a flap hinged on the bed: 4 (sinh kd/kd)(kd sinh kd − cosh kd + 1)/(sinh 2kd + 2kd)
/// (Dean & Dalrymple eq. 6.21). S is the stroke at the still-water level.
double flapHeightToStroke(double kd);

/// One sinusoid of a paddle motion: displacement at the still-water level
/// X(t) = amplitude · sin(ω t + phase).
struct PaddleComponent {
    double amplitude = 0.0;  ///< S/2, m
    double omega = 0.0;      ///< rad/s
    double phase = 0.0;      ///< rad
    double waveAmplitude = 0.0;  ///< the progressive wave's H/2 it makes, m
};

/// JONSWAP variance density S(f), m²·s, for peak frequency fp = 1/Tp, normalised so that
/// ∫ S df = Hs²/16 (m0 = (Hs/4)²): the shape f⁻⁵ exp(−5/4 (fp/f)⁴) γ^exp(−(f − fp)²/(2σ² fp²)),
/// σ = 0.07 below fp and 0.09 above (Hasselmann et al. 1973); the constant in front is found
/// by integrating the shape numerically (γ = 1 is Pierson–Moskowitz, whose constant is
/// 5/16 Hs² fp⁴ in closed form).
class JonswapSpectrum {
public:
    JonswapSpectrum(double significantHeight, double peakPeriod, double gamma);
    [[nodiscard]] double operator()(double f) const;
    /// The constant in front of the shape, m²·s⁻⁴.
    [[nodiscard]] double scale() const { return scale_; }

private:
    [[nodiscard]] double shape(double f) const;
    double fp_, gamma_, scale_ = 1.0;
};

/// Amplitude of the second-order correction of a piston's stroke for regular waves of height
/// H, wave number k in depth d, X₂(t) = a₂ sin(2ωt + 2φ) next to X₁ = (S/2) sin(ωt + φ):
/// a₂ = H²/(32 d) (3 cosh kd / sinh³ kd − 2/m₁), m₁ = H/S the linear transfer function
/// (Madsen 1971, "On the generation of long waves", JGR 76(36), as written by Altomare et al.
/// 2017, Coastal Engineering 127, eq. 8): the long-wave limit of the stroke that cancels the
/// free second harmonic the linear stroke radiates. Wave makers use the full theory
/// (pistonSecondOrderStroke, Schäffer 1996), to which this tends as kd → 0.
double pistonSecondOrderAmplitude(double waveHeight, double kd, double depth);

/// The paddle components of a wave maker: one for regular waves (stroke from the transfer
/// function of its type), or `spectrum.components` for an irregular sea. Irregular seas use
/// the random-phase method: N equal frequency bands Δf over [fmin, fmax]·fp, a component at
/// each band's centre with wave amplitude a_n = √(2 S(f_n) Δf) and a phase uniform in [0, 2π)
/// from std::mt19937(seed) (Tucker, Challenor & Carter 1984 discuss why random amplitudes are
/// not needed for long records); each paddle amplitude is a_n divided by the transfer function
/// at its own k_n d (Dean & Dalrymple §6.2, superposed linearly). With `order` 2 a piston's
/// components are followed by their second-order ones (waveAmplitude 0): regular waves by the
/// stroke at 2ω (pistonSecondOrderStroke), an irregular sea by the super- and subharmonics of
/// every pair (pistonSecondOrderComponents; 3N − 2 components on the N equal bands).
std::vector<PaddleComponent> paddleComponents(const WaveMakerDef& def, double g = kGravity);

/// A piston's trajectory for one solitary wave of height H in depth d (Goring 1978, "Tsunamis:
/// the propagation of long waves onto a shelf", Caltech KH-R-38, eq. 2.31): the paddle moves
/// with the water under the wave, dX/dt = c η/(d + η), η = H sech²(κ(c t − X)), which
/// integrates to ξ = (H/(κd)) tanh(κ(c(t − t₀) − ξ)), with κ = √(3H/(4d³)) and
/// c = √(g(d + H)) (Boussinesq's solitary wave). The stroke is 2H/(κd); it is centred on
/// t₀ = (3.8 + H/d)/(κc), half of Goring's duration, so the paddle starts from rest at t = 0
/// (X(0) = 0) and stops at 2t₀.
class SolitaryStroke {
public:
    SolitaryStroke(double waveHeight, double depth, double g = kGravity);
    struct State {
        double x, v, a;  ///< displacement, m; velocity, m/s; acceleration, m/s²
    };
    [[nodiscard]] State at(double t) const;
    [[nodiscard]] double stroke() const { return 2.0 * amplitude_; }
    [[nodiscard]] double celerity() const { return c_; }
    [[nodiscard]] double duration() const { return 2.0 * t0_; }

private:
    [[nodiscard]] double xi(double t) const;
    double h_, d_, kappa_, c_, amplitude_, t0_, origin_ = 0.0;
};

/// The smooth start ½(1 − cos(π t/T_ramp)) and its first and second time derivatives (1, 0, 0 after T_ramp).
struct Ramp {
    double value, rate, curvature;
};
Ramp ramp(double t, double rampTime);

}  // namespace tide::waves
