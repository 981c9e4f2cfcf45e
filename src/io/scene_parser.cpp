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
#include "scene_reader.hpp"

namespace tide::io {

using namespace scene_reading;

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
    resolveAutomaticKernel(w);  // the support the checks below and the estimates use

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

    if (root.contains("output") && r.object(root["output"], "output", {"fps", "formats", "far_field"})) {
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
        if (out.contains("far_field")) {
            const json& far = out["far_field"];
            if (!scene.ocean) {
                r.fail("output.far_field", "the scene has no ocean to draw beyond the domain");
            } else if (far.is_boolean()) {
                scene.output.farField = far.get<bool>();
            } else if (r.object(far, "output.far_field", {"extent", "spacing"})) {
                if (auto e = r.number(far, "extent", "output.far_field", false, 0.0, 1e300, true)) scene.output.farFieldExtent = *e * scale;
                if (auto d = r.number(far, "spacing", "output.far_field", false, 0.0, 1e300, true)) scene.output.farFieldSpacing = *d * scale;
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
