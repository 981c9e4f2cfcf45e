// The fluid's surface from its particles (Zhu & Bridson 2005), through OpenVDB's level sets.
#include <tide/io/surface_mesh.hpp>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <glm/geometric.hpp>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetFilter.h>
#include <openvdb/tools/ParticlesToLevelSet.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <tbb/global_control.h>

namespace tide::io {

namespace {

/// One material's particle positions as ParticlesToLevelSet reads them (a uniform radius).
struct ParticleList {
    using PosType = openvdb::Vec3R;
    const ParticleStore* particles = nullptr;
    std::vector<std::uint32_t> members;  ///< indices of the material's particles

    [[nodiscard]] std::size_t size() const { return members.size(); }
    void getPos(std::size_t n, openvdb::Vec3R& xyz) const {
        const glm::vec3& x = particles->position[members[n]];
        xyz = openvdb::Vec3R(x.x, x.y, x.z);
    }
};

/// Smoothing passes of the rasterised spheres: each a mean over 3×3×3 voxels, then the level
/// set renormalised. Two take the bumps of single spheres off a flat face of a block.
constexpr int kSmoothingPasses = 2;
/// Each particle's sphere: one spacing, so that neighbours' overlap and the union has no gaps
/// between them.
constexpr double kSphereRadius = 1.0;
/// The bead a particle the smoothing left outside the surface gets, in spacings: a sphere of
/// its own volume, s³.
const double kBeadRadius = std::cbrt(3.0 / (4.0 * M_PI));
/// The erosion after smoothing, in spacings, that puts a flat face of a block of particles
/// where the block's face is, half a spacing beyond its outer particles: measured on a
/// lattice block (tests/test_surface_mesh.cpp; 0.25 left it 0.07 spacings out, 0.3 within
/// 0.01). Less than ½ (a sphere of one spacing less half) because the union dips between
/// the spheres, and the smoothing averages the dips into its face.
constexpr double kErosion = 0.3;

void checkDef(const SurfaceMeshDef& def) {
    if (!(def.particleSpacing > 0.0f) || !std::isfinite(def.particleSpacing)) {
        std::ostringstream msg;
        msg << "surface mesh: particle spacing " << def.particleSpacing << " m: must be positive and finite";
        throw std::invalid_argument(msg.str());
    }
}

/// The smoothing drops what is smaller than its stencil, such as a lone particle of a splash
/// (measured: a lone particle left no surface). Each particle whose centre it left outside the
/// eroded surface gets a bead of its own volume, unioned in: the eroded level of a sphere of
/// the bead's radius plus the erosion.
void addBeads(openvdb::FloatGrid& grid, const ParticleList& list, double spacing, double erosion, float halfWidth) {
    ParticleList dropped{list.particles, {}};
    const openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> phi(grid);
    for (const std::uint32_t i : list.members) {
        const glm::vec3& x = list.particles->position[i];
        if (phi.wsSample(openvdb::Vec3R(x.x, x.y, x.z)) > -erosion) dropped.members.push_back(i);
    }
    if (dropped.members.empty()) return;
    auto beads = openvdb::createLevelSet<openvdb::FloatGrid>(grid.voxelSize()[0], halfWidth);
    openvdb::tools::ParticlesToLevelSet<openvdb::FloatGrid> raster(*beads);
    raster.setRmin(1.0);
    raster.rasterizeSpheres(dropped, kBeadRadius * spacing + erosion);
    raster.finalize(true);
    openvdb::tools::csgUnion(grid, *beads);
}

}  // namespace

SurfaceMesh buildSurfaceMesh(const ParticleStore& particles, const SurfaceMeshDef& def) {
    checkDef(def);
    static std::once_flag initialised;
    std::call_once(initialised, [] { openvdb::initialize(); });
    const int threads = def.threads > 0 ? def.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));

    const double spacing = def.particleSpacing;
    const double voxel = 0.5 * spacing;
    const double radius = kSphereRadius * spacing, erosion = kErosion * spacing;
    // The narrow band holds the erosion and the filter's stencil (4 voxels met the same tests
    // 25 % slower).
    const float halfWidth = static_cast<float>(std::max(3.0, std::ceil(erosion / voxel) + 2.0));

    std::vector<ParticleList> lists;
    for (std::uint32_t i = 0; i < particles.size(); ++i) {
        const std::uint32_t m = particles.material[i];
        if (m >= lists.size()) lists.resize(m + 1, ParticleList{&particles, {}});
        lists[m].members.push_back(i);
    }

    SurfaceMesh mesh;
    for (std::uint32_t m = 0; m < lists.size(); ++m) {
        if (lists[m].members.empty()) continue;
        auto grid = openvdb::createLevelSet<openvdb::FloatGrid>(voxel, halfWidth);
        {
            openvdb::tools::ParticlesToLevelSet<openvdb::FloatGrid> raster(*grid);
            raster.setRmin(1.0);
            raster.rasterizeSpheres(lists[m], radius);
            raster.finalize(true);
        }
        openvdb::tools::LevelSetFilter<openvdb::FloatGrid> filter(*grid);
        for (int pass = 0; pass < kSmoothingPasses; ++pass) filter.mean(1);
        addBeads(*grid, lists[m], spacing, erosion, halfWidth);

        std::vector<openvdb::Vec3s> points;
        std::vector<openvdb::Vec3I> triangles;
        std::vector<openvdb::Vec4I> quads;
        // The eroded surface is the level −erosion of the signed distance the filter keeps: the
        // same as LevelSetFilter::offset and half the time (its renormalisation is the cost).
        openvdb::tools::volumeToMesh(*grid, points, triangles, quads, -erosion, 0.0);

        SurfaceMesh::Object object;
        object.material = m;
        object.name = m < def.materialNames.size() ? def.materialNames[m] : "material_" + std::to_string(m);
        object.firstTriangle = mesh.triangles.size();
        const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
        for (const openvdb::Vec3s& p : points) mesh.vertices.emplace_back(p.x(), p.y(), p.z());
        // volumeToMesh winds its polygons clockwise seen from outside (towards positive φ).
        auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
            mesh.triangles.push_back({base + a, base + c, base + b});
        };
        for (const openvdb::Vec3I& t : triangles) add(t[0], t[1], t[2]);
        for (const openvdb::Vec4I& q : quads) {
            // Split along the shorter diagonal: the flatter pair of triangles.
            const glm::vec3 d02 = mesh.vertices[base + q[0]] - mesh.vertices[base + q[2]];
            const glm::vec3 d13 = mesh.vertices[base + q[1]] - mesh.vertices[base + q[3]];
            if (glm::dot(d02, d02) <= glm::dot(d13, d13)) {
                add(q[0], q[1], q[2]);
                add(q[0], q[2], q[3]);
            } else {
                add(q[0], q[1], q[3]);
                add(q[1], q[2], q[3]);
            }
        }
        object.triangleCount = mesh.triangles.size() - object.firstTriangle;
        mesh.objects.push_back(std::move(object));
    }
    if (def.farField) {
        FarFieldMeshDef farField = *def.farField;
        farField.threads = threads;
        appendFarField(mesh, farField);
    }
    return mesh;
}

double enclosedVolume(const SurfaceMesh& mesh, std::size_t first, std::size_t count) {
    double volume = 0.0;
    for (std::size_t t = first; t < first + count; ++t) {
        const glm::dvec3 a(mesh.vertices[mesh.triangles[t][0]]);
        const glm::dvec3 b(mesh.vertices[mesh.triangles[t][1]]);
        const glm::dvec3 c(mesh.vertices[mesh.triangles[t][2]]);
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return volume;
}

}  // namespace tide::io
