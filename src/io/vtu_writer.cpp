// VTU particle frames: a VTK XML UnstructuredGrid (version 1.0, UInt64 headers) whose arrays
// live in one raw AppendedData block, with one VTK_VERTEX cell per point so that ParaView
// draws the points.
#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <string_view>

#include "io/frame_writers.hpp"

namespace tide::io::detail {

namespace {

/// One array of the appended block: its XML description and its byte size.
struct ArrayLayout {
    std::string_view type;  ///< VTK type name, e.g. Float32
    std::string_view name;
    int components;
    std::uint64_t bytes;  ///< payload size, without the UInt64 size header
};

constexpr std::uint8_t kVtkVertex = 1;

void declare(std::ostream& out, std::string_view indent, const ArrayLayout& a, std::uint64_t offset) {
    out << indent << "<DataArray type=\"" << a.type << "\" Name=\"" << a.name << "\"";
    if (a.components != 1) out << " NumberOfComponents=\"" << a.components << "\"";
    // meshio looks arrays up by the exact text of offset: no padding.
    out << " format=\"appended\" offset=\"" << offset << "\"/>\n";
}

}  // namespace

void writeVtu(std::ostream& out, const ParticleStore& particles) {
    const std::uint32_t n = particles.size();
    const std::uint64_t count = n;

    // The order of the XML declarations. The appended block holds the arrays in the reverse
    // order: meshio (5.0) converts raw appended data by looking each raw offset up among
    // DataArray tags it has already given new (base64) offsets, in document order, and picks
    // the wrong tag when numbers coincide (e.g. with 1, 3 or 5 points); with the block
    // reversed, the tag it wants always comes first in the document.
    enum { Velocity, Density, Pressure, Concentration, Material, Id, Points, Connectivity, Offsets, Types, ArrayCount };
    const ArrayLayout arrays[ArrayCount] = {
        {"Float32", "velocity", 3, count * 3 * sizeof(float)},
        {"Float32", "density", 1, count * sizeof(float)},
        {"Float32", "pressure", 1, count * sizeof(float)},
        {"Float32", "concentration", 1, count * sizeof(float)},
        {"Int32", "material", 1, count * sizeof(std::int32_t)},
        {"UInt32", "id", 1, count * sizeof(std::uint32_t)},
        {"Float32", "Points", 3, count * 3 * sizeof(float)},
        {"Int64", "connectivity", 1, count * sizeof(std::int64_t)},
        {"Int64", "offsets", 1, count * sizeof(std::int64_t)},
        {"UInt8", "types", 1, count * sizeof(std::uint8_t)},
    };
    std::uint64_t offsets[ArrayCount];
    std::uint64_t next = 0;
    for (int k = ArrayCount - 1; k >= 0; --k) {
        offsets[k] = next;
        next += sizeof(std::uint64_t) + arrays[k].bytes;
    }

    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
           "  <UnstructuredGrid>\n"
           "    <Piece NumberOfPoints=\""
        << n << "\" NumberOfCells=\"" << n << "\">\n";
    out << "      <PointData Scalars=\"density\" Vectors=\"velocity\">\n";
    for (int k = Velocity; k <= Id; ++k) declare(out, "        ", arrays[k], offsets[k]);
    out << "      </PointData>\n"
           "      <Points>\n";
    declare(out, "        ", arrays[Points], offsets[Points]);
    out << "      </Points>\n"
           "      <Cells>\n";
    for (int k = Connectivity; k <= Types; ++k) declare(out, "        ", arrays[k], offsets[k]);
    out << "      </Cells>\n"
           "    </Piece>\n"
           "  </UnstructuredGrid>\n"
           "  <AppendedData encoding=\"raw\">\n"
           "   _";

    LittleEndianWriter binary(out);
    const auto header = [&](int k) { binary.put<std::uint64_t>(arrays[k].bytes); };

    header(Types);
    for (std::uint32_t i = 0; i < n; ++i) binary.put<std::uint8_t>(kVtkVertex);
    header(Offsets);  // end of each cell's connectivity
    for (std::int64_t i = 1; i <= static_cast<std::int64_t>(n); ++i) binary.put<std::int64_t>(i);
    header(Connectivity);
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(n); ++i) binary.put<std::int64_t>(i);
    header(Points);
    for (const glm::vec3& x : particles.position) {
        binary.put<float>(x.x);
        binary.put<float>(x.y);
        binary.put<float>(x.z);
    }
    header(Id);
    for (const std::uint32_t id : particles.id) binary.put<std::uint32_t>(id);
    header(Material);
    for (const MaterialIndex m : particles.material) binary.put<std::int32_t>(static_cast<std::int32_t>(m));
    header(Concentration);
    for (const float c : particles.concentration) binary.put<float>(c);
    header(Pressure);
    for (const float p : particles.pressure) binary.put<float>(p);
    header(Density);
    for (const float rho : particles.density) binary.put<float>(rho);
    header(Velocity);
    for (const glm::vec3& v : particles.velocity) {
        binary.put<float>(v.x);
        binary.put<float>(v.y);
        binary.put<float>(v.z);
    }
    binary.flush();

    // meshio drops everything after the last newline of the block: end it with one.
    out << "\n  </AppendedData>\n"
           "</VTKFile>\n";
}

void writePvtu(std::ostream& out, std::span<const std::string> pieces) {
    // The arrays writeVtu declares, in its order (ParaView checks each piece against these).
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
           "  <PUnstructuredGrid GhostLevel=\"0\">\n"
           "    <PPointData Scalars=\"density\" Vectors=\"velocity\">\n"
           "      <PDataArray type=\"Float32\" Name=\"velocity\" NumberOfComponents=\"3\"/>\n"
           "      <PDataArray type=\"Float32\" Name=\"density\"/>\n"
           "      <PDataArray type=\"Float32\" Name=\"pressure\"/>\n"
           "      <PDataArray type=\"Float32\" Name=\"concentration\"/>\n"
           "      <PDataArray type=\"Int32\" Name=\"material\"/>\n"
           "      <PDataArray type=\"UInt32\" Name=\"id\"/>\n"
           "    </PPointData>\n"
           "    <PPoints>\n"
           "      <PDataArray type=\"Float32\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
           "    </PPoints>\n";
    for (const std::string& piece : pieces) out << "    <Piece Source=\"" << piece << "\"/>\n";
    out << "  </PUnstructuredGrid>\n"
           "</VTKFile>\n";
}

}  // namespace tide::io::detail
