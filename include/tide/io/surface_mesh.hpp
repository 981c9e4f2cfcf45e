#pragma once
/// \file
/// The fluid's surface as a triangle mesh, built from its particles, for renderers that want a
/// surface rather than points (Blender, Houdini): the `obj` frame format.
///
/// Each particle is a sphere of one particle spacing; their union is a narrow-band level set
/// (Zhu & Bridson 2005, "Animating sand as a fluid", §3.1, with a uniform radius) on voxels of
/// half a spacing, smoothed (two mean-value passes) and meshed 0.3 spacings inside its zero
/// level, which puts a flat face of a block of fluid where the block's face is (half a spacing
/// beyond its outer particles). A particle the smoothing leaves outside (a lone drop) keeps a
/// bead of its own volume. OpenVDB does each stage: ParticlesToLevelSet, LevelSetFilter,
/// csgUnion, volumeToMesh.

#include <array>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include <tide/io/far_field_mesh.hpp>
#include <tide/particles.hpp>

namespace tide::io {

/// What the surface mesh needs beyond the particles.
struct SurfaceMeshDef {
    /// m: the fluid's particle spacing (> 0). The level set's voxels are half of it: finer ones
    /// resolve no more than the particles do, and cost their cube.
    float particleSpacing = 0.0f;
    /// The mesh's object names, by material index; a material beyond the list is "material_<index>".
    std::vector<std::string> materialNames;
    int threads = 0;  ///< worker threads; 0: all cores
    /// An ocean scene's far field, appended as the object "far_field" (appendFarField) with
    /// this def's threads; none when empty.
    std::optional<FarFieldMeshDef> farField;
};

/// One triangle mesh per material present, in one vertex array.
struct SurfaceMesh {
    struct Object {
        std::string name;             ///< the material's (SurfaceMeshDef::materialNames)
        std::uint32_t material = 0;   ///< material index
        std::size_t firstTriangle = 0;
        std::size_t triangleCount = 0;
    };
    std::vector<glm::vec3> vertices;  ///< m
    /// Indices into vertices, counter-clockwise seen from outside the fluid (normals point out).
    std::vector<std::array<std::uint32_t, 3>> triangles;
    /// By increasing material index, materials with particles only; then "far_field" (material 0,
    /// the ocean's water) when SurfaceMeshDef::farField is set.
    std::vector<Object> objects;
};

/// The surface of each material's particles. Throws std::invalid_argument naming the particle
/// spacing if it is not positive and finite.
[[nodiscard]] SurfaceMesh buildSurfaceMesh(const ParticleStore& particles, const SurfaceMeshDef& def);

/// Writes `mesh` as Wavefront OBJ text: `o <name>` and smooth shading (`s 1`) per object,
/// `v x y z` vertices, `f a b c` triangles (1-based).
void writeObj(std::ostream& out, const SurfaceMesh& mesh);

/// The volume a closed, outward-oriented triangle mesh encloses (m³; divergence theorem), of
/// the triangles [first, first + count).
[[nodiscard]] double enclosedVolume(const SurfaceMesh& mesh, std::size_t first, std::size_t count);

}  // namespace tide::io
