#pragma once
/// \file
/// Argument checks that throw std::invalid_argument naming the field and the value.

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include <glm/vec3.hpp>

namespace tide {

inline std::string show(float v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

inline std::string show(const glm::vec3& v) {
    std::ostringstream out;  // not "[" + std::string: GCC 12 raises a false -Wrestrict on it
    out << '[' << v.x << ", " << v.y << ", " << v.z << ']';
    return out.str();
}

inline void requireFinite(const std::string& field, float v) {
    if (!std::isfinite(v)) throw std::invalid_argument(field + ": must be finite, got " + show(v));
}

inline void requirePositive(const std::string& field, float v) {
    if (!(v > 0.0f) || !std::isfinite(v)) throw std::invalid_argument(field + ": must be > 0, got " + show(v));
}

inline void requireInRange(const std::string& field, float v, float lo, float hi) {
    if (!(v >= lo && v <= hi))
        throw std::invalid_argument(field + ": must be in [" + show(lo) + ", " + show(hi) + "], got " + show(v));
}

}  // namespace tide
