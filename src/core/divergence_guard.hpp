#pragma once
/// \file
/// The per-step divergence guard. It rides on the pass over the particles that World's
/// statistics already make (max speed, density error; one guard per block of particles, the
/// lowest block's find kept), so it costs a few compares
/// per particle: a non-finite position, velocity, density or pressure, or a particle that
/// moved more than kRunawaySupports support radii in one step, is recorded for the first
/// (lowest) index, which makes the report the same for any thread count.

#include <cmath>
#include <cstdint>
#include <optional>

#include <tide/particles.hpp>
#include <tide/world.hpp>

namespace tide {

class DivergenceGuard {
public:
    /// For a step of length dt with kernel support h.
    DivergenceGuard(double dt, float h) : runawaySpeed2_(square(kRunawaySupports * h / dt)) {}

    /// Checks particle i, whose squared speed the caller has computed.
    void check(const ParticleStore& p, std::uint32_t i, double speed2) {
        if (found_) return;
        const glm::vec3& x = p.position[i];
        const glm::vec3& v = p.velocity[i];
        if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z))
            record(p, i, DivergedQuantity::Position, firstNonFinite(x));
        else if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            record(p, i, DivergedQuantity::Velocity, firstNonFinite(v));
        else if (!std::isfinite(p.density[i]))
            record(p, i, DivergedQuantity::Density, p.density[i]);
        else if (!std::isfinite(p.pressure[i]))
            record(p, i, DivergedQuantity::Pressure, p.pressure[i]);
        else if (speed2 > runawaySpeed2_) {
            record(p, i, DivergedQuantity::Speed, static_cast<float>(std::sqrt(speed2)));
            found_->limit = static_cast<float>(std::sqrt(runawaySpeed2_));
        }
    }

    /// The first bad particle, if any (step, time and dt are the caller's to fill in).
    [[nodiscard]] std::optional<Divergence>& found() { return found_; }

private:
    static double square(double x) { return x * x; }
    static float firstNonFinite(const glm::vec3& v) {
        return !std::isfinite(v.x) ? v.x : !std::isfinite(v.y) ? v.y : v.z;
    }
    void record(const ParticleStore& p, std::uint32_t i, DivergedQuantity q, float value) {
        found_ = Divergence{};
        found_->particle = i;
        found_->id = p.id[i];
        found_->quantity = q;
        found_->value = value;
    }

    double runawaySpeed2_;
    std::optional<Divergence> found_;
};

}  // namespace tide
