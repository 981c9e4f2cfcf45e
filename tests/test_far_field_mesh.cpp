// The far field's mesh in obj frames (issue 43, "--format obj also writes the far-field
// surface"): a grid around the near field with a hole exactly over it, on the sea the zones use.
#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <tide/io/far_field_mesh.hpp>
#include <tide/io/surface_mesh.hpp>

#include "ocean/sea.hpp"

namespace {

using namespace tide;

io::FarFieldMeshDef farField() {
    io::FarFieldMeshDef def;
    def.ocean.depth = 0.5;
    def.ocean.waves.type = OceanWavesDef::Type::Regular;
    def.ocean.waves.height = 0.1;
    def.ocean.waves.period = 1.5;
    def.ocean.waves.direction = 30.0;
    def.nearMin = {1.0f, -0.2f, 0.0f};
    def.nearMax = {3.4f, 0.6f, 1.3f};
    def.extent = 2.0;
    def.spacing = 0.17;
    def.time = 2.3;
    def.threads = 2;
    return def;
}

TEST(FarFieldMesh, CoversTheSeaAroundTheNearFieldAndNothingOverIt) {
    const io::FarFieldMeshDef def = farField();
    io::SurfaceMesh mesh;
    io::appendFarField(mesh, def);
    ASSERT_EQ(mesh.objects.size(), 1u);
    EXPECT_EQ(mesh.objects[0].name, "far_field");
    // Plan area of the triangles = the grid's rectangle less the near field's, exactly: the
    // grid's lines fall on the hole's edges. Cells: 2.4/15, 1.3/8; the margin whole cells ≥ 2 m.
    const double dx = 2.4 / 15, dz = 1.3 / 8;
    const double outerX = 2.4 + 2 * std::ceil(2.0 / dx - 1e-9) * dx, outerZ = 1.3 + 2 * std::ceil(2.0 / dz - 1e-9) * dz;
    int facingDown = 0;
    const ocean::Sea sea = ocean::Sea::fromDef(def.ocean, def.gravity);
    int ring = 0;
    double worstRing = 0.0;
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 a(mesh.vertices[t[0]]), b(mesh.vertices[t[1]]), c(mesh.vertices[t[2]]);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        facingDown += n.y <= 0.0;
    }
    for (const glm::vec3& v : mesh.vertices) {
        const bool inX = v.x > 1.0f - 1e-4f && v.x < 3.4f + 1e-4f, inZ = v.z > -1e-4f && v.z < 1.3f + 1e-4f;
        EXPECT_FALSE(inX && inZ && v.x > 1.0001f && v.x < 3.3999f && v.z > 1e-4f && v.z < 1.2999f) << "a point inside the hole";
        if (inX && inZ) {  // the hole's edge: not shifted sideways, raised by η there
            ++ring;
            worstRing = std::max(worstRing, std::abs(v.y - (-0.2 + 0.5 + sea.elevation(v.x, v.z, def.time))));
        }
    }
    // Plan area from the rest grid: every triangle is half a cell.
    const double area = 0.5 * dx * dz * static_cast<double>(mesh.triangles.size());
    EXPECT_NEAR(area, outerX * outerZ - 2.4 * 1.3, 1e-9);
    EXPECT_EQ(facingDown, 0);
    EXPECT_EQ(ring, 2 * (15 + 8));
    EXPECT_LT(worstRing, 1e-5);  // float positions
    // The rest of the sea reaches the wave's crest and trough (a point's height is η at its rest
    // point): H = 0.1 m apart, the crest higher than the trough is deep (a Stokes wave's).
    double highest = -1.0, lowest = 1.0;
    for (const glm::vec3& v : mesh.vertices) highest = std::max(highest, double(v.y)), lowest = std::min(lowest, double(v.y));
    const double crest = sea.elevation(0.0, 0.0, 0.0), trough = crest - 0.1;
    EXPECT_GT(crest, 0.052);
    EXPECT_NEAR(highest - 0.3, crest, 0.002);
    EXPECT_NEAR(lowest - 0.3, trough, 0.002);
}

TEST(FarFieldMesh, FollowsTheRampAndRefusesBadSizesNamingThem) {
    io::FarFieldMeshDef def = farField();
    def.ramp = 0.0;  // before the sea has begun: still water
    io::SurfaceMesh still;
    io::appendFarField(still, def);
    for (const glm::vec3& v : still.vertices) ASSERT_NEAR(v.y, 0.3f, 1e-6f);

    auto refused = [&](io::FarFieldMeshDef bad, const std::string& field) {
        io::SurfaceMesh mesh;
        try {
            io::appendFarField(mesh, bad);
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
            EXPECT_TRUE(mesh.vertices.empty());
            return;
        }
        ADD_FAILURE() << field << " not refused";
    };
    io::FarFieldMeshDef bad = farField();
    bad.extent = 0.0;
    refused(bad, "output.far_field.extent");
    bad = farField();
    bad.spacing = -1.0;
    refused(bad, "output.far_field.spacing");
    bad = farField();
    bad.spacing = 1e-4;  // 10⁸ points
    refused(bad, "output.far_field.spacing");
    bad = farField();
    bad.extent = 1e30;  // more cells than a size_t holds
    refused(bad, "output.far_field.extent");
}

TEST(FarFieldMesh, TheDefaultsFollowThePeakWavelength) {
    const io::FarFieldMeshDef def = farField();
    const double wavelength = oceanPeakWavelength(def.ocean, def.gravity);
    EXPECT_NEAR(io::defaultFarFieldExtent(def.ocean, def.gravity), 2.0 * wavelength, 1e-12);
    EXPECT_NEAR(io::defaultFarFieldSpacing(def.ocean, def.gravity), wavelength / 16.0, 1e-12);
}

}  // namespace
