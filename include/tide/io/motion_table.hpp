#pragma once
/// \file
/// Motion tables from CSV files, for obstacles moved by a time series (MotionDef::Type::Table).
///
/// The format (docs/scene-format.md § Moving obstacles): lines starting with `#` and blank
/// lines are skipped; the first other line is the header, `time,x,y,z` (a translation) or
/// `time,x,y,z,angle` (radians) or `time,x,y,z,angle_deg` (degrees), the angle about the
/// motion's axis through its centre; then one row of numbers per line, times in seconds and
/// strictly increasing, x, y, z the displacement from the rest pose in the scene's length unit.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <tide/defs.hpp>

namespace tide::io {

/// A motion table that cannot be used; what() is "FILE: problem", the problem naming the line.
class MotionTableError : public std::runtime_error {
public:
    MotionTableError(const std::filesystem::path& file, const std::string& problem);
    std::string problem;  ///< the problem alone, without the file name, e.g. "line 4: ..."
};

/// A table's rows and whether it has an angle column.
struct MotionTable {
    std::vector<MotionKey> keys;  ///< displacements already scaled to metres, angles in radians
    bool hasAngle = false;
};

/// Parse a motion table's text; displacements are multiplied by `lengthScale`. Throws
/// MotionTableError (naming `file`) for a bad header, a bad row or times that do not increase.
MotionTable parseMotionTable(const std::string& text, const std::filesystem::path& file, float lengthScale = 1.0f);
/// Read and parse a motion table file. Throws MotionTableError, also when it cannot be read.
MotionTable readMotionTable(const std::filesystem::path& file, float lengthScale = 1.0f);

}  // namespace tide::io
