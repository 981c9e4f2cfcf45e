// `tide._tide`: the compiled half of the `tide` Python package (python/tide/__init__.py is the
// other). Registration is split by job: errors, the World, the seed's Fluid, writers, waves.
#include "bindings.hpp"

PYBIND11_MODULE(_tide, m) {
    m.doc() = "tide: SPH fluid simulation (the compiled part of the tide package)";
    tide::python::bindErrors(m);
    tide::python::bindWorld(m);
    tide::python::bindFluid(m);
    tide::python::bindIo(m);
    tide::python::bindWaves(m);
}
