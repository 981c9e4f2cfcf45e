#pragma once
/// \file
/// Measuring the fluid at fixed points, for wave gauges and probes.
///
/// Free-surface height (a wave gauge at (x, z)): the highest y on the vertical line through
/// (x, z) where the SPH colour field c(y) = Σ_j V_j W(|x − x_j|) reaches ½, with V_j = m_j/ρ0_j
/// (rest volumes: a full lattice sums to exactly 1 inside the fluid, see World's mass
/// calibration, and the sum drops to ½ half a spacing above the top layer, where a lattice's
/// surface is). This is the kernel-sum criterion of DualSPHysics' MeasureTool (Crespo et al.
/// 2015, "DualSPHysics: open-source parallel CFD solver based on SPH", Comput. Phys. Commun.
/// 187, §5). The line is scanned downwards in steps of h/8 from above the highest fluid
/// particle near it, then the crossing is refined by bisection; where no fluid lies within
/// a support of the line (a dry gauge on a beach) the height is NaN.
///
/// Probes interpolate density, pressure and velocity with the Shepard-normalised SPH sum
/// A(x) = Σ_j V_j A_j W / Σ_j V_j W (NaN where no fluid is within a support).

#include <span>

#include <glm/vec3.hpp>

#include <tide/defs.hpp>
#include <tide/particles.hpp>

#include "core/kernels.hpp"
#include "core/periodic_box.hpp"

namespace tide {

/// Free-surface height y at (x, z), m; NaN where the line is dry.
float freeSurfaceHeight(const ParticleStore& particles, std::span<const MaterialDef> materials, const PeriodicBox& box,
                        const kernels::SmoothingKernel& w, float x, float z);

/// Shepard-interpolated fluid state at a point.
struct FieldSample {
    float density;       ///< kg/m³
    float pressure;      ///< Pa
    glm::vec3 velocity;  ///< m/s
};
FieldSample sampleField(const ParticleStore& particles, std::span<const MaterialDef> materials, const PeriodicBox& box,
                        const kernels::SmoothingKernel& w, const glm::vec3& point);

}  // namespace tide
