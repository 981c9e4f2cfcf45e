#pragma once
/// \file
/// The second-order stroke of a piston making regular waves, by the full second-order
/// wavemaker theory of Schäffer 1996 ("Second-order wavemaker theory for irregular waves",
/// Ocean Engineering 23(1), 47–88), in its monochromatic (superharmonic, n = m) and piston
/// (M₁ = M₂ = 0) limits: the stroke at 2ω that cancels the spurious free wave a linear stroke
/// radiates, with every first-order evanescent mode the paddle makes.
///
/// Madsen 1971 (pistonSecondOrderAmplitude) keeps the progressive mode and the long-wave
/// limit: it agrees to 0.1 % at kd = 0.2 and 0.5 % at 0.3, but at kd = 0.95 asks for 0.38 of
/// the full stroke and from kd ≈ 1.15 for the opposite sign (docs/notes/waves.md § Second order).

#include <complex>

namespace tide::waves {

/// The stroke X₂(t) = Re C sin 2ωt + Im C cos 2ωt, m, that cancels the free second harmonic
/// of the first-order stroke X₁ = (S/2) sin ωt making waves of height H (amplitude a = H/2)
/// at angular frequency ω in depth d. With k_j the first-order modes (k₀ = k, the evanescent
/// k_j = −iκ_j, ω² = g k_j tanh k_j d) and K the free wave's at 2ω (K tanh Kd = 4ω²/g):
///
///   C = a² K² (3 g ω S₁ + S₃) / (16 ω³ c₀²),
///   S₁ = Σ_j c_j k_j² / (k_j² − K²),
///   S₃ = Σ_j Σ_l c_j c_l (k_j + k_l) H_jl / ((k_j + k_l)² − K²),
///   H_jl = 3ω³ − (g²/ω)(2 k_j k_l + (k_j² + k_l²)/2)                    (Schäffer eq. 25d, n = m),
///   c_j = ω² sinh k_j d cosh k_j d / (g k_j² N_j),  N_j = d/2 + sinh 2k_j d / (4 k_j)   (eq. 20–21),
///
/// c₀ = H/S the linear transfer function. This is Schäffer's eq. 41a–b for a piston
/// (X₂ = Re[−i (a²/d) F⁺ e^{2iωt}], δ = ½); S₁ is the paddle's displacement term (X₁ φ₁,xx at
/// the paddle), S₃ the free surface's forcing. The sums converge as 1/N in the number of
/// evanescent modes: `modes` and 2·`modes` are extrapolated (Richardson), 2e-5 relative at 400.
/// Throws std::invalid_argument for ω, d, H, g or modes ≤ 0.
std::complex<double> pistonSecondOrderStroke(double waveHeight, double omega, double depth, double g,
                                             int modes = 400);

/// The elevation amplitude a piston's stroke harmonic X sin(2ωt + φ) radiates as a free wave at
/// 2ω (linear theory, c₀ at K d), m: what pistonSecondOrderStroke's C, added to the stroke,
/// cancels, c₀(Kd)|C|.
double freeSecondHarmonic(std::complex<double> stroke, double omega, double depth, double g);

}  // namespace tide::waves
