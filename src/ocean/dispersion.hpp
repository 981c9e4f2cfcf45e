#pragma once
/// \file
/// The linear dispersion relation of water waves on finite depth, ω² = g k tanh(k d).

namespace tide::ocean {

inline constexpr double kGravity = 9.81;  ///< m/s², the g of the ocean unless given

/// Wave number k (rad/m) of angular frequency ω on depth d: Newton's method on
/// f(k) = g k tanh(kd) − ω² from Fenton & McKee's explicit approximation
/// k ≈ (ω²/g) / tanh((ω √(d/g))^{3/2})^{2/3} (Fenton & McKee 1990, "On calculating the lengths
/// of water waves", Coastal Engineering 14; within 1.7 % everywhere), to machine
/// precision (relative residual below 1e-14 in tests). Throws std::invalid_argument unless
/// ω, d and g are > 0 and finite.
double waveNumber(double omega, double depth, double g = kGravity);

/// ω of wave number k on depth d: √(g k tanh(kd)).
double angularFrequency(double k, double depth, double g = kGravity);

}  // namespace tide::ocean
