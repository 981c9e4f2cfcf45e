// Snapshot of a World, copied between steps.
#include <tide/render/snapshot.hpp>

namespace tide::render {

void takeSnapshot(const World& world, Snapshot& out) {
    const ParticleStore& p = world.particles();
    out.position.assign(p.position.begin(), p.position.end());
    out.velocity.assign(p.velocity.begin(), p.velocity.end());
    out.density.assign(p.density.begin(), p.density.end());
    out.pressure.assign(p.pressure.begin(), p.pressure.end());
    out.material.assign(p.material.begin(), p.material.end());
    out.materials.clear();
    for (const MaterialDef& m : world.materials()) out.materials.push_back({m.name, m.color, m.restDensity});
    out.obstacles = world.obstacles();
    out.obstaclePoses.clear();
    for (std::uint32_t k = 0; k < out.obstacles.size(); ++k) out.obstaclePoses.push_back(world.obstaclePose(k, world.time()));
    out.domainMin = world.def().domainMin;
    out.domainMax = world.def().domainMax;
    out.particleSpacing = world.def().particleSpacing;
    out.time = world.time();
    out.gravity = world.def().gravity;
    out.ocean = world.ocean();
    out.oceanRamp = world.oceanRamp();
    out.stats = world.stats();
    ++out.version;
}

}  // namespace tide::render
