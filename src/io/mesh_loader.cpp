// Mesh files → tide::TriangleMesh: OBJ through tinyobjloader, PLY by a small reader of its
// three encodings (ascii, binary little- and big-endian).
#include <tide/io/mesh.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include <tiny_obj_loader.h>

namespace tide::io {

namespace fs = std::filesystem;

MeshError::MeshError(const fs::path& file, const std::string& problemIn)
    : std::runtime_error(file.string() + ": " + problemIn), problem(problemIn) {}

namespace {

/// A problem inside one file, caught and re-thrown as a MeshError naming the file.
struct Problem {
    std::string message;
};

MeshData readObj(const fs::path& file) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(file.string(), config)) {
        std::string error = reader.Error();
        while (!error.empty() && std::isspace(static_cast<unsigned char>(error.back()))) error.pop_back();
        throw Problem{"not a readable OBJ file" + (error.empty() ? std::string() : " (" + error + ")")};
    }
    MeshData mesh;
    const auto& xyz = reader.GetAttrib().vertices;
    for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
        mesh.vertices.emplace_back(static_cast<float>(xyz[i]), static_cast<float>(xyz[i + 1]), static_cast<float>(xyz[i + 2]));
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        std::size_t offset = 0;
        for (const auto corners : shape.mesh.num_face_vertices) {
            // Triangulated by tinyobjloader; a face it could not split keeps its corners: fan it.
            for (std::size_t k = 1; k + 1 < corners; ++k) {
                glm::uvec3 t;
                const std::size_t at[3] = {offset, offset + k, offset + k + 1};
                for (int c = 0; c < 3; ++c) {
                    const int v = shape.mesh.indices[at[c]].vertex_index;
                    if (v < 0) throw Problem{"face " + std::to_string(mesh.triangles.size()) + " has a bad vertex index"};
                    t[c] = static_cast<std::uint32_t>(v);
                }
                mesh.triangles.push_back(t);
            }
            offset += corners;
        }
    }
    return mesh;
}

// ---- PLY ----

enum class PlyType { Int8, Uint8, Int16, Uint16, Int32, Uint32, Float32, Float64 };

std::optional<PlyType> plyType(const std::string& name) {
    static const std::pair<const char*, PlyType> names[] = {
        {"char", PlyType::Int8},     {"int8", PlyType::Int8},       {"uchar", PlyType::Uint8},
        {"uint8", PlyType::Uint8},   {"short", PlyType::Int16},     {"int16", PlyType::Int16},
        {"ushort", PlyType::Uint16}, {"uint16", PlyType::Uint16},   {"int", PlyType::Int32},
        {"int32", PlyType::Int32},   {"uint", PlyType::Uint32},     {"uint32", PlyType::Uint32},
        {"float", PlyType::Float32}, {"float32", PlyType::Float32}, {"double", PlyType::Float64},
        {"float64", PlyType::Float64}};
    for (const auto& [n, t] : names)
        if (name == n) return t;
    return std::nullopt;
}

std::size_t sizeOf(PlyType t) {
    switch (t) {
        case PlyType::Int8:
        case PlyType::Uint8: return 1;
        case PlyType::Int16:
        case PlyType::Uint16: return 2;
        case PlyType::Int32:
        case PlyType::Uint32:
        case PlyType::Float32: return 4;
        case PlyType::Float64: return 8;
    }
    return 1;
}

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Float32;
    bool list = false;
    PlyType countType = PlyType::Uint8;
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

enum class PlyEncoding { Ascii, LittleEndian, BigEndian };

/// Reads one value at a time, as text or binary.
class PlyValues {
public:
    PlyValues(std::istream& in, PlyEncoding encoding) : in_(in), encoding_(encoding) {}

    /// The next value; `what` names it in the message when the file ends early.
    double read(PlyType type, const std::string& what) {
        if (encoding_ == PlyEncoding::Ascii) {
            std::string token;
            if (!(in_ >> token)) throw Problem{"the file ends early, in " + what};
            char* end = nullptr;
            const double v = std::strtod(token.c_str(), &end);
            if (end != token.c_str() + token.size()) throw Problem{"\"" + token + "\" is not a number, in " + what};
            return v;
        }
        std::array<unsigned char, 8> bytes{};
        const std::size_t n = sizeOf(type);
        if (!in_.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(n)))
            throw Problem{"the file ends early, in " + what};
        if ((encoding_ == PlyEncoding::BigEndian) != (std::endian::native == std::endian::big))
            std::reverse(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(n));
        switch (type) {
            case PlyType::Int8: return static_cast<double>(static_cast<std::int8_t>(bytes[0]));
            case PlyType::Uint8: return static_cast<double>(bytes[0]);
            case PlyType::Int16: return decode<std::int16_t>(bytes);
            case PlyType::Uint16: return decode<std::uint16_t>(bytes);
            case PlyType::Int32: return decode<std::int32_t>(bytes);
            case PlyType::Uint32: return decode<std::uint32_t>(bytes);
            case PlyType::Float32: return decode<float>(bytes);
            case PlyType::Float64: return decode<double>(bytes);
        }
        return 0.0;
    }

private:
    template <class T>
    static double decode(const std::array<unsigned char, 8>& bytes) {
        T v;
        std::memcpy(&v, bytes.data(), sizeof v);
        return static_cast<double>(v);
    }

    std::istream& in_;
    PlyEncoding encoding_;
};

MeshData readPly(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string line;
    auto nextLine = [&]() -> bool {
        if (!std::getline(in, line)) return false;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        return true;
    };
    if (!nextLine() || line != "ply") throw Problem{"not a PLY file (it must start with the line \"ply\")"};
    std::optional<PlyEncoding> encoding;
    std::vector<PlyElement> elements;
    bool ended = false;
    for (int lineNumber = 2; !ended && nextLine(); ++lineNumber) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        const std::string where = "header line " + std::to_string(lineNumber);
        if (keyword == "format") {
            std::string name, version;
            words >> name >> version;
            if (name == "ascii") encoding = PlyEncoding::Ascii;
            else if (name == "binary_little_endian") encoding = PlyEncoding::LittleEndian;
            else if (name == "binary_big_endian") encoding = PlyEncoding::BigEndian;
            else throw Problem{where + ": unknown format \"" + name + "\""};
        } else if (keyword == "element") {
            PlyElement e;
            if (!(words >> e.name >> e.count)) throw Problem{where + ": expected \"element NAME COUNT\""};
            elements.push_back(e);
        } else if (keyword == "property") {
            if (elements.empty()) throw Problem{where + ": a property before any element"};
            PlyProperty p;
            std::string type;
            words >> type;
            if (type == "list") {
                std::string countType, itemType;
                words >> countType >> itemType >> p.name;
                const auto c = plyType(countType), t = plyType(itemType);
                if (!c || !t || p.name.empty()) throw Problem{where + ": expected \"property list COUNT_TYPE TYPE NAME\""};
                p.list = true;
                p.countType = *c;
                p.type = *t;
            } else {
                words >> p.name;
                const auto t = plyType(type);
                if (!t || p.name.empty()) throw Problem{where + ": unknown property type \"" + type + "\""};
                p.type = *t;
            }
            elements.back().properties.push_back(p);
        } else if (keyword == "end_header") {
            ended = true;
        } else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
            throw Problem{where + ": unknown keyword \"" + keyword + "\""};
        }
    }
    if (!ended) throw Problem{"the header has no end_header line"};
    if (!encoding) throw Problem{"the header has no format line"};

    const auto vertexElement = std::find_if(elements.begin(), elements.end(), [](const PlyElement& e) { return e.name == "vertex"; });
    const auto faceElement = std::find_if(elements.begin(), elements.end(), [](const PlyElement& e) { return e.name == "face"; });
    if (vertexElement == elements.end()) throw Problem{"no \"vertex\" element"};
    if (faceElement == elements.end()) throw Problem{"no \"face\" element (a point cloud is not a surface)"};
    for (const char* axis : {"x", "y", "z"})
        if (std::none_of(vertexElement->properties.begin(), vertexElement->properties.end(),
                         [&](const PlyProperty& p) { return p.name == axis && !p.list; }))
            throw Problem{std::string("the vertex element has no \"") + axis + "\" property"};
    if (std::none_of(faceElement->properties.begin(), faceElement->properties.end(), [](const PlyProperty& p) {
            return p.list && (p.name == "vertex_indices" || p.name == "vertex_index");
        }))
        throw Problem{"the face element has no \"vertex_indices\" list"};

    MeshData mesh;
    PlyValues values(in, *encoding);
    constexpr std::uint64_t kReserveAtMost = 1u << 22;  // a corrupt count must not allocate the machine
    for (const PlyElement& e : elements) {
        const bool isVertex = &e == &*vertexElement, isFace = &e == &*faceElement;
        if (isVertex) mesh.vertices.reserve(std::min(e.count, kReserveAtMost));
        for (std::uint64_t row = 0; row < e.count; ++row) {
            const std::string what = e.name + " " + std::to_string(row);
            glm::vec3 position{0.0f};
            std::vector<std::uint32_t> corners;
            for (const PlyProperty& p : e.properties) {
                if (!p.list) {
                    const double v = values.read(p.type, what);
                    if (isVertex && p.name.size() == 1 && p.name[0] >= 'x' && p.name[0] <= 'z')
                        position[p.name[0] - 'x'] = static_cast<float>(v);
                    continue;
                }
                const double n = values.read(p.countType, what);
                if (!(n >= 0.0 && n <= 1e6) || n != std::floor(n)) throw Problem{"bad list length in " + what};
                const bool indices = isFace && (p.name == "vertex_indices" || p.name == "vertex_index");
                for (int k = 0; k < static_cast<int>(n); ++k) {
                    const double v = values.read(p.type, what);
                    if (!indices) continue;
                    if (!(v >= 0.0 && v < 4294967295.0) || v != std::floor(v))
                        throw Problem{"bad vertex index in " + what};
                    corners.push_back(static_cast<std::uint32_t>(v));
                }
            }
            if (isVertex) mesh.vertices.push_back(position);
            if (isFace) {
                if (corners.size() < 3) throw Problem{what + " has fewer than 3 vertices"};
                for (std::size_t k = 1; k + 1 < corners.size(); ++k)
                    mesh.triangles.emplace_back(corners[0], corners[k], corners[k + 1]);
            }
        }
    }
    return mesh;
}

glm::vec3 rotate(const glm::vec3& v, const glm::vec3& degrees) {
    const glm::dvec3 r = glm::dvec3(degrees) * (3.14159265358979323846 / 180.0);
    glm::dvec3 p(v);
    p = {p.x, std::cos(r.x) * p.y - std::sin(r.x) * p.z, std::sin(r.x) * p.y + std::cos(r.x) * p.z};
    p = {std::cos(r.y) * p.x + std::sin(r.y) * p.z, p.y, -std::sin(r.y) * p.x + std::cos(r.y) * p.z};
    p = {std::cos(r.z) * p.x - std::sin(r.z) * p.y, std::sin(r.z) * p.x + std::cos(r.z) * p.y, p.z};
    return glm::vec3(p);
}

}  // namespace

MeshData readMeshFile(const fs::path& file) {
    std::error_code ec;
    if (!fs::exists(file, ec)) throw MeshError(file, "no such file");
    if (fs::is_directory(file, ec)) throw MeshError(file, "is a directory, not a mesh file");
    if (!std::ifstream(file, std::ios::binary)) throw MeshError(file, "cannot open the file");
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    try {
        if (ext == ".obj") return readObj(file);
        if (ext == ".ply") return readPly(file);
    } catch (const Problem& p) {
        throw MeshError(file, p.message);
    }
    throw MeshError(file, "unknown mesh format \"" + ext + "\" (use .obj or .ply)");
}

std::shared_ptr<const TriangleMesh> loadMesh(const fs::path& file, const MeshPlacement& placement) {
    MeshData data = readMeshFile(file);
    for (glm::vec3& v : data.vertices)
        v = rotate(v * placement.scale, placement.rotateDegrees) + placement.translate;
    try {
        return std::make_shared<const TriangleMesh>(std::move(data.vertices), std::move(data.triangles));
    } catch (const std::invalid_argument& e) {
        throw MeshError(file, e.what());
    }
}

}  // namespace tide::io
