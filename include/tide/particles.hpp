#pragma once
/// \file
/// The particle store: one structure of arrays for every material.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include <tide/defs.hpp>

namespace tide {

/// All fluid particles, structure of arrays, 32-bit indices.
///
/// Every array has size(); reordering (by grid cell, for cache locality) applies one
/// permutation to all of them, so `id` is the way to follow a particle over time.
/// Later work appends halo particles (owned by another process) after the owned ones.
class ParticleStore {
public:
    std::vector<glm::vec3> position;      ///< m
    std::vector<glm::vec3> velocity;      ///< m/s
    std::vector<glm::vec3> acceleration;  ///< m/s², of the last step
    std::vector<float> density;           ///< kg/m³
    std::vector<float> pressure;          ///< Pa
    std::vector<float> mass;              ///< kg
    // Solver state carried from step to step (warm starts of the pressure solves):
    std::vector<float> warmKappa;         ///< κ = p/ρ the last density solve ended with, m²/s²
    std::vector<float> warmDivergence;    ///< κᵛΔt the last divergence solve ended with, m²/s
    std::vector<MaterialIndex> material;
    /// Dye concentration, a passive scalar (0 = clear) carried by each particle and spread
    /// between miscible materials (MaterialPairDef); mass-weighted Σ m c is conserved.
    std::vector<float> concentration;
    std::vector<std::uint32_t> id;        ///< stable identity, unchanged by reordering

    /// Number of particles.
    [[nodiscard]] std::uint32_t size() const { return static_cast<std::uint32_t>(position.size()); }
    [[nodiscard]] bool empty() const { return position.empty(); }

    /// Reserve room for n particles in every array.
    void reserve(std::uint32_t n);
    /// Room for `more` particles beyond size() in every array, growing by an eighth at least
    /// rather than doubling as append alone would (a 50,653-particle block left a quarter of
    /// every array unused).
    void makeRoomFor(std::uint32_t more);
    /// Append one particle at rest pressure with dye concentration `c`; its id is the next free id.
    void append(const glm::vec3& x, const glm::vec3& v, float m, MaterialIndex mat, float rho0, float c = 0.0f);
    /// Reorder every array so that new[k] = old[order[k]]; order is a permutation of [0, size()).
    void permute(std::span<const std::uint32_t> order);
    /// Keep the particles whose keep[i] is non-zero, in their order, and drop the others
    /// (an open boundary's outflow). keep has size().
    void retain(std::span<const std::uint8_t> keep);
    /// Drop every particle.
    void clear();
    /// Calls f(array) for every per-particle array above, in this fixed order: the one list
    /// of the fields (reserve, retain, permute, clear and the records sent to other
    /// processes walk it), so a new field is added here and in `append`.
    template <class F>
    void forEachArray(F&& f) {
        visitArrays(*this, f);
    }
    template <class F>
    void forEachArray(F&& f) const {
        visitArrays(*this, f);
    }

    /// The id the next appended particle gets.
    [[nodiscard]] std::uint32_t nextId() const { return nextId_; }
    /// Continue numbering at `next` (restoring a saved store; must exceed every id in it).
    void setNextId(std::uint32_t next) { nextId_ = next; }

private:
    template <class Self, class F>
    static void visitArrays(Self& self, F& f) {
        f(self.position);
        f(self.velocity);
        f(self.acceleration);
        f(self.density);
        f(self.pressure);
        f(self.mass);
        f(self.warmKappa);
        f(self.warmDivergence);
        f(self.material);
        f(self.concentration);
        f(self.id);
    }

    std::uint32_t nextId_ = 0;
};

}  // namespace tide
