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

/// The paddle components of a wave maker: one for regular waves (stroke from the transfer
/// function of its type), or `spectrum.components` for an irregular sea. Irregular seas use
/// the random-phase method: N equal frequency bands Δf over [fmin, fmax]·fp, a component at
/// each band's centre with wave amplitude a_n = √(2 S(f_n) Δf) and a phase uniform in [0, 2π)
/// from std::mt19937(seed) (Tucker, Challenor & Carter 1984 discuss why random amplitudes are
/// not needed for long records); each paddle amplitude is a_n divided by the transfer function
/// at its own k_n d (Dean & Dalrymple §6.2, superposed linearly).
std::vector<PaddleComponent> paddleComponents(const WaveMakerDef& def, double g = kGravity);

/// The smooth start ½(1 − cos(π t/T_ramp)) and its first and second time derivatives (1, 0, 0 after T_ramp).
struct Ramp {
    double value, rate, curvature;
};
Ramp ramp(double t, double rampTime);

}  // namespace tide::waves
