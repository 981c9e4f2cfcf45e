#include <tide/particles.hpp>

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
template <class T>
void permuteArray(std::vector<T>& values, std::span<const std::uint32_t> order, std::vector<T>& scratch) {
    scratch.resize(values.size());
    for (std::size_t k = 0; k < order.size(); ++k) scratch[k] = values[order[k]];
    values.swap(scratch);
}
}  // namespace

void ParticleStore::permute(std::span<const std::uint32_t> order) {
    assert(order.size() == size());
    {
        std::vector<glm::vec3> scratch;
        permuteArray(position, order, scratch);
        permuteArray(velocity, order, scratch);
        permuteArray(acceleration, order, scratch);
    }
    {
        std::vector<float> scratch;
        permuteArray(density, order, scratch);
        permuteArray(pressure, order, scratch);
        permuteArray(mass, order, scratch);
        permuteArray(warmKappa, order, scratch);
        permuteArray(warmDivergence, order, scratch);
        permuteArray(concentration, order, scratch);
    }
    std::vector<MaterialIndex> materialScratch;
    permuteArray(material, order, materialScratch);
    std::vector<std::uint32_t> idScratch;
    permuteArray(id, order, idScratch);
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
