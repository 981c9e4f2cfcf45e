// The scene keys of the water's sources and sinks and of what measures it: "wavemaker",
// "ocean", "damping", "gauges" and "probes".
#include "scene_reader.hpp"

namespace tide::io::scene_reading {

/// "wavemaker": a piston or flap paddle making regular waves (wave_height, period) or an
/// irregular sea (spectrum). Lengths scaled by `scale`.
void readWaveMaker(Reader& r, const json& j, Scene& scene, float scale, bool domainOk) {
    const std::string path = "wavemaker";
    if (!r.object(j, path, {"type", "x", "depth", "wave_height", "period", "ramp_time", "spectrum", "order", "absorption"}))
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
    if (auto absorption = r.boolean(j, "absorption", path))
        w.absorption = *absorption ? WaveMakerDef::Absorption::On : WaveMakerDef::Absorption::Off;
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
            checkRoomAboveWaves(w, static_cast<double>(world.domainMax.y - world.domainMin.y) - w.depth);
        } catch (const std::invalid_argument& e) {
            const std::string message = e.what();
            const std::size_t colon = message.find(": ");
            r.fail(message.substr(0, colon), colon == std::string::npos ? message : message.substr(colon + 2));
            ok = false;
        }
    }
    if (ok) scene.waveMakers.push_back(w);
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
                          "components", "directions", "order", "mean_current"}))
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
    for (const char* key : {"order", "mean_current"})
        if (!regular && w.contains(key)) {
            r.fail(join(wp, key), "applies to regular waves (a spectrum is a linear sea)");
            ok = false;
        }
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
        if (w.contains("order")) {
            if (auto v = wholeNumber(r, w, "order", wp, 1.0, 5.0)) waves.order = static_cast<int>(*v);
            else ok = false;
        }
        if (const auto current = r.string(w, "mean_current", wp, false)) {
            if (*current == "return") waves.meanCurrent = OceanWavesDef::MeanCurrent::Return;
            else if (*current == "none") waves.meanCurrent = OceanWavesDef::MeanCurrent::None;
            else {
                r.fail(join(wp, "mean_current"), "must be \"return\" or \"none\", got \"" + *current + "\"");
                ok = false;
            }
        }
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
        // The lid World::setOcean refuses too (so `tide validate` reports it); metres, as
        // the wave maker's checks.
        try {
            checkRoomAboveSea(def, static_cast<double>(height) - def.depth);
        } catch (const std::invalid_argument& e) {
            const std::string message = e.what();
            const std::size_t colon = message.find(": ");
            r.fail(message.substr(0, colon), message.substr(colon + 2));
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

}  // namespace tide::io::scene_reading
