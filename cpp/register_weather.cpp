// Bindings for weather routing: time through a forecast, fuel, wave danger
// (seaway/weather.py validates first and passes fields and vessel as dicts).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "seaway/danger_time.hpp"
#include "seaway/waves.hpp"
#include "seaway/weather.hpp"
#include "results.hpp"
#include "static_router.hpp"

namespace py = pybind11;
using namespace seaway;

namespace {

using Field = py::array_t<float, py::array::c_style>;

// The field `name` of `fields` (float32, frames x rows x cols on the chart grid), or null.
const float* field(const py::dict& fields, const char* name, const Grid& g, std::int64_t frames) {
  if (!fields.contains(name) || fields[name].is_none()) return nullptr;
  if (!py::isinstance<Field>(fields[name]))
    throw std::invalid_argument(std::string(name) + " must be a C-contiguous float32 array");
  const Field f = fields[name].cast<Field>();
  if (f.ndim() != 3 || f.shape(0) != frames || f.shape(1) != g.rows || f.shape(2) != g.cols)
    throw std::invalid_argument(std::string(name) + " must be a (time, rows, cols) array on the chart grid");
  return f.data();
}

Forecast forecast(const Grid& g, const py::dict& fields, std::int64_t frames, double first_h, double step_h) {
  if (!g.geographic) throw std::invalid_argument("weather routing needs a lat/lon chart");
  if (frames < 1 || !(step_h > 0)) throw std::invalid_argument("the forecast needs frames >= 1 and a positive step");
  Forecast f;
  f.frames = frames;
  f.first_h = first_h;
  f.step_h = step_h;
  f.current_east = field(fields, "current_east", g, frames);
  f.current_north = field(fields, "current_north", g, frames);
  if (bool(f.current_east) != bool(f.current_north)) throw std::invalid_argument("give both current components or neither");
  f.wave_height = field(fields, "wave_height", g, frames);
  f.wave_from = field(fields, "wave_from", g, frames);
  f.wind_speed = field(fields, "wind_speed", g, frames);
  return f;
}

Vessel vessel(const py::dict& d) {
  Vessel v;
  v.speed_kn = d["speed_kn"].cast<double>();
  v.displacement_t = d["displacement_t"].cast<double>();
  const std::string loss = d["speed_loss"].cast<std::string>();
  if (loss == "khokhlov") v.speed_loss = SpeedLoss::khokhlov;
  else if (loss == "none") v.speed_loss = SpeedLoss::none;
  else if (loss == "stawave1") v.speed_loss = SpeedLoss::stawave1;
  else throw std::invalid_argument("speed_loss must be 'khokhlov', 'stawave1' or 'none', got '" + loss + "'");
  v.beam_m = d["beam_m"].cast<double>();
  v.length_m = d["length_m"].cast<double>();
  v.calm_resistance_kn = d["calm_resistance_kn"].cast<double>();
  v.max_wind_ms = d["max_wind_ms"].cast<double>();
  v.max_wave_m = d["max_wave_m"].cast<double>();
  return v;
}


py::tuple route_time(StaticRouter& r, std::int64_t start, std::int64_t target, double weight,
                     const py::dict& fields, std::int64_t frames, double first_h, double step_h,
                     const py::dict& ship, double best_speed_kn, const CancelToken* cancel) {
  const Grid& g = r.grid->grid();
  const Forecast f = forecast(g, fields, frames, first_h, step_h);
  const Vessel v = vessel(ship);
  RouteResult out;
  {
    py::gil_scoped_release release;
    const WeatherTime model(g, r.grid->stencil(), f, v, best_speed_kn);
    out = r.grid->route(model, start, target, weight, flag_of(cancel));
  }
  return route_tuple(out);
}

// Least fuel + lambda x time; also each step's chosen setting, hours and fuel.
py::tuple route_fuel(StaticRouter& r, std::int64_t start, std::int64_t target, double weight,
                     const py::dict& fields, const py::dict& ship, std::vector<double> settings_kn,
                     std::vector<double> rate_t_per_h, double lambda, double best_extra_kn,
                     const CancelToken* cancel) {
  const Grid& g = r.grid->grid();
  if (settings_kn.empty() || settings_kn.size() != rate_t_per_h.size())
    throw std::invalid_argument("give one fuel rate per engine setting");
  const Forecast f = forecast(g, fields, 1, 0.0, 1.0);
  const Vessel v = vessel(ship);
  RouteResult out;
  std::vector<int> setting;
  std::vector<double> hours, fuel;
  {
    py::gil_scoped_release release;
    const WeatherTime physics(g, r.grid->stencil(), f, v, 1.0);
    const FuelLagrangian model(physics, settings_kn, rate_t_per_h, lambda, best_extra_kn);
    out = r.grid->route(model, start, target, weight, flag_of(cancel));
    for (std::size_t i = 1; i < out.path.size(); ++i) {
      const std::int64_t a = out.path[i - 1], b = out.path[i], row = a / g.cols;
      std::int64_t dj = b % g.cols - a % g.cols;
      if (g.wrap && dj > g.cols / 2) dj -= g.cols;
      if (g.wrap && dj < -g.cols / 2) dj += g.cols;
      const int o = r.grid->offset_index(int(b / g.cols - row), int(dj));
      const auto c = model.best(a, b, o, r.grid->lengths().row(row)[o]);
      setting.push_back(c.setting);
      hours.push_back(c.hours);
      fuel.push_back(c.fuel_t);
    }
  }
  return py::make_tuple(route_tuple(out), py::cast(setting), py::cast(hours), py::cast(fuel));
}

py::tuple route_danger(StaticRouter& r, std::int64_t start, std::int64_t target, double weight,
                       const py::dict& fields, double ship_length_m, double speed_kn,
                       const CancelToken* cancel) {
  const Grid& g = r.grid->grid();
  if (!g.geographic) throw std::invalid_argument("wave danger routing needs a lat/lon chart");
  const float* h = field(fields, "wave_height", g, 1);
  const float* d = field(fields, "wave_from", g, 1);
  const float* t = field(fields, "wave_period", g, 1);
  if (!h || !d || !t) throw std::invalid_argument("wave danger needs wave_height, wave_from and wave_period");
  RouteResult out;
  {
    py::gil_scoped_release release;
    const WaveDangerCost model(g, r.grid->stencil(), h, d, t, ship_length_m, speed_kn);
    out = r.grid->route(model, start, target, weight, flag_of(cancel));
  }
  return route_tuple(out);
}

// Paper 004's fallback: least hours in danger, then least hours; also each step's danger hours.
py::tuple least_danger(StaticRouter& r, std::int64_t start, std::int64_t target, double weight,
                             const py::dict& fields, std::int64_t frames, double first_h,
                             double step_h, const py::dict& ship, double best_speed_kn,
                             double danger_wind_ms, double danger_wave_m, const CancelToken* cancel) {
  const Grid& g = r.grid->grid();
  const Forecast f = forecast(g, fields, frames, first_h, step_h);
  const Vessel v = vessel(ship);
  DangerRoute out;
  {
    py::gil_scoped_release release;
    const WeatherTime physics(g, r.grid->stencil(), f, v, best_speed_kn);
    const DangerZones zones{&g, f, danger_wind_ms, danger_wave_m};
    out = route_least_danger(*r.grid, physics, zones, v.speed_kn, best_speed_kn, start, target,
                             weight, flag_of(cancel));
  }
  return py::make_tuple(route_tuple(out.route), py::cast(out.danger_h));
}

}  // namespace

void register_weather(py::module_& m) {
  m.def("route_least_danger", &least_danger, py::arg("router"), py::arg("start"),
        py::arg("target"), py::arg("heuristic_weight"), py::arg("fields"), py::arg("frames"),
        py::arg("first_h"), py::arg("step_h"), py::arg("vessel"), py::arg("best_speed_kn"),
        py::arg("danger_wind_ms"), py::arg("danger_wave_m"), py::arg("cancel") = nullptr,
        "Least hours in danger, then least hours (paper 004 when no route avoids the danger "
        "zones): ((hours, flat path, stats, hours to each path pixel), danger hours per step).");
  m.def("route_time", &route_time, py::arg("router"), py::arg("start"), py::arg("target"),
        py::arg("heuristic_weight"), py::arg("fields"), py::arg("frames"), py::arg("first_h"),
        py::arg("step_h"), py::arg("vessel"), py::arg("best_speed_kn"), py::arg("cancel") = nullptr,
        "Time-optimal route (cost in hours) through a forecast on a prepared lat/lon chart.");
  m.def("route_fuel", &route_fuel, py::arg("router"), py::arg("start"), py::arg("target"),
        py::arg("heuristic_weight"), py::arg("fields"), py::arg("vessel"), py::arg("settings_kn"),
        py::arg("rate_t_per_h"), py::arg("lambda_t_per_h"), py::arg("best_extra_kn"),
        py::arg("cancel") = nullptr,
        "Least fuel + lambda x time route with an engine setting per step (paper 004).");
  m.def("route_danger", &route_danger, py::arg("router"), py::arg("start"), py::arg("target"),
        py::arg("heuristic_weight"), py::arg("fields"), py::arg("ship_length_m"), py::arg("speed_kn"),
        py::arg("cancel") = nullptr,
        "Least wave-danger route (paper 003 with MSC.1/Circ.1228's criteria), (1, rows, cols) fields.");
  m.def("wave_danger", &wave_danger, py::arg("hs_m"), py::arg("wave_length_m"), py::arg("alpha_rad"),
        py::arg("ship_length_m"), py::arg("speed_kn"), "Danger u in [1, 10] of one wave encounter.");
  m.def("khokhlov_speed_kn", &khokhlov_speed_kn, py::arg("v0_kn"), py::arg("h3_m"), py::arg("q_rad"),
        py::arg("displacement_t"), "Speed through water in wind waves (paper 001, eq. 8).");
  m.def("stawave1_speed_kn", &stawave1_speed_kn, py::arg("v0_kn"), py::arg("hs_m"), py::arg("beam_m"),
        py::arg("length_m"), py::arg("calm_resistance_kn"),
        "Speed at constant power in head waves from STAWAVE-1's added resistance.");
  m.def("speed_over_ground_kn", &speed_over_ground_kn, py::arg("v_kn"), py::arg("current_kn"),
        py::arg("q_rad"), "Speed over ground holding the track through a current (paper 001, eq. 6).");
}
