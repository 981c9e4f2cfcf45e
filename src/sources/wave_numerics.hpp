#pragma once
/// \file
/// The solver settings a world with a wave maker gets unless its scene sets them: the ones
/// that keep progressive waves their height and speed (docs/waves.md § Defaults, each chosen
/// by a measurement in a flume). Other worlds keep the solvers' own defaults.

#include <tide/defs.hpp>

namespace tide {

/// Fills the automatic (negative) fields of `solver` with the wave settings: dfsph takes
/// particle shifting 0.2 (Lind et al. 2012) and, in 3D, half its pressure's own term in the
/// difference form; every solver drops XSPH smoothing (an artificial viscosity acting every
/// step). Set fields stay as they are (docs/notes/waves.md § The heavy ball on another flume):
/// - in 2D the difference form stays off: issue 42's flume in 2D at 3.75 mm (67 layers)
///   diverged with it within 0.2–0.8 s and runs without it;
/// - the density solve keeps its heavy ball: without it the suite's flume kept more height
///   (−3.2 % against −7.7 %) but issue 42's flume less (−10.5 % against +0.7 % in 3D, −26.7 %
///   against −19.0 % in 2D), at twice the iterations.
inline void applyWaveNumerics(SolverDef& solver, int dimensions) {
    if (solver.xsph < 0.0f) solver.xsph = 0.0f;
    if (solver.method != "dfsph") return;
    if (solver.shifting < 0.0f) solver.shifting = 0.2f;
    if (solver.differenceForm < 0.0f) solver.differenceForm = dimensions == 2 ? 0.0f : 0.5f;
}

}  // namespace tide
