// Scene files: reading, size estimates and turning a Scene into a World.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include <glm/geometric.hpp>

#include <tide/io/scene.hpp>

#include "sources/lattice.hpp"

namespace tide::io {

Scene loadScene(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw SceneError({file.string() + ": cannot open the scene file"});
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw SceneError({file.string() + ": cannot read the scene file"});
    return parseScene(text.str(), file.string(), file.parent_path());
}

std::uint64_t availableMemoryBytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    std::uint64_t kib = 0;
    std::string unit;
    while (meminfo >> key >> kib >> unit)
        if (key == "MemAvailable:") return kib * 1024;
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long size = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && size > 0 ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(size) : ~0ull;
}

SceneEstimate estimate(const Scene& scene) {
    SceneEstimate e;
    e.initialParticles.assign(scene.materials.size(), 0);
    e.emittedParticles.assign(scene.materials.size(), 0);
    const float s = scene.world.particleSpacing;
    for (const BlockDef& b : scene.blocks) e.initialParticles[b.material] += Lattice(b.min, b.max, s).size();
    for (const EmitterDef& em : scene.emitters) {
        const double active = std::min(em.end, scene.endTime) - em.start;
        if (active <= 0.0) continue;
        const double layers = std::floor(glm::length(em.velocity) * active / s) + 1.0;
        e.emittedParticles[em.material] += static_cast<std::uint64_t>(layers) * Lattice(em.min, em.max, s).size();
    }
    for (std::size_t m = 0; m < scene.materials.size(); ++m)
        e.totalParticles += e.initialParticles[m] + e.emittedParticles[m];
    // Boundary particles: the container's shell, a few layers deep, ~40 bytes each.
    const glm::vec3 extent = (scene.world.domainMax - scene.world.domainMin) / s;
    const double shell = 2.0 * (double{extent.x} * extent.y + double{extent.y} * extent.z + double{extent.z} * extent.x) *
                         std::ceil(scene.world.supportRatio);
    e.bytes = e.totalParticles * kBytesPerParticle + static_cast<std::uint64_t>(shell * 40.0);
    return e;
}

World buildWorld(const Scene& scene) {
    World world(scene.world);
    for (const MaterialDef& m : scene.materials) world.addMaterial(m);
    for (const MaterialPairDef& pair : scene.materialPairs) world.setMaterialPair(pair);
    for (const ObstacleDef& o : scene.obstacles) world.addObstacle(o);
    for (const WaveMakerDef& w : scene.waveMakers) world.addWaveMaker(w);
    for (const DampingZoneDef& d : scene.dampingZones) world.addDampingZone(d);
    for (std::size_t i = 0; i < scene.blocks.size(); ++i)
        if (world.addBlock(scene.blocks[i]) != AddStatus::Added)
            throw SceneError({"blocks[" + std::to_string(i) + "]: does not fit (outside the domain or over capacity)"});
    for (const EmitterDef& e : scene.emitters) world.addEmitter(e);
    return world;
}

}  // namespace tide::io
