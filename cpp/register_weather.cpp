// Bindings for time-optimal routing through a forecast (seaway/weather.py validates first).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "seaway/waves.hpp"
#include "seaway/weather.hpp"
#include "static_router.hpp"

namespace py = pybind11;
using namespace seaway;

namespace {

using Field = py::array_t<float, py::array::c_style>;

const float* data_of(const std::optional<Field>& f, const Grid& g, std::int64_t frames, const char* name) {
  if (!f) return nullptr;
  if (f->ndim() != 3 || f->shape(0) != frames || f->shape(1) != g.rows || f->shape(2) != g.cols)
    throw std::invalid_argument(std::string(name) + " must be a float32 (time, rows, cols) array on the chart grid");
  return f->data();
}

// (cost, flat path, stats, cost to each path pixel), as seaway.PreparedChart expects.
py::tuple as_tuple(const RouteResult& out) {
  py::dict stats;
  stats["settled"] = out.stats.settled;
  stats["state_bytes"] = out.stats.state_bytes;
  return py::make_tuple(out.cost, py::array_t<std::int64_t>(py::ssize_t(out.path.size()), out.path.data()),
                        stats, py::array_t<double>(py::ssize_t(out.cumulative.size()), out.cumulative.data()));
}

py::tuple route_time(StaticRouter& r, std::int64_t start, std::int64_t target, double weight,
                     std::int64_t frames, double first_h, double step_h,
                     const std::optional<Field>& current_east, const std::optional<Field>& current_north,
                     const std::optional<Field>& wave_height, const std::optional<Field>& wave_from,
                     const std::optional<Field>& wind_speed, double speed_kn, double displacement_t,
                     const std::string& speed_loss, double max_wind_ms, double max_wave_m,
                     double best_speed_kn) {
  const Grid& g = r.grid->grid();
  if (!g.geographic) throw std::invalid_argument("time routing needs a lat/lon chart");
  if (frames < 1 || !(step_h > 0)) throw std::invalid_argument("the forecast needs frames >= 1 and a positive step");
  if (bool(current_east) != bool(current_north)) throw std::invalid_argument("give both current components or neither");
  Forecast f;
  f.frames = frames;
  f.first_h = first_h;
  f.step_h = step_h;
  f.current_east = data_of(current_east, g, frames, "current_east");
  f.current_north = data_of(current_north, g, frames, "current_north");
  f.wave_height = data_of(wave_height, g, frames, "wave_height");
  f.wave_from = data_of(wave_from, g, frames, "wave_from");
  f.wind_speed = data_of(wind_speed, g, frames, "wind_speed");
  Vessel v;
  v.speed_kn = speed_kn;
  v.displacement_t = displacement_t;
  if (speed_loss == "khokhlov") v.speed_loss = SpeedLoss::khokhlov;
  else if (speed_loss == "none") v.speed_loss = SpeedLoss::none;
  else throw std::invalid_argument("speed_loss must be 'khokhlov' or 'none', got '" + speed_loss + "'");
  v.max_wind_ms = max_wind_ms;
  v.max_wave_m = max_wave_m;
  RouteResult out;
  {
    py::gil_scoped_release release;
    const WeatherTime model(g, r.grid->stencil(), f, v, best_speed_kn);
    out = r.grid->route(model, start, target, weight);
  }
  return as_tuple(out);
}

py::tuple route_danger(StaticRouter& r, std::int64_t start, std::int64_t target, double weight,
                       const Field& hs, const Field& from, const Field& period,
                       double ship_length_m, double speed_kn) {
  const Grid& g = r.grid->grid();
  if (!g.geographic) throw std::invalid_argument("wave danger routing needs a lat/lon chart");
  const float* h = data_of(hs, g, 1, "wave_height");
  const float* d = data_of(from, g, 1, "wave_from");
  const float* t = data_of(period, g, 1, "wave_period");
  RouteResult out;
  {
    py::gil_scoped_release release;
    const WaveDangerCost model(g, r.grid->stencil(), h, d, t, ship_length_m, speed_kn);
    out = r.grid->route(model, start, target, weight);
  }
  return as_tuple(out);
}

}  // namespace

void register_weather(py::module_& m) {
  m.def("route_time", &route_time, py::arg("router"), py::arg("start"), py::arg("target"),
        py::arg("heuristic_weight"), py::arg("frames"), py::arg("first_h"), py::arg("step_h"),
        py::arg("current_east").noconvert(), py::arg("current_north").noconvert(),
        py::arg("wave_height").noconvert(), py::arg("wave_from").noconvert(),
        py::arg("wind_speed").noconvert(), py::arg("speed_kn"), py::arg("displacement_t"),
        py::arg("speed_loss"), py::arg("max_wind_ms"), py::arg("max_wave_m"),
        py::arg("best_speed_kn"),
        "Time-optimal route (cost in hours) through a forecast on a prepared lat/lon chart.");
  m.def("route_danger", &route_danger, py::arg("router"), py::arg("start"), py::arg("target"),
        py::arg("heuristic_weight"), py::arg("wave_height").noconvert(),
        py::arg("wave_from").noconvert(), py::arg("wave_period").noconvert(),
        py::arg("ship_length_m"), py::arg("speed_kn"),
        "Least wave-danger route (paper 003 with MSC.1/Circ.1228's criteria), (1, rows, cols) fields.");
  m.def("wave_danger", &wave_danger, py::arg("hs_m"), py::arg("wave_length_m"), py::arg("alpha_rad"),
        py::arg("ship_length_m"), py::arg("speed_kn"), "Danger u in [1, 10] of one wave encounter.");
  m.def("khokhlov_speed_kn", &khokhlov_speed_kn, py::arg("v0_kn"), py::arg("h3_m"), py::arg("q_rad"),
        py::arg("displacement_t"), "Speed through water in wind waves (paper 001, eq. 8).");
  m.def("speed_over_ground_kn", &speed_over_ground_kn, py::arg("v_kn"), py::arg("current_kn"),
        py::arg("q_rad"), "Speed over ground holding the track through a current (paper 001, eq. 6).");
}
