/// \file
/// Constraints by axis name: "x", "y", "z" (translations), "rx", "ry", "rz" (rotations).

#include <tide/bodies.hpp>

#include <stdexcept>

namespace tide::bodies {

namespace {

ConstraintDef namedAxes(const std::vector<std::string>& axes, const std::string& path, bool fixed) {
    ConstraintDef c;
    c.type = ConstraintDef::Type::FixedAxes;
    c.fixedTranslation = {!fixed, !fixed, !fixed};
    c.fixedRotation = {!fixed, !fixed, !fixed};
    static const char* const kNames[6] = {"x", "y", "z", "rx", "ry", "rz"};
    for (std::size_t i = 0; i < axes.size(); ++i) {
        int found = -1;
        for (int k = 0; k < 6; ++k)
            if (axes[i] == kNames[k]) found = k;
        if (found < 0)
            throw std::invalid_argument(path + "[" + std::to_string(i) + "]: unknown axis \"" + axes[i] +
                                        "\" (expected x, y, z, rx, ry or rz)");
        (found < 3 ? c.fixedTranslation[found] : c.fixedRotation[found - 3]) = fixed;
    }
    return c;
}

}  // namespace

ConstraintDef fixedAxes(const std::vector<std::string>& axes, const std::string& path) {
    return namedAxes(axes, path, true);
}

ConstraintDef freeAxes(const std::vector<std::string>& axes, const std::string& path) {
    return namedAxes(axes, path, false);
}

}  // namespace tide::bodies
