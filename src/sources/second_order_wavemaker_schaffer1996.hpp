#pragma once
/// \file
/// The second-order stroke of a piston, by the full second-order wavemaker theory of Schäffer
/// 1996 ("Second-order wavemaker theory for irregular waves", Ocean Engineering 23(1), 47–88)
/// in its piston limit (M₁ = M₂ = 0): the strokes that cancel the spurious free waves a linear
/// stroke radiates, with every first-order evanescent mode the paddle makes. For regular waves
/// (the superharmonic of a component with itself, n = m) and for every pair of components of an
/// irregular stroke (the superharmonic at ω_n + ω_m and the subharmonic at ω_n − ω_m).
///
/// Madsen 1971 (pistonSecondOrderAmplitude) keeps the progressive mode and the long-wave
/// limit: it agrees to 0.1 % at kd = 0.2 and 0.5 % at 0.3, but at kd = 0.95 asks for 0.38 of
/// the full stroke and from kd ≈ 1.15 for the opposite sign (docs/notes/waves.md § Second order).

#include <complex>
#include <span>
#include <vector>

#include "sources/wave_theory.hpp"

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
/// the paddle), S₃ the free surface's forcing: the n = m case of pistonSecondOrderPair (half its
/// superharmonic), which computes it. The sums converge as 1/N in the number of evanescent
/// modes: `modes` and 2·`modes` are extrapolated (Richardson), 1e-5 relative from 100.
/// Throws std::invalid_argument for ω, d, H, g or modes ≤ 0.
std::complex<double> pistonSecondOrderStroke(double waveHeight, double omega, double depth, double g,
                                             int modes = 50);

/// The elevation amplitude a piston's stroke harmonic X sin(2ωt + φ) radiates as a free wave at
/// 2ω (linear theory, c₀ at K d), m: what pistonSecondOrderStroke's C, added to the stroke,
/// cancels, c₀(Kd)|C|.
double freeSecondHarmonic(std::complex<double> stroke, double omega, double depth, double g);

/// The second-order strokes of two distinct components of a piston's first-order stroke
/// X₁ = A_n sin(ω_n t + φ_n) + A_m sin(ω_m t + φ_m) (A = S/2, as PaddleComponent::amplitude):
///
///   X₂ = Re C⁺ sin(Ω⁺t + φ_n + φ_m) + Im C⁺ cos(Ω⁺t + φ_n + φ_m)      Ω⁺ = ω_n + ω_m   (`sum`)
///      + Re C⁻ sin(Ω⁻t + φ_n − φ_m) + Im C⁻ cos(Ω⁻t + φ_n − φ_m),     Ω⁻ = ω_n − ω_m   (`difference`)
///
/// cancel the free waves at Ω± the pair radiates through the free surface and the paddle's
/// displacement, leaving the bound ones. With a component written Re[ξ e^{iωt}], ξ = −iA e^{iφ},
/// and its conjugate as a component of frequency −ω (modes k_j → −k_j*, so k₀ → −k₀ and the
/// evanescent −iκ_j stay, c_j → −c_j*), for two components a, b (Ω = ω_a + ω_b, K the free wave
/// number at |Ω|; the superharmonic is a = n, b = m, the subharmonic a = n, b = m̄):
///
///   ξ₂ = i δ ξ_a ξ_b (K²/Ω³) B,
///   B = −(g/2ω_a) Σ_j c_ja k_ja² (ω_a² − Ω²)/(k_ja² − K²) − (g/2ω_b) Σ_l c_lb k_lb² (ω_b² − Ω²)/(k_lb² − K²)
///       + Σ_j Σ_l c_ja c_lb (k_ja + k_lb) H_jl / ((k_ja + k_lb)² − K²),
///   H_jl = Ω (ω_a ω_b − g² k_ja k_lb/(ω_a ω_b)) + (ω_a³ + ω_b³)/2 − (g²/2)(k_ja²/ω_a + k_lb²/ω_b),
///
/// c_j as in pistonSecondOrderStroke, δ = 1 here (a pair of distinct components) and ½ for a
/// component with itself. So C⁺ = A_n A_m K⁺² B(n, m)/Ω⁺³ and C⁻ = −A_n A_m K⁻² B(n, m̄)/Ω⁻³,
/// C = (a_n a_m/d) F with F = E·[…] in the form of Schäffer's eq. 41a–b for a piston
/// (E = δ K² d/(c₀ₙ c₀ₘ Ω³), a = c₀ A; H his eq. 25d, upper and lower signs; the subharmonic's
/// m-sums over the conjugate modes k_lm*, c_lm*), derived here as for the regular stroke.
/// Both hold for either order of n and m: swapping them leaves C⁺ and turns C⁻ into −conj C⁻
/// (the same motion). C⁻ grows as 1/Ω⁻ for close frequencies: the paddle carries the flux of the
/// bound set-down, d X₂' → c_g η_b. A component with itself (n = m) makes sum/2
/// (pistonSecondOrderStroke's C for H = 2 c₀ A) and no subharmonic: `difference` is 0 when
/// ω_n = ω_m. The sums converge as 1/N in the number of evanescent modes: `modes` and 2·`modes`
/// are extrapolated, 4e-5 relative at 50 near kd 1, 7e-4 at kd 4–5. Throws
/// std::invalid_argument for ω, d, g or modes ≤ 0.
struct SecondOrderPair {
    std::complex<double> sum;         ///< C⁺, m
    std::complex<double> difference;  ///< C⁻, m
};
SecondOrderPair pistonSecondOrderPair(double strokeN, double omegaN, double strokeM, double omegaM, double depth,
                                      double g, int modes = 50);

/// The second-order components of a piston's irregular first-order stroke `first` (its
/// components' ω > 0 and distinct): pistonSecondOrderPair for every pair n < m (superharmonic
/// and subharmonic) and half the superharmonic of every component with itself, as
/// PaddleComponent (amplitude ≥ 0, phase, waveAmplitude 0: no progressive wave of their own).
/// Terms at the same frequency (within 1e-9 relative) are added into one component, in
/// increasing ω: on paddleComponents' N equal bands the N² terms fall on 2N − 1 sums and N − 1
/// differences, 3N − 2 components (fewer where a sum meets a difference).
std::vector<PaddleComponent> pistonSecondOrderComponents(std::span<const PaddleComponent> first, double depth,
                                                         double g, int modes = 50);

}  // namespace tide::waves
