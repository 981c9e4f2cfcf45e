#pragma once
/// \file
/// A regular wave of finite height by Stokes' theory to fifth order (Fenton 1985, "A
/// fifth-order Stokes theory for steady waves", J. Waterway, Port, Coastal and Ocean Eng.
/// 111(2), 216–234; Table 1 as reprinted in Fenton 1990, "Nonlinear wave theories", The Sea 9).
///
/// The expansion parameter is ε = kH/2 (H crest to trough, exactly, at every order). With
/// θ = kx − ωt and y from still water (the floor at y = −d):
///   kη = ε cos θ + ε² B22 cos 2θ + ε³ B31 (cos θ − cos 3θ) + ε⁴ (B42 cos 2θ + B44 cos 4θ)
///        + ε⁵ (−(B53 + B55) cos θ + B53 cos 3θ + B55 cos 5θ)                   (eq. 14)
///   φ  = C0 √(g/k³) Σ_{i=1..5} ε^i Σ_j A_ij cosh(jk(y + d)) sin jθ             (eq. 13)
/// and the celerity c = c_E + ū from the mean Eulerian current c_E and the mean fluid speed in
/// the wave's frame, ū √(k/g) = C0 + ε² C2 + ε⁴ C4 (eq. 15), with one of Fenton's two
/// definitions of the current:
///   - no current (c_E = 0, the open sea): c = ū; the water drifts with the waves;
///   - no mass flux (c_S = 0, a closed flume's waves): c = Q/d, the volume flux under the wave
///     in its frame, Q/d √(k/g) = C0 + ε² (C2 + D2/kd) + ε⁴ (C4 + D4/kd) (eq. 16–17); the water
///     carries a uniform return current c_E = c − ū < 0 against the waves' Stokes drift.
/// With c = ω/k and ε = kH/2 this is solved for k given H, T and d. A lower order keeps the
/// terms up to ε^order (order 1: Airy's wave; below order 3 the current is 0).
///
/// Each harmonic j is a component of the sea at jk and jω: η amplitude a_j and a horizontal
/// velocity u = V_j cosh(jk(y+d))/sinh(jkd) cos jθ, the vertical v = V_j sinh(..)/sinh(..) sin jθ
/// (ocean/sea.hpp's form for a linear wave, V = a ω; here a bound harmonic's own V).

#include <array>
#include <optional>

#include <tide/ocean.hpp>

namespace tide::ocean {

/// A Stokes wave as harmonics (index 0 is the first harmonic).
struct StokesWave {
    int order = 1;        ///< the terms kept, ε^1 … ε^order
    double k = 0.0;       ///< wave number, rad/m
    double omega = 0.0;   ///< 2π/T, rad/s
    double epsilon = 0.0; ///< kH/2
    std::array<double, 5> elevation{};  ///< a_j, m (cos jθ)
    std::array<double, 5> velocity{};   ///< V_j, m/s
    double current = 0.0;  ///< c_E: the uniform current along the wave, m/s (0, or < 0 with no mass flux)
};

/// The Stokes wave of height H and period T on depth d, to `order` (1 … 5). Throws
/// std::invalid_argument naming `field` (the scene's path of the order) when the wave is beyond
/// the theory: steeper than the breaking limit H/L = 0.142 tanh kd (Miche 1944), or so shallow
/// that its series does not fall off (a harmonic larger than the one before it: Stokes theory
/// needs a small Ursell number; cnoidal theory holds there instead).
StokesWave stokesWave(double height, double period, double depth, double g, int order,
                      OceanWavesDef::MeanCurrent current = OceanWavesDef::MeanCurrent::None, const char* field = "order");

/// The Stokes wave of an ocean's regular sea at its order (tide::oceanWaveOrder: `order`, or
/// 5 where the series holds for the wave when it is 0), or none for Airy's wave and spectra.
/// The one place the automatic order is decided. Validates `def` first.
std::optional<StokesWave> oceanStokesWave(const OceanDef& def, double g);

}  // namespace tide::ocean
