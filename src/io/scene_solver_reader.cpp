// The scene keys "solver", "materials" and "material_pairs".
#include "scene_reader.hpp"

namespace tide::io::scene_reading {

void readSolver(Reader& r, const json& j, Scene& scene) {
    const std::string path = "solver";
    if (!r.object(j, path, {"method", "kernel", "equation_of_state", "sound_speed", "cfl", "min_dt", "max_dt", "viscosity",
                            "xsph", "momentum", "shifting", "difference_form", "smooth_density_error", "clamp_negative_pressure", "support_ratio", "max_density_error",
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
    if (auto v = r.boolean(j, "smooth_density_error", path)) {
        s.smoothDensityError = *v;
        if (*v && s.method != "dfsph")
            r.fail(join(path, "smooth_density_error"), "only the dfsph solver takes it, got solver \"" + s.method + "\"");
    }
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
    // Unset, the kernel's own (resolveAutomaticKernel): Wendland C2 wants a wider support than
    // the cubic spline (at 2 spacings a standing wave runs 15 % fast, at 3 within 0.5 %).
    if (auto v = r.number(j, "support_ratio", path, false, 1.0, 4.0)) scene.world.supportRatio = static_cast<float>(*v);
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

}  // namespace tide::io::scene_reading
