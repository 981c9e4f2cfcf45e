#pragma once
/// \file
/// A wave paddle: a slab of boundary particles at one end of a flume, moved by a prescribed
/// motion from linear wavemaker theory (sources/wave_theory.hpp).
///
/// The paddle is ceil(h/s) lattice layers thick behind its face (a complete kernel support,
/// like the wall shell) and spans the domain from the floor to the top and across z. Each
/// step the World places its particles at the pose of the step's start time and gives them
/// the paddle's velocity and acceleration, which the solvers use as a moving wall: the
/// density rate sees (v_i − v_b), no-slip viscosity mirrors 2v_b − v_i, the wall pressure of
/// Adami et al. 2012 (eq. 27) takes g − a_b, and dfsph's predicted density x_b + Δt v_b.
/// After the step, particles that slipped behind the face (at the pose of the step's end)
/// are put back in front of it, losing their velocity into the paddle relative to it.
///
/// Piston (and solitary: a piston on Goring's 1978 trajectory): the face translates by X(t) along x. Flap: the paddle rotates about a hinge on the
/// floor at the face by θ = X(t)/d (X the stroke at the still-water level; the small-angle
/// form, as the linear theory assumes). X(t) = ramp(t) Σ_n A_n sin(ω_n t + φ_n).

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include <tide/defs.hpp>
#include <tide/particles.hpp>

#include "core/periodic_box.hpp"
#include "sources/wave_theory.hpp"

namespace tide {

/// Throws std::invalid_argument naming the field (wavemaker.period, .wave_height, .order, ...)
/// and its value for a wave the tank cannot hold: longer than the tank's `length` in front of
/// the paddle (it could never run as a progressive wave), shorter than kMinSpacingsPerWave
/// spacings or lower than kMinSpacingsPerHeight (the particles cannot resolve it), steeper
/// than the breaking limit H/λ = 1/7 (Michell 1893) or, for a solitary wave, H/d above 0.6
/// (Goring's trajectory is valid to about there); an order other than 1 or 2, or 2 where
/// only the piston's regular waves have it.
void checkWaveFitsTank(const WaveMakerDef& def, float length, float spacing, double g);

/// Throws std::invalid_argument naming domain.max[1] when the domain's top stands less than
/// the waves' crest height (wave_height, or spectrum.hs) above the paddle's still water
/// (`headroom`, m): a lid that clips every crest (the ocean's check, World::setOcean).
void checkRoomAboveWaves(const WaveMakerDef& def, double headroom);

/// Fewest particle spacings a wave length may span, and a wave height.
inline constexpr double kMinSpacingsPerWave = 10.0;
inline constexpr double kMinSpacingsPerHeight = 0.5;

class WaveMaker {
public:
    /// `floor` is the y of the bed (the flap's hinge); g the magnitude of gravity.
    WaveMaker(const WaveMakerDef& def, float floor, double g);

    /// Displacement of the face at the still-water level X(t), m, and its two time derivatives.
    struct Motion {
        double x, v, a;
    };
    [[nodiscard]] Motion motion(double t) const;

    /// Lattice points of the paddle at rest: `layers` layers behind the face, the domain's
    /// lattice in y (from the floor up) and z (stretched to the width, as the wall shell is).
    [[nodiscard]] std::vector<glm::vec3> sample(const glm::vec3& domainMin, const glm::vec3& domainMax, float spacing,
                                                int layers) const;

    /// Positions, velocities and accelerations at time t of particles whose rest positions are `rest`.
    void place(double t, std::span<const glm::vec3> rest, std::span<glm::vec3> position, std::span<glm::vec3> velocity,
               std::span<glm::vec3> acceleration) const;

    /// The face at time t: for many points at one time, the stroke summed once (an irregular
    /// sea's second-order stroke has hundreds of components).
    struct Face {
        glm::vec3 point, normal;  ///< a point on the face; its normal, into the fluid
        /// Distance of x in front of the face (negative behind it), m.
        [[nodiscard]] float distanceInFront(const glm::vec3& x) const {
            return (x.x - point.x) * normal.x + (x.y - point.y) * normal.y;
        }
    };
    [[nodiscard]] Face face(double t) const;
    /// Distance of x in front of the face at time t (negative behind it), m.
    [[nodiscard]] float distanceInFront(double t, const glm::vec3& x) const { return face(t).distanceInFront(x); }

    /// Puts particles behind the face at time t back `margin` in front of it, without
    /// velocity into the paddle relative to it.
    void project(double t, ParticleStore& particles, float margin, int threads) const;

    /// A correction added to the prescribed stroke (active absorption, piston):
    /// X(t) += offset + velocity (t − since), constant in velocity over a step.
    struct Correction {
        double offset = 0.0, velocity = 0.0, since = 0.0;
        [[nodiscard]] double at(double t) const { return offset + velocity * (t - since); }
    };
    void setCorrection(const Correction& c) { correction_ = c; }
    [[nodiscard]] const Correction& correction() const { return correction_; }

    [[nodiscard]] const WaveMakerDef& def() const { return def_; }
    [[nodiscard]] const std::vector<waves::PaddleComponent>& components() const { return components_; }

private:
    /// The face at time t: a point on it, its normal (into the fluid), and the paddle's
    /// rotation angle and its rates (flap) or translation (piston).
    struct Pose {
        glm::vec3 point, normal;
        Motion m;
        double angle, rate, angularAcceleration;
    };
    [[nodiscard]] Pose pose(double t) const;

    WaveMakerDef def_;
    glm::vec3 hinge_;
    std::optional<waves::SolitaryStroke> solitary_;
    std::vector<waves::PaddleComponent> components_;
    Correction correction_;
};

}  // namespace tide
