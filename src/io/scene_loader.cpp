// Scene files: reading, size estimates and turning a Scene into a World.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
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

namespace {
/// ⌊end_time · fps⌋; the margin keeps an end time that is a whole number of frames in decimal
/// (0.3 s at 10 fps) from losing its last frame to rounding.
double frameCount(const Scene& scene) { return std::floor(scene.endTime * scene.output.fps + 1e-9); }
}  // namespace

int framesAfterTheFirst(const Scene& scene) { return static_cast<int>(std::clamp(frameCount(scene), 0.0, kMaxFrames)); }

std::string endTimeProblem(const Scene& scene) {
    const double frames = frameCount(scene);
    std::ostringstream msg;
    if (frames < 1.0)
        msg << scene.endTime << " s is shorter than one frame at output.fps " << scene.output.fps << " ("
            << 1.0 / scene.output.fps << " s): nothing would be simulated";
    else if (frames > kMaxFrames)
        msg << scene.endTime << " s at output.fps " << scene.output.fps << " is " << frames << " frames, more than the "
            << kMaxFrames << " a run may write";
    return msg.str();
}

std::string endTimeBetweenFrames(const Scene& scene) {
    const int frames = framesAfterTheFirst(scene);
    const double last = frames / scene.output.fps;
    if (frames == 0 || scene.endTime - last <= 1e-9 * std::max(1.0, scene.endTime)) return {};
    std::ostringstream msg;
    msg << scene.endTime << " s is not a whole number of frames at output.fps " << scene.output.fps
        << ": the run stops at frame " << frames << ", t = " << last << " s";
    return msg.str();
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

namespace {
constexpr std::uint64_t kMaxCount = std::numeric_limits<std::uint64_t>::max();
/// A non-negative double as a count, saturating at 2^64 − 1 (the plain cast is undefined there).
std::uint64_t saturatingCount(double x) {
    return !(x < 1.8e19) ? kMaxCount : static_cast<std::uint64_t>(std::max(x, 0.0));
}
std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b) { return a > kMaxCount - b ? kMaxCount : a + b; }
}  // namespace

std::string memoryShortfall(const Scene& scene) {
    const SceneEstimate size = estimate(scene);
    const std::uint64_t available = availableMemoryBytes();
    if (size.bytes <= available) return {};
    std::ostringstream msg;
    msg << "the scene needs about " << size.totalParticles << " particles and " << (size.bytes >> 20)
        << " MiB, more than the " << (available >> 20) << " MiB this machine has free";
    return msg.str();
}

SceneEstimate estimate(const Scene& scene) {
    SceneEstimate e;
    e.initialParticles.assign(scene.materials.size(), 0);
    e.emittedParticles.assign(scene.materials.size(), 0);
    const float s = scene.world.particleSpacing;
    glm::vec3 latticeOrigin = scene.world.domainMin;  // as World::addBlock fills (buildWorld)
    if (!scene.waveMakers.empty()) latticeOrigin.x = scene.waveMakers.front().x;
    for (const BlockDef& b : scene.blocks)
        e.initialParticles[b.material] =
            saturatingAdd(e.initialParticles[b.material], Lattice::onDomainLattice(b.min, b.max, s, latticeOrigin).size());
    // An ocean's still water (World::fillOcean; the inflow keeps the count near it).
    if (scene.ocean && !scene.materials.empty()) {
        glm::vec3 top = scene.world.domainMax;
        top.y = scene.world.domainMin.y + s;  // one layer: the columns across
        const double columns = static_cast<double>(Lattice::onDomainLattice(scene.world.domainMin, top, s, latticeOrigin).size());
        e.initialParticles[0] = saturatingAdd(
            e.initialParticles[0], saturatingCount(columns * oceanStillWaterLayers(scene.ocean->depth, s)));
    }
    for (const EmitterDef& em : scene.emitters) {
        const double active = std::min(em.end, scene.endTime) - em.start;
        if (active <= 0.0) continue;
        // In double, saturating: a fast jet over a long end time overflows 64 bits (a fuzzed
        // scene did: the cast's result was undefined and the estimate said 8 particles).
        const double layers = std::floor(glm::length(em.velocity) * active / s) + 1.0;
        const double emitted = layers * static_cast<double>(Lattice(em.min, em.max, s).size());
        e.emittedParticles[em.material] = saturatingAdd(e.emittedParticles[em.material], saturatingCount(emitted));
    }
    for (std::size_t m = 0; m < scene.materials.size(); ++m)
        e.totalParticles = saturatingAdd(e.totalParticles, saturatingAdd(e.initialParticles[m], e.emittedParticles[m]));
    // Boundary particles: the container's shell, a few layers deep, ~40 bytes each.
    const glm::vec3 extent = (scene.world.domainMax - scene.world.domainMin) / s;
    const double faces = scene.world.dimensions == 2
                             ? double{extent.x} + extent.y  // 2D: the shell is the x and y faces' lines
                             : double{extent.x} * extent.y + double{extent.y} * extent.z + double{extent.z} * extent.x;
    const double shell = 2.0 * faces * std::ceil(scene.world.supportRatio);
    e.bytes = saturatingCount(static_cast<double>(e.totalParticles) * kBytesPerParticle + shell * 40.0);
    return e;
}

World buildWorld(const Scene& scene) {
    World world(scene.world);
    for (const MaterialDef& m : scene.materials) world.addMaterial(m);
    for (const MaterialPairDef& pair : scene.materialPairs) world.setMaterialPair(pair);
    // The wave maker first: obstacles and blocks are sampled on a lattice that starts at its face.
    for (const WaveMakerDef& w : scene.waveMakers) world.addWaveMaker(w);
    // The ocean opens its sides before obstacles are sampled, and fills its still water after.
    if (scene.ocean) world.setOcean(*scene.ocean);
    for (const ObstacleDef& o : scene.obstacles) world.addObstacle(o);
    for (const DampingZoneDef& d : scene.dampingZones) world.addDampingZone(d);
    if (scene.ocean && world.fillOcean() != AddStatus::Added)
        throw SceneError({"ocean: its still water does not fit (over capacity)"});
    for (std::size_t i = 0; i < scene.blocks.size(); ++i)
        if (world.addBlock(scene.blocks[i]) != AddStatus::Added)
            throw SceneError({"blocks[" + std::to_string(i) + "]: does not fit (outside the domain or over capacity)"});
    for (const EmitterDef& e : scene.emitters) world.addEmitter(e);
    return world;
}

World buildSettledWorld(const Scene& scene) {
    World world = buildWorld(scene);
    if (scene.settleTime > 0.0) world.settle(scene.settleTime, scene.settleSpeed);
    return world;
}

}  // namespace tide::io
