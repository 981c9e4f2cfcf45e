#include "progress.hpp"

#include <algorithm>
#include <cmath>

#include <unistd.h>

namespace tide::cli {

namespace {
void formatDuration(double seconds, char* out, std::size_t size) {
    const auto s = static_cast<long>(std::max(0.0, seconds) + 0.5);
    std::snprintf(out, size, "%02ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
}
}  // namespace

Progress::Progress(double endTime, int frames, bool quiet)
    : endTime_(endTime), frames_(frames), quiet_(quiet), terminal_(isatty(fileno(stdout)) != 0) {}

double Progress::elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::draw(double simTime, int frame, std::uint32_t particles, std::uint64_t particleSteps) {
    const double wall = elapsed();
    const double fraction = std::clamp(simTime / endTime_, 0.0, 1.0);
    constexpr int kWidth = 30;
    char bar[kWidth + 1];
    const int filled = static_cast<int>(fraction * kWidth);
    for (int k = 0; k < kWidth; ++k) bar[k] = k < filled ? '#' : '-';
    bar[kWidth] = '\0';
    char eta[32];
    formatDuration(fraction > 0.0 ? wall * (1.0 - fraction) / fraction : 0.0, eta, sizeof eta);
    std::printf("\r[%s] %7.3f/%.3f s  frame %d/%d  %u particles  %.2f M particle-steps/s  ETA %s  ", bar, simTime,
                endTime_, frame, frames_, particles, particleSteps / std::max(wall, 1e-9) / 1e6, eta);
    std::fflush(stdout);
    drawn_ = true;
}

void Progress::step(double simTime, int frame, std::uint32_t particles, std::uint64_t particleSteps) {
    if (quiet_ || !terminal_) return;
    const double now = elapsed();
    if (now - lastDraw_ < 0.1) return;
    lastDraw_ = now;
    draw(simTime, frame, particles, particleSteps);
}

void Progress::frame(double simTime, int frame, std::uint32_t particles, std::uint64_t particleSteps) {
    if (quiet_) return;
    if (terminal_) {
        draw(simTime, frame, particles, particleSteps);
        return;
    }
    std::printf("frame %d/%d  t=%.4f s  particles=%u  %.2f M particle-steps/s  wall=%.1f s\n", frame, frames_, simTime,
                particles, particleSteps / std::max(elapsed(), 1e-9) / 1e6, elapsed());
    std::fflush(stdout);
}

void Progress::finish() {
    if (drawn_) std::printf("\n");
    std::fflush(stdout);
}

SettleReport settleAndReport(World& world, double seconds, float quietSpeed, bool quiet) {
    if (!quiet) {
        std::printf("settling for %g s (settle.time) before frame 0...\n", seconds);
        std::fflush(stdout);
    }
    const SettleReport settled = world.settle(seconds, quietSpeed);
    if (!quiet)
        std::printf("settled for %g s%s (%llu steps; the fastest particle at %.3g m/s), velocities zeroed: the run starts at rest\n",
                    settled.seconds, settled.quiet ? ", quiet" : "", static_cast<unsigned long long>(settled.steps),
                    settled.maxSpeed);
    return settled;
}

}  // namespace tide::cli
