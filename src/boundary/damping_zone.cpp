#include "boundary/damping_zone.hpp"

#include <algorithm>

#include "core/parallel.hpp"

namespace tide {

void applyDampingZones(std::span<const DampingZoneDef> zones, ParticleStore& particles, double dt, int threads) {
    for (const DampingZoneDef& zone : zones) {
        const float length = zone.xEnd - zone.xStart;
        const float rate = static_cast<float>(zone.strength * dt);
        parallelFor(particles.size(), threads, [&](std::uint32_t i) {
            const float s = (particles.position[i].x - zone.xStart) / length;
            if (s <= 0.0f) return;
            const float clamped = std::min(s, 1.0f);
            particles.velocity[i] *= std::max(0.0f, 1.0f - rate * clamped * clamped);
        });
    }
}

}  // namespace tide
