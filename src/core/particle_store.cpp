#include <tide/particles.hpp>

#include <algorithm>
#include <cassert>

namespace tide {

void ParticleStore::reserve(std::uint32_t n) {
    forEachArray([n](auto& values) { values.reserve(n); });
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
    forEachArray([keep](auto& values) { retainIn(values, keep); });
}

void ParticleStore::permute(std::span<const std::uint32_t> order) {
    assert(order.size() == size());
    std::vector<bool> placed;
    forEachArray([&](auto& values) { permuteInPlace(values, order, placed); });
}

void ParticleStore::clear() {
    forEachArray([](auto& values) { values.clear(); });
    nextId_ = 0;
}

}  // namespace tide
