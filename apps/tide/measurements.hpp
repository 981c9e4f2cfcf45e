#pragma once
/// \file
/// The scene's wave gauges and probes, sampled at every frame of `tide run` and written as
/// OUT/gauges.csv (`time,<gauge names...>`: free-surface height y, m) and OUT/probes.csv
/// (`time,<name>_p,<name>_vx,<name>_vy,<name>_vz,...`: Pa, m/s), and the loads on the solids
/// as OUT/forces.csv (`time`, then for every obstacle in the scene's order, every wave maker and
/// every wall face: `<name>_fx,<name>_fy,<name>_fz,<name>_mx,<name>_my,<name>_mz`, N and N·m
/// about the solid's reference point, each the mean over the frame interval that ends at the
/// row's time: the momentum exchanged, which an instant's value would alias; then for the
/// same solids the pressure part `<name>_fx_p,<name>_fy_p,<name>_fz_p`), and the dynamic
/// obstacles' motion as OUT/bodies.csv (`time`, then per body `<name>_x,<name>_y,<name>_z`, its
/// centre of mass, m, `<name>_qw,<name>_qx,<name>_qy,<name>_qz`, its rotation from the rest
/// pose; then per body `<name>_vx,<name>_vy,<name>_vz,<name>_wx,<name>_wy,<name>_wz`, m/s and
/// rad/s; then per mooring line `<line>_tension`, N). Each file is written whole
/// and atomically (temporary file, rename): a run that stops early leaves the rows sampled
/// so far, never half a file.

#include <filesystem>
#include <cstdint>
#include <string>
#include <vector>

#include <tide/io/scene.hpp>
#include <tide/world.hpp>

#include "comm/communicator.hpp"

namespace tide::cli {

class Measurements {
public:
    explicit Measurements(const io::Scene& scene);
    /// Whether the scene has gauges or probes.
    [[nodiscard]] bool any() const { return !gauges_.empty() || !probes_.empty(); }
    /// One row of every file at simulated time t (forces.csv: the mean load since the last row,
    /// World::takeMeanSolidLoads). A World split among processes passes their communicator:
    /// every rank calls it, the gauges and probes are read over all of them, and rank 0's rows
    /// are the run's.
    void sample(World& world, double t, comm::Communicator* split = nullptr);
    /// gauges.csv and probes.csv (only those the scene asks for) in `dir`.
    void write(const std::filesystem::path& dir) const;
    /// The rows sampled so far, for a checkpoint, and taking them back on resume.
    [[nodiscard]] const std::string& gaugeRows() const { return gaugeRows_; }
    [[nodiscard]] const std::string& probeRows() const { return probeRows_; }
    [[nodiscard]] const std::string& forceRows() const { return forceRows_; }
    [[nodiscard]] const std::string& bodyRows() const { return bodyRows_; }
    void restoreRows(std::string gaugeRows, std::string probeRows, std::string forceRows, std::string bodyRows) {
        gaugeRows_ = std::move(gaugeRows);
        probeRows_ = std::move(probeRows);
        forceRows_ = std::move(forceRows);
        bodyRows_ = std::move(bodyRows);
    }

private:
    std::vector<io::GaugeDef> gauges_;
    std::vector<io::ProbeDef> probes_;
    bool loads_ = false;                ///< WorldDef::loads: forces.csv is written
    std::vector<std::uint32_t> solids_;  ///< forces.csv's solids, indices in World::solids()
    std::vector<std::string> solidNames_;
    std::vector<std::string> bodyNames_;  ///< bodies.csv's bodies
    std::vector<std::string> mooringNames_;  ///< bodies.csv's mooring lines (`<line>_tension`)
    std::string gaugeRows_, probeRows_, forceRows_, bodyRows_;
};

}  // namespace tide::cli
