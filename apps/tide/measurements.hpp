#pragma once
/// \file
/// The scene's wave gauges and probes, sampled at every frame of `tide run` and written as
/// OUT/gauges.csv (`time,<gauge names...>`: free-surface height y, m) and OUT/probes.csv
/// (`time,<name>_p,<name>_vx,<name>_vy,<name>_vz,...`: Pa, m/s). Each file is written whole
/// and atomically (temporary file, rename): a run that stops early leaves the rows sampled
/// so far, never half a file.

#include <filesystem>
#include <string>
#include <vector>

#include <tide/io/scene.hpp>
#include <tide/world.hpp>

namespace tide::cli {

class Measurements {
public:
    explicit Measurements(const io::Scene& scene);
    /// Whether the scene has gauges or probes.
    [[nodiscard]] bool any() const { return !gauges_.empty() || !probes_.empty(); }
    /// One row of every file at simulated time t.
    void sample(const World& world, double t);
    /// gauges.csv and probes.csv (only those the scene asks for) in `dir`.
    void write(const std::filesystem::path& dir) const;
    /// The rows sampled so far, for a checkpoint, and taking them back on resume.
    [[nodiscard]] const std::string& gaugeRows() const { return gaugeRows_; }
    [[nodiscard]] const std::string& probeRows() const { return probeRows_; }
    void restoreRows(std::string gaugeRows, std::string probeRows) {
        gaugeRows_ = std::move(gaugeRows);
        probeRows_ = std::move(probeRows);
    }

private:
    std::vector<io::GaugeDef> gauges_;
    std::vector<io::ProbeDef> probes_;
    std::string gaugeRows_, probeRows_;
};

}  // namespace tide::cli
