// tide.Fluid: the seed's one-class API with its method names (init, reset, addPoint,
// addPointTick, addMaterial, step, getPointCounts, getPosData), in the seed's world units.
#include <pybind11/stl.h>

#include <tide/fluid.hpp>

#include "bindings.hpp"

namespace tide::python {

namespace {
/// Whether init() was called (and not reset() since): the facade's world() needs one.
struct PyFluid {
    Fluid fluid;
    bool live = false;

    const World& world(const char* method) const {
        if (!live) throw std::logic_error(std::string("Fluid.") + method + ": call init() first");
        return fluid.world();
    }
};
}  // namespace

void bindFluid(py::module_& m) {
    py::class_<Material>(m, "Material", "A fluid as the seed describes it: viscosity relative to water, rest density kg/m³, colour.")
        .def(py::init([](float viscosity, float restDensity, py::object color) {
                 return Material(viscosity, restDensity, toVec3(color, "color"));
             }),
             py::arg("viscosity") = 1.0f, py::arg("restDensity") = 1000.0f,
             py::arg("color") = py::make_tuple(0.6f, 0.8f, 1.0f))
        .def_readwrite("viscosity", &Material::viscosity)
        .def_readwrite("restDensity", &Material::restDensity)
        .def_property("color", [](const Material& mat) { return py::make_tuple(mat.color.x, mat.color.y, mat.color.z); },
                      [](Material& mat, py::object c) { mat.color = toVec3(c, "color"); });

    py::class_<FluidSettings>(m, "FluidSettings", "How world units map to metres, and the solver (FluidSettings in C++).")
        .def(py::init<>())
        .def_readwrite("metresPerUnit", &FluidSettings::metresPerUnit)
        .def_readwrite("particleSpacing", &FluidSettings::particleSpacing)
        .def_readwrite("waterViscosity", &FluidSettings::waterViscosity)
        .def_readwrite("threads", &FluidSettings::threads)
        .def_property("solver", [](const FluidSettings& s) { return s.solver.method; },
                      [](FluidSettings& s, const std::string& method) { s.solver = FluidSettings::solverNamed(method); },
                      "The solver's name: pbf (live, default), classic (the seed's), wcsph, pcisph, dfsph.")
        .def_readwrite("substeps", &FluidSettings::substeps, "pbf: steps per step() call, in [1, 100].")
        .def_property("constraintIterations", [](const FluidSettings& s) { return s.solver.constraintIterations; },
                      [](FluidSettings& s, int n) { s.solver.constraintIterations = n; },
                      "pbf: constraint iterations per step, in [1, 100].");

    py::class_<PyFluid>(m, "Fluid", "The seed's Fluid API over a World (include/tide/fluid.hpp).")
        .def(py::init<>())
        .def("init",
             [](PyFluid& f, std::uint32_t maxPointCounts, py::object wallMin, py::object wallMax, py::object fluidMin,
                py::object fluidMax, py::object gravity, const FluidSettings& settings) {
                 const glm::vec3 a = toVec3(wallMin, "wallBox_min"), b = toVec3(wallMax, "wallBox_max");
                 const glm::vec3 c = toVec3(fluidMin, "initFluidBox_min"), d = toVec3(fluidMax, "initFluidBox_max");
                 const glm::vec3 g = toVec3(gravity, "gravity");
                 py::gil_scoped_release nogil;
                 f.fluid.init(maxPointCounts, a, b, c, d, g, settings);
                 f.live = true;
             },
             py::arg("maxPointCounts"), py::arg("wallBox_min"), py::arg("wallBox_max"), py::arg("initFluidBox_min"),
             py::arg("initFluidBox_max"), py::arg("gravity"), py::arg("settings") = FluidSettings{})
        .def("reset",
             [](PyFluid& f) {
                 f.fluid.reset();
                 f.live = false;
             })
        .def("addPoint",
             [](PyFluid& f, py::object min, py::object max, py::object velocity, MaterialIndex material) {
                 const glm::vec3 a = toVec3(min, "min"), b = toVec3(max, "max"), v = toVec3(velocity, "velocity");
                 py::gil_scoped_release nogil;
                 return f.fluid.addPoint(a, b, v, material);
             },
             py::arg("min"), py::arg("max"), py::arg("velocity"), py::arg("material") = 0)
        .def("addPointTick",
             [](PyFluid& f, py::object min, py::object max, py::object velocity, MaterialIndex material) {
                 return f.fluid.addPointTick(toVec3(min, "min"), toVec3(max, "max"), toVec3(velocity, "velocity"), material);
             },
             py::arg("min"), py::arg("max"), py::arg("velocity"), py::arg("material") = 0)
        .def("addMaterial",
             [](PyFluid& f, const Material& material) {
                 f.world("addMaterial");
                 return f.fluid.addMaterial(material);
             },
             py::arg("material"))
        .def("step",
             [](PyFluid& f, float frameTime) {
                 py::gil_scoped_release nogil;
                 f.fluid.step(frameTime);
             },
             py::arg("frameTime"))
        .def("getPointCounts", [](const PyFluid& f) { return f.fluid.getPointCounts(); })
        .def("getPosData",
             [](py::object o) {
                 PyFluid& f = o.cast<PyFluid&>();
                 const float* data = f.fluid.getPosData();
                 const auto n = static_cast<py::ssize_t>(f.fluid.getPointCounts());
                 return view(o, py::dtype::of<float>(), {n, 3}, {3 * py::ssize_t{sizeof(float)}, py::ssize_t{sizeof(float)}},
                             data);
             },
             "(n, 3) float32 positions in world units: a read-only view of the facade's buffer, valid until "
             "the next step, addPoint or reset (as in C++).")
        .def("getMaterialIndex",
             [](const PyFluid& f, unsigned i) {
                 if (i >= f.fluid.getPointCounts())
                     throw py::index_error("i: " + std::to_string(i) + " is not below getPointCounts() " +
                                           std::to_string(f.fluid.getPointCounts()));
                 return f.fluid.getMaterialIndex(i);
             },
             py::arg("i"))
        .def("getMaterialData",
             [](py::object o) {
                 const PyFluid& f = o.cast<const PyFluid&>();
                 if (!f.live) return py::array(py::dtype::of<MaterialIndex>(), {py::ssize_t{0}}, {py::ssize_t{sizeof(MaterialIndex)}});
                 const auto& material = f.fluid.world().particles().material;
                 return view(o, py::dtype::of<MaterialIndex>(), {static_cast<py::ssize_t>(material.size())},
                             {py::ssize_t{sizeof(MaterialIndex)}}, material.data());
             },
             "(n,) uint16 material of each particle, in getPosData's order: a read-only view.")
        .def("materialNames",
             [](const PyFluid& f) {
                 std::vector<std::string> names;
                 for (const MaterialDef& mat : f.world("materialNames").materials()) names.push_back(mat.name);
                 return names;
             })
        .def("time", [](const PyFluid& f) { return f.fluid.time(); })
        .def("metresPerUnit", [](const PyFluid& f) { return f.fluid.metresPerUnit(); })
        .def("stats", [](const PyFluid& f) { return statsDict(f.world("stats")); },
             "The World's statistics as a dict (as tide.World.stats).");
}

}  // namespace tide::python
