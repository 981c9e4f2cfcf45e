// tide.waves: linear (Airy) wave theory as the wave makers use it (src/sources/wave_theory.hpp:
// the dispersion relation and Biesel & Suquet's transfer functions, Dean & Dalrymple 1991 §6.2),
// for comparing a wave tank's gauges with theory.
#include "sources/wave_theory.hpp"

#include "bindings.hpp"

namespace tide::python {

void bindWaves(py::module_& m) {
    py::module_ w = m.def_submodule("waves", "Linear wave theory (src/sources/wave_theory.hpp).");
    w.def("wave_number", &waves::waveNumber, py::arg("omega"), py::arg("depth"), py::arg("g") = waves::kGravity,
          "k (rad/m) with ω² = g k tanh(k d) (the dispersion relation).");
    w.def("piston_height_to_stroke", &waves::pistonHeightToStroke, py::arg("kd"),
          "H/S of a piston paddle, 2(cosh 2kd − 1)/(sinh 2kd + 2kd) (Dean & Dalrymple eq. 6.20).");
    w.def("flap_height_to_stroke", &waves::flapHeightToStroke, py::arg("kd"),
          "H/S of a flap hinged on the bed (Dean & Dalrymple eq. 6.21).");
    w.def("ramp", [](double t, double rampTime) { return waves::ramp(t, rampTime).value; }, py::arg("t"),
          py::arg("ramp_time"), "The wave makers' smooth start ½(1 − cos(π t/T_ramp)), 1 after T_ramp.");
}

}  // namespace tide::python
