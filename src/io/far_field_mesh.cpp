// The far field's sea as a mesh around the near field (the obj frames' "far_field" object).
#include <tide/io/far_field_mesh.hpp>
#include <tide/io/surface_mesh.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "ocean/sea.hpp"
#include "ocean/sea_surface.hpp"

namespace tide::io {

double defaultFarFieldExtent(const OceanDef& ocean, double gravity) { return 2.0 * oceanPeakWavelength(ocean, gravity); }

double defaultFarFieldSpacing(const OceanDef& ocean, double gravity) { return oceanPeakWavelength(ocean, gravity) / 16.0; }

FarFieldMeshDef farFieldMeshFor(const OceanDef& ocean, const WorldDef& world, double extent, double spacing) {
    FarFieldMeshDef far;
    far.ocean = ocean;
    far.gravity = glm::length(world.gravity);
    far.nearMin = world.domainMin;
    far.nearMax = world.domainMax;
    far.extent = extent > 0.0 ? extent : defaultFarFieldExtent(ocean, far.gravity);
    far.spacing = spacing > 0.0 ? spacing : defaultFarFieldSpacing(ocean, far.gravity);
    return far;
}

namespace {

void fail(const std::string& field, double value, const std::string& why) {
    std::ostringstream msg;
    msg << "output.far_field." << field << ": " << why << ", got " << value;
    throw std::invalid_argument(msg.str());
}

/// Grid lines along one axis: the near field's [lo, hi] cut into equal cells no longer than
/// `spacing`, continued by cells of the same length for at least `extent` on both sides.
struct Axis {
    std::vector<double> lines;
    std::size_t first = 0, last = 0;  ///< the indices of the lines at lo and hi
};

/// The most points along one axis (16 million in all at most, a grid of 4000 × 4000).
constexpr double kMostLines = 4000.0;

Axis axisThrough(double lo, double hi, double extent, double spacing) {
    const double width = hi - lo;
    const double insideCells = std::max(1.0, std::ceil(width / spacing - 1e-9));
    if (!(insideCells < kMostLines)) fail("spacing", spacing, "makes a far-field mesh of more than 16 million points; take a larger one");
    const double step = width > 0.0 ? width / insideCells : spacing;
    const double outsideCells = std::ceil(extent / step - 1e-9);
    if (!(insideCells + 2.0 * outsideCells < kMostLines))
        fail("extent", extent, "makes a far-field mesh of more than 16 million points at this spacing; take a smaller one");
    const auto inside = static_cast<std::size_t>(insideCells), outside = static_cast<std::size_t>(outsideCells);
    Axis a;
    a.first = outside;
    a.last = outside + inside;
    for (std::size_t i = 0; i <= inside + 2 * outside; ++i)
        a.lines.push_back(lo + (static_cast<double>(i) - static_cast<double>(outside)) * step);
    return a;
}

}  // namespace

void appendFarField(SurfaceMesh& mesh, const FarFieldMeshDef& def) {
    if (!(def.extent > 0.0) || !std::isfinite(def.extent)) fail("extent", def.extent, "must be > 0");
    if (!(def.spacing > 0.0) || !std::isfinite(def.spacing)) fail("spacing", def.spacing, "must be > 0");
    const Axis ax = axisThrough(def.nearMin.x, def.nearMax.x, def.extent, def.spacing);
    const Axis az = axisThrough(def.nearMin.z, def.nearMax.z, def.extent, def.spacing);
    const std::size_t nx = ax.lines.size(), nz = az.lines.size();

    // Points i (along x) and j (along z). Those strictly inside the hole belong to no triangle
    // and are neither sampled nor written; those on its edge (the ring of lines first..last)
    // are sampled without the choppy shift.
    auto inHole = [&](std::size_t i, std::size_t j) { return i > ax.first && i < ax.last && j > az.first && j < az.last; };
    auto onRing = [&](std::size_t i, std::size_t j) {
        const bool inX = i >= ax.first && i <= ax.last, inZ = j >= az.first && j <= az.last;
        return inX && inZ && (i == ax.first || i == ax.last || j == az.first || j == az.last);
    };
    std::vector<glm::dvec2> rest, ringRest;
    std::vector<std::uint32_t> index(nx * nz), ringVertex;
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    for (std::size_t j = 0; j < nz; ++j)
        for (std::size_t i = 0; i < nx; ++i) {
            if (inHole(i, j)) continue;
            index[j * nx + i] = base + static_cast<std::uint32_t>(rest.size());
            if (onRing(i, j)) ringVertex.push_back(static_cast<std::uint32_t>(rest.size())), ringRest.emplace_back(ax.lines[i], az.lines[j]);
            rest.emplace_back(ax.lines[i], az.lines[j]);
        }
    const double cell = std::max(ax.lines[1] - ax.lines[0], az.lines[1] - az.lines[0]);
    const ocean::Sea sea = ocean::Sea::fromDef(def.ocean, def.gravity);
    ocean::SurfaceSampling sampling;
    sampling.time = def.time;
    sampling.ramp = def.ramp;
    sampling.stillWaterY = static_cast<double>(def.nearMin.y) + def.ocean.depth;
    const int threads = def.threads > 0 ? def.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<ocean::SurfacePoint> points(rest.size()), ring(ringRest.size());
    ocean::sampleSurface(sea, rest, std::vector<float>(rest.size(), static_cast<float>(cell)), sampling, points, threads);
    sampling.choppy = false;
    ocean::sampleSurface(sea, ringRest, std::vector<float>(ringRest.size(), static_cast<float>(cell)), sampling, ring, threads);
    for (std::size_t r = 0; r < ringVertex.size(); ++r) points[ringVertex[r]] = ring[r];

    SurfaceMesh::Object object;
    object.name = "far_field";
    object.material = 0;  // the ocean's water: the scene's first material
    object.firstTriangle = mesh.triangles.size();
    for (const ocean::SurfacePoint& p : points) mesh.vertices.push_back(p.position);
    auto at = [&](std::size_t i, std::size_t j) { return index[j * nx + i]; };
    for (std::size_t j = 0; j + 1 < nz; ++j)
        for (std::size_t i = 0; i + 1 < nx; ++i) {
            if (i >= ax.first && i < ax.last && j >= az.first && j < az.last) continue;  // over the near field
            // (x, z) → (x, z + dz) → (x + dx, z) faces up (+y).
            mesh.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j)});
            mesh.triangles.push_back({at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)});
        }
    object.triangleCount = mesh.triangles.size() - object.firstTriangle;
    mesh.objects.push_back(std::move(object));
}

}  // namespace tide::io
