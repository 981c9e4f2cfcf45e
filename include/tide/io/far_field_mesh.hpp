#pragma once
/// \file
/// An ocean scene's far-field sea around its near field as a triangle mesh: the object
/// "far_field" of the `obj` frames, for Blender and Houdini. One mesh per frame: a grid of the
/// still-water plane displaced by the sea (elevation and choppy displacement, as tide render
/// draws it: ocean::sampleSurface), with a hole over the near field's x–z rectangle, where the
/// particles' own surface is. Its connectivity is the same in every frame.

#include <glm/vec3.hpp>

#include <tide/defs.hpp>
#include <tide/ocean.hpp>

namespace tide::io {

struct SurfaceMesh;

/// What the far field's mesh is made of.
struct FarFieldMeshDef {
    OceanDef ocean;         ///< the scene's sea
    double gravity = 9.81;  ///< |g|, m/s²
    /// The near field (the domain), m: the mesh's hole is its x–z rectangle, the still water at
    /// nearMin.y + ocean.depth.
    glm::vec3 nearMin{0.0f}, nearMax{0.0f};
    double extent = 0.0;   ///< how far the mesh reaches beyond the near field on every side, m (> 0)
    double spacing = 0.0;  ///< the largest distance between neighbouring points, m (> 0)
    double time = 0.0;     ///< the frame's simulated time, s
    double ramp = 1.0;     ///< the far field's ramp factor at that time (World::oceanRamp)
    int threads = 0;       ///< worker threads; 0: all cores
};

/// The default reach of the far field's mesh: two peak wavelengths, m.
[[nodiscard]] double defaultFarFieldExtent(const OceanDef& ocean, double gravity);
/// The default spacing of its points: a sixteenth of the peak wavelength, m.
[[nodiscard]] double defaultFarFieldSpacing(const OceanDef& ocean, double gravity);

/// The far field's mesh of an ocean over the near field `world` (its domain and gravity), at
/// time 0 and full ramp (set `time` and `ramp` per frame); `extent` and `spacing` ≤ 0 take the
/// defaults.
[[nodiscard]] FarFieldMeshDef farFieldMeshFor(const OceanDef& ocean, const WorldDef& world, double extent = 0.0,
                                              double spacing = 0.0);

/// Appends the object "far_field" to `mesh`: a grid whose lines fall on the near field's edges,
/// every cell outside the near field's rectangle, triangles facing up. The points on the hole's
/// edge keep their x and z (no choppy shift), so the mesh meets the particles' surface there.
/// Throws std::invalid_argument naming the field if extent or spacing is not positive, or the
/// grid would exceed 4000 points along an axis (16 million in all).
void appendFarField(SurfaceMesh& mesh, const FarFieldMeshDef& def);

}  // namespace tide::io
