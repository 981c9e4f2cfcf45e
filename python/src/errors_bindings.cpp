// tide.SceneError (a ValueError: the scene's problems, each naming its JSON path) and
// tide.DivergenceError (a RuntimeError: where a run blew up), with their details as attributes.
#include <pybind11/stl.h>

#include <tide/io/scene.hpp>

#include "bindings.hpp"

namespace tide::python {

namespace {
PyObject* sceneErrorType = nullptr;       // owned by the module (an attribute of it)
PyObject* divergenceErrorType = nullptr;

const char* quantityName(DivergedQuantity q) {
    switch (q) {
        case DivergedQuantity::Position: return "position";
        case DivergedQuantity::Velocity: return "velocity";
        case DivergedQuantity::Density: return "density";
        case DivergedQuantity::Pressure: return "pressure";
        case DivergedQuantity::Speed: return "speed";
        case DivergedQuantity::Compression: return "compression";
    }
    return "unknown";
}

void raise(PyObject* type, const std::string& message, const py::dict& attributes) {
    py::object error = py::reinterpret_borrow<py::object>(type)(message);
    for (const auto& [key, value] : attributes) error.attr(key) = value;
    PyErr_SetObject(type, error.ptr());
}
}  // namespace

void bindErrors(py::module_& m) {
    sceneErrorType = py::exception<io::SceneError>(m, "SceneError", PyExc_ValueError).ptr();
    divergenceErrorType = py::exception<DivergenceError>(m, "DivergenceError", PyExc_RuntimeError).ptr();
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const io::SceneError& e) {
            // Every problem, one per line, each "json.path: message".
            std::string message;
            for (const std::string& problem : e.problems) message += (message.empty() ? "" : "\n") + problem;
            py::dict attributes;
            attributes["problems"] = py::cast(e.problems);
            raise(sceneErrorType, message.empty() ? std::string(e.what()) : message, attributes);
        } catch (const DivergenceError& e) {
            const Divergence& d = e.divergence;
            py::dict attributes;
            attributes["step"] = d.step;
            attributes["time"] = d.time;
            attributes["dt"] = d.dt;
            attributes["particle"] = d.particle;
            attributes["id"] = d.id;
            attributes["quantity"] = quantityName(d.quantity);
            attributes["value"] = d.value;
            attributes["limit"] = d.limit;
            raise(divergenceErrorType, e.what(), attributes);
        }
    });
}

}  // namespace tide::python
