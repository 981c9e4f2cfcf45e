// CSV particle frames: a fixed header, then one row per particle.
#include <charconv>
#include <string>
#include <system_error>

#include "io/frame_writers.hpp"

namespace tide::io::detail {

namespace {

/// Appends the shortest decimal form that reads back as exactly `value`.
template <class T>
void appendNumber(std::string& line, T value) {
    char text[32];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, value);
    if (ec == std::errc{}) line.append(text, end);
}

}  // namespace

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
