// Surface-mesh frames as Wavefront OBJ text: an object per material, triangles only.
#include <string>

#include <tide/io/surface_mesh.hpp>

#include "io/frame_writers.hpp"

namespace tide::io {

void writeObj(std::ostream& out, const SurfaceMesh& mesh) {
    std::string block;
    block.reserve(std::size_t{1} << 17);
    auto spill = [&] {
        if (block.size() < (std::size_t{1} << 16)) return;
        out.write(block.data(), static_cast<std::streamsize>(block.size()));
        block.clear();
    };
    block += "# tide: the fluid's surface, one object per material (m)\n";
    for (const glm::vec3& v : mesh.vertices) {
        block += "v ";
        detail::appendNumber(block, v.x);
        block += ' ';
        detail::appendNumber(block, v.y);
        block += ' ';
        detail::appendNumber(block, v.z);
        block += '\n';
        spill();
    }
    for (const SurfaceMesh::Object& object : mesh.objects) {
        block += "o " + object.name + "\ns 1\n";
        for (std::size_t t = object.firstTriangle; t < object.firstTriangle + object.triangleCount; ++t) {
            block += 'f';
            for (const std::uint32_t index : mesh.triangles[t]) {
                block += ' ';
                detail::appendNumber(block, index + 1u);
            }
            block += '\n';
            spill();
        }
    }
    out.write(block.data(), static_cast<std::streamsize>(block.size()));
}

}  // namespace tide::io
