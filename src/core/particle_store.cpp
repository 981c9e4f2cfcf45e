#include <tide/particles.hpp>

#include <algorithm>
#include <cassert>

namespace tide {

void ParticleStore::reserve(std::uint32_t n) {
    position.reserve(n);
    velocity.reserve(n);
    acceleration.reserve(n);
    density.reserve(n);
    pressure.reserve(n);
    mass.reserve(n);
    warmKappa.reserve(n);
    warmDivergence.reserve(n);
    material.reserve(n);
    concentration.reserve(n);
    id.reserve(n);
}

void ParticleStore::makeRoomFor(std::uint32_t more) {
    const std::size_t needed = std::size_t{size()} + more;
    if (needed <= position.capacity()) return;
    const std::size_t grown = std::max(needed, position.capacity() + position.capacity() / 8);
    reserve(static_cast<std::uint32_t>(std::min<std::size_t>(grown, 0xffffffffu)));
}

void ParticleStore::append(const glm::vec3& x, const glm::vec3& v, float m, MaterialIndex mat, float rho0, float c) {
    position.push_back(x);
    velocity.push_back(v);
    acceleration.emplace_back(0.0f);
    density.push_back(rho0);
    pressure.push_back(0.0f);
    mass.push_back(m);
    warmKappa.push_back(0.0f);
    warmDivergence.push_back(0.0f);
    material.push_back(mat);
    concentration.push_back(c);
    id.push_back(nextId_++);
}

namespace {
/// new[k] = old[order[k]] in place, cycle by cycle: a copy of the array was the re-sorting
/// step's extra memory (12 bytes a particle for the positions).
template <class T>
void permuteInPlace(std::vector<T>& values, std::span<const std::uint32_t> order, std::vector<bool>& placed) {
    placed.assign(values.size(), false);
    for (std::size_t start = 0; start < values.size(); ++start) {
        if (placed[start]) continue;
        T first = values[start];
        std::size_t k = start;
        for (;;) {
            placed[k] = true;
            const std::size_t from = order[k];
            if (from == start) break;
            values[k] = values[from];
            k = from;
        }
        values[k] = first;
    }
}
}  // namespace

namespace {
template <class T>
void retainIn(std::vector<T>& values, std::span<const std::uint8_t> keep) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < values.size(); ++i)
        if (keep[i]) values[kept++] = values[i];
    values.resize(kept);
}
}  // namespace

void ParticleStore::retain(std::span<const std::uint8_t> keep) {
    assert(keep.size() == size());
    retainIn(position, keep);
    retainIn(velocity, keep);
    retainIn(acceleration, keep);
    retainIn(density, keep);
    retainIn(pressure, keep);
    retainIn(mass, keep);
    retainIn(warmKappa, keep);
    retainIn(warmDivergence, keep);
    retainIn(concentration, keep);
    retainIn(material, keep);
    retainIn(id, keep);
}

void ParticleStore::permute(std::span<const std::uint32_t> order) {
    assert(order.size() == size());
    std::vector<bool> placed;
    permuteInPlace(position, order, placed);
    permuteInPlace(velocity, order, placed);
    permuteInPlace(acceleration, order, placed);
    permuteInPlace(density, order, placed);
    permuteInPlace(pressure, order, placed);
    permuteInPlace(mass, order, placed);
    permuteInPlace(warmKappa, order, placed);
    permuteInPlace(warmDivergence, order, placed);
    permuteInPlace(concentration, order, placed);
    permuteInPlace(material, order, placed);
    permuteInPlace(id, order, placed);
}

void ParticleStore::clear() {
    position.clear();
    velocity.clear();
    acceleration.clear();
    density.clear();
    pressure.clear();
    mass.clear();
    warmKappa.clear();
    warmDivergence.clear();
    material.clear();
    concentration.clear();
    id.clear();
    nextId_ = 0;
}

}  // namespace tide
