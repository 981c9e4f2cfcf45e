#pragma once
/// \file
/// The far field's surface as a mesh sees it (tide render, tide-view, OBJ frames): points of the
/// still-water plane moved by the sea's choppy displacement and raised by its elevation, with
/// normals from the elevation's slope, by direct summation of the same components the coupling
/// zones use, so the rendered sea meets the near field's water without a seam.
///
/// A mesh samples the sea at its own spacing: components shorter than four samples a
/// wavelength would alias into noise there (a far ring of a camera-centred grid is metres
/// wide), so each point takes its components with a weight that falls from 1 at two samples
/// a half wavelength to 0 at one (the usual detail fade of ocean rendering, e.g. Tessendorf 2001 §4.3).

#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "ocean/sea.hpp"

namespace tide::ocean {

/// A point of the surface, world units (m).
struct SurfacePoint {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
};

/// What the surface samples are taken with.
struct SurfaceSampling {
    double time = 0.0;         ///< s
    double ramp = 1.0;         ///< the far field's ramp factor (RelaxationZones::ramp)
    double stillWaterY = 0.0;  ///< world y of still water, m
    bool choppy = true;        ///< move points horizontally by Sea::horizontalDisplacement
};

/// out[i] = the surface over rest point rest[i] = (x, z), sampled at a spacing of spacing[i] m
/// (components with k·spacing[i] > π/2 faded out, none at > π). `out` and `spacing` must have
/// the size of `rest` (else std::invalid_argument). On `threads` threads, the same for any count.
void sampleSurface(const Sea& sea, std::span<const glm::dvec2> rest, std::span<const float> spacing,
                   const SurfaceSampling& sampling, std::span<SurfacePoint> out, int threads = 1);

}  // namespace tide::ocean
