#pragma once
/// \file
/// Splits a step's wall time into the phases of WorldStats::phaseSeconds: lap(phase) books
/// the time since the previous lap to that phase. Costs one clock read per phase per step.

#include <chrono>

#include <tide/world.hpp>

namespace tide {

enum class Phase { NeighborSearch, Density, PressureSolve, NonPressureForces, Integration, Coupling };

class PhaseClock {
public:
    explicit PhaseClock(PhaseSeconds& sink) : sink_(&sink), last_(std::chrono::steady_clock::now()) {}

    void lap(Phase phase) {
        const auto now = std::chrono::steady_clock::now();
        const double seconds = std::chrono::duration<double>(now - last_).count();
        last_ = now;
        switch (phase) {
            case Phase::NeighborSearch: sink_->neighborSearch += seconds; break;
            case Phase::Density: sink_->density += seconds; break;
            case Phase::PressureSolve: sink_->pressureSolve += seconds; break;
            case Phase::NonPressureForces: sink_->nonPressureForces += seconds; break;
            case Phase::Integration: sink_->integration += seconds; break;
            case Phase::Coupling: sink_->coupling += seconds; break;
        }
    }

private:
    PhaseSeconds* sink_;
    std::chrono::steady_clock::time_point last_;
};

}  // namespace tide
