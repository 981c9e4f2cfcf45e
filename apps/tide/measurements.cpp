#include "measurements.hpp"

#include <charconv>
#include <cmath>
#include <optional>
#include <ostream>

#include <tide/io/exporters.hpp>

#include "core/world_distributed.hpp"

namespace tide::cli {

namespace {
/// Shortest decimal form that reads back exactly; "nan" for a dry gauge.
void append(std::string& line, double value) {
    if (!std::isfinite(value)) {
        line += "nan";
        return;
    }
    char text[32];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, value);
    if (ec == std::errc{}) line.append(text, end);
}
void append(std::string& line, float value) { append(line, std::isfinite(value) ? static_cast<double>(value) : NAN); }
}  // namespace

Measurements::Measurements(const io::Scene& scene) : gauges_(scene.gauges), probes_(scene.probes), loads_(scene.world.loads) {}

void Measurements::sample(World& world, double t, comm::Communicator* split) {
    if (loads_) {
        if (solids_.empty()) {
            // Obstacles first (the contract), then wave makers, then the walls that exist.
            const std::vector<SolidInfo>& solids = world.solids();
            for (const SolidInfo::Kind kind : {SolidInfo::Kind::Obstacle, SolidInfo::Kind::WaveMaker, SolidInfo::Kind::Wall})
                for (std::uint32_t s = 0; s < solids.size(); ++s) {
                    if (solids[s].kind != kind) continue;
                    if (kind == SolidInfo::Kind::Wall) {
                        const int axis = static_cast<int>(solids[s].index / 2);
                        if (!world.def().walls || world.def().periodic[axis]) continue;
                        if (axis == 2 && world.def().dimensions == 2) continue;  // a 2D world has no z faces
                    }
                    solids_.push_back(s);
                    solidNames_.push_back(solids[s].name);
                }
        }
        const std::vector<SolidLoad> mean = world.takeMeanSolidLoads();
        append(forceRows_, t);
        for (const std::uint32_t s : solids_) {
            const glm::dvec3 f = mean[s].force();
            for (const double value : {f.x, f.y, f.z, mean[s].moment.x, mean[s].moment.y, mean[s].moment.z}) {
                forceRows_ += ',';
                append(forceRows_, value);
            }
        }
        for (const std::uint32_t s : solids_)
            for (int axis = 0; axis < 3; ++axis) {
                forceRows_ += ',';
                append(forceRows_, mean[s].pressureForce[axis]);
            }
        forceRows_ += '\n';
    }
    if (const std::vector<BodyState> bodies = world.bodies(); !bodies.empty()) {
        if (bodyNames_.empty())
            for (const BodyState& b : bodies) {
                bodyNames_.push_back(b.name);
                for (const BodyState::Mooring& line : b.moorings) mooringNames_.push_back(line.name);
            }
        append(bodyRows_, t);
        for (const BodyState& b : bodies)
            for (const double value : {b.position.x, b.position.y, b.position.z, b.orientation.w, b.orientation.x,
                                       b.orientation.y, b.orientation.z}) {
                bodyRows_ += ',';
                append(bodyRows_, value);
            }
        for (const BodyState& b : bodies)
            for (const double value : {b.velocity.x, b.velocity.y, b.velocity.z, b.angularVelocity.x, b.angularVelocity.y,
                                       b.angularVelocity.z}) {
                bodyRows_ += ',';
                append(bodyRows_, value);
            }
        for (const BodyState& b : bodies)
            for (const BodyState::Mooring& line : b.moorings) {
                bodyRows_ += ',';
                append(bodyRows_, line.tension);
            }
        bodyRows_ += '\n';
    }
    std::optional<FieldSamples> overRanks;
    if (split && any()) {
        std::vector<glm::vec2> lines;
        std::vector<glm::vec3> points;
        for (const io::GaugeDef& g : gauges_) lines.emplace_back(g.x, g.z);
        for (const io::ProbeDef& p : probes_) points.push_back(p.position);
        overRanks = sampleOverRanks(world, *split, lines, points);
        if (split->rank() != 0) return;
    }
    if (!gauges_.empty()) {
        append(gaugeRows_, t);
        for (std::size_t k = 0; k < gauges_.size(); ++k) {
            gaugeRows_ += ',';
            append(gaugeRows_, overRanks ? overRanks->heights[k] : world.surfaceHeight(gauges_[k].x, gauges_[k].z));
        }
        gaugeRows_ += '\n';
    }
    if (!probes_.empty()) {
        append(probeRows_, t);
        for (std::size_t k = 0; k < probes_.size(); ++k) {
            const ProbeSample s = overRanks ? overRanks->probes[k] : world.probe(probes_[k].position);
            for (const float value : {s.pressure, s.velocity.x, s.velocity.y, s.velocity.z}) {
                probeRows_ += ',';
                append(probeRows_, value);
            }
        }
        probeRows_ += '\n';
    }
}

void Measurements::write(const std::filesystem::path& dir) const {
    if (!bodyNames_.empty())
        io::writeFileAtomically(dir / "bodies.csv", [&](std::ostream& out) {
            out << "time";
            for (const std::string& name : bodyNames_)
                for (const char* column : {"_x", "_y", "_z", "_qw", "_qx", "_qy", "_qz"}) out << ',' << name << column;
            for (const std::string& name : bodyNames_)
                for (const char* column : {"_vx", "_vy", "_vz", "_wx", "_wy", "_wz"}) out << ',' << name << column;
            for (const std::string& name : mooringNames_) out << ',' << name << "_tension";
            out << '\n' << bodyRows_;
        });
    if (loads_ && !solids_.empty())
        io::writeFileAtomically(dir / "forces.csv", [&](std::ostream& out) {
            out << "time";
            for (const std::string& name : solidNames_)
                for (const char* column : {"_fx", "_fy", "_fz", "_mx", "_my", "_mz"}) out << ',' << name << column;
            for (const std::string& name : solidNames_)
                for (const char* column : {"_fx_p", "_fy_p", "_fz_p"}) out << ',' << name << column;
            out << '\n' << forceRows_;
        });
    if (!gauges_.empty())
        io::writeFileAtomically(dir / "gauges.csv", [&](std::ostream& out) {
            out << "time";
            for (const io::GaugeDef& g : gauges_) out << ',' << g.name;
            out << '\n' << gaugeRows_;
        });
    if (!probes_.empty())
        io::writeFileAtomically(dir / "probes.csv", [&](std::ostream& out) {
            out << "time";
            for (const io::ProbeDef& p : probes_)
                out << ',' << p.name << "_p," << p.name << "_vx," << p.name << "_vy," << p.name << "_vz";
            out << '\n' << probeRows_;
        });
}

}  // namespace tide::cli
