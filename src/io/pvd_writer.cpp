// ParaView time series (.pvd): a Collection of frame files, rewritten atomically after each frame.
#include <tide/io/exporters.hpp>

#include <charconv>
#include <ostream>
#include <string>
#include <system_error>
#include <utility>

namespace tide::io {

namespace {

/// `text` with the five XML special characters escaped, for an attribute value.
std::string xmlEscaped(std::string_view text) {
    std::string escaped;
    escaped.reserve(text.size());
    for (const char c : text) {
        switch (c) {
            case '&': escaped.append("&amp;"); break;
            case '<': escaped.append("&lt;"); break;
            case '>': escaped.append("&gt;"); break;
            case '"': escaped.append("&quot;"); break;
            case '\'': escaped.append("&apos;"); break;
            default: escaped.push_back(c);
        }
    }
    return escaped;
}

/// The shortest decimal form that reads back as exactly `value`.
std::string shortest(double value) {
    char text[32];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, value);
    return ec == std::errc{} ? std::string(text, end) : std::string("0");
}

}  // namespace

PvdWriter::PvdWriter(std::filesystem::path pvdFile) : pvdFile_(std::move(pvdFile)) {}

void PvdWriter::add(double time, const std::string& relativeFile) { entries_.push_back({time, relativeFile}); }

void PvdWriter::write() const {
    writeFileAtomically(pvdFile_, [this](std::ostream& out) {
        out << "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"Collection\" version=\"0.1\">\n"
               "  <Collection>\n";
        for (const Entry& e : entries_) {
            out << "    <DataSet timestep=\"" << shortest(e.time) << "\" group=\"\" part=\"0\" file=\""
                << xmlEscaped(e.file) << "\"/>\n";
        }
        out << "  </Collection>\n"
               "</VTKFile>\n";
    });
}

}  // namespace tide::io
