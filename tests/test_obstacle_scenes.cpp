// Mesh files (OBJ, PLY) and the obstacle entries of scene files: what they make, and the
// messages that name the JSON path and the file when they are wrong.
#include <unistd.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <tide/io/mesh.hpp>
#include <tide/io/scene.hpp>
#include <tide/triangle_mesh.hpp>

namespace {

using namespace tide;
namespace fs = std::filesystem;

fs::path scratchDir() {
    const fs::path dir = fs::temp_directory_path() / ("tide_obstacle_scenes_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

fs::path writeFile(const std::string& name, const std::string& bytes) {
    const fs::path file = scratchDir() / name;
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << bytes;
    return file;
}

// The unit cube as 8 corners and 6 quads, counter-clockwise from outside (1-based for OBJ).
const float kCorners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const int kQuads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};

std::string cubeObj() {
    std::ostringstream out;
    out << "# unit cube\nmtllib missing.mtl\no cube\n";
    for (const auto& c : kCorners) out << "v " << c[0] << ' ' << c[1] << ' ' << c[2] << '\n';
    out << "vn 0 0 1\n";
    for (const auto& q : kQuads) out << "f " << q[0] + 1 << "//1 " << q[1] + 1 << "//1 " << q[2] + 1 << "//1 " << q[3] + 1 << "//1\n";
    return out.str();
}

template <class T>
void put(std::string& out, T value, bool bigEndian) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (bigEndian != (std::endian::native == std::endian::big)) std::reverse(bytes, bytes + sizeof(T));
    out.append(bytes, sizeof(T));
}

/// The cube as PLY with extra properties and an extra element that the reader must skip.
std::string cubePly(const std::string& format) {
    std::ostringstream header;
    header << "ply\nformat " << format << " 1.0\ncomment made by tide's tests\n"
           << "element vertex 8\nproperty double x\nproperty float y\nproperty float z\nproperty uchar red\n"
           << "element face 6\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\n"
           << "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
    std::string body;
    if (format == "ascii") {
        std::ostringstream text;
        for (const auto& c : kCorners) text << c[0] << ' ' << c[1] << ' ' << c[2] << " 255\n";
        for (const auto& q : kQuads) text << "4 " << q[0] << ' ' << q[1] << ' ' << q[2] << ' ' << q[3] << " 2 0.5 0.5\n";
        text << "0 1\n";
        body = text.str();
    } else {
        const bool big = format == "binary_big_endian";
        for (const auto& c : kCorners) {
            put<double>(body, c[0], big);
            put<float>(body, c[1], big);
            put<float>(body, c[2], big);
            put<std::uint8_t>(body, 255, big);
        }
        for (const auto& q : kQuads) {
            put<std::uint8_t>(body, 4, big);
            for (int k = 0; k < 4; ++k) put<std::int32_t>(body, q[k], big);
            put<std::uint8_t>(body, 2, big);
            put<float>(body, 0.5f, big);
            put<float>(body, 0.5f, big);
        }
        put<std::int32_t>(body, 0, big);
        put<std::int32_t>(body, 1, big);
    }
    return header.str() + body;
}

void expectUnitCube(const TriangleMesh& mesh) {
    EXPECT_EQ(mesh.triangles().size(), 12u);
    EXPECT_NEAR(mesh.volume(), 1.0, 1e-6);
    EXPECT_NEAR(mesh.signedDistance({0.5f, 0.5f, 0.5f}), -0.5f, 1e-6f);
    EXPECT_NEAR(mesh.signedDistance({0.5f, 3.0f, 0.5f}), 2.0f, 1e-6f);
}

TEST(MeshFiles, ObjAndEveryPlyEncodingGiveTheSameCube) {
    expectUnitCube(*io::loadMesh(writeFile("cube.obj", cubeObj())));
    for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
        SCOPED_TRACE(format);
        const auto data = io::readMeshFile(writeFile(std::string("cube_") + format + ".ply", cubePly(format)));
        EXPECT_EQ(data.vertices.size(), 8u);
        EXPECT_EQ(data.triangles.size(), 12u);
        expectUnitCube(*io::loadMesh(writeFile(std::string("cube_") + format + ".PLY", cubePly(format))));
    }
}

TEST(MeshFiles, PlacementScalesRotatesThenTranslates) {
    io::MeshPlacement place;
    place.scale = {2.0f, 1.0f, 1.0f};
    place.rotateDegrees = {0.0f, 0.0f, 90.0f};  // x → y
    place.translate = {10.0f, 0.0f, 0.0f};
    const auto mesh = io::loadMesh(writeFile("placed.obj", cubeObj()), place);
    EXPECT_NEAR(mesh->volume(), 2.0, 1e-5);
    EXPECT_NEAR(mesh->boundsMin().x, 9.0f, 1e-5f);
    EXPECT_NEAR(mesh->boundsMax().x, 10.0f, 1e-5f);
    EXPECT_NEAR(mesh->boundsMax().y, 2.0f, 1e-5f);
}

TEST(MeshFiles, ProblemsNameTheFileAndTheCause) {
    auto expectProblem = [](const fs::path& file, const std::string& cause) {
        try {
            io::loadMesh(file);
            ADD_FAILURE() << "loaded " << file;
        } catch (const io::MeshError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(file.string()), std::string::npos) << what;
            EXPECT_NE(what.find(cause), std::string::npos) << what;
        }
    };
    expectProblem(scratchDir() / "absent.obj", "no such file");
    expectProblem(scratchDir(), "directory");
    expectProblem(writeFile("cube.stl", "solid x\nendsolid x\n"), "unknown mesh format \".stl\"");
    expectProblem(writeFile("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"), "no triangles");
    std::string open = cubeObj();
    open.erase(open.rfind("f "));  // drop the last quad: a box without a lid
    expectProblem(writeFile("open.obj", open), "borders only one triangle");
    expectProblem(writeFile("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"), "degenerate");
    expectProblem(writeFile("bad_index.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                             "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                             "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
                  "vertex 7");
    expectProblem(writeFile("not.ply", "solid\n"), "not a PLY file");
    expectProblem(writeFile("noformat.ply", "ply\nelement vertex 0\nend_header\n"), "no format line");
    expectProblem(writeFile("cloud.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                         "property float z\nend_header\n0 0 0\n"),
                  "no \"face\" element");
    expectProblem(writeFile("noz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                       "element face 0\nproperty list uchar int vertex_indices\nend_header\n0 0\n"),
                  "no \"z\" property");
    std::string truncated = cubePly("binary_little_endian");
    truncated.resize(truncated.size() - 40);
    expectProblem(writeFile("truncated.ply", truncated), "ends early, in face");
    expectProblem(writeFile("text.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                        "property float z\nelement face 0\nproperty list uchar int vertex_indices\n"
                                        "end_header\n0 zero 0\n"),
                  "\"zero\" is not a number, in vertex 0");
}

/// A small valid scene with `obstacles` as its obstacle list.
std::string sceneWith(const std::string& obstacles) {
    return R"({"domain": {"min": [0, 0, 0], "max": [1, 0.5, 0.5]}, "particle_spacing": 0.05, "end_time": 0.1,
  "materials": [{"name": "water", "density": 1000}],
  "blocks": [{"min": [0, 0, 0], "max": [0.2, 0.2, 0.2]}],
  "obstacles": )" + obstacles + "}";
}

TEST(ObstacleScenes, NewTypesParseInMetres) {
    writeFile("models/cube.obj", cubeObj());
    const std::string text = R"({"unit_scale": 0.01, "domain": {"min": [0, 0, 0], "max": [100, 50, 50]},
  "particle_spacing": 5, "end_time": 0.1, "materials": [{"name": "water", "density": 1000}],
  "obstacles": [
    {"type": "cylinder", "center": [50, 25, 25], "axis": "-x", "radius": 10, "length": 40},
    {"type": "cylinder", "center": [50, 25, 25], "axis": [0, 3, 4], "radius": 10, "length": 40},
    {"type": "plane", "point": [0, 10, 0], "normal": [-1, 2, 0]},
    {"type": "mesh", "file": "models/cube.obj", "scale": 20, "rotate": [0, 0, 0], "translate": [70, 0, 10]},
    {"type": "mesh", "file": "models/cube.obj", "scale": [10, 20, 30]}]})";
    const io::Scene scene = io::parseScene(text, "units.json", scratchDir());
    ASSERT_EQ(scene.obstacles.size(), 5u);
    const ObstacleDef& c = scene.obstacles[0];
    EXPECT_EQ(c.shape, ObstacleDef::Shape::Cylinder);
    EXPECT_NEAR(glm::distance(c.center, glm::vec3(0.5f, 0.25f, 0.25f)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(c.axis, glm::vec3(-1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(c.radius, 0.1f, 1e-6f);
    EXPECT_NEAR(c.length, 0.4f, 1e-6f);
    EXPECT_NEAR(glm::distance(scene.obstacles[1].axis, glm::vec3(0, 0.6f, 0.8f)), 0.0f, 1e-6f);
    const ObstacleDef& p = scene.obstacles[2];
    EXPECT_EQ(p.shape, ObstacleDef::Shape::Plane);
    EXPECT_NEAR(p.point.y, 0.1f, 1e-6f);
    EXPECT_NEAR(glm::distance(p.normal, glm::normalize(glm::vec3(-1, 2, 0))), 0.0f, 1e-6f);
    const ObstacleDef& m = scene.obstacles[3];
    ASSERT_EQ(m.shape, ObstacleDef::Shape::Mesh);
    ASSERT_TRUE(m.mesh);
    EXPECT_NEAR(glm::distance(m.mesh->boundsMin(), glm::vec3(0.7f, 0.0f, 0.1f)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(m.mesh->boundsMax(), glm::vec3(0.9f, 0.2f, 0.3f)), 0.0f, 1e-5f);
    EXPECT_NEAR(scene.obstacles[4].mesh->volume(), 0.1 * 0.2 * 0.3, 1e-7);

    // The scene builds: a world with the five obstacles.
    const World world = io::buildWorld(scene);
    EXPECT_EQ(world.obstacles().size(), 5u);
}

TEST(ObstacleScenes, MeshPathsAreRelativeToTheSceneFile) {
    const fs::path dir = scratchDir() / "relative";
    writeFile("relative/models/cube.obj", cubeObj());
    const fs::path scene = writeFile("relative/scene.json", sceneWith(R"([{"type": "mesh", "file": "models/cube.obj",
      "scale": 0.1, "translate": [0.5, 0, 0.2]}])"));
    const fs::path elsewhere = fs::current_path();
    fs::current_path(fs::temp_directory_path());
    EXPECT_NO_THROW(io::loadScene(scene));
    fs::current_path(elsewhere);
}

struct BadObstacle {
    std::string obstacles;
    std::vector<std::string> expected;  ///< each must appear in one problem
};

TEST(ObstacleScenes, ProblemsNameTheJsonPath) {
    writeFile("models/cube.obj", cubeObj());
    std::string open = cubeObj();
    open.erase(open.rfind("f "));
    writeFile("models/open.obj", open);
    const std::vector<BadObstacle> cases = {
        {R"([{"type": "cylindre", "center": [0, 0, 0]}])", {"obstacles[0].type", "did you mean \"cylinder\""}},
        {R"([{"type": "cylinder", "center": [0.5, 0.2, 0.2], "radius": 0.1, "length": 0.2}])", {"obstacles[0].axis: missing"}},
        {R"([{"type": "cylinder", "center": [0.5, 0.2, 0.2], "axis": "w", "radius": 0.1, "length": 0.2}])", {"obstacles[0].axis"}},
        {R"([{"type": "cylinder", "center": [0.5, 0.2, 0.2], "axis": [0, 0, 0], "radius": 0.1, "length": 0.2}])", {"obstacles[0].axis"}},
        {R"([{"type": "cylinder", "center": [0.5, 0.2, 0.2], "axis": "y", "radius": -1, "length": 0.2}])", {"obstacles[0].radius"}},
        {R"([{"type": "cylinder", "center": [0.5, 0.2, 0.2], "axis": "y", "radius": 0.1}])", {"obstacles[0].length: missing"}},
        {R"([{"type": "cylinder", "center": [0.5, 0.2, 0.2], "axis": "y", "radius": 0.1, "height": 0.2}])",
         {"obstacles[0].height: unknown key", "obstacles[0].length: missing"}},
        {R"([{"type": "plane", "point": [0, 0.1, 0]}])", {"obstacles[0].normal: missing"}},
        {R"([{"type": "plane", "point": [0, 0.1, 0], "normal": [0, 0, 0]}])", {"obstacles[0].normal"}},
        {R"([{"type": "plane", "point": [0, 0.1], "normal": "y"}])", {"obstacles[0].point"}},
        {R"([{"type": "plane", "point": [0, 0.1, 0], "normal": "y", "radius": 1}])", {"obstacles[0].radius: unknown key"}},
        {R"([{"type": "box", "min": [0, 0, 0], "max": [0.1, 0.1, 0.1]}, {"type": "mesh"}])", {"obstacles[1].file: missing"}},
        {R"([{"type": "mesh", "file": "models/none.obj"}])", {"obstacles[0].file", "models/none.obj", "no such file"}},
        {R"([{"type": "mesh", "file": "models/open.obj"}])", {"obstacles[0].file", "models/open.obj", "not closed"}},
        {R"([{"type": "mesh", "file": "models/cube.obj", "scale": 0}])", {"obstacles[0].scale"}},
        {R"([{"type": "mesh", "file": "models/cube.obj", "scale": [1, -1, 1]}])", {"obstacles[0].scale"}},
        {R"([{"type": "mesh", "file": "models/cube.obj", "scale": "big"}])", {"obstacles[0].scale: must be a number or 3 numbers"}},
        {R"([{"type": "mesh", "file": "models/cube.obj", "translate": [1, 2]}])", {"obstacles[0].translate"}},
        {R"([{"type": "mesh", "file": "models/cube.obj", "rotate": "90"}])", {"obstacles[0].rotate"}},
        {R"([{"type": "mesh", "file": "models/cube.obj", "scael": 2}])", {"obstacles[0].scael", "did you mean \"scale\""}},
        {R"([{"type": "mesh", "file": ""}])", {"obstacles[0].file"}},
    };
    for (const BadObstacle& c : cases) {
        SCOPED_TRACE(c.obstacles);
        try {
            io::parseScene(sceneWith(c.obstacles), "bad.json", scratchDir());
            ADD_FAILURE() << "accepted";
        } catch (const io::SceneError& e) {
            std::string all;
            for (const std::string& p : e.problems) all += p + "\n";
            for (const std::string& text : c.expected) EXPECT_NE(all.find(text), std::string::npos) << text << " in\n" << all;
        }
    }
}

}  // namespace
