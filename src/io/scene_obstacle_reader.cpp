// The scene key "obstacles": shapes, motions, floating bodies and their moorings.
#include "scene_reader.hpp"

namespace tide::io::scene_reading {

namespace {

const std::vector<std::string> kObstacleTypes{"box", "sphere", "cylinder", "plane", "mesh", "circle", "polygon"};
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
    if (r.dimensions == 2) {  // about z, the only axis a 2D body turns about
        if (auto v = r.number(j, "angular_velocity", path, false, -1e6, 1e6)) body.angularVelocity = {0.0f, 0.0f, static_cast<float>(*v)};
    } else if (auto v = r.vec3(j, "angular_velocity", path, false)) {
        body.angularVelocity = *v;
    }
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
                else if (r.dimensions == 2 && free[k] != "x" && free[k] != "y" && free[k] != "rz")
                    r.fail(indexed(where, k), "a 2D body moves in x, y and rz only, got " + show(free[k]));
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

}  // namespace

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
    if (planar && *type == "polygon" && j.is_object() && j.contains("dynamic")) {
        r.fail(join(path, "dynamic"), "a polygon cannot be a floating body; in 2D a body is a \"box\" or a \"circle\"");
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
        if (!r.object(j, path, {"type", "center", "radius", "motion", "name", "load_reference", "dynamic", "density", "mass", "center_of_mass", "velocity", "angular_velocity", "constraint", "moorings"})) return std::nullopt;
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

}  // namespace tide::io::scene_reading
