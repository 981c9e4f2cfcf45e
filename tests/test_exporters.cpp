// Particle-frame exporters (CSV, PLY, VTU), the ParaView series (.pvd) and atomic writing.
#include <algorithm>
#include <atomic>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include <tide/io/exporters.hpp>
#include <tide/particles.hpp>

namespace {

namespace fs = std::filesystem;
using namespace tide;
using namespace tide::io;

constexpr std::uint32_t kCount = 5;

/// Five particles with distinct, awkward values; reversed so that id != index.
ParticleStore makeParticles() {
    ParticleStore p;
    for (std::uint32_t i = 0; i < kCount; ++i) {
        const float f = static_cast<float>(i);
        p.append({0.123456789f + 0.1f * f, -1.5f + f, 3.0e-5f * f - 7.25f}, {1.0f / 3.0f + f, -2.0f * f, 1.0e-7f + f},
                 0.001f, static_cast<MaterialIndex>(i % 3 == 2 ? 65535 : i % 3), 1000.0f);
        p.density[i] = 998.2f + 1.37f * f;
        p.pressure[i] = -12.5f + 1234.5678f * f;
        p.concentration[i] = 0.0625f + 0.2f * f;
    }
    p.permute(std::vector<std::uint32_t>{4, 3, 2, 1, 0});
    return p;
}

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeText(const fs::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary);
    out << text;
}

/// Decodes a little-endian value at `pos`, whatever the host's byte order.
template <class T>
T readLE(const std::string& bytes, std::size_t pos) {
    using U = std::conditional_t<sizeof(T) == 1, std::uint8_t,
                                 std::conditional_t<sizeof(T) == 2, std::uint16_t,
                                                    std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
    U u = 0;
    for (std::size_t k = 0; k < sizeof(T); ++k) {
        u = static_cast<U>(u | static_cast<U>(static_cast<U>(static_cast<unsigned char>(bytes.at(pos + k))) << (8 * k)));
    }
    return std::bit_cast<T>(u);
}

std::string shortest(float value) {
    char text[32];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, value);
    return std::string(text, end);
}

std::vector<std::string> directoryEntries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

/// A Python interpreter that can `import <module>`, or nothing.
std::optional<std::string> pythonWith(const std::string& module) {
    for (const char* candidate : {"python3", "/usr/bin/python3"}) {
        std::ostringstream cmd;
        cmd << candidate << " -c 'import " << module << "' >/dev/null 2>&1";
        if (std::system(cmd.str().c_str()) == 0) return std::string(candidate);
    }
    return std::nullopt;
}

class Exporters : public ::testing::Test {
protected:
    void SetUp() override {
        static std::atomic<int> counter{0};
        std::ostringstream name;
        name << "tide_test_exporters_" << ::getpid() << '_' << counter++;
        dir_ = fs::temp_directory_path() / name.str();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }

    fs::path dir_;
    ParticleStore particles_ = makeParticles();
};

TEST(ExportFormat, ParsesExactLowercaseNamesAndGivesExtensions) {
    EXPECT_EQ(parseFormat("vtu"), Format::Vtu);
    EXPECT_EQ(parseFormat("ply"), Format::Ply);
    EXPECT_EQ(parseFormat("csv"), Format::Csv);
    EXPECT_EQ(parseFormat("obj"), Format::Obj);
    EXPECT_EQ(parseFormat("VTU"), std::nullopt);
    EXPECT_EQ(parseFormat(".csv"), std::nullopt);
    EXPECT_EQ(parseFormat(""), std::nullopt);
    EXPECT_EQ(extension(Format::Vtu), "vtu");
    EXPECT_EQ(extension(Format::Ply), "ply");
    EXPECT_EQ(extension(Format::Csv), "csv");
    EXPECT_EQ(extension(Format::Obj), "obj");
    for (const Format f : {Format::Vtu, Format::Ply, Format::Csv, Format::Obj}) EXPECT_EQ(parseFormat(extension(f)), f);
}

TEST_F(Exporters, CsvHasTheContractHeaderAndRoundTripsEveryValue) {
    const fs::path file = dir_ / "frame.csv";
    writeFrame(file, Format::Csv, particles_);
    EXPECT_EQ(directoryEntries(dir_), std::vector<std::string>{"frame.csv"});

    std::istringstream in(readFile(file));
    std::string line;
    ASSERT_TRUE(std::getline(in, line));
    EXPECT_EQ(line, "x,y,z,vx,vy,vz,density,pressure,material");
    std::uint32_t row = 0;
    while (std::getline(in, line)) {
        ASSERT_LT(row, kCount) << "extra row: " << line;
        std::vector<std::string> fields;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
        ASSERT_EQ(fields.size(), 9u) << line;
        const glm::vec3& x = particles_.position[row];
        const glm::vec3& v = particles_.velocity[row];
        const float expected[8] = {x.x, x.y, x.z, v.x, v.y, v.z, particles_.density[row], particles_.pressure[row]};
        for (int k = 0; k < 8; ++k) {
            EXPECT_EQ(std::strtof(fields[static_cast<std::size_t>(k)].c_str(), nullptr), expected[k])
                << "row " << row << " column " << k << ": " << fields[static_cast<std::size_t>(k)];
        }
        EXPECT_EQ(fields[8], std::to_string(particles_.material[row])) << "material is printed as an integer";
        ++row;
    }
    EXPECT_EQ(row, kCount);
}

TEST_F(Exporters, PlyHeaderIsExactAndPayloadDecodesToTheSameValues) {
    const fs::path file = dir_ / "frame.ply";
    writeFrame(file, Format::Ply, particles_);
    const std::string bytes = readFile(file);

    const std::string expectedHeader =
        "ply\n"
        "format binary_little_endian 1.0\n"
        "element vertex 5\n"
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
    ASSERT_GE(bytes.size(), expectedHeader.size());
    EXPECT_EQ(bytes.substr(0, expectedHeader.size()), expectedHeader);

    constexpr std::size_t kVertexBytes = 9 * 4 + 2 + 4;
    ASSERT_EQ(bytes.size(), expectedHeader.size() + kCount * kVertexBytes);
    for (std::uint32_t i = 0; i < kCount; ++i) {
        const std::size_t at = expectedHeader.size() + i * kVertexBytes;
        const glm::vec3& x = particles_.position[i];
        const glm::vec3& v = particles_.velocity[i];
        const float expected[9] = {x.x, x.y, x.z, v.x, v.y, v.z, particles_.density[i], particles_.pressure[i],
                                   particles_.concentration[i]};
        for (std::size_t k = 0; k < 9; ++k) EXPECT_EQ(readLE<float>(bytes, at + 4 * k), expected[k]) << i << ' ' << k;
        EXPECT_EQ(readLE<std::uint16_t>(bytes, at + 36), particles_.material[i]);
        EXPECT_EQ(readLE<std::uint32_t>(bytes, at + 38), particles_.id[i]);
    }
    EXPECT_EQ(particles_.id[0], 4u) << "the fixture reorders particles so ids differ from indices";
}

/// One DataArray declared in a VTU header.
struct VtuArray {
    std::string type;
    int components = 1;
    std::uint64_t offset = 0;
};

TEST_F(Exporters, VtuHeaderAndRawAppendedBlockAreConsistent) {
    const fs::path file = dir_ / "frame.vtu";
    writeFrame(file, Format::Vtu, particles_);
    const std::string bytes = readFile(file);

    EXPECT_EQ(bytes.rfind("<?xml version=\"1.0\"?>\n", 0), 0u);
    EXPECT_NE(bytes.find("<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
                         "header_type=\"UInt64\">"),
              std::string::npos);
    EXPECT_NE(bytes.find("<Piece NumberOfPoints=\"5\" NumberOfCells=\"5\">"), std::string::npos);

    const std::string marker = "<AppendedData encoding=\"raw\">";
    const std::size_t appended = bytes.find(marker);
    ASSERT_NE(appended, std::string::npos);
    const std::string xml = bytes.substr(0, appended);

    std::map<std::string, VtuArray> arrays;
    const std::regex declaration(
        R"re(<DataArray type="(\w+)" Name="(\w+)"(?: NumberOfComponents="(\d+)")? format="appended" offset="(\d+)"/>)re");
    for (auto it = std::sregex_iterator(xml.begin(), xml.end(), declaration); it != std::sregex_iterator(); ++it) {
        const std::smatch& m = *it;
        arrays[m[2]] = {m[1], m[3].matched ? std::stoi(m[3]) : 1, std::stoull(m[4])};
    }
    const std::map<std::string, std::pair<std::string, int>> expected = {
        {"Points", {"Float32", 3}},     {"velocity", {"Float32", 3}},   {"density", {"Float32", 1}},
        {"pressure", {"Float32", 1}},   {"material", {"Int32", 1}},     {"id", {"UInt32", 1}},
        {"concentration", {"Float32", 1}},
        {"connectivity", {"Int64", 1}}, {"offsets", {"Int64", 1}},      {"types", {"UInt8", 1}},
    };
    ASSERT_EQ(arrays.size(), expected.size()) << xml;
    const std::map<std::string, std::size_t> typeSize = {{"Float32", 4}, {"Int32", 4}, {"UInt32", 4}, {"Int64", 8}, {"UInt8", 1}};
    for (const auto& [name, typeAndComponents] : expected) {
        ASSERT_TRUE(arrays.count(name)) << name;
        EXPECT_EQ(arrays[name].type, typeAndComponents.first) << name;
        EXPECT_EQ(arrays[name].components, typeAndComponents.second) << name;
    }
    // PointData holds exactly the per-particle fields; Points and Cells sit in their sections.
    const std::size_t pointData = xml.find("<PointData"), pointDataEnd = xml.find("</PointData>");
    ASSERT_NE(pointData, std::string::npos);
    for (const char* name : {"velocity", "density", "pressure", "concentration", "material", "id"}) {
        const std::size_t at = xml.find(std::string("Name=\"").append(name).append("\""));
        EXPECT_TRUE(at > pointData && at < pointDataEnd) << name;
    }

    // The raw block: `_`, then for each array a UInt64 byte count and the bytes, back to back.
    const std::size_t underscore = bytes.find('_', appended + marker.size());
    ASSERT_NE(underscore, std::string::npos);
    const std::size_t base = underscore + 1;
    std::vector<std::pair<std::uint64_t, std::string>> byOffset;
    for (const auto& [name, a] : arrays) byOffset.emplace_back(a.offset, name);
    std::sort(byOffset.begin(), byOffset.end());
    std::uint64_t next = 0;
    for (const auto& [offset, name] : byOffset) {
        const VtuArray& a = arrays[name];
        EXPECT_EQ(offset, next) << name << ": arrays must be contiguous";
        const std::uint64_t size = readLE<std::uint64_t>(bytes, base + offset);
        EXPECT_EQ(size, kCount * static_cast<std::uint64_t>(a.components) * typeSize.at(a.type)) << name;
        next = offset + 8 + size;
    }
    EXPECT_EQ(bytes.substr(base + next), "\n  </AppendedData>\n</VTKFile>\n");

    // Decode the values.
    const auto data = [&](const std::string& name) { return base + arrays[name].offset + 8; };
    for (std::uint32_t i = 0; i < kCount; ++i) {
        for (std::size_t c = 0; c < 3; ++c) {
            EXPECT_EQ(readLE<float>(bytes, data("Points") + 4 * (3 * i + c)), particles_.position[i][static_cast<int>(c)]);
            EXPECT_EQ(readLE<float>(bytes, data("velocity") + 4 * (3 * i + c)), particles_.velocity[i][static_cast<int>(c)]);
        }
        EXPECT_EQ(readLE<float>(bytes, data("density") + 4 * i), particles_.density[i]);
        EXPECT_EQ(readLE<float>(bytes, data("pressure") + 4 * i), particles_.pressure[i]);
        EXPECT_EQ(readLE<float>(bytes, data("concentration") + 4 * i), particles_.concentration[i]);
        EXPECT_EQ(readLE<std::int32_t>(bytes, data("material") + 4 * i), particles_.material[i]);
        EXPECT_EQ(readLE<std::uint32_t>(bytes, data("id") + 4 * i), particles_.id[i]);
        EXPECT_EQ(readLE<std::int64_t>(bytes, data("connectivity") + 8 * i), static_cast<std::int64_t>(i));
        EXPECT_EQ(readLE<std::int64_t>(bytes, data("offsets") + 8 * i), static_cast<std::int64_t>(i) + 1);
        EXPECT_EQ(readLE<std::uint8_t>(bytes, data("types") + i), 1u) << "VTK_VERTEX";
    }
}

TEST_F(Exporters, VtuLoadsInMeshio) {
    const std::optional<std::string> python = pythonWith("meshio");
    if (!python) GTEST_SKIP() << "no python3 with meshio on this machine";

    const fs::path file = dir_ / "frame.vtu";
    writeFrame(file, Format::Vtu, particles_);

    std::ostringstream list[4];  // points, velocity, density, pressure
    std::ostringstream materials, ids;
    for (std::uint32_t i = 0; i < kCount; ++i) {
        for (int c = 0; c < 3; ++c) {
            list[0] << shortest(particles_.position[i][c]) << ',';
            list[1] << shortest(particles_.velocity[i][c]) << ',';
        }
        list[2] << shortest(particles_.density[i]) << ',';
        list[3] << shortest(particles_.pressure[i]) << ',';
        materials << particles_.material[i] << ',';
        ids << particles_.id[i] << ',';
    }
    const fs::path script = dir_ / "check.py";
    std::ostringstream py;
    py << "import sys\n"
          "import numpy as np\n"
          "import meshio\n"
          "m = meshio.read(sys.argv[1])\n"
          "f = lambda v: np.array(v, dtype=np.float64).astype(np.float32)\n"
          "assert m.points.shape == (5, 3), m.points.shape\n"
          "assert (m.points.astype(np.float32) == f([" << list[0].str() << "]).reshape(5, 3)).all(), m.points\n"
          "pd = m.point_data\n"
          "assert set(pd.keys()) == {'velocity', 'density', 'pressure', 'concentration', 'material', 'id'}, pd.keys()\n"
          "assert (pd['velocity'] == f([" << list[1].str() << "]).reshape(5, 3)).all(), pd['velocity']\n"
          "assert (pd['density'] == f([" << list[2].str() << "])).all(), pd['density']\n"
          "assert (pd['pressure'] == f([" << list[3].str() << "])).all(), pd['pressure']\n"
          "assert pd['material'].tolist() == [" << materials.str() << "], pd['material']\n"
          "assert pd['id'].tolist() == [" << ids.str() << "], pd['id']\n"
          "assert len(m.cells) == 1 and m.cells[0].type == 'vertex', m.cells\n"
          "assert m.cells[0].data.ravel().tolist() == list(range(5)), m.cells[0].data\n"
          "print('meshio ok', m.points.shape, sorted(pd.keys()))\n";
    writeText(script, py.str());
    std::ostringstream cmd;
    cmd << *python << " '" << script.string() << "' '" << file.string() << "'";
    EXPECT_EQ(std::system(cmd.str().c_str()), 0) << cmd.str();

    // meshio's raw-data conversion is sensitive to the array byte counts: try many sizes.
    std::ostringstream sizes;
    sizes << *python << " -c \"import sys, meshio; "
          << "[meshio.read(f).points.shape == (int(n), 3) or sys.exit(f) for f, n in zip(sys.argv[1::2], sys.argv[2::2])]\"";
    for (std::uint32_t n : {1u, 2u, 3u, 4u, 6u, 7u, 8u, 9u, 10u, 11u, 13u, 17u, 100u, 1001u}) {
        ParticleStore p;
        for (std::uint32_t i = 0; i < n; ++i) p.append({0.5f * static_cast<float>(i), 1.0f, 2.0f}, {0, 0, 0}, 1.0f, 0, 1000.0f);
        const fs::path frame = dir_ / std::string("n").append(std::to_string(n)).append(".vtu");
        writeFrame(frame, Format::Vtu, p);
        sizes << " '" << frame.string() << "' " << n;
    }
    EXPECT_EQ(std::system(sizes.str().c_str()), 0) << sizes.str();
}

TEST_F(Exporters, VtuLoadsInVtksXmlReader) {
    // vtkXMLUnstructuredGridReader is what ParaView uses for .vtu files.
    const std::optional<std::string> python = pythonWith("vtk");
    if (!python) GTEST_SKIP() << "no python3 with vtk on this machine";

    const fs::path file = dir_ / "frame.vtu";
    writeFrame(file, Format::Vtu, particles_);
    std::ostringstream points, ids, materials;
    for (std::uint32_t i = 0; i < kCount; ++i) {
        for (int c = 0; c < 3; ++c) points << shortest(particles_.position[i][c]) << ',';
        ids << particles_.id[i] << ',';
        materials << particles_.material[i] << ',';
    }
    std::ostringstream py;
    py << "import sys\n"
          "import numpy as np\n"
          "import vtk\n"
          "from vtk.util.numpy_support import vtk_to_numpy\n"
          "r = vtk.vtkXMLUnstructuredGridReader()\n"
          "r.SetFileName(sys.argv[1])\n"
          "r.Update()\n"
          "assert r.GetErrorCode() == 0, r.GetErrorCode()\n"
          "g = r.GetOutput()\n"
          "assert g.GetNumberOfPoints() == 5 and g.GetNumberOfCells() == 5\n"
          "assert all(g.GetCellType(i) == vtk.VTK_VERTEX for i in range(5))\n"
          "p = vtk_to_numpy(g.GetPoints().GetData())\n"
          "assert (p == np.array([" << points.str() << "], dtype=np.float64).astype(np.float32).reshape(5, 3)).all(), p\n"
          "pd = g.GetPointData()\n"
          "assert sorted(pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())) == "
          "['concentration', 'density', 'id', 'material', 'pressure', 'velocity']\n"
          "assert vtk_to_numpy(pd.GetArray('id')).tolist() == [" << ids.str() << "]\n"
          "assert vtk_to_numpy(pd.GetArray('material')).tolist() == [" << materials.str() << "]\n"
          "assert pd.GetArray('velocity').GetNumberOfComponents() == 3\n";
    const fs::path script = dir_ / "check_vtk.py";
    writeText(script, py.str());
    std::ostringstream cmd;
    cmd << *python << " '" << script.string() << "' '" << file.string() << "'";
    EXPECT_EQ(std::system(cmd.str().c_str()), 0) << cmd.str();
}

TEST_F(Exporters, PvdListsEveryFrameWithItsTimeAfterEachWrite) {
    const fs::path pvd = dir_ / "series.pvd";
    PvdWriter series(pvd);
    EXPECT_FALSE(fs::exists(pvd)) << "nothing is written before write()";

    const std::string head = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
    const std::string tail = "  </Collection>\n</VTKFile>\n";
    const std::pair<double, std::string> frames[] = {{0.0, "frame_00000.vtu"}, {0.1, "frame_00001.vtu"},
                                                     {0.25, "frames/frame_00002.vtu"}, {1.0 / 3.0, "a&b<c>\"'.vtu"}};
    const std::string lines[] = {
        "    <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"frame_00000.vtu\"/>\n",
        "    <DataSet timestep=\"0.1\" group=\"\" part=\"0\" file=\"frame_00001.vtu\"/>\n",
        "    <DataSet timestep=\"0.25\" group=\"\" part=\"0\" file=\"frames/frame_00002.vtu\"/>\n",
        "    <DataSet timestep=\"0.3333333333333333\" group=\"\" part=\"0\" file=\"a&amp;b&lt;c&gt;&quot;&apos;.vtu\"/>\n",
    };
    std::string body;
    for (std::size_t k = 0; k < std::size(frames); ++k) {
        series.add(frames[k].first, frames[k].second);
        series.write();
        body += lines[k];
        EXPECT_EQ(readFile(pvd), head + body + tail) << "after frame " << k;
        EXPECT_EQ(directoryEntries(dir_), std::vector<std::string>{"series.pvd"});
    }

    if (const auto python = pythonWith("xml.etree.ElementTree")) {
        std::ostringstream cmd;
        cmd << *python << " -c \"import sys, xml.etree.ElementTree as E; r = E.parse(sys.argv[1]).getroot(); "
            << "d = r.find('Collection').findall('DataSet'); "
            << "assert r.get('type') == 'Collection' and len(d) == 4, d; "
            << "assert [float(x.get('timestep')) for x in d] == [0.0, 0.1, 0.25, 1/3]; "
            << "assert d[3].get('file') == 'a&b<c>' + chr(34) + chr(39) + '.vtu', d[3].get('file')\" '" << pvd.string()
            << "'";
        EXPECT_EQ(std::system(cmd.str().c_str()), 0) << cmd.str();
    }
}

TEST_F(Exporters, AtomicWriteLeavesNoTemporaryFileBehind) {
    const fs::path file = dir_ / "data.txt";
    writeFileAtomically(file, [](std::ostream& out) { out << "first\n"; });
    EXPECT_EQ(readFile(file), "first\n");
    writeFileAtomically(file, [](std::ostream& out) { out << std::string(200000, 'x'); });  // bigger than a buffer
    EXPECT_EQ(readFile(file), std::string(200000, 'x'));
    EXPECT_EQ(directoryEntries(dir_), std::vector<std::string>{"data.txt"});
}

TEST_F(Exporters, AtomicWriteKeepsTheOldContentWhenTheWriterThrows) {
    const fs::path file = dir_ / "data.txt";
    writeFileAtomically(file, [](std::ostream& out) { out << "old content\n"; });
    try {
        writeFileAtomically(file, [](std::ostream& out) {
            out << std::string(100000, 'n') << std::flush;  // partly on disk already
            throw std::runtime_error("simulated failure");
        });
        FAIL() << "the callback's exception was swallowed";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(file.string()), std::string::npos) << what;
        EXPECT_NE(what.find("simulated failure"), std::string::npos) << what;
    }
    EXPECT_EQ(readFile(file), "old content\n");
    EXPECT_EQ(directoryEntries(dir_), std::vector<std::string>{"data.txt"});
}

TEST_F(Exporters, WritingIntoAMissingDirectoryThrowsNamingThePath) {
    for (const Format format : {Format::Csv, Format::Ply, Format::Vtu, Format::Obj}) {
        const fs::path file = dir_ / "missing" / (std::string("frame.").append(extension(format)));
        try {
            writeFrame(file, format, particles_, SurfaceMeshDef{0.02f, {}, 1, {}});
            FAIL() << "wrote into a missing directory";
        } catch (const std::runtime_error& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(file.string()), std::string::npos) << what;
            EXPECT_NE(what.find("No such file or directory"), std::string::npos) << what;
        }
    }
    PvdWriter series(dir_ / "missing" / "series.pvd");
    series.add(0.0, "frame_00000.vtu");
    EXPECT_THROW(series.write(), std::runtime_error);
    EXPECT_EQ(directoryEntries(dir_), std::vector<std::string>{});
}

TEST_F(Exporters, EmptyStoreGivesHeaderOnlyFrames) {
    const ParticleStore empty;
    writeFrame(dir_ / "f.csv", Format::Csv, empty);
    EXPECT_EQ(readFile(dir_ / "f.csv"), "x,y,z,vx,vy,vz,density,pressure,material\n");
    writeFrame(dir_ / "f.ply", Format::Ply, empty);
    EXPECT_NE(readFile(dir_ / "f.ply").find("element vertex 0\n"), std::string::npos);
    writeFrame(dir_ / "f.vtu", Format::Vtu, empty);
    EXPECT_NE(readFile(dir_ / "f.vtu").find("NumberOfPoints=\"0\""), std::string::npos);
    writeFrame(dir_ / "f.obj", Format::Obj, empty, SurfaceMeshDef{0.02f, {}, 1, {}});
    EXPECT_EQ(readFile(dir_ / "f.obj"), "# tide: the fluid's surface, one object per material (m)\n");
}

// The surface mesh needs the particle spacing: without it nothing is written, and the error
// names it.
TEST_F(Exporters, ObjWithoutAParticleSpacingIsRefusedBeforeTheFileIsTouched) {
    try {
        writeFrame(dir_ / "f.obj", Format::Obj, particles_);
        FAIL() << "wrote a surface mesh without a particle spacing";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("particle spacing 0 m"), std::string::npos) << e.what();
    }
    EXPECT_EQ(directoryEntries(dir_), std::vector<std::string>{});
}

TEST_F(Exporters, InconsistentArraysAreRejected) {
    ParticleStore broken = makeParticles();
    broken.density.pop_back();
    EXPECT_THROW(writeFrame(dir_ / "f.csv", Format::Csv, broken), std::invalid_argument);
    EXPECT_FALSE(fs::exists(dir_ / "f.csv"));
}

}  // namespace
