// Motion tables (CSV) → MotionKey rows for obstacles moved by a time series.
#include <tide/io/motion_table.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>

namespace tide::io {

namespace fs = std::filesystem;

MotionTableError::MotionTableError(const fs::path& file, const std::string& problemIn)
    : std::runtime_error(file.string() + ": " + problemIn), problem(problemIn) {}

namespace {

std::string trim(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> fields(const std::string& line) {
    std::vector<std::string> out;
    std::istringstream in(line);
    std::string field;
    while (std::getline(in, field, ',')) out.push_back(trim(field));
    if (!line.empty() && line.back() == ',') out.emplace_back();
    return out;
}

}  // namespace

MotionTable parseMotionTable(const std::string& text, const fs::path& file, float lengthScale) {
    MotionTable table;
    std::istringstream in(text);
    std::string line;
    std::size_t lineNumber = 0;
    std::size_t columns = 0;  // 0 until the header
    double angleScale = 1.0;
    const auto fail = [&](const std::string& problem) {
        throw MotionTableError(file, "line " + std::to_string(lineNumber) + ": " + problem);
    };
    while (std::getline(in, line)) {
        ++lineNumber;
        const std::string content = trim(line);
        if (content.empty() || content[0] == '#') continue;
        const std::vector<std::string> cells = fields(content);
        if (columns == 0) {
            std::string header;
            for (const std::string& c : cells) header += (header.empty() ? "" : ",") + c;
            if (header == "time,x,y,z") columns = 4;
            else if (header == "time,x,y,z,angle") columns = 5;
            else if (header == "time,x,y,z,angle_deg") {
                columns = 5;
                angleScale = std::numbers::pi / 180.0;
            } else {
                fail("the header must be time,x,y,z or time,x,y,z,angle or time,x,y,z,angle_deg, got \"" + content + "\"");
            }
            table.hasAngle = columns == 5;
            continue;
        }
        if (cells.size() != columns)
            fail("expected " + std::to_string(columns) + " numbers, got " + std::to_string(cells.size()));
        double value[5] = {};
        for (std::size_t c = 0; c < columns; ++c) {
            char* end = nullptr;
            errno = 0;
            value[c] = std::strtod(cells[c].c_str(), &end);
            if (cells[c].empty() || *end != '\0' || errno == ERANGE || !std::isfinite(value[c]))
                fail("\"" + cells[c] + "\" is not a finite number");
        }
        MotionKey key;
        key.time = value[0];
        key.offset = glm::vec3(static_cast<float>(value[1]), static_cast<float>(value[2]), static_cast<float>(value[3])) * lengthScale;
        key.angle = static_cast<float>(value[4] * angleScale);
        if (!table.keys.empty() && !(key.time > table.keys.back().time)) {
            std::ostringstream msg;
            msg << "time " << key.time << " is not after the previous row's " << table.keys.back().time;
            fail(msg.str());
        }
        table.keys.push_back(key);
    }
    if (columns == 0) throw MotionTableError(file, "no header line (time,x,y,z or time,x,y,z,angle)");
    if (table.keys.empty()) throw MotionTableError(file, "no rows after the header");
    return table;
}

MotionTable readMotionTable(const fs::path& file, float lengthScale) {
    std::error_code ec;
    if (fs::is_directory(file, ec)) throw MotionTableError(file, "is a directory, not a CSV file");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw MotionTableError(file, "cannot open (no such file or no permission)");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw MotionTableError(file, "cannot read");
    return parseMotionTable(text.str(), file, lengthScale);
}

}  // namespace tide::io
