#pragma once
/// \file
/// The solver settings a world with a wave maker gets unless its scene sets them: the ones
/// that keep progressive waves their height and speed (docs/waves.md § Defaults, each chosen
/// by a measurement in a flume). Other worlds keep the solvers' own defaults.

#include <tide/defs.hpp>

namespace tide {

/// Fills the automatic (negative or unset) fields of `solver` with the wave settings: dfsph
/// takes particle shifting 0.2 (Lind et al. 2012) and, in 3D, half its pressure's own term in
/// the difference form, in 2D the Shepard-filtered residual (SolverDef::smoothDensityError);
/// every solver drops XSPH smoothing (an artificial viscosity acting every step). Set fields
/// stay as they are (docs/notes/waves.md § The heavy ball on another flume, § The filtered
/// residual as a 2D wave default):
/// - in 2D the difference form stays off: issue 42's flume in 2D at 3.75 mm (67 layers)
///   diverged with it within 0.2–0.8 s and runs without it;
/// - the density solve keeps its heavy ball: without it the suite's flume kept more height
///   (−3.2 % against −7.7 %) but issue 42's flume less (−10.5 % against +0.7 % in 3D, −26.7 %
///   against −19.0 % in 2D), at twice the iterations;
/// - the filtered residual only in 2D and only for trains of waves (`waveTrain`: regular or
///   irregular paddles, an ocean): issue 42's 2D flume at 8 particles per H kept its height
///   within 5 % to 1.5 λ with it (−6.8 % at 2.5 m without), but the 3D bench flume at 2 per H
///   lost 41.6 % at 5 λ with it against 15.2 % (45.4 % without the difference form), and a
///   2D solitary wave at 5 per H kept no more height with it (−5.3 % against −5.4 % over 8–12
///   depths; at 10 per H −2.8 against −4.9 % at 10 depths), at 16 % more a step.
inline void applyWaveNumerics(SolverDef& solver, int dimensions, bool waveTrain) {
    if (solver.xsph < 0.0f) solver.xsph = 0.0f;
    if (solver.method != "dfsph") return;
    if (solver.shifting < 0.0f) solver.shifting = 0.2f;
    if (!solver.smoothDensityError) solver.smoothDensityError = dimensions == 2 && waveTrain;
    if (solver.differenceForm < 0.0f) solver.differenceForm = dimensions == 2 ? 0.0f : 0.5f;
}

}  // namespace tide
