// The fluid's surface mesh (tide::io::buildSurfaceMesh, the obj frame format): closed, outward,
// where a block's faces are, enclosing the volume its particles fill.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <tide/io/surface_mesh.hpp>

namespace {

using namespace tide;
using namespace tide::io;

/// Particles on the cubic lattice of spacing s filling [lo, hi] (centres half a spacing in),
/// as World::addBlock puts them, of material `material`.
void addBlock(ParticleStore& p, glm::vec3 lo, glm::vec3 hi, float s, MaterialIndex material = 0) {
    for (float x = lo.x + 0.5f * s; x < hi.x; x += s)
        for (float y = lo.y + 0.5f * s; y < hi.y; y += s)
            for (float z = lo.z + 0.5f * s; z < hi.z; z += s) {
                p.position.emplace_back(x, y, z);
                p.material.push_back(material);
            }
}

/// Every directed edge once, and its reverse too: a closed, consistently wound surface.
bool closedAndConsistent(const SurfaceMesh& mesh, std::size_t first, std::size_t count) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (std::size_t t = first; t < first + count; ++t)
        for (int k = 0; k < 3; ++k) ++edges[{mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]}];
    for (const auto& [edge, uses] : edges)
        if (uses != 1 || !edges.contains({edge.second, edge.first})) return false;
    return !edges.empty();
}

/// Connected pieces of the triangles [first, first + count) (union-find over shared vertices).
int pieces(const SurfaceMesh& mesh, std::size_t first, std::size_t count) {
    std::vector<std::uint32_t> parent(mesh.vertices.size());
    for (std::uint32_t v = 0; v < parent.size(); ++v) parent[v] = v;
    auto root = [&](std::uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (std::size_t t = first; t < first + count; ++t)
        for (int k = 1; k < 3; ++k) parent[root(mesh.triangles[t][k])] = root(mesh.triangles[t][0]);
    std::vector<bool> seen(parent.size(), false);
    int n = 0;
    for (std::size_t t = first; t < first + count; ++t) {
        const std::uint32_t r = root(mesh.triangles[t][0]);
        if (!seen[r]) ++n;
        seen[r] = true;
    }
    return n;
}

struct Bounds {
    glm::vec3 lo{1e30f}, hi{-1e30f};
};

Bounds boundsOf(const SurfaceMesh& mesh) {
    Bounds b;
    for (const glm::vec3& v : mesh.vertices) {
        b.lo = glm::min(b.lo, v);
        b.hi = glm::max(b.hi, v);
    }
    return b;
}

}  // namespace

// A block of particles: its surface is the block's faces, [0, 0.2] × [0, 0.1] × [0, 0.16],
// with its edges rounded by the spheres and the smoothing to a radius of one spacing: the
// volume is the block's less (1 − π/4) s² along each edge (measured: 4.64 % less at 2 cm,
// 0.89 % at 1 cm; that model says 4.93 % and 1.23 %).
class SurfaceMeshBlock : public testing::TestWithParam<float> {};

TEST_P(SurfaceMeshBlock, SurfaceLiesOnItsFaces) {
    const float s = GetParam();
    ParticleStore p;
    addBlock(p, {0, 0, 0}, {0.2f, 0.1f, 0.16f}, s);
    const SurfaceMesh mesh = buildSurfaceMesh(p, SurfaceMeshDef{s, {"water"}, 1, {}});
    ASSERT_EQ(mesh.objects.size(), 1u);
    EXPECT_EQ(mesh.objects[0].name, "water");
    EXPECT_TRUE(closedAndConsistent(mesh, 0, mesh.triangles.size()));
    EXPECT_EQ(pieces(mesh, 0, mesh.triangles.size()), 1);  // no stray shell inside or out
    const double volume = enclosedVolume(mesh, 0, mesh.triangles.size());
    const double block = 0.2 * 0.1 * 0.16;
    const Bounds b = boundsOf(mesh);
    // The flat top, away from the edges: its height.
    double topSum = 0.0, topSquares = 0.0, topCount = 0.0;
    for (const glm::vec3& v : mesh.vertices) {
        if (v.y < 0.08f || v.x < 0.05f || v.x > 0.15f || v.z < 0.05f || v.z > 0.11f) continue;
        topSum += v.y;
        topSquares += v.y * v.y;
        topCount += 1.0;
    }
    const double topMean = topSum / topCount, topSpread = std::sqrt(std::max(0.0, topSquares / topCount - topMean * topMean));
    std::printf("block at %.3f m: %zu vertices, %zu triangles, volume %.6f m3 (block %.6f: %+.2f %%), bounds [%.4f %.4f "
                "%.4f] - [%.4f %.4f %.4f], top %.5f m (spread %.2e)\n",
                s, mesh.vertices.size(), mesh.triangles.size(), volume, block, 100.0 * (volume / block - 1.0), b.lo.x, b.lo.y,
                b.lo.z, b.hi.x, b.hi.y, b.hi.z, topMean, topSpread);
    const double edges = 4.0 * (0.2 + 0.1 + 0.16), rounded = block - edges * (1.0 - M_PI / 4.0) * s * s;
    EXPECT_NEAR(volume / rounded, 1.0, 0.01);
    for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(b.lo[axis], 0.0f, 0.25f * s) << "axis " << axis;
    EXPECT_NEAR(b.hi.x, 0.2f, 0.25f * s);
    EXPECT_NEAR(b.hi.y, 0.1f, 0.25f * s);
    EXPECT_NEAR(b.hi.z, 0.16f, 0.25f * s);
    EXPECT_NEAR(topMean, 0.1, 0.05 * s);
    EXPECT_LT(topSpread, 0.05 * s);  // flat: no bumps of single spheres
}

INSTANTIATE_TEST_SUITE_P(Spacings, SurfaceMeshBlock, testing::Values(0.02f, 0.01f));

// A ball of particles: the mesh holds the volume they fill (one s³ each) and is round.
TEST(SurfaceMesh, BallEnclosesItsParticlesVolume) {
    const float s = 0.01f, radius = 0.06f;
    const glm::vec3 centre(0.1f);
    ParticleStore all, p;
    addBlock(all, centre - radius, centre + radius, s);
    for (std::size_t i = 0; i < all.position.size(); ++i)
        if (glm::length(all.position[i] - centre) < radius) {
            p.position.push_back(all.position[i]);
            p.material.push_back(0);
        }
    const SurfaceMesh mesh = buildSurfaceMesh(p, SurfaceMeshDef{s, {}, 1, {}});
    ASSERT_EQ(mesh.objects.size(), 1u);
    EXPECT_EQ(mesh.objects[0].name, "material_0");
    EXPECT_TRUE(closedAndConsistent(mesh, 0, mesh.triangles.size()));
    EXPECT_EQ(pieces(mesh, 0, mesh.triangles.size()), 1);
    const double volume = enclosedVolume(mesh, 0, mesh.triangles.size());
    const double filled = static_cast<double>(p.position.size()) * s * s * s;
    double rMin = 1e30, rMax = 0.0;
    for (const glm::vec3& v : mesh.vertices) {
        const double r = glm::length(v - centre);
        rMin = std::min(rMin, r);
        rMax = std::max(rMax, r);
    }
    std::printf("ball: %zu particles, volume %.7f m3 against %.7f (%+.2f %%), radius %.4f to %.4f m\n", p.position.size(),
                volume, filled, 100.0 * (volume / filled - 1.0), rMin, rMax);
    EXPECT_NEAR(volume / filled, 1.0, 0.05);
    const double equivalent = std::cbrt(3.0 * filled / (4.0 * M_PI));
    EXPECT_GT(rMin, equivalent - 0.5 * s);
    EXPECT_LT(rMax, equivalent + 0.5 * s);
}

// Two materials, two objects, each closed around its own block; written as OBJ.
TEST(SurfaceMesh, OneObjectPerMaterialInTheObjText) {
    const float s = 0.02f;
    ParticleStore p;
    addBlock(p, {0, 0, 0}, {0.1f, 0.1f, 0.1f}, s, 0);
    addBlock(p, {0.2f, 0, 0}, {0.3f, 0.06f, 0.1f}, s, 2);  // material 1 has no particles
    const SurfaceMesh mesh = buildSurfaceMesh(p, SurfaceMeshDef{s, {"oil", "air", "water"}, 1, {}});
    ASSERT_EQ(mesh.objects.size(), 2u);
    EXPECT_EQ(mesh.objects[0].name, "oil");
    EXPECT_EQ(mesh.objects[1].name, "water");
    EXPECT_EQ(mesh.objects[1].material, 2u);
    for (const SurfaceMesh::Object& o : mesh.objects) {
        EXPECT_TRUE(closedAndConsistent(mesh, o.firstTriangle, o.triangleCount)) << o.name;
        EXPECT_EQ(pieces(mesh, o.firstTriangle, o.triangleCount), 1) << o.name;
        EXPECT_GT(enclosedVolume(mesh, o.firstTriangle, o.triangleCount), 0.0) << o.name;
        // Each object around its own block only.
        const float lo = o.material == 0 ? 0.0f : 0.2f, hi = o.material == 0 ? 0.1f : 0.3f;
        for (std::size_t t = o.firstTriangle; t < o.firstTriangle + o.triangleCount; ++t)
            for (const std::uint32_t v : mesh.triangles[t]) {
                ASSERT_GT(mesh.vertices[v].x, lo - 0.25f * s) << o.name;
                ASSERT_LT(mesh.vertices[v].x, hi + 0.25f * s) << o.name;
            }
    }
    std::ostringstream out;
    writeObj(out, mesh);
    std::istringstream in(out.str());
    std::string line;
    std::size_t vertices = 0, faces = 0, badIndices = 0;
    std::vector<std::string> objects;
    while (std::getline(in, line)) {
        if (line.rfind("v ", 0) == 0) ++vertices;
        if (line.rfind("o ", 0) == 0) objects.push_back(line.substr(2));
        if (line.rfind("f ", 0) == 0) {
            ++faces;
            std::istringstream f(line.substr(2));
            long index = 0;
            for (int k = 0; k < 3; ++k) {
                f >> index;
                if (index < 1 || static_cast<std::size_t>(index) > mesh.vertices.size()) ++badIndices;
            }
        }
    }
    EXPECT_EQ(vertices, mesh.vertices.size());
    EXPECT_EQ(faces, mesh.triangles.size());
    EXPECT_EQ(badIndices, 0u);
    EXPECT_EQ(objects, (std::vector<std::string>{"oil", "water"}));
}

TEST(SurfaceMesh, BadSpacingIsRefusedByName) {
    ParticleStore p;
    addBlock(p, {0, 0, 0}, {0.1f, 0.1f, 0.1f}, 0.02f);
    auto message = [&](float spacing) {
        try {
            (void)buildSurfaceMesh(p, SurfaceMeshDef{spacing, {}, 0, {}});
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(0.0f).find("particle spacing 0 m"), std::string::npos) << message(0.0f);
    EXPECT_NE(message(-0.01f).find("particle spacing -0.01 m"), std::string::npos) << message(-0.01f);
    EXPECT_NE(message(NAN).find("particle spacing"), std::string::npos);
    EXPECT_NE(message(INFINITY).find("particle spacing"), std::string::npos);
    EXPECT_EQ(message(0.02f), "no error");
}

TEST(SurfaceMesh, NoParticlesNoObjects) {
    const SurfaceMesh mesh = buildSurfaceMesh(ParticleStore{}, SurfaceMeshDef{0.02f, {}, 0, {}});
    EXPECT_TRUE(mesh.objects.empty());
    EXPECT_TRUE(mesh.triangles.empty());
}

// A splash's lone particle and a sheet one particle thick keep a surface. The smoothing alone
// dropped the lone particle (no triangles, measured): it gets a bead of its own volume, which
// the half-spacing voxels mesh at 0.38 s³; the sheet is a film a spacing thick (0.85 s³ a
// particle, its edges rounded).
TEST(SurfaceMesh, LoneParticleAndThinSheetShow) {
    const float s = 0.02f;
    ParticleStore p;
    p.position.emplace_back(0.5f, 0.5f, 0.5f);
    p.material.push_back(0);
    addBlock(p, {0, 0, 0}, {0.2f, s, 0.2f}, s, 1);  // one layer of 10 × 10
    const SurfaceMesh mesh = buildSurfaceMesh(p, SurfaceMeshDef{s, {"drop", "sheet"}, 1, {}});
    ASSERT_EQ(mesh.objects.size(), 2u);
    const double cube = static_cast<double>(s) * s * s;
    for (const SurfaceMesh::Object& o : mesh.objects) {
        EXPECT_TRUE(closedAndConsistent(mesh, o.firstTriangle, o.triangleCount)) << o.name;
        EXPECT_EQ(pieces(mesh, o.firstTriangle, o.triangleCount), 1) << o.name;
        const double perParticle = enclosedVolume(mesh, o.firstTriangle, o.triangleCount) / (o.material == 0 ? 1.0 : 100.0) / cube;
        std::printf("%s: %zu triangles, %.2f s^3 a particle\n", o.name.c_str(), o.triangleCount, perParticle);
        if (o.material == 0) {
            EXPECT_GT(perParticle, 0.25);
            EXPECT_LT(perParticle, 1.2);
        } else {
            EXPECT_GT(perParticle, 0.7);
            EXPECT_LT(perParticle, 1.2);
        }
    }
}

// Frames are the same on any thread count (as the simulation's are: docs/robustness.md §
// Determinism), the surface too: OpenVDB's passes combine their threads' work by min and by
// prefix sums, not in the order threads finish.
TEST(SurfaceMesh, SameMeshOnAnyThreadCount) {
    const float s = 0.01f;
    ParticleStore p;
    addBlock(p, {0, 0, 0}, {0.2f, 0.1f, 0.1f}, s);
    for (std::size_t i = 0; i < p.position.size(); ++i) {  // a disordered cloud, and a splash above it
        const float k = static_cast<float>(i);
        p.position[i] += 0.3f * s * glm::vec3(std::sin(1.7f * k), std::sin(2.3f * k + 1.0f), std::sin(3.1f * k + 2.0f));
        if (i % 97 == 0) p.position[i].y += 0.05f + 0.002f * static_cast<float>(i % 7);
    }
    const SurfaceMesh one = buildSurfaceMesh(p, SurfaceMeshDef{s, {}, 1, {}});
    const SurfaceMesh two = buildSurfaceMesh(p, SurfaceMeshDef{s, {}, 2, {}});
    ASSERT_GT(one.triangles.size(), 1000u);
    EXPECT_EQ(one.vertices, two.vertices);
    EXPECT_EQ(one.triangles, two.triangles);
}
