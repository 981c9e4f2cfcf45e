// tide.io.write_frame: one frame of a World in any format `tide run` writes (vtu, ply, csv, obj),
// through the same writers (tide::io::writeFrame).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <tide/io/exporters.hpp>
#include <tide/io/far_field_mesh.hpp>

#include "bindings.hpp"

namespace tide::python {

void bindIo(py::module_& m) {
    py::module_ io = m.def_submodule("io", "Frame writers (the compiled part of tide.io).");
    io.def(
        "_write_frame",
        [](py::handle world, const std::filesystem::path& path, const std::string& format,
           const std::vector<std::string>& materialNames) {
            const auto f = tide::io::parseFormat(format);
            if (!f) throw py::value_error("format: must be \"vtu\", \"ply\", \"csv\" or \"obj\", got \"" + format + "\"");
            const World& w = worldOf(world);
            tide::io::SurfaceMeshDef surface{w.def().particleSpacing, materialNames, w.threads(), {}};
            // An ocean's obj frame carries the far field around the domain, as `tide run` writes it.
            if (const auto ocean = w.ocean(); ocean && w.def().dimensions == 3) {
                surface.farField = tide::io::farFieldMeshFor(*ocean, w.def());
                surface.farField->time = w.time();
                surface.farField->ramp = w.oceanRamp();
            }
            py::gil_scoped_release nogil;
            tide::io::writeFrame(path, *f, w.particles(), surface);
        },
        py::arg("world"), py::arg("path"), py::arg("format"), py::arg("material_names"));
    io.attr("FORMATS") = py::make_tuple("vtu", "ply", "csv", "obj");
}

}  // namespace tide::python
