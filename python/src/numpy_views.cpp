// numpy arrays over the engine's memory, vec3 conversion, statistics, Ctrl-C between steps.
#include <cmath>
#include <sstream>

#include "bindings.hpp"

namespace tide::python {

py::array view(py::handle owner, py::dtype dtype, std::vector<py::ssize_t> shape, std::vector<py::ssize_t> strides,
               const void* data, bool writable) {
    // With a base object pybind11 wraps the pointer instead of copying; an empty store may
    // have no buffer at all, and numpy wants a pointer anyway.
    static const double kNoData = 0.0;
    py::array a(std::move(dtype), std::move(shape), std::move(strides), data != nullptr ? data : &kNoData, owner);
    if (!writable) py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

glm::vec3 toVec3(py::handle value, const char* name) {
    const auto bad = [&] {
        std::ostringstream msg;
        msg << name << ": must be 3 finite numbers, got " << py::str(py::repr(value)).cast<std::string>();
        return py::value_error(msg.str());
    };
    if (!py::isinstance<py::sequence>(value) && !py::isinstance<py::array>(value)) throw bad();
    py::sequence s = py::isinstance<py::array>(value) ? py::sequence(value.attr("tolist")()) : value.cast<py::sequence>();
    if (py::len(s) != 3) throw bad();
    glm::vec3 v;
    for (int a = 0; a < 3; ++a) {
        py::handle e = s[static_cast<std::size_t>(a)];
        if (!py::isinstance<py::int_>(e) && !py::isinstance<py::float_>(e) &&
            !py::hasattr(e, "__float__"))
            throw bad();
        const double x = py::float_(py::reinterpret_borrow<py::object>(e)).cast<double>();
        if (!std::isfinite(x)) throw bad();
        v[a] = static_cast<float>(x);
    }
    return v;
}

py::dict statsDict(const World& world) {
    const WorldStats& s = world.stats();
    const double steps = static_cast<double>(s.steps);
    py::dict d;
    d["particles"] = world.particles().size();
    d["steps"] = s.steps;
    d["sim_time"] = world.time();
    d["last_dt"] = s.lastDt;
    d["dt_min"] = s.dtMin;
    d["dt_mean"] = s.steps ? s.dtSum / steps : 0.0;
    d["dt_max"] = s.dtMax;
    d["max_speed"] = s.maxSpeed;
    d["density_error"] = s.meanDensityError;
    d["compression"] = s.meanCompression;
    d["max_density_error"] = s.maxMeanDensityError;
    d["avg_density_error"] = s.steps ? s.sumMeanDensityError / steps : 0.0;
    d["pressure_iterations"] = s.lastPressureIterations;
    d["pressure_iterations_mean"] = s.steps ? static_cast<double>(s.pressureIterationsSum) / steps : 0.0;
    d["divergence_iterations_mean"] = s.steps ? static_cast<double>(s.divergenceIterationsSum) / steps : 0.0;
    d["pressure_unconverged_steps"] = s.unconvergedSolves;
    d["emitter_capacity_hits"] = s.emitterCapacityHits;
    d["particles_lost"] = world.countEscapedParticles();
    d["total_mass"] = world.totalMass();
    d["threads"] = world.threads();
    d["solver"] = world.def().solver.method;
    py::dict phases;
    phases["neighbor_search"] = s.phaseSeconds.neighborSearch;
    phases["density"] = s.phaseSeconds.density;
    phases["pressure_solve"] = s.phaseSeconds.pressureSolve;
    phases["non_pressure_forces"] = s.phaseSeconds.nonPressureForces;
    phases["integration"] = s.phaseSeconds.integration;
    d["phase_seconds"] = phases;
    return d;
}

void checkSignals() {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

}  // namespace tide::python
