#pragma once
// Shared by the binding files of the `tide._tide` extension: one registration function per
// job, and the conversions several of them use.

#include <string>

#include <glm/vec3.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <tide/world.hpp>

namespace tide::python {

namespace py = pybind11;

void bindErrors(py::module_& m);
void bindWorld(py::module_& m);
void bindFluid(py::module_& m);
void bindIo(py::module_& m);
void bindWaves(py::module_& m);

/// A sequence of 3 numbers as a vec3; ValueError naming `name` and the value otherwise.
glm::vec3 toVec3(py::handle value, const char* name);

/// The World's statistics as a dict (the keys of `tide run`'s stats.json where they overlap).
py::dict statsDict(const World& world);

/// A numpy array over memory the engine owns: no copy; `owner` (the Python object that owns
/// the engine) is kept alive as the array's base. Read-only unless `writable`.
py::array view(py::handle owner, py::dtype dtype, std::vector<py::ssize_t> shape, std::vector<py::ssize_t> strides,
               const void* data, bool writable = false);

/// Raises KeyboardInterrupt (through py::error_already_set) if Ctrl-C was pressed; call
/// between steps, without the GIL: it takes it for the check.
void checkSignals();

}  // namespace tide::python

namespace tide::python {
/// The World inside a tide.World Python object (TypeError if it is not one).
const World& worldOf(py::handle world);
}  // namespace tide::python
