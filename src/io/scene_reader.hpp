#pragma once
/// \file
/// What the parts of the scene parser share (src/io/scene_*.cpp, internal to tide::io): the
/// Reader that collects every problem with its JSON path, the helpers for paths, boxes,
/// directions and names, and one reader per section of a scene file.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <nlohmann/json.hpp>

#include <tide/io/mesh.hpp>
#include <tide/io/motion_table.hpp>
#include <tide/io/scene.hpp>

#include "core/planar.hpp"
#include "json_error_path.hpp"
#include "sources/wave_maker.hpp"

namespace tide::io::scene_reading {

using nlohmann::json;

/// "path.key", or "key" at the top.
inline std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }
/// "path[i]".
std::string indexed(const std::string& path, std::size_t i);
std::string suggestion(std::string_view given, const std::vector<std::string>& known);
std::string show(const json& value);

/// Reads typed values, recording a problem (and returning nothing) for each bad one.
class Reader {
public:
    std::vector<std::string> problems;
    /// The scene's "dimensions": points and vectors have this many components (z = 0 in 2D).
    int dimensions = 3;

    void fail(const std::string& path, const std::string& message) { problems.push_back(path + ": " + message); }

    /// True when j is an object; flags every key not in `known`.
    bool object(const json& j, const std::string& path, std::initializer_list<const char*> known) {
        if (!j.is_object()) {
            fail(path.empty() ? "(scene)" : path, "must be an object, got " + show(j));
            return false;
        }
        const std::vector<std::string> names(known.begin(), known.end());
        for (const auto& [key, value] : j.items())
            if (std::find(names.begin(), names.end(), key) == names.end())
                fail(join(path, key), "unknown key" + suggestion(key, names));
        return true;
    }

    std::optional<double> number(const json& obj, const char* key, const std::string& path, bool required,
                                 double lo, double hi, bool exclusiveLow = false) {
        const std::string where = join(path, key);
        if (!obj.contains(key)) {
            if (required) fail(where, "missing (required)");
            return std::nullopt;
        }
        const json& v = obj.at(key);
        if (!v.is_number()) {
            fail(where, "must be a number, got " + show(v));
            return std::nullopt;
        }
        const double x = v.get<double>();
        if (!std::isfinite(x) || x < lo || x > hi || (exclusiveLow && x <= lo)) {
            std::ostringstream range;
            range << (exclusiveLow ? "> " : ">= ") << lo;
            if (hi < 1e300) range << " and <= " << hi;
            fail(where, "must be " + range.str() + ", got " + show(v));
            return std::nullopt;
        }
        return x;
    }

    /// A point or vector of the scene's space: [x, y, z], or [x, y] in a 2D scene (z = 0).
    /// `components` 3 reads 3 numbers whatever the dimension (a colour).
    std::optional<glm::vec3> vec3(const json& obj, const char* key, const std::string& path, bool required,
                                  int components = 0) {
        const std::string where = join(path, key);
        if (!obj.contains(key)) {
            if (required) fail(where, "missing (required)");
            return std::nullopt;
        }
        const json& v = obj.at(key);
        const int n = components > 0 ? components : dimensions;
        if (!v.is_array() || v.size() != static_cast<std::size_t>(n) ||
            !std::all_of(v.begin(), v.end(), [](const json& e) { return e.is_number(); })) {
            std::string message = n == 2 ? "must be an array of 2 numbers [x, y] (the scene is 2D), got "
                                         : "must be an array of 3 numbers, got ";
            if (components == 0 && n == 3 && v.is_array() && v.size() == 2)
                message = "must be an array of 3 numbers (a 3D scene; [x, y] needs \"dimensions\": 2), got ";
            fail(where, message + show(v));
            return std::nullopt;
        }
        glm::vec3 out(0.0f);
        for (int a = 0; a < n; ++a) {
            const double x = v[static_cast<std::size_t>(a)].get<double>();
            if (!std::isfinite(x) || std::abs(x) > 1e30) {
                fail(where, "must be finite, got " + show(v));
                return std::nullopt;
            }
            out[a] = static_cast<float>(x);
        }
        return out;
    }

    std::optional<std::string> string(const json& obj, const char* key, const std::string& path, bool required) {
        const std::string where = join(path, key);
        if (!obj.contains(key)) {
            if (required) fail(where, "missing (required)");
            return std::nullopt;
        }
        if (!obj.at(key).is_string()) {
            fail(where, "must be a string, got " + show(obj.at(key)));
            return std::nullopt;
        }
        return obj.at(key).get<std::string>();
    }

    std::optional<bool> boolean(const json& obj, const char* key, const std::string& path) {
        if (!obj.contains(key)) return std::nullopt;
        if (!obj.at(key).is_boolean()) {
            fail(join(path, key), "must be true or false, got " + show(obj.at(key)));
            return std::nullopt;
        }
        return obj.at(key).get<bool>();
    }

    /// The "type" of an entry that must be an object with one (an obstacle, a motion).
    std::optional<std::string> typeOf(const json& j, const std::string& path) {
        if (!j.is_object()) {
            fail(path, "must be an object, got " + show(j));
            return std::nullopt;
        }
        return string(j, "type", path, true);
    }

    /// The array at key (empty when absent); flags a non-array.
    const json& array(const json& obj, const char* key, const std::string& path, bool required) {
        static const json empty = json::array();
        if (!obj.contains(key)) {
            if (required) fail(join(path, key), "missing (required)");
            return empty;
        }
        if (!obj.at(key).is_array()) {
            fail(join(path, key), "must be an array, got " + show(obj.at(key)));
            return empty;
        }
        return obj.at(key);
    }
};

bool boxInside(const glm::vec3& min, const glm::vec3& max, const WorldDef& w);
std::string showVec(const glm::vec3& v);
bool readBox(Reader& r, const json& j, const std::string& path, float scale, glm::vec3& min, glm::vec3& max);
std::optional<MaterialIndex> readMaterialRef(Reader& r, const json& obj, const std::string& path, const Scene& scene);
std::optional<glm::vec3> readDirection(Reader& r, const json& j, const char* key, const std::string& path);
std::optional<glm::vec3> readRotationAxis(Reader& r, const json& j, const std::string& path);
std::optional<glm::vec3> readMeshScale(Reader& r, const json& j, const std::string& path);
std::string shownFile(const std::string& named, const std::filesystem::path& resolved);
std::optional<double> wholeNumber(Reader& r, const json& obj, const char* key, const std::string& path, double lo, double hi);
bool checkColumnName(Reader& r, const std::string& name, const std::string& path, std::vector<std::string>& used);

// The sections (scene_solver_reader.cpp, scene_obstacle_reader.cpp, scene_water_reader.cpp).
void readSolver(Reader& r, const json& j, Scene& scene);
void readMaterials(Reader& r, const json& list, Scene& scene, std::vector<std::optional<float>>& ownTension);
void readMaterialPairs(Reader& r, const json& list, Scene& scene, const std::vector<std::optional<float>>& ownTension);
std::optional<ObstacleDef> readObstacle(Reader& r, const json& j, const std::string& path, float scale,
                                        const std::filesystem::path& baseDirectory);
void readWaveMaker(Reader& r, const json& j, Scene& scene, float scale, bool domainOk);
void readOcean(Reader& r, const json& j, Scene& scene, float scale, bool domainOk);
void readDamping(Reader& r, const json& j, Scene& scene, float scale);
void readGaugesAndProbes(Reader& r, const json& root, Scene& scene, float scale, bool domainOk);

}  // namespace tide::io::scene_reading
