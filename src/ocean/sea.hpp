#pragma once
/// \file
/// The far-field sea: a linear (Airy) superposition of wave components on finite depth,
/// evaluated by direct summation at any point and time.
///
/// Coordinates are tide's: y up, still water at y = 0, the floor at y = −d, the surface the
/// x–z plane. A component of amplitude a, wave vector k = k (cos β, sin β) (β from +x towards +z)
/// and phase φ has the phase θ = kx x + kz z − ω t + φ and, with ω² = g k tanh(kd)
/// (small-amplitude wave theory; Dean & Dalrymple 1991, "Water wave mechanics for engineers and
/// scientists", ch. 3–4):
///   η = a cos θ
///   u_h = a ω cosh(k(y+d))/sinh(kd) cos θ · k/|k|          (horizontal, along the wave)
///   v   = a ω sinh(k(y+d))/sinh(kd) sin θ                   (vertical)
///   p   = ρ g a cosh(k(y+d))/cosh(kd) cos θ − ρ g y          (dynamic + hydrostatic)
/// The hyperbolic ratios are evaluated as exponentials, so deep water does not overflow.
///
/// Above still water the linear field is extended by Wheeler stretching (Wheeler 1970,
/// "Method for calculating forces produced by irregular waves", J. Petroleum Technology 22(3)):
/// a point at height y under the local surface η is evaluated at y' = d (y + d)/(d + η) − d,
/// so the surface maps to y' = 0 and the floor to itself; the pressure at the surface is then
/// exactly 0. Stretching is applied over the whole column, as Wheeler (and DNV-RP-C205
/// describe it) do; the unstretched linear field (Stretching::None) is exactly divergence-free and
/// satisfies the linear surface conditions at y = 0.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <tide/ocean.hpp>

#include "ocean/dispersion.hpp"

namespace tide::ocean {

/// One wave: η = a cos(kx x + kz z − ω t + φ). A free linear wave's ω satisfies the dispersion
/// relation on the sea's depth and its velocity amplitude is a ω; a bound harmonic of a
/// nonlinear wave (ocean/stokes_wave_fenton1985.hpp) has its own ω and `velocity` V, in
/// u_h = V cosh(k(y+d))/sinh(kd) cos θ, v = V sinh(k(y+d))/sinh(kd) sin θ.
struct WaveComponent {
    double amplitude = 0.0;  ///< a, m
    double omega = 0.0;      ///< ω, rad/s
    double kx = 0.0;         ///< wave vector along x, rad/m
    double kz = 0.0;         ///< wave vector along z, rad/m
    double phase = 0.0;      ///< φ, rad
    bool bound = false;      ///< a harmonic of a nonlinear wave: ω and `velocity` as given
    double velocity = 0.0;   ///< V of a bound harmonic, m/s (a free wave's is a ω)
};

/// How kinematics are evaluated away from still water.
enum class Stretching {
    None,     ///< the linear field at the point itself (grows exponentially above y = 0)
    Wheeler,  ///< Wheeler 1970: the column from the floor to η mapped onto the floor to 0
    /// The field at the point itself up to the surface, the surface's above it: a Stokes
    /// wave's series holds up to its own surface (Fenton 1985), so it needs no stretching.
    Truncated,
};

/// The water at a point and time.
struct WaterSample {
    double elevation = 0.0;  ///< η above (x, z), m
    glm::dvec3 velocity{0.0};  ///< m/s
    double pressure = 0.0;   ///< dynamic + hydrostatic, relative to the atmosphere, Pa
    /// The point is at or below the surface. Above it (Wheeler stretching) the velocity is the
    /// surface's and the pressure 0.
    bool wet = true;
};

/// Frequency range of a discretised spectrum, as multiples of the peak frequency ωp.
struct SpectrumRange {
    double low = 0.5;   ///< holds all but e^(−5/4·16) of a JONSWAP's shape below
    double high = 4.0;  ///< the ω⁻⁵ tail above holds 0.5 % of m0 (5/64 · 4⁻⁴ Hs² of Hs²/16)
};

/// The components of an ocean's sea state (validated first: std::invalid_argument).
/// Regular waves: one component, a = H/2, crest at the origin at t = 0; of order n > 1
/// (oceanWaveOrder), the Stokes wave of that order (stokesWave, c_E = 0) as n bound harmonics
/// at jk, jω, the crest at the origin.
/// Spectra: N = components × directions components on a comb of frequencies
/// ω_n = (n0 + n + ½) δω, δω = (high − low) ωp / N, n0 = round(low ωp/δω), each carrying the
/// variance a_n²/2 = S(ω_n) δω (S the JONSWAP or Pierson–Moskowitz spectrum; midpoint rule).
/// Spread seas split each band of `directions` consecutive frequencies over as many
/// directions of equal energy of cos-2s (Cos2sSpreading::equalEnergyDirections), in an order
/// shuffled per band, so every component has its own frequency and direction: the sea is
/// ergodic at a point, and repeats exactly after 4π/δω (the ω_n are odd multiples of δω/2). Phases are uniform in [0, 2π) from
/// std::mt19937_64(seed) through uniform01 (per band: the shuffle's draws, then its phases).
std::vector<WaveComponent> discretise(const OceanDef& def, double g = kGravity, SpectrumRange range = {});

/// The uniform current under the sea, (x, z) m/s: a Stokes wave's c_E along its direction
/// (the return current with OceanWavesDef::MeanCurrent::Return), else 0.
glm::dvec2 meanCurrent(const OceanDef& def, double g = kGravity);

/// The time after which discretise(def)'s sea repeats exactly: T (regular) or 4π/δω, s.
double repeatPeriod(const OceanDef& def, SpectrumRange range = {});

/// A sea of wave components on depth d, summed directly: free linear waves, or the bound
/// harmonics of a Stokes wave. Its pressure is the linearised Bernoulli's, −ρ ∂φ/∂t − ρ g y
/// (for a Stokes wave without its ½ρ|u|²).
class Sea {
public:
    /// Throws std::invalid_argument for a depth, g or density ≤ 0, a free component whose ω is
    /// not that of its wave vector (relative 1e-9), or one whose amplitude is negative.
    Sea(std::vector<WaveComponent> components, double depth, double g = kGravity, double density = 1000.0,
        glm::dvec2 current = glm::dvec2(0.0));
    /// The sea of an ocean definition: discretise(def, g) on def.depth, with meanCurrent(def, g).
    static Sea fromDef(const OceanDef& def, double g = kGravity, double density = 1000.0);

    /// η at (x, z), time t, m.
    [[nodiscard]] double elevation(double x, double z, double t) const;
    /// ∂η/∂t at (x, z), m/s.
    [[nodiscard]] double elevationRate(double x, double z, double t) const;
    /// The mean of η over the rectangle [lo.x, hi.x] × [lo.y, hi.y] of (x, z) at time t, m
    /// (a side of zero length: along the other only). Exact: each component's cosine averages
    /// to its value at the centre times sinc(k_x L_x/2) sinc(k_z L_z/2).
    [[nodiscard]] double meanElevation(glm::dvec2 lo, glm::dvec2 hi, double t) const;
    /// The horizontal displacement of the surface particle that rests at (x, z), m, linear:
    /// −Σ a coth(kd) sin θ k/|k| (the time integral of the surface velocity; Tessendorf 2001's
    /// "choppy" displacement, eq. 29, with its λ = −1 and finite depth). The surface point
    /// (x, η, z) of a choppy mesh moves to (x + D_x, η, z + D_z).
    [[nodiscard]] glm::dvec2 horizontalDisplacement(double x, double z, double t) const;
    /// Velocity and pressure at `point` (x, y, z), time t; by default with the sea's own
    /// kinematics().
    [[nodiscard]] WaterSample sample(const glm::dvec3& point, double t, std::optional<Stretching> stretching = {}) const;
    /// sample() at every point, on `threads` threads (parallelFor: the same results for any
    /// count). `out` must have the size of `points` (else std::invalid_argument).
    void sample(std::span<const glm::dvec3> points, double t, std::span<WaterSample> out, int threads = 1,
                std::optional<Stretching> stretching = {}) const;
    /// How the sea's velocity is evaluated away from still water: Wheeler for linear waves,
    /// Truncated for a Stokes wave (any bound component).
    [[nodiscard]] Stretching kinematics() const { return kinematics_; }
    /// The highest y, above still water, at which the velocity is read: 0 with Wheeler's
    /// stretching (the surface maps to still water), the highest crest the components can make,
    /// Σ a, for a Stokes wave (read at the point itself).
    [[nodiscard]] double kinematicTop() const { return kinematicTop_; }
    /// The uniform horizontal current (x, z) added to every velocity, m/s (not to the choppy
    /// displacement: it would carry the surface away).
    [[nodiscard]] glm::dvec2 current() const { return current_; }
    /// V of component i (a ω for a free wave), m/s.
    [[nodiscard]] double velocityAmplitude(std::size_t i) const { return profiles_[i].velocity; }

    /// Σ a²/2: the variance of η (m²) over space or, with distinct frequencies, over time.
    [[nodiscard]] double variance() const;
    [[nodiscard]] const std::vector<WaveComponent>& components() const { return components_; }
    [[nodiscard]] double depth() const { return depth_; }
    [[nodiscard]] double gravity() const { return g_; }
    [[nodiscard]] double density() const { return density_; }

private:
    // What a component's vertical profiles need, computed once.
    struct Profile {
        double k;        // |k|
        double ux, uz;   // k/|k|
        double decay;    // e^(−2kd)
        double coth;     // coth(kd)
        double overSinh; // e^{kd}/sinh(kd) = 1/(1 − e^(−2kd))
        double velocity; // V
        double head;     // V ω/(g k): the pressure head −(∂φ/∂t)/g of the profile cosh/sinh
    };
    [[nodiscard]] double phaseAt(const WaveComponent& c, double x, double z, double t) const;

    std::vector<WaveComponent> components_;
    std::vector<Profile> profiles_;
    double depth_, g_, density_;
    Stretching kinematics_ = Stretching::Wheeler;
    double kinematicTop_ = 0.0;
    glm::dvec2 current_{0.0};
};

}  // namespace tide::ocean
