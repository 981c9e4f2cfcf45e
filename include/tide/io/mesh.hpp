#pragma once
/// \file
/// Triangle meshes from files (Wavefront OBJ, PLY), for mesh obstacles.

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/ext/vector_uint3.hpp>
#include <glm/vec3.hpp>

#include <tide/triangle_mesh.hpp>

namespace tide::io {

/// Where a mesh goes: file coordinates are scaled per axis, rotated about x, then y, then z
/// (degrees, right-handed), then translated.
struct MeshPlacement {
    glm::vec3 scale{1.0f};
    glm::vec3 rotateDegrees{0.0f};
    glm::vec3 translate{0.0f};
};

/// A mesh file that cannot be used; what() is "FILE: problem".
class MeshError : public std::runtime_error {
public:
    MeshError(const std::filesystem::path& file, const std::string& problem);
    std::string problem;  ///< the problem alone, without the file name
};

/// Vertices and triangles as a file holds them (polygons split into fans).
struct MeshData {
    std::vector<glm::vec3> vertices;
    std::vector<glm::uvec3> triangles;
};

/// Read an OBJ (`.obj`) or PLY (`.ply`: ascii, binary_little_endian or binary_big_endian;
/// a `vertex` element with x, y, z and a `face` element with a `vertex_indices` list) file.
/// Throws MeshError when the file cannot be read or parsed.
MeshData readMeshFile(const std::filesystem::path& file);

/// Read a mesh file, place it and make it a closed TriangleMesh. Throws MeshError when the
/// file cannot be read or the mesh is not closed, is degenerate or encloses no volume.
std::shared_ptr<const TriangleMesh> loadMesh(const std::filesystem::path& file, const MeshPlacement& placement = {});

}  // namespace tide::io
