#pragma once
/// \file
/// Active wave absorption at a piston paddle from the free-surface elevation measured in
/// front of it (Schäffer & Klopman 2000, "Review of multidirectional active wave absorption
/// methods", J. Waterway Port Coastal Ocean Eng. 126(2): 2D absorption by near-field
/// elevation feedback; in SPH as DualSPHysics' AWAS, Altomare et al. 2017, "Long-crested wave
/// generation and absorption for SPH-based DualSPHysics model", Coastal Engineering 127). The
/// papers were not at hand when this was written: the law below is the piston's linear
/// transfer function inverted, and its shallow-water limit is DualSPHysics' form.
///
/// A wave travelling towards the paddle (elevation η_R at its face) leaves the tank when the
/// paddle moves with the water under it. The paddle velocity that radiates −η_R is the
/// inverse of the piston's transfer function, U_a = −(ω / F(kd)) η_R with F = H/S of linear
/// wavemaker theory (Dean & Dalrymple eq. 6.20); in shallow water F → kd and ω/F → √(g/d),
/// the form DualSPHysics uses. η_R is the measured elevation η_M minus the target η_I, the
/// wave the paddle is asked to make, both at the gauge a few spacings in front of the face:
///
///     U(t) = U_I(t) − G (η_M(t) − η_I(t)),   G = ω_p / F(k_p d)            (the absorption law)
///
/// with G taken at the design frequency ω_p (the regular wave's, the spectrum's peak), so a
/// wave of that frequency is absorbed exactly and the shallow-water √(g/d) is the limit
/// for long waves. A measured elevation carries a bias (the SPH colour-field gauge, the
/// wave's mean set-down) that the law would integrate into a paddle that wanders off; the
/// drift correction (ours; DualSPHysics pulls the paddle back once past a stroke limit) makes
/// the correction band-limited: the error's slow mean ē (time constant τ) is taken out
/// before the gain, and the correction's displacement X_a relaxes back over the same τ:
///
///     U_a = −G (e − ē) − X_a / τ,   dē/dt = (e − ē)/τ,   τ = 4 T_p          (drift correction)
///
/// which leaves waves near ω_p absorbed (2.3° of phase per stage at 4 periods) and a steady
/// bias e₀ without effect. A misreading (a splash on the gauge's line next to a receding
/// paddle) would jerk the paddle: the error is limited to ± H and the correction's
/// acceleration to twice the stroke's peak (DualSPHysics' `limitace`, 2 by default); the
/// correction's displacement stays within twice the stroke amplitude. The target η_I is the linear wave of each paddle component at the
/// gauge, plus Stokes' bound second harmonic for regular waves, η₂ = (πH²/8λ) cosh kd
/// (2 + cosh 2kd)/sinh³ kd cos 2θ, which the measurement contains and the paddle must not try
/// to cancel.

#include <span>
#include <vector>

#include <tide/defs.hpp>

#include "sources/wave_theory.hpp"

namespace tide {

class ActiveAbsorption {
public:
    /// For the paddle `def` (a piston making regular or irregular waves), the components it
    /// makes, gravity g and the fluid's particle spacing (the gauge stands 5 spacings in front
    /// of the face, as DualSPHysics' default).
    ActiveAbsorption(const WaveMakerDef& def, std::span<const waves::PaddleComponent> components, double g,
                     float spacing);

    /// The state carried from step to step (checkpointed): the error's slow mean, and whether
    /// it has been started (on the first measurement, of still water).
    struct State {
        double mean = 0.0;
        double lastTime = 0.0;
        bool started = false;
    };

    /// The correction velocity U_a (m/s) for the step starting at t, from the surface height y
    /// measured at the gauge (NaN if dry: the last velocity is kept), the still-water level y0,
    /// the correction's displacement X_a now and its velocity over the last step. Zero during
    /// the wave maker's ramp. The error η_M − η_I − ē is limited to ± the wave height, the
    /// velocity's change to twice the stroke's peak acceleration (Σ A ω²) times the step, and
    /// past twice the stroke amplitude (2 Σ A) the correction only comes back.
    double correctionVelocity(double t, float measuredY, double stillY, double offset, double previousVelocity);

    /// The elevation the paddle is asked to make at the gauge at time t, m.
    [[nodiscard]] double targetElevation(double t) const;

    /// Gauge distance in front of the face, m.
    [[nodiscard]] double gaugeDistance() const { return gaugeDistance_; }
    /// G = ω_p / F(k_p d), 1/s.
    [[nodiscard]] double gain() const { return gain_; }
    /// τ, s.
    [[nodiscard]] double driftTime() const { return driftTime_; }

    [[nodiscard]] const State& state() const { return state_; }
    void setState(const State& s) { state_ = s; }

private:
    struct Component {
        double amplitude, omega, phase, k;
    };
    std::vector<Component> components_;
    double rampTime_, gain_, driftTime_, gaugeDistance_, waveHeight_ = 0.0, peakAcceleration_ = 0.0;
    double maxOffset_ = 0.0;  ///< twice the stroke amplitude Σ A, m
    double boundAmplitude_ = 0.0;  ///< Stokes' second harmonic of a regular wave at the gauge, m
    State state_;
};

}  // namespace tide
