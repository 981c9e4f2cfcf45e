#pragma once
/// \file
/// The solver settings a world with a wave maker gets unless its scene sets them: the ones
/// that keep progressive waves their height and speed (docs/waves.md § Defaults, each chosen
/// by a measurement in a flume). Other worlds keep the solvers' own defaults.

#include <tide/defs.hpp>

namespace tide {

/// Fills the automatic (negative) fields of `solver` with the wave settings: dfsph takes
/// particle shifting 0.2 (Lind et al. 2012), half its pressure's own term in the difference
/// form, no heavy ball in the density solve; every solver drops XSPH smoothing (an artificial
/// viscosity acting every step). Set fields stay as they are.
inline void applyWaveNumerics(SolverDef& solver) {
    if (solver.xsph < 0.0f) solver.xsph = 0.0f;
    if (solver.method != "dfsph") return;
    if (solver.shifting < 0.0f) solver.shifting = 0.2f;
    if (solver.differenceForm < 0.0f) solver.differenceForm = 0.5f;
    if (solver.momentum < 0.0f) solver.momentum = 0.0f;
}

}  // namespace tide
