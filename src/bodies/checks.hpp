#pragma once
/// \file
/// Argument checks in double for tide::bodies: std::invalid_argument naming field and value.

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include <glm/vec3.hpp>

namespace tide::bodies {

inline std::string showd(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

inline std::string showd(const glm::dvec3& v) {
    std::ostringstream out;
    out << '[' << v.x << ", " << v.y << ", " << v.z << ']';
    return out.str();
}

inline void requirePositiveD(const std::string& field, double v) {
    if (!(v > 0.0) || !std::isfinite(v)) throw std::invalid_argument(field + ": must be > 0, got " + showd(v));
}

inline void requireNonNegativeD(const std::string& field, double v) {
    if (!(v >= 0.0) || !std::isfinite(v)) throw std::invalid_argument(field + ": must be >= 0, got " + showd(v));
}

inline void requireFiniteD(const std::string& field, const glm::dvec3& v) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw std::invalid_argument(field + ": must be finite, got " + showd(v));
}

}  // namespace tide::bodies
