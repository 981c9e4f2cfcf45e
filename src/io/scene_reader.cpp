// The scene parser's shared helpers (scene_reader.hpp).
#include "scene_reader.hpp"

namespace tide::io::scene_reading {

namespace {

std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string indexed(const std::string& path, std::size_t i) {
    std::ostringstream out;
    out << path << '[' << i << ']';
    return out.str();
}

/// ` (did you mean "x"?)` for the closest known name, when it is close.
std::string suggestion(std::string_view given, const std::vector<std::string>& known) {
    std::string best;
    std::size_t bestDistance = 3;
    for (const auto& k : known) {
        const std::size_t d = editDistance(given, k);
        if (d < bestDistance) {
            bestDistance = d;
            best = k;
        }
    }
    return best.empty() ? std::string() : " (did you mean \"" + best + "\"?)";
}

std::string show(const json& value) {
    std::string text = value.dump();
    if (text.size() > 60) text = text.substr(0, 57) + "...";
    return text;
}

bool boxInside(const glm::vec3& min, const glm::vec3& max, const WorldDef& w) {
    const float slack = 1e-5f * glm::length(w.domainMax - w.domainMin);
    for (int a = 0; a < 3; ++a)
        if (min[a] < w.domainMin[a] - slack || max[a] > w.domainMax[a] + slack) return false;
    return true;
}

std::string showVec(const glm::vec3& v) {
    std::ostringstream out;
    out << '[' << v.x << ", " << v.y << ", " << v.z << ']';
    return out.str();
}

/// Reads `min`/`max` of a box and checks min ≤ max.
bool readBox(Reader& r, const json& j, const std::string& path, float scale, glm::vec3& min, glm::vec3& max) {
    const auto lo = r.vec3(j, "min", path, true);
    const auto hi = r.vec3(j, "max", path, true);
    if (!lo || !hi) return false;
    for (int a = 0; a < 3; ++a)
        if ((*lo)[a] > (*hi)[a]) {
            r.fail(join(path, "max"), "must not be below min " + showVec(*lo) + " on any axis, got " + showVec(*hi));
            return false;
        }
    min = *lo * scale;
    max = *hi * scale;
    return true;
}
/// Index of the material named at obj.material (default: the first material).
std::optional<MaterialIndex> readMaterialRef(Reader& r, const json& obj, const std::string& path, const Scene& scene) {
    auto name = r.string(obj, "material", path, false);
    if (!name) return scene.materials.empty() ? std::nullopt : std::optional<MaterialIndex>(0);
    std::vector<std::string> known;
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        if (scene.materials[m].name == *name) return static_cast<MaterialIndex>(m);
        known.push_back(scene.materials[m].name);
    }
    r.fail(join(path, "material"), "no material named \"" + *name + "\"" + suggestion(*name, known));
    return std::nullopt;
}

/// A unit direction: "x", "y", "z" (optionally signed: "-y") or 3 numbers, not all zero.
std::optional<glm::vec3> readDirection(Reader& r, const json& j, const char* key, const std::string& path) {
    const std::string where = join(path, key);
    if (!j.contains(key)) {
        r.fail(where, "missing (required)");
        return std::nullopt;
    }
    if (j.at(key).is_string()) {
        std::string name = j.at(key).get<std::string>();
        const float sign = !name.empty() && name[0] == '-' ? -1.0f : 1.0f;
        if (!name.empty() && (name[0] == '-' || name[0] == '+')) name = name.substr(1);
        if (name.size() == 1 && name[0] >= 'x' && name[0] <= 'z') {
            glm::vec3 v(0.0f);
            v[name[0] - 'x'] = sign;
            return v;
        }
        r.fail(where, "must be \"x\", \"y\", \"z\" (or \"-x\" ...) or an array of 3 numbers, got " + show(j.at(key)));
        return std::nullopt;
    }
    const auto v = r.vec3(j, key, path, true);
    if (!v) return std::nullopt;
    if (!(glm::length(*v) > 0.0f)) {
        r.fail(where, "must not be [0, 0, 0]");
        return std::nullopt;
    }
    return glm::normalize(*v);
}

/// A rotation's "axis": any direction in 3D; in 2D only z, the default there.
std::optional<glm::vec3> readRotationAxis(Reader& r, const json& j, const std::string& path) {
    if (r.dimensions != 2) return readDirection(r, j, "axis", path);
    if (!j.contains("axis")) return glm::vec3(0.0f, 0.0f, 1.0f);
    const json& v = j.at("axis");
    if (v.is_string() && (v == "z" || v == "+z" || v == "-z"))
        return glm::vec3(0.0f, 0.0f, v == "-z" ? -1.0f : 1.0f);
    r.fail(join(path, "axis"), "a 2D scene rotates about z only: \"z\" or \"-z\" (or leave it out), got " + show(v));
    return std::nullopt;
}

/// A mesh's `scale`: a number or 3 numbers, all > 0 (default 1).
std::optional<glm::vec3> readMeshScale(Reader& r, const json& j, const std::string& path) {
    if (!j.contains("scale")) return glm::vec3(1.0f);
    const json& v = j.at("scale");
    const auto positive = [](const json& e) { return e.is_number() && e.get<double>() > 0.0 && e.get<double>() <= 1e6; };
    if (positive(v)) return glm::vec3(static_cast<float>(v.get<double>()));
    if (v.is_array() && v.size() == 3 && std::all_of(v.begin(), v.end(), positive))
        return glm::vec3(static_cast<float>(v[0].get<double>()), static_cast<float>(v[1].get<double>()),
                         static_cast<float>(v[2].get<double>()));
    r.fail(join(path, "scale"), "must be a number or 3 numbers, all > 0, got " + show(v));
    return std::nullopt;
}

/// A file as the scene names it, and where that led when it differs: "a.csv (scenes/a.csv)".
std::string shownFile(const std::string& named, const std::filesystem::path& resolved) {
    return resolved.string() == named ? named : named + " (" + resolved.string() + ")";
}

/// A whole number in [lo, hi] at obj[key] (absent: nothing, no problem).
std::optional<double> wholeNumber(Reader& r, const json& obj, const char* key, const std::string& path, double lo, double hi) {
    const auto v = r.number(obj, key, path, false, lo, hi);
    if (v && *v != std::floor(*v)) {
        r.fail(join(path, key), "must be a whole number, got " + show(obj.at(key)));
        return std::nullopt;
    }
    return v;
}

/// A gauge or probe name: a CSV column header, so non-empty, unique and free of commas, quotes and line breaks.
bool checkColumnName(Reader& r, const std::string& name, const std::string& path, std::vector<std::string>& used) {
    if (name.empty() || name.find_first_of(",\"\n\r") != std::string::npos) {
        r.fail(join(path, "name"), "must be non-empty, without commas, quotes or line breaks, got \"" + name + "\"");
        return false;
    }
    if (std::find(used.begin(), used.end(), name) != used.end()) {
        r.fail(join(path, "name"), "\"" + name + "\" is already used by another gauge or probe");
        return false;
    }
    used.push_back(name);
    return true;
}

}  // namespace tide::io::scene_reading
