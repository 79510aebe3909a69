// Bindings for the weather physics (the models themselves are in register_models.cpp).
#include <pybind11/pybind11.h>


#include "seaway/waves.hpp"
#include "seaway/weather.hpp"

namespace py = pybind11;
using namespace seaway;

void register_weather(py::module_& m) {
  m.def("wave_danger", &wave_danger, py::arg("hs_m"), py::arg("wave_length_m"), py::arg("alpha_rad"),
        py::arg("ship_length_m"), py::arg("speed_kn"), "Danger u in [1, 10] of one wave encounter.");
  m.def("khokhlov_speed_kn", &khokhlov_speed_kn, py::arg("v0_kn"), py::arg("h3_m"), py::arg("q_rad"),
        py::arg("displacement_t"), "Speed through water in wind waves (Olovyannikov 2025, eq. 8).");
  m.def("stawave1_speed_kn", &stawave1_speed_kn, py::arg("v0_kn"), py::arg("hs_m"), py::arg("beam_m"),
        py::arg("length_m"), py::arg("calm_resistance_kn"),
        "Speed at constant power in head waves from STAWAVE-1's added resistance.");
  m.def("speed_over_ground_kn", &speed_over_ground_kn, py::arg("v_kn"), py::arg("current_kn"),
        py::arg("q_rad"), "Speed over ground holding the track through a current (Olovyannikov 2025, eq. 6).");
}
