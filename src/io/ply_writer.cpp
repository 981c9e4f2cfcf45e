// PLY particle frames: a binary little-endian point cloud, one 38-byte vertex per particle.
#include <ostream>

#include "io/frame_writers.hpp"

namespace tide::io::detail {

static_assert(sizeof(MaterialIndex) == 2, "PLY declares material as ushort");

void writePly(std::ostream& out, const ParticleStore& particles) {
    const std::uint32_t n = particles.size();
    out << "ply\n"
           "format binary_little_endian 1.0\n"
           "element vertex "
        << n
        << "\n"
           "property float x\n"
           "property float y\n"
           "property float z\n"
           "property float vx\n"
           "property float vy\n"
           "property float vz\n"
           "property float density\n"
           "property float pressure\n"
           "property float concentration\n"
           "property ushort material\n"
           "property uint id\n"
           "end_header\n";
    LittleEndianWriter binary(out);
    for (std::uint32_t i = 0; i < n; ++i) {
        const glm::vec3& x = particles.position[i];
        const glm::vec3& v = particles.velocity[i];
        binary.put<float>(x.x);
        binary.put<float>(x.y);
        binary.put<float>(x.z);
        binary.put<float>(v.x);
        binary.put<float>(v.y);
        binary.put<float>(v.z);
        binary.put<float>(particles.density[i]);
        binary.put<float>(particles.pressure[i]);
        binary.put<float>(particles.concentration[i]);
        binary.put<std::uint16_t>(particles.material[i]);
        binary.put<std::uint32_t>(particles.id[i]);
    }
    binary.flush();
}

}  // namespace tide::io::detail
