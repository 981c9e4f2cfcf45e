#pragma once
// Progress of a run: a live bar on a terminal, one plain line per frame otherwise.

#include <chrono>
#include <cstdint>
#include <cstdio>

#include <tide/world.hpp>

namespace tide::cli {

/// World::settle for the scene's settle.time and settle.speed, saying so before and after
/// (unless quiet).
SettleReport settleAndReport(World& world, double seconds, float quietSpeed, bool quiet);

class Progress {
public:
    Progress(double endTime, int frames, bool quiet);
    /// After every step: redraws the bar at most ~10 times a second (terminal only).
    void step(double simTime, int frame, std::uint32_t particles, std::uint64_t particleSteps);
    /// After every written frame: the plain line (not on a terminal).
    void frame(double simTime, int frame, std::uint32_t particles, std::uint64_t particleSteps);
    /// Ends the bar's line.
    void finish();

private:
    void draw(double simTime, int frame, std::uint32_t particles, std::uint64_t particleSteps);
    [[nodiscard]] double elapsed() const;

    double endTime_;
    int frames_;
    bool quiet_;
    bool terminal_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    double lastDraw_ = -1.0;
};

}  // namespace tide::cli
