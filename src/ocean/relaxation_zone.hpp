#pragma once
/// \file
/// Coupling zones between the far-field sea and the SPH near field (issue 43): on each open
/// side of the domain, a band of width W in which particle velocities relax towards the far
/// field's, an outflow edge where particles leave, and an inflow strip where particles are
/// added wherever the far field's water stands and no particle is.
///
/// The relaxation follows the generating–absorbing zones of Jacobsen, Fuhrman & Fredsøe 2012
/// ("A wave generation toolbox for the open-source CFD library: OpenFoam", Int. J. Numer.
/// Meth. Fluids 70, eq. 10–11: u ← α u_computed + (1 − α) u_target, α_R(χ) = 1 − (exp(χ^p)
/// − 1)/(exp(1) − 1), p = 3.5 there, kRelaxationExponent here), used in SPH by Altomare et al.
/// 2018 (DualSPHysics' relaxation zone, Coastal Engineering 138). Their blend acts once per
/// step, so its strength depends on the step; here it is the exact solution of
/// du/dt = −(u − u_far)/τ over the step,
///   u ← u_far + (u − u_far) exp(−Δt/τ(x)),   1/τ(x) = (1 − α_R(χ)) / τ0,
/// with χ = 1 − s/W (s the distance to the open face: χ = 1 at the outer edge, 0 at the inner)
/// and τ0 = Tp/kRelaxationSteps: the same relaxation whatever the step. A particle in two
/// bands (a corner) takes the nearer face's χ.
///
/// Along the open face, a buffer kBufferSpacings deep has no water beyond it: under the
/// hydrostatic pressure of the water inside, its particles would spill out as a dam breaks.
/// Its particles are driven kinematically instead (an inflow/outflow buffer of prescribed
/// velocity, as Lastiwka, Basa & Quinlan 2009, "Permeable and non-reflecting boundary
/// conditions in SPH", Int. J. Numer. Meth. Fluids 61, and DualSPHysics' open boundaries,
/// Tafuni et al. 2018, do): each step moves them with the far field's velocity, whatever the
/// pressure did, while they still fill the kernel support of the water inside.
///
/// One-way: the far field does not see the near field. It is ramped in over the first peak
/// period (½(1 − cos πt/Tp)), so still water starts smoothly.

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <tide/ocean.hpp>
#include <tide/particles.hpp>

#include "ocean/sea.hpp"
#include "ocean/sea_lattice.hpp"

namespace tide::ocean {

/// τ0 = Tp / this: at the outer edge a particle follows the far field within a twentieth of a
/// period. Stronger relaxation reflects more of what arrives unlike the far field: in issue
/// 43's 2D flume (H 0.16 m, T 2 s, d 0.7 m, zones one wavelength wide) at 3 cm the reflection
/// coefficient was 0.135 / 0.098 / 0.050 / 0.028 / 0.163 at Tp/800, /200, /50, /20, /10 (at
/// /10 too weak, presumably letting the wave through to the outer edge), at 2 cm 0.094 at /200
/// and 0.020 at /20, with the same height past the zone (−6.5 and −6.8 %).
inline constexpr double kRelaxationSteps = 20.0;
/// The exponent p of Jacobsen et al. 2012's weight (exp(χ^p) − 1)/(e − 1); they take 3.5. With
/// 3.5 the relaxation is negligible over the inner ~40 % of the band (1/τ·Tp = 0.09 at χ = ¼,
/// 1.1 at ½), where the generated wave then travels as a free SPH wave and loses height before
/// it leaves the zone. In issue 43's 2D flume (H 0.16 m, T 2 s, d 0.7 m, zones 1 L, 1.6 cm,
/// gauges 0.5–1.5 L, 8 periods), p = 3.5 / 2.5 / 1.5 / 1: height −6.0 / −5.4 / −5.1 / −4.9 %,
/// Kr 0.018 / 0.011 / 0.015 / 0.021, RMS(η − η_far) 3.8 / 3.6 / 3.1 / 2.7 % of H.
inline constexpr double kRelaxationExponent = 1.5;
/// The kinematic buffer along an open face, in spacings (1.5 kernel supports at a support
/// of 2 spacings: the water inside sees full, moving neighbours).
inline constexpr double kBufferSpacings = 3.0;
/// The refill (RelaxationZones::refill) adds a particle at a lattice point of the inflow strips
/// with no particle nearer than this many spacings. Adding only where there is room, and never
/// removing, the strips keep more water or less depending on that distance alone: in issue 43's
/// 2D flume (H 0.16 m, T 2 s, d 0.7 m, 3 cm) the mean level rose by +0.31 H, +0.027 H and
/// −0.080 H over 20 periods at 0.75, 0.9 and 1.0 spacings. So the distance follows the near
/// field's level error e (levelError) about this value, kRefillRoomPerSpacing per spacing of
/// e, within ±kRefillRoomSwing: the water the refill adds balances what leaves.
inline constexpr double kRefillRoomSpacings = 0.9;
inline constexpr double kRefillRoomPerSpacing = 1.0;
inline constexpr double kRefillRoomSwing = 0.1;
/// The far field reaches the particles of the bands through a SeaLattice with columns this
/// many spacings apart and levels half as far (its error against the direct sum:
/// OceanZones.TheLatticeHoldsTheDirectSumsWhereParticlesReadIt).
inline constexpr double kLatticeSpacings = 1.0;
/// The lattice is summed exactly at knots in time and blended between them (SeaLattice::blend)
/// at every step: this many knots a period for the largest component; see knotStep.
inline constexpr double kKnotsPerPeriod = 12.0;

/// The time between the lattice's knots for `sea`, s: the Hermite blend's error for a
/// component, about a (ω Δt)⁴/384, stays within what kKnotsPerPeriod gives the largest
/// component, (2π/12)⁴/384 ≈ 2e-4 of its amplitude, for every component. A spectrum's short
/// components are small (its ω⁻⁵ tail) and need no knots of their own: ocean_pile's sea takes
/// knots further apart than 8 a period of its shortest component did (the first lattice's
/// rule), and its blended error is as small (OceanZones.TheLatticeHoldsTheDirectSums…).
double knotStep(const Sea& sea);

/// Where the near field is: its faces (the planes the walls would stand on), its floor, still
/// water and lattice.
struct NearField {
    glm::vec3 min{0.0f};          ///< faces, m (the open sides' outer edges)
    glm::vec3 max{0.0f};
    double stillWaterY = 0.0;     ///< world y of the sea's still water (floor + depth), m
    float spacing = 0.02f;        ///< the particles' lattice spacing, m
    glm::vec3 latticeOrigin{0.0f};  ///< lattice points at origin + (k + ½) spacing (x and z)
    /// The still water's layers (tide::oceanStillWaterLayers): points at latticeOrigin.y +
    /// (k + ½) layer, whole layers ending at the still water level; the spacing when the depth
    /// is a multiple of it, m.
    double layer = 0.02;
};

/// The coupling zones of one ocean around one near field.
class RelaxationZones {
public:
    /// Throws std::invalid_argument (naming ocean.zone_width) when the zones of an axis do not
    /// fit in the near field side by side.
    RelaxationZones(const OceanDef& def, const NearField& near, double g);

    /// The faces the zones open, as a bit mask (bit 2·axis + 1 for the max side).
    [[nodiscard]] unsigned openFaces() const { return openFaces_; }
    [[nodiscard]] double width() const { return width_; }
    [[nodiscard]] const Sea& sea() const { return sea_; }
    [[nodiscard]] const NearField& nearField() const { return near_; }
    /// The ramp factor of the far field at time t (0 at t = 0, 1 after one peak period).
    [[nodiscard]] double ramp(double t) const;
    /// 1/τ at x: 0 outside the bands, 1/τ0 at the outer edge, 1/s.
    [[nodiscard]] double rate(const glm::vec3& x) const;
    /// The far field's surface (world y) at (x, z), ramped, m.
    [[nodiscard]] double surfaceY(double x, double z, double t) const;
    /// The far field's velocity at a world point, ramped, m/s.
    [[nodiscard]] glm::dvec3 velocity(const glm::vec3& x, double t) const;
    /// Whether x is past an open face (outside the near field through it).
    [[nodiscard]] bool outside(const glm::vec3& x) const;

    /// The far field's velocity at a world point, ramped, from the lattice at time t (what the
    /// particles of the bands see; velocity() is the direct sum), m/s.
    [[nodiscard]] glm::dvec3 latticeVelocity(const glm::vec3& x, double t, int threads = 1);
    /// The lattice of the far field at time t (updated when it holds another time).
    const SeaLattice& lattice(double t, int threads = 1);

    /// Records the particles of the buffers and where they are, before a step.
    void holdBegin(const ParticleStore& particles);
    /// Moves the recorded particles from where they were by dt at the mean of their velocity
    /// then and the far field's at t0 + dt (the trapezoid rule: for a particle held the step
    /// before, the far field's at both ends), and gives them the far field's velocity at
    /// t0 + dt; the step's arrays must be
    /// in the order holdBegin saw. `clockHeld` (a settling pre-roll): the far field of t0.
    void holdEnd(ParticleStore& particles, double t0, double dt, bool clockHeld, int threads);
    /// Relaxes every particle in a band over a step of dt ending at time t (not those of the
    /// buffers: they move with the far field already).
    void relax(ParticleStore& particles, double t, double dt, int threads);
    /// Removes the particles past an open face; returns how many.
    std::uint32_t removeOutflow(ParticleStore& particles);
    /// How far the near field's water stands above the far field's at time t, m, from the
    /// particles it has exchanged with the sea (`exchanged`: added − removed since the start,
    /// every rank's): each is a cell of the still water's lattice (spacing × layer × spacing;
    /// in 2D spacing × layer), against the far field's mean elevation over the near field
    /// (Sea::meanElevation, ramped). The near field keeps the water it started with.
    [[nodiscard]] double levelError(std::int64_t exchanged, double t) const;
    /// The distance, in spacings, within which a particle takes a lattice point's room from
    /// the refill, for a level error (levelError): kRefillRoomSpacings, more when the near
    /// field holds too much water, less when too little (see there).
    [[nodiscard]] double refillRoom(double levelError) const;
    /// Adds a particle (far-field velocity, given mass and rest density) at each lattice point
    /// of the inflow strips that lies under the far field's surface, has room (`room`: the
    /// solids) and has no particle within refillRoom(levelError) spacings; at most `capacity`
    /// particles in all.
    /// Returns how many. Two lattice points are a spacing apart, so one added never blocks
    /// another: a split run's rank decides the points in its own cells (`room` says which)
    /// from its particles and ghosts, and `visits` (when given) receives each added point's
    /// number in the visiting order, which is the same on every rank (the ids' global order).
    std::uint32_t refill(ParticleStore& particles, double t, double levelError, float mass, MaterialIndex material,
                         float restDensity,
                         std::uint32_t capacity, const std::function<bool(const glm::vec3&)>& room, int threads = 1,
                         std::vector<std::uint64_t>* visits = nullptr);

private:
    // 1/τ at a distance s inward from the nearest open face.
    [[nodiscard]] double rateAt(double s) const;
    // Distance from x to the nearest open face, inward; +inf with no open face.
    [[nodiscard]] double distanceToOpenFace(const glm::vec3& x) const;
    // The far field's velocity at a world point from a lattice, ramped by r.
    [[nodiscard]] glm::dvec3 velocityFrom(const SeaLattice& lattice, const glm::vec3& x, double r) const;

    Sea sea_;
    NearField near_;
    std::vector<OceanSide> sides_;
    unsigned openFaces_ = 0;
    glm::dvec2 faceLow_{0.0}, faceHigh_{0.0};  // (x, z) of the open faces; ∓inf where closed
    double width_ = 0.0;
    double rampTime_ = 0.0;
    double tau0_ = 0.0;
    std::vector<std::uint8_t> keep_;  // scratch of removeOutflow
    std::vector<std::uint32_t> held_;  // the buffers' particles at the step's start
    std::vector<glm::vec3> heldFrom_;
    std::vector<glm::vec3> heldVelocity_;
    std::vector<std::vector<std::uint8_t>> taken_;  // scratch of refill: per side, its strip's points with no room
    std::optional<SeaLattice> lattice_;  // the far field for the bands, at the last time asked
    std::vector<SeaLattice> knots_;      // two exact lattices at knots in time, with rates
    double knotStep_ = 1.0;
};

}  // namespace tide::ocean
