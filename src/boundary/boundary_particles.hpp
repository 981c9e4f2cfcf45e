#pragma once
/// \file
/// Static boundary particles: walls sampled as particles that take part in the fluid's
/// SPH sums (Akinci, Ihmsen, Akinci, Solenthaler & Teschner 2012, "Versatile rigid-fluid
/// coupling for incompressible SPH"). A boundary particle b adds ρ0_i V_b W_ib to the
/// density of fluid particle i (eq. 4 with Ψ_b = ρ0_i V_b) and mirrors i's pressure in the
/// pressure force (p_b = p_i, ρ_b = ρ0_i).
///
/// The container's walls are a shell of whole lattice layers, thick enough to cover the
/// kernel support, continuing the fluid's own lattice beyond each wall. A shell of full
/// thickness is a complete lattice, so each particle's volume is simply that of a lattice
/// particle (Akinci's per-particle volume correction is for single-layer sampling);
/// a block of fluid resting against a wall, edge or corner then has exactly rest density.
///
/// A periodic axis has no walls across it: the shell leaves out those two faces, and the
/// remaining walls run through the period on the same stretched lattice, so the lattice
/// continues across the seam without a gap or a double layer.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/periodic_box.hpp"
#include "neighbors/neighbor_list.hpp"
#include "neighbors/uniform_grid.hpp"

namespace tide {

class BoundaryParticles {
public:
    /// Sample the walls of the box [min, max] with a shell `layers` deep at `spacing`;
    /// every particle gets `volume` (m³). No walls across the axes that `periodic` wraps,
    /// nor across z in 2D (`dimensions` 2: the x and y faces as lines of particles in z = min.z).
    /// Faces in `openFaces` (bit 2·axis + 1 on the max side, as the wall solids count them) get
    /// no particles, nor does anything of the shell beyond them (an ocean's open sides).
    void sampleBoxShell(const glm::vec3& min, const glm::vec3& max, float spacing, int layers, float volume,
                        float searchRadius, int threads, unsigned openFaces = 0, int dimensions = 3);

    /// Add more boundary particles (an obstacle), each of `volume` m³, and rebuild the grid.
    /// Points closer than `minSeparation` to an existing boundary particle are left out:
    /// where solids overlap (an obstacle and the wall shell, two obstacles) their union is
    /// sampled once, not twice. Returns how many were added.
    /// They belong to solid `solidIndex` (see `solid`).
    std::uint32_t add(std::span<const glm::vec3> points, float volume, float minSeparation, float searchRadius,
                      int threads, std::uint16_t solidIndex = 0);

    /// Add the particles of a moving boundary (a paddle, a moving obstacle), each of `volume`
    /// m³, all of them: they do not coincide with the fixed ones for long. Their positions are
    /// the World's to set every step. Returns the index of the first one.
    std::uint32_t addMoving(std::span<const glm::vec3> points, float volume, std::uint16_t solidIndex = 0);

    /// Whether a boundary particle lies closer than `radius` (at most the grid's cell size)
    /// to x; with `fixedOnly`, a fixed one. Reads the grid as last built.
    [[nodiscard]] bool anyCloserThan(const glm::vec3& x, float radius, bool fixedOnly = false) const;

    [[nodiscard]] std::uint32_t size() const { return static_cast<std::uint32_t>(position.size()); }

    std::vector<glm::vec3> position;  ///< m
    /// V_b, m³: one for every boundary particle, as all of them sample the fluid's lattice (an
    /// array of it cost 4 B a boundary particle, ~11 B a fluid particle in the 50k benchmark).
    float volume = 0.0f;
    /// Velocity and acceleration of each boundary particle (zero for walls at rest). Moving
    /// boundaries (paddles, moving obstacles) set them every step; solvers read them only when
    /// `moving`. Empty while nothing moves: fixed walls would spend 24 B a particle on zeros.
    std::vector<glm::vec3> velocity;      ///< v_b, m/s
    std::vector<glm::vec3> acceleration;  ///< a_b, m/s²
    bool moving = false;                  ///< whether any boundary particle moves
    /// The solid each particle samples, whose load it counts towards (World::solidLoads): the
    /// container shell's particles its faces, kWallFace + 2·axis (+1 on the max side), the
    /// outermost distance deciding in edges and corners (ties to x, then z, then y: the side
    /// walls own the floor's edges); added ones the index they were added with. Where solids
    /// overlap, the one sampled first keeps the shared particles.
    std::vector<std::uint16_t> solid;
    static constexpr std::uint16_t kWallFace = 0;  ///< solid of the −x face; −y is 2, +z is 5
    std::vector<std::uint8_t> movable;    ///< 1 for particles of moving boundaries
    float maxSpeed = 0.0f;                ///< largest |v_b|, m/s (set with the velocities)
    UniformGrid grid;                 ///< rebuilt whenever boundary particles move
    PeriodicBox periodic;             ///< the domain's periodic axes (set before sampling): the grid wraps there

private:
    /// Takes `particleVolume` as every particle's; throws std::invalid_argument if particles of
    /// another volume are already there.
    void setVolume(float particleVolume);
};

}  // namespace tide
