#include "measurements.hpp"

#include <charconv>
#include <cmath>
#include <ostream>

#include <tide/io/exporters.hpp>

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

Measurements::Measurements(const io::Scene& scene) : gauges_(scene.gauges), probes_(scene.probes) {}

void Measurements::sample(const World& world, double t) {
    if (!gauges_.empty()) {
        append(gaugeRows_, t);
        for (const io::GaugeDef& g : gauges_) {
            gaugeRows_ += ',';
            append(gaugeRows_, world.surfaceHeight(g.x, g.z));
        }
        gaugeRows_ += '\n';
    }
    if (!probes_.empty()) {
        append(probeRows_, t);
        for (const io::ProbeDef& p : probes_) {
            const ProbeSample s = world.probe(p.position);
            for (const float value : {s.pressure, s.velocity.x, s.velocity.y, s.velocity.z}) {
                probeRows_ += ',';
                append(probeRows_, value);
            }
        }
        probeRows_ += '\n';
    }
}

void Measurements::write(const std::filesystem::path& dir) const {
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
