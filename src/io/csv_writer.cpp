// CSV particle frames: a fixed header, then one row per particle.
#include <string>

#include "io/frame_writers.hpp"

namespace tide::io::detail {

void writeCsv(std::ostream& out, const ParticleStore& particles) {
    // The header is a contract with downstream tools: do not add columns.
    out << "x,y,z,vx,vy,vz,density,pressure,material\n";
    std::string block;
    block.reserve(std::size_t{1} << 17);
    const std::uint32_t n = particles.size();
    for (std::uint32_t i = 0; i < n; ++i) {
        const glm::vec3& x = particles.position[i];
        const glm::vec3& v = particles.velocity[i];
        for (const float value : {x.x, x.y, x.z, v.x, v.y, v.z, particles.density[i], particles.pressure[i]}) {
            appendNumber(block, value);
            block.push_back(',');
        }
        appendNumber(block, static_cast<unsigned>(particles.material[i]));
        block.push_back('\n');
        if (block.size() >= (std::size_t{1} << 16)) {
            out.write(block.data(), static_cast<std::streamsize>(block.size()));
            block.clear();
        }
    }
    out.write(block.data(), static_cast<std::streamsize>(block.size()));
}

}  // namespace tide::io::detail
