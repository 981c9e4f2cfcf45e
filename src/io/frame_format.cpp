// Frame formats by name, and writeFrame: the dispatcher every exporter goes through.
#include <sstream>
#include <stdexcept>

#include <tide/io/exporters.hpp>

#include "io/frame_writers.hpp"

namespace tide::io {

std::optional<Format> parseFormat(std::string_view name) {
    if (name == "vtu") return Format::Vtu;
    if (name == "ply") return Format::Ply;
    if (name == "csv") return Format::Csv;
    if (name == "obj") return Format::Obj;
    return std::nullopt;
}

std::string_view extension(Format format) {
    switch (format) {
        case Format::Vtu: return "vtu";
        case Format::Ply: return "ply";
        case Format::Csv: return "csv";
        case Format::Obj: return "obj";
    }
    return "";
}

void writePvtu(const std::filesystem::path& file, const std::vector<std::string>& pieces) {
    writeFileAtomically(file, [&](std::ostream& out) { detail::writePvtu(out, pieces); });
}

void writeFrame(const std::filesystem::path& file, Format format, const ParticleStore& particles,
                const SurfaceMeshDef& surface) {
    const std::size_t n = particles.position.size();
    if (particles.velocity.size() != n || particles.density.size() != n || particles.pressure.size() != n ||
        particles.material.size() != n || particles.id.size() != n || particles.concentration.size() != n) {
        std::ostringstream msg;
        msg << "tide::io: cannot write \"" << file.string() << "\"" << ": particle arrays have different sizes";
        throw std::invalid_argument(msg.str());
    }
    switch (format) {
        case Format::Vtu:
            writeFileAtomically(file, [&](std::ostream& out) { detail::writeVtu(out, particles); });
            return;
        case Format::Ply:
            writeFileAtomically(file, [&](std::ostream& out) { detail::writePly(out, particles); });
            return;
        case Format::Csv:
            writeFileAtomically(file, [&](std::ostream& out) { detail::writeCsv(out, particles); });
            return;
        case Format::Obj: {
            const SurfaceMesh mesh = buildSurfaceMesh(particles, surface);  // before the file is touched
            writeFileAtomically(file, [&](std::ostream& out) { writeObj(out, mesh); });
            return;
        }
    }
    throw std::invalid_argument("tide::io::writeFrame: unknown format");
}

}  // namespace tide::io
