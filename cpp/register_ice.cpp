// Bindings for ice that changes during the voyage: a season of charts (seaway/ice/season.py
// validates the charts and turns them into hours per km first).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <vector>

#include "seaway/ice_time.hpp"
#include "results.hpp"
#include "static_router.hpp"

namespace py = pybind11;
using namespace seaway;

namespace {

using Frames = py::array_t<float, py::array::c_style>;
using Times = py::array_t<double, py::array::c_style>;

IceSeries series(const Grid& g, const Frames& hours_per_km, const Times& valid_from_h,
                 double min_hours_per_km) {
  if (hours_per_km.ndim() != 3 || hours_per_km.shape(1) != g.rows || hours_per_km.shape(2) != g.cols)
    throw std::invalid_argument("hours_per_km must be a (time, rows, cols) array on the chart grid");
  if (valid_from_h.ndim() != 1 || valid_from_h.shape(0) != hours_per_km.shape(0) || valid_from_h.shape(0) < 1)
    throw std::invalid_argument("give one validity time per chart");
  const double* t = valid_from_h.data();
  for (py::ssize_t k = 1; k < valid_from_h.shape(0); ++k)
    if (!(t[k] > t[k - 1])) throw std::invalid_argument("chart times must increase");
  if (!(t[0] <= 0)) throw std::invalid_argument("the first chart must be valid at departure (time <= 0)");
  if (!(min_hours_per_km > 0 && min_hours_per_km < inf))
    throw std::invalid_argument("min_hours_per_km must be positive and finite");
  return {hours_per_km.shape(0), t, hours_per_km.data(), min_hours_per_km};
}

// The route, and for each step the hour the ship leaves its first pixel (after any wait).
py::tuple route_ice_season(StaticRouter& r, std::int64_t start, std::int64_t target, double weight,
                           const Frames& hours_per_km, const Times& valid_from_h,
                           double min_hours_per_km, const CancelToken* cancel) {
  const Grid& g = r.grid->grid();
  const IceSeries s = series(g, hours_per_km, valid_from_h, min_hours_per_km);
  RouteResult out;
  std::vector<double> depart;
  {
    py::gil_scoped_release release;
    const IceSeasonTime model(g, r.grid->stencil(), s);
    out = r.grid->route(model, start, target, weight, flag_of(cancel));
    for (std::size_t i = 1; i < out.path.size(); ++i) {
      const std::int64_t a = out.path[i - 1], b = out.path[i], row = a / g.cols;
      std::int64_t dj = b % g.cols - a % g.cols;
      if (g.wrap && dj > g.cols / 2) dj -= g.cols;
      if (g.wrap && dj < -g.cols / 2) dj += g.cols;
      const int o = r.grid->offset_index(int(b / g.cols - row), int(dj));
      depart.push_back(model.step(a, o, r.grid->lengths().row(row)[o], out.cumulative[i - 1]).depart_h);
    }
  }
  return py::make_tuple(route_tuple(out), py::cast(depart));
}

// Earliest arrival (hours after departure) at every pixel; inf where never reachable.
py::tuple ice_season_field(StaticRouter& r, std::int64_t start, const Frames& hours_per_km,
                           const Times& valid_from_h, double min_hours_per_km,
                           const CancelToken* cancel) {
  const Grid& g = r.grid->grid();
  const IceSeries s = series(g, hours_per_km, valid_from_h, min_hours_per_km);
  py::array_t<double> field({g.rows, g.cols});
  SearchStats stats;
  double* d = field.mutable_data();
  {
    py::gil_scoped_release release;
    const IceSeasonTime model(g, r.grid->stencil(), s);
    stats = r.grid->field(model, start, d, flag_of(cancel));
  }
  return py::make_tuple(field, stats_dict(stats));
}

}  // namespace

void register_ice(py::module_& m) {
  m.def("route_ice_season", &route_ice_season, py::arg("router"), py::arg("start"),
        py::arg("target"), py::arg("heuristic_weight"), py::arg("hours_per_km"),
        py::arg("valid_from_h"), py::arg("min_hours_per_km"), py::arg("cancel") = nullptr,
        "Earliest-arrival route through a season of ice charts (waiting allowed); also each "
        "step's departure hour.");
  m.def("ice_season_field", &ice_season_field, py::arg("router"), py::arg("start"),
        py::arg("hours_per_km"), py::arg("valid_from_h"), py::arg("min_hours_per_km"),
        py::arg("cancel") = nullptr, "Earliest arrival (h) at every pixel through a season of ice charts.");
}
