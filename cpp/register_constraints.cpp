// Bindings for the time-window zones (seaway/timed_zones.hpp) and Sotnikova 2009's least-danger
// search (seaway/danger_time.hpp). seaway/constraints.py and seaway/_danger.py validate first.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <utility>
#include <vector>

#include "results.hpp"
#include "seaway/danger_time.hpp"

namespace py = pybind11;
using namespace seaway;

namespace {

using Mask = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>;

Zoned<TravelTimeModel> zoned_time(const TravelTimeModel& base, const Mask& mask, const Mask& near,
                                  std::vector<double> closes_h, std::vector<double> opens_h) {
  if (closes_h.size() != opens_h.size() || closes_h.size() > 8)
    throw std::invalid_argument("give at most 8 zones, each with a closing and an opening time");
  if (mask.ndim() != 2 || mask.shape(0) != base.forecast->rows || mask.shape(1) != base.forecast->cols)
    throw std::invalid_argument("the zone mask must be on the forecast's grid");
  Zoned<TravelTimeModel> z{base, {}};
  if (near.size() != mask.size()) throw std::invalid_argument("near must have the mask's shape");
  z.zones.mask.assign(mask.data(), mask.data() + mask.size());
  z.zones.near.assign(near.data(), near.data() + near.size());
  z.zones.closes_h = std::move(closes_h);
  z.zones.opens_h = std::move(opens_h);
  return z;
}

const ForecastFields& fields_of(const TravelTimeModel& m) { return *m.forecast; }
const ForecastFields& fields_of(const Zoned<TravelTimeModel>& m) { return *m.base.forecast; }
double best_of(const TravelTimeModel& m) { return m.best_speed_kn; }
double best_of(const Zoned<TravelTimeModel>& m) { return m.base.best_speed_kn; }

template <class M>
void def_least_danger(py::module_& m) {
  m.def(
      "route_least_danger",
      [](PreparedChart& chart, const M& model, double danger_wind_ms, double danger_wave_m, std::int64_t start,
         std::int64_t target, double weight, const CancelToken* cancel) {
        DangerRoute out;
        {
          py::gil_scoped_release release;
          const DangerZones zones{&chart.geometry(), fields_of(model).f, danger_wind_ms, danger_wave_m};
          model.visit(chart, [&](const auto& time) {
            out = route_least_danger(chart, time, zones, best_of(model), start, target, weight,
                                     flag_of(cancel));
            return 0;
          });
        }
        return py::make_tuple(answer(std::move(out.route)), as_array(out.danger_h));
      },
      py::arg("router"), py::arg("model"), py::arg("danger_wind_ms"), py::arg("danger_wave_m"),
      py::arg("start"), py::arg("target"), py::arg("heuristic_weight"), py::arg("cancel") = nullptr,
      "Least hours in danger, then least hours (Sotnikova 2009, when no route avoids the danger "
      "zones): (PreparedChart.route's QueryResult, danger hours per step). The model's vessel carries the "
      "hard limits only.");
}

}  // namespace

void register_constraints(py::module_& m) {
  py::class_<Zoned<TravelTimeModel>>(m, "ZonedTravelTimeModel",
                                     "Hours through a forecast with zones closed in time windows")
      .def(py::init(&zoned_time), py::arg("model"), py::arg("mask"), py::arg("near"), py::arg("closes_h"),
           py::arg("opens_h"));
  def_least_danger<TravelTimeModel>(m);
  def_least_danger<Zoned<TravelTimeModel>>(m);
}
