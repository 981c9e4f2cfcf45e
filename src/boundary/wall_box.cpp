#include "boundary/wall_box.hpp"

#include "core/parallel.hpp"

namespace tide {

void WallBox::enforce(ParticleStore& particles, int threads) const {
    const glm::vec3 lo = min + glm::vec3(margin);
    const glm::vec3 hi = max - glm::vec3(margin);
    parallelFor(particles.size(), threads, [&](std::uint32_t i) {
        glm::vec3& x = particles.position[i];
        glm::vec3& v = particles.velocity[i];
        for (int axis = 0; axis < 3; ++axis) {
            if (x[axis] < lo[axis]) {
                x[axis] = lo[axis];
                if (v[axis] < 0.0f) v[axis] *= -restitution;
            } else if (x[axis] > hi[axis]) {
                x[axis] = hi[axis];
                if (v[axis] > 0.0f) v[axis] *= -restitution;
            }
        }
    });
}

}  // namespace tide
