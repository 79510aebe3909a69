// What every bound model shares (models.hpp): the cancel token, the typed per-step values a
// model reports beside its route, the query's answer, and the check that a model's data lie on
// the prepared chart's grid.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "seaway/prepared_chart.hpp"
#include "seaway/route_result.hpp"
#include "seaway/search_control.hpp"

namespace seaway {

// Set from Python (e.g. on Ctrl-C) to stop a running search (it throws Cancelled); it also
// reports the pixels settled so far (progress).
using CancelToken = SearchControl;
inline const SearchControl* flag_of(const CancelToken* t) { return t; }

// The prepared chart's Python class, _core.PreparedChart (one chart serves every model).
using ChartClass = pybind11::class_<PreparedChart, std::unique_ptr<PreparedChart>>;

// What a model reports per step beside the route, one typed slot each (unset when the model
// reports none): bound as _core.StepValues, read by the Python model's finish().
struct StepValues {
  std::optional<std::vector<double>> setting;   // FuelModel: the engine setting's index
  std::optional<std::vector<double>> hours;     // FuelModel: hours of the step
  std::optional<std::vector<double>> fuel_t;    // FuelModel: tonnes burnt on the step
  std::optional<std::vector<double>> depart_h;  // IceSeasonModel: when the step leaves its first pixel
  std::optional<std::vector<double>> wait_h;    // Zoned: hours waited for a zone to open
};

// A query's answer, bound as _core.QueryResult: the route with the search's figures, and the
// model's values per step.
struct QueryResult {
  RouteResult route;
  StepValues steps;
};

struct NoStepValues {
  template <class Fn>
  StepValues step_values(const Fn&, const PreparedChart&, const RouteResult&) const { return {}; }
};

inline void check_on_grid(const PreparedChart& p, std::int64_t rows, std::int64_t cols, const char* what) {
  const Geometry& g = p.geometry();
  if (rows != g.rows || cols != g.cols)
    throw std::invalid_argument(std::string(what) + " has " + std::to_string(rows) + " x " +
                                std::to_string(cols) + " pixels but the chart " + std::to_string(g.rows) +
                                " x " + std::to_string(g.cols) + ": build the model on the chart's grid");
}

// The hour each step of a found route leaves its first pixel (after any wait), for the models
// whose ships may wait (m.step(pixel, offset, length, arrival there).depart_h).
template <class Functor>
StepValues departures(const Functor& m, const PreparedChart& g, const RouteResult& out) {
  std::vector<double> depart;
  for (std::size_t i = 0; i < out.offsets.size(); ++i) {
    const std::int64_t a = out.path[i], row = a / g.geometry().cols;
    const int o = out.offsets[i];
    depart.push_back(m.step(a, o, g.lengths().row(row)[o], out.cumulative[i]).depart_h);
  }
  StepValues values;
  values.depart_h = std::move(depart);
  return values;
}

}  // namespace seaway
