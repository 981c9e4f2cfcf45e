// Scene JSON → tide::io::Scene, collecting every problem with its JSON path.
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

namespace tide::io {

namespace {

using nlohmann::json;

std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

std::string indexed(const std::string& path, std::size_t i) {
    std::ostringstream out;
    out << path << '[' << i << ']';
    return out.str();
}

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

void readSolver(Reader& r, const json& j, Scene& scene) {
    const std::string path = "solver";
    if (!r.object(j, path, {"method", "kernel", "equation_of_state", "sound_speed", "cfl", "min_dt", "max_dt", "viscosity",
                            "xsph", "momentum", "shifting", "difference_form", "clamp_negative_pressure", "support_ratio", "max_density_error",
                            "max_divergence_error", "min_iterations", "min_divergence_iterations", "divergence_warm_start",
                            "max_iterations", "constraint_iterations", "vorticity"}))
        return;
    SolverDef& s = scene.world.solver;
    if (auto method = r.string(j, "method", path, false)) {
        const auto known = solverNames();
        if (std::find(known.begin(), known.end(), *method) == known.end()) {
            std::string list;
            for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
            r.fail(join(path, "method"), "unknown solver \"" + *method + "\"" + suggestion(*method, known) +
                                             "; known: " + list);
        } else {
            s.method = *method;
        }
    }
    if (auto kernel = r.string(j, "kernel", path, false)) {
        if (*kernel == "cubic_spline") s.kernel = KernelShape::CubicSpline;
        else if (*kernel == "wendland_c2") s.kernel = KernelShape::WendlandC2;
        else r.fail(join(path, "kernel"), "must be \"cubic_spline\" or \"wendland_c2\", got \"" + *kernel + "\"");
    }
    if (auto eos = r.string(j, "equation_of_state", path, false)) {
        if (*eos == "linear") s.equationOfState = EquationOfState::Linear;
        else if (*eos == "tait") s.equationOfState = EquationOfState::Tait;
        else r.fail(join(path, "equation_of_state"), "must be \"linear\" or \"tait\", got \"" + *eos + "\"");
    }
    if (auto v = r.number(j, "sound_speed", path, false, 0.0, 1e5)) s.soundSpeed = static_cast<float>(*v);
    if (auto v = r.number(j, "cfl", path, false, 0.0, 1.0, true)) s.cflNumber = static_cast<float>(*v);
    if (auto v = r.number(j, "min_dt", path, false, 0.0, 1.0, true)) s.minDt = static_cast<float>(*v);
    if (auto v = r.number(j, "max_dt", path, false, 0.0, 1.0, true)) s.maxDt = static_cast<float>(*v);
    if (s.minDt > s.maxDt) r.fail(join(path, "min_dt"), "must not exceed max_dt");
    if (auto model = r.string(j, "viscosity", path, false)) {
        const auto known = viscosityNames();
        if (std::find(known.begin(), known.end(), *model) == known.end()) {
            std::string list;
            for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
            r.fail(join(path, "viscosity"), "unknown viscosity model \"" + *model + "\"" + suggestion(*model, known) +
                                                "; known: " + list);
        } else {
            s.viscosity = *model;
        }
    }
    if (auto v = r.number(j, "xsph", path, false, 0.0, 1.0)) s.xsph = static_cast<float>(*v);
    if (auto v = r.number(j, "momentum", path, false, 0.0, 0.95)) s.momentum = static_cast<float>(*v);
    if (auto v = r.number(j, "shifting", path, false, 0.0, 1.0)) {
        s.shifting = static_cast<float>(*v);
        if (s.shifting > 0.0f && s.method != "dfsph")
            r.fail(join(path, "shifting"), "only the dfsph solver shifts particles, got solver \"" + s.method + "\"");
    }
    if (auto v = r.number(j, "difference_form", path, false, 0.0, 1.0)) {
        s.differenceForm = static_cast<float>(*v);
        if (s.differenceForm > 0.0f && s.method != "dfsph")
            r.fail(join(path, "difference_form"), "only the dfsph solver takes it, got solver \"" + s.method + "\"");
    }
    if (auto v = r.boolean(j, "clamp_negative_pressure", path)) s.clampNegativePressure = *v;
    if (auto v = r.number(j, "max_density_error", path, false, 0.0, 0.5, true)) s.maxDensityError = static_cast<float>(*v);
    if (auto v = r.number(j, "max_divergence_error", path, false, 0.0, 0.5, true))
        s.maxDivergenceError = static_cast<float>(*v);
    if (auto v = r.number(j, "min_iterations", path, false, 0.0, 1000.0)) s.minIterations = static_cast<int>(*v);
    if (auto v = r.number(j, "min_divergence_iterations", path, false, 0.0, 1000.0))
        s.minDivergenceIterations = static_cast<int>(*v);
    if (auto v = r.number(j, "divergence_warm_start", path, false, 0.0, 1.0)) {
        s.divergenceWarmStart = static_cast<float>(*v);
        if (s.method != "dfsph")
            r.fail(join(path, "divergence_warm_start"), "only the dfsph solver takes it, got solver \"" + s.method + "\"");
    }
    if (auto v = r.number(j, "max_iterations", path, false, 1.0, 10000.0)) s.maxIterations = static_cast<int>(*v);
    if (s.maxIterations < s.minIterations) r.fail(join(path, "max_iterations"), "must not be below min_iterations");
    if (auto v = r.number(j, "constraint_iterations", path, false, 1.0, 100.0)) {
        if (*v != std::floor(*v)) r.fail(join(path, "constraint_iterations"), "must be a whole number, got " + std::to_string(*v));
        s.constraintIterations = static_cast<int>(*v);
    }
    if (auto v = r.number(j, "vorticity", path, false, 0.0, 10.0)) s.vorticity = static_cast<float>(*v);
    if (auto v = r.number(j, "support_ratio", path, false, 1.0, 4.0)) scene.world.supportRatio = static_cast<float>(*v);
    // Wendland C2 wants a wider support than the cubic spline (at 2 spacings a standing wave
    // runs 15 % fast, at 3 within 0.5 %): 3 spacings unless the scene says otherwise.
    else if (s.kernel == KernelShape::WendlandC2) scene.world.supportRatio = kWendlandSupportRatio;
}

/// "materials": [...]; `ownTension` gets each material's `surface_tension` shortcut (the
/// pair of the material with itself, merged into the pairs by readMaterialPairs).
void readMaterials(Reader& r, const json& list, Scene& scene, std::vector<std::optional<float>>& ownTension) {
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string path = indexed("materials", i);
        if (!r.object(list[i], path, {"name", "density", "viscosity", "color", "surface_tension", "adhesion"})) continue;
        MaterialDef m;
        if (auto name = r.string(list[i], "name", path, true)) {
            for (const MaterialDef& other : scene.materials)
                if (other.name == *name) r.fail(join(path, "name"), "\"" + *name + "\" is already used by another material");
            m.name = *name;
        }
        if (auto v = r.number(list[i], "density", path, true, 0.0, 1e6, true)) m.restDensity = static_cast<float>(*v);
        if (auto v = r.number(list[i], "viscosity", path, false, 0.0, 1e6)) m.viscosity = static_cast<float>(*v);
        if (auto v = r.number(list[i], "adhesion", path, false, 0.0, 1e6)) m.adhesion = static_cast<float>(*v);
        std::optional<float> tension;
        if (auto v = r.number(list[i], "surface_tension", path, false, 0.0, 1e6)) tension = static_cast<float>(*v);
        ownTension.push_back(tension);
        if (auto c = r.vec3(list[i], "color", path, false, 3)) {
            if (glm::any(glm::lessThan(*c, glm::vec3(0.0f))) || glm::any(glm::greaterThan(*c, glm::vec3(1.0f))))
                r.fail(join(path, "color"), "components must be in [0, 1], got " + showVec(*c));
            else
                m.color = *c;
        }
        scene.materials.push_back(m);
    }
}

/// "material_pairs": [{"materials": [name, name], "miscible", "diffusivity", "surface_tension"}],
/// then the materials' `surface_tension` shortcuts (`ownTension`, see readMaterials) as the
/// pairs (a, a); a material may not give it both ways.
void readMaterialPairs(Reader& r, const json& list, Scene& scene, const std::vector<std::optional<float>>& ownTension) {
    std::vector<bool> pairGaveTension;  // per scene.materialPairs entry
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string path = indexed("material_pairs", i);
        if (!r.object(list[i], path, {"materials", "miscible", "diffusivity", "surface_tension"})) continue;
        MaterialPairDef pair;
        bool ok = true;
        if (!list[i].contains("materials") || !list[i]["materials"].is_array() || list[i]["materials"].size() != 2 ||
            !list[i]["materials"][0].is_string() || !list[i]["materials"][1].is_string()) {
            r.fail(join(path, "materials"), "must be an array of two material names, got " +
                                                (list[i].contains("materials") ? show(list[i]["materials"]) : std::string("nothing")));
            ok = false;
        } else {
            MaterialIndex* ends[2] = {&pair.a, &pair.b};
            for (std::size_t k = 0; k < 2; ++k) {
                const std::string name = list[i]["materials"][k].get<std::string>();
                bool found = false;
                for (std::size_t m = 0; m < scene.materials.size(); ++m)
                    if (scene.materials[m].name == name) {
                        *ends[k] = static_cast<MaterialIndex>(m);
                        found = true;
                    }
                if (!found) {
                    r.fail(indexed(join(path, "materials"), k), "no material named \"" + name + "\"");
                    ok = false;
                }
            }
        }
        if (auto v = r.boolean(list[i], "miscible", path)) pair.miscible = *v;
        if (auto v = r.number(list[i], "diffusivity", path, false, 0.0, 1e3)) pair.diffusivity = static_cast<float>(*v);
        const auto tension = r.number(list[i], "surface_tension", path, false, 0.0, 1e6);
        if (tension) pair.surfaceTension = static_cast<float>(*tension);
        if (!ok) continue;
        if (pair.a == pair.b && pair.miscible) {
            r.fail(join(path, "miscible"), "a material is always miscible with itself");
        } else if (pair.a != pair.b && !pair.miscible && pair.diffusivity > 0.0f) {
            r.fail(join(path, "diffusivity"), "needs \"miscible\": true between two materials");
        } else {
            scene.materialPairs.push_back(pair);
            pairGaveTension.push_back(list[i].contains("surface_tension"));
        }
    }
    for (std::size_t m = 0; m < ownTension.size() && m < scene.materials.size(); ++m) {
        if (!ownTension[m]) continue;
        const auto own = static_cast<MaterialIndex>(m);
        bool merged = false;
        for (std::size_t k = 0; k < scene.materialPairs.size(); ++k) {
            MaterialPairDef& pair = scene.materialPairs[k];
            if (pair.a != own || pair.b != own) continue;
            if (pairGaveTension[k])
                r.fail(join(indexed("materials", m), "surface_tension"),
                       "\"" + scene.materials[m].name + "\" also has a surface_tension in material_pairs; give it once");
            else
                pair.surfaceTension = *ownTension[m];
            merged = true;
        }
        if (!merged) {
            MaterialPairDef pair;
            pair.a = pair.b = own;
            pair.surfaceTension = *ownTension[m];
            scene.materialPairs.push_back(pair);
        }
    }
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

const std::vector<std::string> kObstacleTypes{"box", "sphere", "cylinder", "plane", "mesh", "circle", "polygon"};

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

const std::vector<std::string> kMotionTypes{"translation", "rotation", "csv"};

/// An obstacle's "motion": a translation, a rotation or a CSV time series (files relative to
/// `baseDirectory`, lengths scaled by `scale`).
std::optional<MotionDef> readMotion(Reader& r, const json& j, const std::string& path, float scale,
                                    const std::filesystem::path& baseDirectory) {
    const auto type = r.typeOf(j, path);
    if (!type) return std::nullopt;
    MotionDef m;
    const std::size_t problemsBefore = r.problems.size();
    const auto startAndRamp = [&](bool ramp) {
        if (auto v = r.number(j, "start_time", path, false, 0.0, 1e7)) m.startTime = *v;
        if (!ramp) return;
        if (auto v = r.number(j, "ramp_time", path, false, 0.0, 1e7)) m.rampTime = static_cast<float>(*v);
    };
    const auto period = [&](bool needed) {  // of the oscillation, needed with an amplitude
        if (auto v = r.number(j, "period", path, needed, 0.0, 1e7, true)) m.period = static_cast<float>(*v);
    };
    if (*type == "translation") {
        if (!r.object(j, path, {"type", "velocity", "amplitude", "period", "start_time", "ramp_time"})) return std::nullopt;
        m.type = MotionDef::Type::Translation;
        if (auto v = r.vec3(j, "velocity", path, false)) m.velocity = *v * scale;
        if (auto v = r.vec3(j, "amplitude", path, false)) m.amplitude = *v * scale;
        if (!j.contains("velocity") && !j.contains("amplitude")) r.fail(path, "needs \"velocity\" or \"amplitude\" (or both)");
        period(j.contains("amplitude"));
        startAndRamp(true);
    } else if (*type == "rotation") {
        if (!r.object(j, path, {"type", "axis", "center", "angular_velocity", "amplitude", "period", "start_time", "ramp_time"}))
            return std::nullopt;
        m.type = MotionDef::Type::Rotation;
        if (auto a = readRotationAxis(r, j, path)) m.axis = *a;
        if (auto c = r.vec3(j, "center", path, true)) m.center = *c * scale;
        if (auto v = r.number(j, "angular_velocity", path, false, -1e6, 1e6)) m.angularVelocity = static_cast<float>(*v);
        if (auto v = r.number(j, "amplitude", path, false, -1e6, 1e6)) m.angularAmplitude = static_cast<float>(*v);
        if (!j.contains("angular_velocity") && !j.contains("amplitude"))
            r.fail(path, "needs \"angular_velocity\" or \"amplitude\" (or both)");
        period(j.contains("amplitude"));
        startAndRamp(true);
    } else if (*type == "csv") {
        if (!r.object(j, path, {"type", "file", "axis", "center", "start_time"})) return std::nullopt;
        m.type = MotionDef::Type::Table;
        startAndRamp(false);
        const auto file = r.string(j, "file", path, true);
        if (!file) return std::nullopt;
        if (file->empty()) {
            r.fail(join(path, "file"), "must name a CSV file (time,x,y,z[,angle]), got \"\"");
            return std::nullopt;
        }
        const std::filesystem::path resolved = baseDirectory / *file;
        try {
            MotionTable table = readMotionTable(resolved, scale);
            m.keys = std::move(table.keys);
            if (table.hasAngle) {
                if (auto a = readRotationAxis(r, j, path)) m.axis = *a;
                if (auto c = r.vec3(j, "center", path, true)) m.center = *c * scale;
            } else if (j.contains("axis") || j.contains("center")) {
                r.fail(path, *file + " has no angle column: \"axis\" and \"center\" would not be used");
            }
        } catch (const MotionTableError& e) {
            r.fail(join(path, "file"), shownFile(*file, resolved) + ": " + e.problem);
        }
    } else {
        std::string list;
        for (const auto& k : kMotionTypes) list += (list.empty() ? "" : ", ") + k;
        r.fail(join(path, "type"), "\"" + *type + "\" is not one of " + list + suggestion(*type, kMotionTypes));
        return std::nullopt;
    }
    if (r.problems.size() != problemsBefore) return std::nullopt;
    return m;
}

/// An obstacle's "dynamic": true and its body's keys (density or mass, center_of_mass,
/// velocity, angular_velocity, constraint.free) into o.dynamics; false on a problem.
bool readBodyDynamics(Reader& r, const json& j, const std::string& path, float scale, ObstacleDef& o) {
    const bool bodyKeys = j.contains("density") || j.contains("mass") || j.contains("center_of_mass") ||
                          j.contains("velocity") || j.contains("angular_velocity") || j.contains("constraint") ||
                          j.contains("moorings");
    if (!j.contains("dynamic") && !bodyKeys) return true;
    const auto dynamic = r.boolean(j, "dynamic", path);
    if (j.contains("dynamic") && !dynamic) return false;
    if (!dynamic.value_or(false)) {
        if (!bodyKeys) return true;  // "dynamic": false, a fixed obstacle
        r.fail(join(path, "dynamic"), "must be true for a body's density, mass, velocity, constraint or moorings");
        return false;
    }
    if (o.shape == ObstacleDef::Shape::Plane) {
        r.fail(join(path, "dynamic"), "a plane cannot be a body (it is infinite); use a box");
        return false;
    }
    if (j.contains("motion")) {
        r.fail(join(path, "motion"), "a dynamic body moves by the fluid's loads, not a prescribed motion; drop one");
        return false;
    }
    if (j.contains("density") == j.contains("mass")) {
        r.fail(join(path, "density"), "a dynamic body needs exactly one of density (kg/m³) and mass (kg)");
        return false;
    }
    const std::size_t before = r.problems.size();
    BodyDynamicsDef body;
    if (auto v = r.number(j, "density", path, false, 0.0, 1e6, true)) body.density = *v;
    if (auto v = r.number(j, "mass", path, false, 0.0, 1e12, true)) body.mass = *v;
    if (j.contains("center_of_mass"))
        if (auto v = r.vec3(j, "center_of_mass", path, false)) body.centerOfMass = *v * scale;
    if (auto v = r.vec3(j, "velocity", path, false)) body.velocity = *v * scale;
    if (auto v = r.vec3(j, "angular_velocity", path, false)) body.angularVelocity = *v;
    if (j.contains("constraint") && r.object(j.at("constraint"), join(path, "constraint"), {"free"})) {
        const std::string where = join(path, "constraint.free");
        const json& free = j.at("constraint").contains("free") ? j.at("constraint").at("free") : json();
        static const std::vector<std::string> kAxes{"x", "y", "z", "rx", "ry", "rz"};
        if (!free.is_array() || free.empty()) {
            r.fail(where, "must list the free axes, of \"x\", \"y\", \"z\", \"rx\", \"ry\", \"rz\", got " + show(free));
        } else {
            for (std::size_t k = 0; k < free.size(); ++k) {
                if (!free[k].is_string() || std::find(kAxes.begin(), kAxes.end(), free[k].get<std::string>()) == kAxes.end())
                    r.fail(indexed(where, k), "unknown axis " + show(free[k]) + ": one of x, y, z, rx, ry, rz");
                else
                    body.freeAxes.push_back(free[k].get<std::string>());
            }
        }
    }
    const json& moorings = r.array(j, "moorings", path, false);
    for (std::size_t k = 0; k < moorings.size(); ++k) {
        const std::string where = indexed(join(path, "moorings"), k);
        if (!r.object(moorings[k], where, {"name", "fairlead", "anchor", "length", "stiffness", "damping"})) continue;
        MooringLineDef line;
        if (auto v = r.string(moorings[k], "name", where, false)) line.name = *v;
        if (auto v = r.vec3(moorings[k], "fairlead", where, true)) line.fairlead = *v * scale;
        if (auto v = r.vec3(moorings[k], "anchor", where, true)) line.anchor = *v * scale;
        if (auto v = r.number(moorings[k], "length", where, true, 0.0, 1e6, true)) line.length = *v * scale;
        if (auto v = r.number(moorings[k], "stiffness", where, true, 0.0, 1e12, true)) line.stiffness = *v;
        if (auto v = r.number(moorings[k], "damping", where, false, 0.0, 1e12)) line.damping = *v;
        body.moorings.push_back(line);
    }
    if (r.problems.size() != before) return false;
    o.dynamics = body;
    return true;
}

/// One entry of "obstacles"; lengths scaled by `scale`, mesh files relative to `baseDirectory`.
std::optional<ObstacleDef> readObstacle(Reader& r, const json& j, const std::string& path, float scale,
                                        const std::filesystem::path& baseDirectory) {
    const auto type = r.typeOf(j, path);
    if (!type) return std::nullopt;
    ObstacleDef o;
    const bool planar = r.dimensions == 2;
    if (planar && (*type == "sphere" || *type == "cylinder" || *type == "mesh")) {
        r.fail(join(path, "type"), "\"" + *type + "\" is a 3D shape; a 2D scene takes \"box\", \"plane\", \"circle\" or \"polygon\"");
        return std::nullopt;
    }
    if (!planar && (*type == "circle" || *type == "polygon")) {
        r.fail(join(path, "type"), "\"" + *type + "\" is a 2D shape; it needs \"dimensions\": 2 (in 3D: \"" +
                                       (*type == "circle" ? "sphere" : "mesh") + "\")");
        return std::nullopt;
    }
    if (planar && j.is_object() && j.contains("dynamic")) {
        r.fail(join(path, "dynamic"), "floating bodies are 3D only");
        return std::nullopt;
    }
    if (*type == "box") {
        if (!r.object(j, path, {"type", "min", "max", "motion", "name", "load_reference", "dynamic", "density", "mass", "center_of_mass", "velocity", "angular_velocity", "constraint", "moorings"})) return std::nullopt;
        if (!readBox(r, j, path, scale, o.min, o.max)) return std::nullopt;
        o.shape = ObstacleDef::Shape::Box;
    } else if (*type == "sphere") {
        if (!r.object(j, path, {"type", "center", "radius", "motion", "name", "load_reference", "dynamic", "density", "mass", "center_of_mass", "velocity", "angular_velocity", "constraint", "moorings"})) return std::nullopt;
        const auto c = r.vec3(j, "center", path, true);
        const auto radius = r.number(j, "radius", path, true, 0.0, 1e6, true);
        if (!c || !radius) return std::nullopt;
        o.shape = ObstacleDef::Shape::Sphere;
        o.center = *c * scale;
        o.radius = static_cast<float>(*radius) * scale;
    } else if (*type == "cylinder") {
        if (!r.object(j, path, {"type", "center", "axis", "radius", "length", "motion", "name", "load_reference", "dynamic", "density", "mass", "center_of_mass", "velocity", "angular_velocity", "constraint", "moorings"})) return std::nullopt;
        const auto c = r.vec3(j, "center", path, true);
        const auto axis = readDirection(r, j, "axis", path);
        const auto radius = r.number(j, "radius", path, true, 0.0, 1e6, true);
        const auto length = r.number(j, "length", path, true, 0.0, 1e6, true);
        if (!c || !axis || !radius || !length) return std::nullopt;
        o.shape = ObstacleDef::Shape::Cylinder;
        o.center = *c * scale;
        o.axis = *axis;
        o.radius = static_cast<float>(*radius) * scale;
        o.length = static_cast<float>(*length) * scale;
    } else if (*type == "circle") {
        if (!r.object(j, path, {"type", "center", "radius", "motion", "name", "load_reference"})) return std::nullopt;
        const auto c = r.vec3(j, "center", path, true);
        const auto radius = r.number(j, "radius", path, true, 0.0, 1e6, true);
        if (!c || !radius) return std::nullopt;
        o.shape = ObstacleDef::Shape::Circle;
        o.center = *c * scale;
        o.radius = static_cast<float>(*radius) * scale;
    } else if (*type == "polygon") {
        if (!r.object(j, path, {"type", "points", "motion", "name", "load_reference"})) return std::nullopt;
        const json& points = r.array(j, "points", path, true);
        const std::size_t before = r.problems.size();
        for (std::size_t k = 0; k < points.size(); ++k) {
            const json holder = {{"p", points[k]}};
            if (auto c = r.vec3(holder, "p", path, true)) o.polygon.emplace_back(c->x * scale, c->y * scale);
            else r.problems.back() = indexed(join(path, "points"), k) + r.problems.back().substr(r.problems.back().find(':'));
        }
        if (r.problems.size() != before || !j.contains("points")) return std::nullopt;
        try {
            validatePolygon(o.polygon);
        } catch (const std::invalid_argument& e) {
            const std::string what = e.what();
            r.fail(join(path, "points"), what.substr(what.find(": ") + 2));
            return std::nullopt;
        }
        o.shape = ObstacleDef::Shape::Polygon;
    } else if (*type == "plane") {
        if (!r.object(j, path, {"type", "point", "normal", "motion", "name", "load_reference", "dynamic", "density", "mass", "center_of_mass", "velocity", "angular_velocity", "constraint", "moorings"})) return std::nullopt;
        const auto point = r.vec3(j, "point", path, true);
        const auto normal = readDirection(r, j, "normal", path);
        if (!point || !normal) return std::nullopt;
        o.shape = ObstacleDef::Shape::Plane;
        o.point = *point * scale;
        o.normal = *normal;
    } else if (*type == "mesh") {
        if (!r.object(j, path, {"type", "file", "scale", "rotate", "translate", "motion", "name", "load_reference", "dynamic", "density", "mass", "center_of_mass", "velocity", "angular_velocity", "constraint", "moorings"})) return std::nullopt;
        const auto file = r.string(j, "file", path, true);
        MeshPlacement placement;
        const auto meshScale = readMeshScale(r, j, path);
        bool ok = meshScale.has_value();
        if (meshScale) placement.scale = *meshScale;
        if (j.contains("rotate")) {
            if (auto v = r.vec3(j, "rotate", path, false)) placement.rotateDegrees = *v;
            else ok = false;
        }
        if (j.contains("translate")) {
            if (auto v = r.vec3(j, "translate", path, false)) placement.translate = *v;
            else ok = false;
        }
        if (!file || !ok) return std::nullopt;
        if (file->empty()) {
            r.fail(join(path, "file"), "must name a mesh file (.obj or .ply), got \"\"");
            return std::nullopt;
        }
        // unit_scale converts the placed mesh to metres.
        placement.scale *= scale;
        placement.translate *= scale;
        const std::filesystem::path resolved = baseDirectory / *file;
        try {
            o.mesh = loadMesh(resolved, placement);
        } catch (const MeshError& e) {
            r.fail(join(path, "file"), shownFile(*file, resolved) + ": " + e.problem);
            return std::nullopt;
        }
        o.shape = ObstacleDef::Shape::Mesh;
    } else {
        r.fail(join(path, "type"), "must be \"box\", \"sphere\", \"cylinder\", \"plane\" or \"mesh\" (in 2D \"box\", \"plane\", \"circle\" or \"polygon\"), got \"" + *type +
                                       "\"" + suggestion(*type, kObstacleTypes));
        return std::nullopt;
    }
    if (j.contains("name")) {
        const auto name = r.string(j, "name", path, false);
        if (!name) return std::nullopt;
        const bool plain = !name->empty() && std::all_of(name->begin(), name->end(), [](char c) {
            return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
        });
        // It heads forces.csv's columns, beside the walls' and wave makers' own.
        if (!plain || name->rfind("wall_", 0) == 0 || name->rfind("wavemaker", 0) == 0) {
            r.fail(join(path, "name"), "must be letters, digits, _ or -, not starting with wall_ or wavemaker, got \"" + *name + "\"");
            return std::nullopt;
        }
        o.name = *name;
    }
    if (j.contains("load_reference")) {
        const auto point = r.vec3(j, "load_reference", path, false);
        if (!point) return std::nullopt;
        o.loadReference = *point * scale;
    }
    if (!readBodyDynamics(r, j, path, scale, o)) return std::nullopt;
    if (j.contains("motion")) {
        if (o.shape == ObstacleDef::Shape::Plane) {
            r.fail(join(path, "motion"), "a plane cannot move (it is infinite); use a box");
            return std::nullopt;
        }
        auto motion = readMotion(r, j.at("motion"), join(path, "motion"), scale, baseDirectory);
        if (!motion) return std::nullopt;
        o.motion = std::move(*motion);
    }
    return o;
}

/// "wavemaker": a piston or flap paddle making regular waves (wave_height, period) or an
/// irregular sea (spectrum). Lengths scaled by `scale`.
void readWaveMaker(Reader& r, const json& j, Scene& scene, float scale, bool domainOk) {
    const std::string path = "wavemaker";
    if (!r.object(j, path, {"type", "x", "depth", "wave_height", "period", "ramp_time", "spectrum", "order"}))
        return;
    WaveMakerDef w;
    bool ok = true;
    if (auto type = r.string(j, "type", path, true)) {
        if (*type == "piston") w.type = WaveMakerDef::Type::Piston;
        else if (*type == "flap") w.type = WaveMakerDef::Type::Flap;
        else if (*type == "solitary") w.type = WaveMakerDef::Type::Solitary;
        else {
            r.fail(join(path, "type"), "must be \"piston\", \"flap\" or \"solitary\", got \"" + *type + "\"" +
                                           suggestion(*type, {"piston", "flap", "solitary"}));
            ok = false;
        }
    } else {
        ok = false;
    }
    const auto x = r.number(j, "x", path, true, -1e6, 1e6);
    const auto depth = r.number(j, "depth", path, true, 0.0, 1e300, true);
    const auto ramp = r.number(j, "ramp_time", path, false, 0.0, 1e300);
    ok = ok && x && depth;
    if (x) w.x = static_cast<float>(*x) * scale;
    if (depth) w.depth = static_cast<float>(*depth) * scale;
    if (ramp) w.rampTime = static_cast<float>(*ramp);
    if (auto order = r.number(j, "order", path, false, 1.0, 2.0)) {
        if (*order != std::floor(*order)) r.fail(join(path, "order"), "must be 1 or 2, got " + show(j.at("order")));
        w.order = static_cast<int>(*order);
    }
    const WorldDef& world = scene.world;
    if (x && domainOk && !(w.x > world.domainMin.x && w.x < world.domainMax.x)) {
        std::ostringstream msg;
        msg << "must lie inside the domain (" << world.domainMin.x / scale << ", " << world.domainMax.x / scale
            << "), got " << *x;
        r.fail(join(path, "x"), msg.str());
        ok = false;
    }
    if (depth && domainOk && w.depth > world.domainMax.y - world.domainMin.y) {
        std::ostringstream msg;
        msg << "must not exceed the domain height " << (world.domainMax.y - world.domainMin.y) / scale << ", got " << *depth;
        r.fail(join(path, "depth"), msg.str());
        ok = false;
    }
    const bool regular = j.contains("wave_height") || j.contains("period");
    if (w.type == WaveMakerDef::Type::Solitary) {
        // One solitary wave of wave_height (Goring 1978): no period, no spectrum.
        for (const char* key : {"period", "spectrum"})
            if (j.contains(key)) {
                r.fail(join(path, key), "a solitary wave has only a wave_height, got " + show(j.at(key)));
                ok = false;
            }
        const auto height = r.number(j, "wave_height", path, true, 0.0, 1e300, true);
        ok = ok && height;
        if (height) w.waveHeight = static_cast<float>(*height) * scale;
    } else if (j.contains("spectrum")) {
        if (regular) {
            r.fail(path, "give either spectrum (irregular waves) or wave_height and period (regular waves), not both");
            return;
        }
        const std::string sp = join(path, "spectrum");
        const json& s = j.at("spectrum");
        if (!r.object(s, sp, {"type", "hs", "tp", "gamma", "seed", "components", "min_frequency", "max_frequency"}))
            return;
        WaveSpectrumDef& d = w.spectrum;
        if (auto type = r.string(s, "type", sp, true)) {
            if (*type == "jonswap") d.type = WaveSpectrumDef::Type::Jonswap;
            else if (*type == "pierson_moskowitz") d.type = WaveSpectrumDef::Type::PiersonMoskowitz;
            else {
                r.fail(join(sp, "type"), "must be \"jonswap\" or \"pierson_moskowitz\", got \"" + *type + "\"" +
                                             suggestion(*type, {"jonswap", "pierson_moskowitz"}));
                ok = false;
            }
        } else {
            ok = false;
        }
        const auto hs = r.number(s, "hs", sp, true, 0.0, 1e300, true);
        const auto tp = r.number(s, "tp", sp, true, 0.0, 1e300, true);
        ok = ok && hs && tp;
        if (hs) d.significantHeight = static_cast<float>(*hs) * scale;
        if (tp) d.peakPeriod = static_cast<float>(*tp);
        if (auto v = r.number(s, "gamma", sp, false, 1.0, 20.0)) d.gamma = static_cast<float>(*v);
        if (auto v = r.number(s, "seed", sp, false, 0.0, 4294967295.0)) {
            if (*v != std::floor(*v)) r.fail(join(sp, "seed"), "must be a whole number, got " + show(s.at("seed")));
            d.seed = static_cast<std::uint32_t>(*v);
        }
        if (auto v = r.number(s, "components", sp, false, 1.0, 10000.0)) {
            if (*v != std::floor(*v)) r.fail(join(sp, "components"), "must be a whole number, got " + show(s.at("components")));
            d.components = static_cast<int>(*v);
        }
        if (auto v = r.number(s, "min_frequency", sp, false, 0.0, 100.0, true)) d.minFrequency = static_cast<float>(*v);
        if (auto v = r.number(s, "max_frequency", sp, false, 0.0, 100.0, true)) d.maxFrequency = static_cast<float>(*v);
        if (!(d.maxFrequency > d.minFrequency)) {
            r.fail(join(sp, "max_frequency"), "must exceed min_frequency");
            ok = false;
        }
    } else {
        const auto height = r.number(j, "wave_height", path, true, 0.0, 1e300, true);
        const auto period = r.number(j, "period", path, true, 0.0, 1e300, true);
        ok = ok && height && period;
        if (height) w.waveHeight = static_cast<float>(*height) * scale;
        if (period) w.period = static_cast<float>(*period);
        if (height && depth && w.waveHeight >= w.depth) {
            r.fail(join(path, "wave_height"), "must be below the depth " + show(j.at("depth")) + ", got " +
                                                  show(j.at("wave_height")));
            ok = false;
        }
    }
    if (ok && domainOk && glm::length(world.gravity) > 0.0f && world.particleSpacing > 0.0f) {
        // A wave the tank or the spacing cannot hold (the World refuses it too; here so that
        // `tide validate` does): the check's message starts with the field.
        try {
            checkWaveFitsTank(w, world.domainMax.x - w.x, world.particleSpacing, glm::length(world.gravity));
        } catch (const std::invalid_argument& e) {
            const std::string message = e.what();
            const std::size_t colon = message.find(": ");
            r.fail(message.substr(0, colon), colon == std::string::npos ? message : message.substr(colon + 2));
            ok = false;
        }
    }
    if (ok) scene.waveMakers.push_back(w);
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

/// "ocean": the far-field sea around the near field (the domain): depth, waves, zone_width,
/// open_sides (issue 43's contract keys). Lengths scaled by `scale`.
void readOcean(Reader& r, const json& j, Scene& scene, float scale, bool domainOk) {
    const std::string path = "ocean";
    if (!r.object(j, path, {"depth", "waves", "zone_width", "open_sides"})) return;
    OceanDef def;
    bool ok = true;
    if (auto v = r.number(j, "depth", path, true, 0.0, 1e300, true)) def.depth = *v * scale;
    else ok = false;
    if (auto v = r.number(j, "zone_width", path, false, 0.0, 1e300)) def.zoneWidth = *v * scale;
    else ok = ok && !j.contains("zone_width");

    const json& sides = r.array(j, "open_sides", path, false);
    const std::vector<std::string> sideNames{"-x", "+x", "-z", "+z"};
    for (std::size_t i = 0; i < sides.size(); ++i) {
        const std::string where = indexed("ocean.open_sides", i);
        const auto found = sides[i].is_string()
                               ? std::find(sideNames.begin(), sideNames.end(), sides[i].get<std::string>())
                               : sideNames.end();
        if (found == sideNames.end()) {
            r.fail(where, "must be \"-x\", \"+x\", \"-z\" or \"+z\", got " + show(sides[i]) +
                              (sides[i].is_string() ? suggestion(sides[i].get<std::string>(), sideNames) : ""));
            ok = false;
            continue;
        }
        def.openSides.push_back(static_cast<OceanSide>(found - sideNames.begin()));
    }

    const std::string wp = "ocean.waves";
    if (!j.contains("waves")) {
        r.fail(wp, "missing (required)");
        return;
    }
    const json& w = j.at("waves");
    if (!r.object(w, wp, {"type", "height", "period", "hs", "tp", "direction", "spreading", "gamma", "seed",
                          "components", "directions"}))
        return;
    OceanWavesDef& waves = def.waves;
    const std::vector<std::string> types{"regular", "jonswap", "pierson_moskowitz"};
    const auto type = r.string(w, "type", wp, true);
    if (!type) return;
    if (*type == "regular") waves.type = OceanWavesDef::Type::Regular;
    else if (*type == "jonswap") waves.type = OceanWavesDef::Type::Jonswap;
    else if (*type == "pierson_moskowitz") waves.type = OceanWavesDef::Type::PiersonMoskowitz;
    else {
        r.fail(join(wp, "type"), "must be \"regular\", \"jonswap\" or \"pierson_moskowitz\", got \"" + *type + "\"" +
                                     suggestion(*type, types));
        return;
    }
    const bool regular = waves.type == OceanWavesDef::Type::Regular;
    // Keys of the other kind of sea are mistakes, not ignored.
    static const std::vector<const char*> spectrumKeys{"hs", "tp", "gamma", "spreading", "components", "directions"};
    static const std::vector<const char*> regularKeys{"height", "period"};
    for (const char* key : regular ? spectrumKeys : regularKeys)
        if (w.contains(key)) {
            r.fail(join(wp, key), std::string("does not apply to ") + (regular ? "regular waves" : "a spectrum (type \"" + *type + "\")"));
            ok = false;
        }
    if (regular) {
        if (auto v = r.number(w, "height", wp, true, 0.0, 1e300, true)) waves.height = *v * scale;
        else ok = false;
        if (auto v = r.number(w, "period", wp, true, 0.0, 1e300, true)) waves.period = *v;
        else ok = false;
    } else {
        if (auto v = r.number(w, "hs", wp, true, 0.0, 1e300, true)) waves.hs = *v * scale;
        else ok = false;
        if (auto v = r.number(w, "tp", wp, true, 0.0, 1e300, true)) waves.tp = *v;
        else ok = false;
        if (w.contains("gamma")) {
            if (waves.type != OceanWavesDef::Type::Jonswap) {
                r.fail(join(wp, "gamma"), "applies to a jonswap spectrum (pierson_moskowitz has gamma 1)");
                ok = false;
            } else if (auto v = r.number(w, "gamma", wp, false, 1.0, 7.0)) {
                waves.gamma = *v;
            } else {
                ok = false;
            }
        }
        if (w.contains("spreading")) {
            if (auto v = r.number(w, "spreading", wp, false, 0.0, 1000.0, true)) waves.spreading = *v;
            else ok = false;
        }
        if (auto v = wholeNumber(r, w, "components", wp, 1.0, 4096.0)) waves.components = static_cast<int>(*v);
        else ok = ok && !w.contains("components");
        if (auto v = wholeNumber(r, w, "directions", wp, 0.0, 360.0)) waves.directions = static_cast<int>(*v);
        else ok = ok && !w.contains("directions");
    }
    if (auto v = r.number(w, "direction", wp, false, -360.0, 360.0)) waves.direction = *v;
    else ok = ok && !w.contains("direction");
    if (auto v = wholeNumber(r, w, "seed", wp, 0.0, 9007199254740992.0)) waves.seed = static_cast<std::uint64_t>(*v);
    else ok = ok && !w.contains("seed");
    if (!ok) return;

    // What only the whole definition tells (directions without spreading, a side twice).
    try {
        validateOcean(def);
    } catch (const std::invalid_argument& e) {
        r.problems.push_back(e.what());
        return;
    }
    const WorldDef& world = scene.world;
    if (domainOk) {
        const float height = world.domainMax.y - world.domainMin.y;
        if (def.depth > height) {
            std::ostringstream msg;
            msg << "must not exceed the domain height " << height / scale << ", got " << j.at("depth").dump();
            r.fail("ocean.depth", msg.str());
            return;
        }
        const double g = std::max(1e-6, static_cast<double>(glm::length(world.gravity)));
        const double width = oceanZoneWidth(def, g);
        bool tooWide[3] = {false, false, false};  // reported once per axis
        for (std::size_t i = 0; i < def.openSides.size(); ++i) {
            const OceanSide side = def.openSides[i];
            const int axis = side == OceanSide::MinusX || side == OceanSide::PlusX ? 0 : 2;
            const char* axisName = axis == 0 ? "x" : "z";
            const std::string where = indexed("ocean.open_sides", i);
            if (world.periodic[axis]) {
                r.fail(where, std::string(oceanSideName(side)) + " is on the periodic " + axisName +
                                  " axis (domain.periodic): it cannot also be open");
                continue;
            }
            if (side == OceanSide::MinusX && !scene.waveMakers.empty()) {
                r.fail(where, "-x has the wave maker (wavemaker) on it: a side is either open or a paddle");
                continue;
            }
            // The zones of both faces of an axis must fit in the region side by side.
            const auto opposite = static_cast<OceanSide>(static_cast<int>(side) ^ 1);
            const bool both = std::find(def.openSides.begin(), def.openSides.end(), opposite) != def.openSides.end();
            const double extent = world.domainMax[axis] - world.domainMin[axis];
            if ((both ? 2.0 : 1.0) * width > extent && !tooWide[axis]) {
                tooWide[axis] = true;
                std::ostringstream msg;
                msg << "its zone (zone_width " << width / scale << (def.zoneWidth > 0.0 ? "" : ", one peak wavelength")
                    << (both ? ", twice: both faces of " : " along ") << axisName << ") is wider than the domain's "
                    << extent / scale << " along " << axisName;
                r.fail(def.zoneWidth > 0.0 ? "ocean.zone_width" : where, msg.str());
            }
        }
    }
    scene.ocean = def;
}

/// "damping": one zone or a list of zones.
void readDamping(Reader& r, const json& j, Scene& scene, float scale) {
    const auto readZone = [&](const json& z, const std::string& path) {
        if (!r.object(z, path, {"x_start", "x_end", "strength"})) return;
        DampingZoneDef d;
        const auto start = r.number(z, "x_start", path, true, -1e6, 1e6);
        const auto end = r.number(z, "x_end", path, true, -1e6, 1e6);
        if (auto v = r.number(z, "strength", path, false, 0.0, 1e300, true)) d.strength = static_cast<float>(*v);
        if (!start || !end) return;
        if (*start == *end) {
            r.fail(join(path, "x_end"), "must differ from x_start, got " + show(z.at("x_end")));
            return;
        }
        d.xStart = static_cast<float>(*start) * scale;
        d.xEnd = static_cast<float>(*end) * scale;
        scene.dampingZones.push_back(d);
    };
    if (j.is_array())
        for (std::size_t i = 0; i < j.size(); ++i) readZone(j[i], indexed("damping", i));
    else
        readZone(j, "damping");
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

void readGaugesAndProbes(Reader& r, const json& root, Scene& scene, float scale, bool domainOk) {
    std::vector<std::string> used;
    const WorldDef& w = scene.world;
    const json& gauges = r.array(root, "gauges", "", false);
    for (std::size_t i = 0; i < gauges.size(); ++i) {
        const std::string path = indexed("gauges", i);
        if (r.dimensions == 2 && gauges[i].is_object() && gauges[i].contains("z")) {
            r.fail(join(path, "z"), "a 2D scene has no z: a gauge stands at x alone");
            continue;
        }
        if (!r.object(gauges[i], path, {"name", "x", "z"})) continue;
        const auto name = r.string(gauges[i], "name", path, true);
        const auto x = r.number(gauges[i], "x", path, true, -1e6, 1e6);
        const auto z = r.number(gauges[i], "z", path, false, -1e6, 1e6);
        if (!name || !x || !checkColumnName(r, *name, path, used)) continue;
        GaugeDef g{*name, static_cast<float>(*x) * scale, z ? static_cast<float>(*z) * scale : 0.5f * (w.domainMin.z + w.domainMax.z)};
        // With an ocean, a gauge outside the near field reads the far field.
        if (domainOk && !scene.ocean && (g.x < w.domainMin.x || g.x > w.domainMax.x || g.z < w.domainMin.z || g.z > w.domainMax.z)) {
            r.fail(path, "(x, z) = (" + show(gauges[i].at("x")) + ", " + (z ? show(gauges[i].at("z")) : std::string("centre")) +
                             ") lies outside the domain");
            continue;
        }
        scene.gauges.push_back(g);
    }
    const json& probes = r.array(root, "probes", "", false);
    for (std::size_t i = 0; i < probes.size(); ++i) {
        const std::string path = indexed("probes", i);
        if (!r.object(probes[i], path, {"name", "position"})) continue;
        const auto name = r.string(probes[i], "name", path, true);
        const auto position = r.vec3(probes[i], "position", path, true);
        if (!name || !position || !checkColumnName(r, *name, path, used)) continue;
        const glm::vec3 x = *position * scale;
        if (domainOk && !boxInside(x, x, w)) {
            r.fail(join(path, "position"), "lies outside the domain, got " + showVec(*position));
            continue;
        }
        scene.probes.push_back({*name, x});
    }
}

}  // namespace

SceneError::SceneError(std::vector<std::string> list)
    : std::runtime_error(list.empty() ? "bad scene" : list.front()), problems(std::move(list)) {}

Scene parseScene(std::string_view text, const std::string& source, const std::filesystem::path& baseDirectory) {
    json root;
    try {
        root = json::parse(text.begin(), text.end());
    } catch (const json::parse_error& e) {
        // e.byte is the 1-based offset where parsing failed; turn it into line:column.
        std::size_t line = 1, column = 1;
        for (std::size_t k = 0; k + 1 < e.byte && k < text.size(); ++k) {
            if (text[k] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        std::string message = e.what();
        const auto colon = message.find(": ", message.find("column"));
        if (colon != std::string::npos) message = message.substr(colon + 2);
        std::ostringstream out;
        out << source << ':' << line << ':' << column << ": " << message;
        throw SceneError({out.str()});
    } catch (const json::out_of_range& e) {
        // A number beyond double ("1e400"): nlohmann names the literal but not where it is.
        // Found by fuzzing: it escaped as an uncaught exception and aborted `tide validate`.
        const std::string message = e.what();
        const auto open = message.find('\''), close = message.rfind('\'');
        const std::string literal = open < close ? message.substr(open + 1, close - open - 1) : std::string();
        const auto at = literal.empty() ? std::string_view::npos : text.find(literal);
        std::size_t line = 1, column = 1;
        for (std::size_t k = 0; at != std::string_view::npos && k < at; ++k) {
            if (text[k] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        std::ostringstream out;
        out << source << ':' << line << ':' << column << ": ";
        if (const std::string path = jsonPathWhereParsingStops(text); !path.empty()) out << path << ": ";
        out << "number " << literal << " is out of range (beyond double precision's 1.8e308)";
        throw SceneError({out.str()});
    }

    Reader r;
    Scene scene;
    if (!r.object(root, "", {"name", "dimensions", "unit_scale", "domain", "gravity", "particle_spacing", "end_time", "settle", "solver",
                             "materials", "material_pairs", "blocks", "emitters", "obstacles", "wavemaker", "damping", "ocean", "gauges", "probes", "output", "camera"}))
        throw SceneError(r.problems);

    float scale = 1.0f;
    if (auto v = r.number(root, "unit_scale", "", false, 0.0, 1e6, true)) scale = static_cast<float>(*v);
    if (auto name = r.string(root, "name", "", false)) scene.name = *name;

    WorldDef& w = scene.world;
    if (root.contains("dimensions")) {
        const json& d = root["dimensions"];
        if (d.is_number_integer() && (d.get<long long>() == 2 || d.get<long long>() == 3))
            r.dimensions = static_cast<int>(d.get<long long>());
        else
            r.fail("dimensions", "must be 2 or 3, got " + show(d));
    }
    w.dimensions = r.dimensions;
    bool domainOk = false;
    if (!root.contains("domain")) {
        r.fail("domain", "missing (required)");
    } else if (r.object(root["domain"], "domain", {"min", "max", "periodic"})) {
        glm::vec3 lo, hi;
        if (readBox(r, root["domain"], "domain", scale, lo, hi)) {
            if (lo.x == hi.x || lo.y == hi.y || (r.dimensions == 3 && lo.z == hi.z)) {
                r.fail("domain.max", "must exceed min on every axis, got " + showVec(hi / scale));
            } else {
                w.domainMin = lo;
                w.domainMax = hi;
                domainOk = true;
            }
        }
        if (root["domain"].contains("periodic")) {
            const json& v = root["domain"]["periodic"];
            const auto isBool = [](const json& e) { return e.is_boolean(); };
            const std::size_t n = static_cast<std::size_t>(r.dimensions);
            if (!v.is_array() || v.size() != n || !std::all_of(v.begin(), v.end(), isBool))
                r.fail("domain.periodic", std::string("must be an array of ") +
                                              (n == 2 ? "2 booleans (x, y) in a 2D scene" : "3 booleans (x, y, z)") +
                                              ", got " + show(v));
            else
                for (std::size_t a = 0; a < n; ++a) w.periodic[static_cast<int>(a)] = v[a].get<bool>();
        }
    }
    if (auto g = r.vec3(root, "gravity", "", false)) w.gravity = *g * scale;
    if (auto v = r.number(root, "particle_spacing", "", true, 0.0, 1e6, true)) w.particleSpacing = static_cast<float>(*v) * scale;
    if (auto v = r.number(root, "end_time", "", true, 0.0, 1e7, true)) scene.endTime = *v;
    if (root.contains("settle") && r.object(root["settle"], "settle", {"time", "speed"})) {
        if (auto v = r.number(root["settle"], "time", "settle", true, 0.0, 1e7)) scene.settleTime = *v;
        if (auto v = r.number(root["settle"], "speed", "settle", false, 0.0, 1e6)) scene.settleSpeed = static_cast<float>(*v) * scale;
    }
    if (root.contains("solver")) readSolver(r, root["solver"], scene);

    if (domainOk) {
        const float support = w.particleSpacing * w.supportRatio;
        for (int a = 0; a < 3; ++a) {
            const float extent = w.domainMax[a] - w.domainMin[a];
            if (w.periodic[a] && !(extent >= 2.0f * support)) {
                std::ostringstream msg;
                msg << "the periodic " << "xyz"[a] << " axis is " << extent / scale
                    << " long, less than 2 kernel supports (2 × " << support / scale
                    << "); lengthen it or make particle_spacing smaller";
                r.fail("domain.periodic", msg.str());
            }
        }
    }

    std::vector<std::optional<float>> ownTension;
    readMaterials(r, r.array(root, "materials", "", true), scene, ownTension);
    if (root.contains("materials") && root["materials"].is_array() && root["materials"].empty())
        r.fail("materials", "must list at least one material");
    readMaterialPairs(r, r.array(root, "material_pairs", "", false), scene, ownTension);

    const json& obstacles = r.array(root, "obstacles", "", false);
    for (std::size_t i = 0; i < obstacles.size(); ++i)
        if (auto o = readObstacle(r, obstacles[i], indexed("obstacles", i), scale, baseDirectory))
            scene.obstacles.push_back(std::move(*o));
    // A mooring's anchor is fixed in the domain (the body system's walls hold it).
    if (domainOk && scene.obstacles.size() == obstacles.size())
        for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
            if (!scene.obstacles[i].dynamics) continue;
            const auto& lines = scene.obstacles[i].dynamics->moorings;
            for (std::size_t k = 0; k < lines.size(); ++k)
                if (!boxInside(lines[k].anchor, lines[k].anchor, scene.world))
                    r.fail(indexed(indexed("obstacles", i) + ".moorings", k) + ".anchor",
                           "must lie inside the domain " + showVec(scene.world.domainMin / scale) + " to " +
                               showVec(scene.world.domainMax / scale) + ", got " + showVec(lines[k].anchor / scale));
        }
    // Names head forces.csv's columns: one each, the unnamed ones' "obstacle<k>" included.
    for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
        const auto nameOf = [&](std::size_t k) {
            return scene.obstacles[k].name.empty() ? "obstacle" + std::to_string(k) : scene.obstacles[k].name;
        };
        for (std::size_t k = 0; k < i; ++k)
            if (nameOf(k) == nameOf(i)) {
                r.fail(indexed("obstacles", i) + ".name", "\"" + nameOf(i) + "\" is already the name of " + indexed("obstacles", k));
                break;
            }
    }

    if (root.contains("wavemaker")) readWaveMaker(r, root["wavemaker"], scene, scale, domainOk);
    if (root.contains("damping")) readDamping(r, root["damping"], scene, scale);
    if (root.contains("ocean") && r.dimensions == 2) r.fail("ocean", "an ocean zone is 3D only; a 2D scene makes waves with \"wavemaker\"");
    else if (root.contains("ocean")) readOcean(r, root["ocean"], scene, scale, domainOk);
    readGaugesAndProbes(r, root, scene, scale, domainOk);

    const json& blocks = r.array(root, "blocks", "", false);
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const std::string path = indexed("blocks", i);
        if (!r.object(blocks[i], path, {"min", "max", "velocity", "material", "concentration"})) continue;
        BlockDef b;
        if (auto c = r.number(blocks[i], "concentration", path, false, 0.0, 1e6)) b.concentration = static_cast<float>(*c);
        const bool boxOk = readBox(r, blocks[i], path, scale, b.min, b.max);
        if (auto v = r.vec3(blocks[i], "velocity", path, false)) b.velocity = *v * scale;
        const auto material = readMaterialRef(r, blocks[i], path, scene);
        if (!boxOk || !material) continue;
        b.material = *material;
        if (domainOk && !boxInside(b.min, b.max, w)) {
            r.fail(path, "box " + showVec(b.min / scale) + ".." + showVec(b.max / scale) +
                             " lies outside the domain " + showVec(w.domainMin / scale) + ".." + showVec(w.domainMax / scale));
            continue;
        }
        scene.blocks.push_back(b);
    }

    const json& emitters = r.array(root, "emitters", "", false);
    for (std::size_t i = 0; i < emitters.size(); ++i) {
        const std::string path = indexed("emitters", i);
        if (!r.object(emitters[i], path, {"min", "max", "velocity", "material", "start", "end", "concentration"})) continue;
        EmitterDef e;
        if (auto c = r.number(emitters[i], "concentration", path, false, 0.0, 1e6)) e.concentration = static_cast<float>(*c);
        const bool boxOk = readBox(r, emitters[i], path, scale, e.min, e.max);
        const auto v = r.vec3(emitters[i], "velocity", path, true);
        if (v && glm::length(*v) == 0.0f) r.fail(join(path, "velocity"), "must be non-zero, got [0, 0, 0]");
        const auto start = r.number(emitters[i], "start", path, false, 0.0, 1e7);
        const auto end = r.number(emitters[i], "end", path, false, 0.0, 1e7);
        const auto material = readMaterialRef(r, emitters[i], path, scene);
        if (start) e.start = *start;
        if (end) e.end = *end;
        if (start && end && *end <= *start) r.fail(join(path, "end"), "must be after start");
        if (!boxOk || !v || glm::length(*v) == 0.0f || !material) continue;
        e.velocity = *v * scale;
        e.material = *material;
        if (domainOk && !boxInside(e.min, e.max, w)) {
            r.fail(path, "outlet " + showVec(e.min / scale) + ".." + showVec(e.max / scale) + " lies outside the domain");
            continue;
        }
        scene.emitters.push_back(e);
    }

    if (root.contains("output") && r.object(root["output"], "output", {"fps", "formats"})) {
        const json& out = root["output"];
        if (auto fps = r.number(out, "fps", "output", false, 0.0, 1e4, true)) scene.output.fps = *fps;
        if (out.contains("formats")) {
            scene.output.formats.clear();
            const json& formats = r.array(out, "formats", "output", false);
            for (std::size_t i = 0; i < formats.size(); ++i) {
                const std::string path = indexed("output.formats", i);
                const auto f = formats[i].is_string() ? parseFormat(formats[i].get<std::string>()) : std::nullopt;
                if (!f) r.fail(path, "must be \"vtu\", \"ply\", \"csv\" or \"obj\", got " + show(formats[i]));
                else if (std::find(scene.output.formats.begin(), scene.output.formats.end(), *f) == scene.output.formats.end())
                    scene.output.formats.push_back(*f);
            }
        }
    }

    if (root.contains("camera") && r.object(root["camera"], "camera", {"eye", "target", "fov"})) {
        const json& cam = root["camera"];
        const auto eye = r.vec3(cam, "eye", "camera", true);
        const auto target = r.vec3(cam, "target", "camera", true);
        const auto fov = r.number(cam, "fov", "camera", false, 0.0, 179.0, true);
        if (eye && target && *eye == *target && r.dimensions == 3)
            r.fail("camera.target", "must differ from camera.eye, got " + showVec(*target));
        else if (eye && target && (!cam.contains("fov") || fov)) {
            const float fovDegrees = fov ? static_cast<float>(*fov) : 45.0f;
            glm::vec3 from = *eye * scale;
            // 2D: the eye looks at the plane from +z, far enough to take in the domain.
            if (r.dimensions == 2)
                from.z = 0.6f * glm::length(w.domainMax - w.domainMin) / std::tan(0.5f * fovDegrees * 3.14159265f / 180.0f);
            scene.camera = CameraDef{from, *target * scale, fovDegrees};
        }
    }

    if (r.problems.empty())
        if (const std::string problem = endTimeProblem(scene); !problem.empty()) r.fail("end_time", problem);
    if (r.problems.empty()) {
        const SceneEstimate size = estimate(scene);
        if (const std::string shortfall = memoryShortfall(scene); !shortfall.empty()) {
            std::ostringstream msg;
            msg << shortfall << " (particle_spacing " << w.particleSpacing / scale << ")";
            r.fail("particle_spacing", msg.str());
        }
        if (size.totalParticles > 0xfffffff0ull) r.fail("particle_spacing", "more than 2^32 particles");
        scene.world.capacity = static_cast<std::uint32_t>(std::min<std::uint64_t>(size.totalParticles + 1, 0xfffffff0ull));
    }
    if (!r.problems.empty()) throw SceneError(r.problems);
    return scene;
}

}  // namespace tide::io
