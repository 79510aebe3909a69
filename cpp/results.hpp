// Search results as typed Python objects (_core.SearchStats, _core.StepValues,
// _core.QueryResult), shared by the binding files; register_results() binds the classes.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <optional>
#include <utility>
#include <vector>

#include "models.hpp"

namespace seaway {

template <class T>
pybind11::array_t<T> as_array(const std::vector<T>& v) {
  return pybind11::array_t<T>(pybind11::ssize_t(v.size()), v.data());
}

inline pybind11::object optional_array(const std::optional<std::vector<double>>& v) {
  return v ? pybind11::object(as_array(*v)) : pybind11::object(pybind11::none());
}

// A query's answer for Python (moved, not copied).
inline QueryResult answer(RouteResult&& route, StepValues&& steps = {}) {
  return QueryResult{std::move(route), std::move(steps)};
}

// The one way a binding runs a search: without the GIL, on model m's functor for this chart
// (search(functor) returns the RouteResult), with the model's values per step.
template <class M, class Search>
QueryResult query(const PreparedChart& chart, const M& m, Search&& search) {
  QueryResult out;
  pybind11::gil_scoped_release release;
  m.visit(chart, [&](const auto& model) {
    out.route = search(model);
    out.steps = m.step_values(model, chart, out.route);
    return 0;
  });
  return out;
}

inline void register_results(pybind11::module_& m) {
  namespace py = pybind11;
  py::class_<SearchStats>(m, "SearchStats", "The search's own figures")
      .def_readonly("settled", &SearchStats::settled, "pixels (or states) taken off the queue")
      .def_readonly("heap_peak", &SearchStats::heap_peak, "the largest frontier")
      .def_readonly("state_bytes", &SearchStats::state_bytes, "the search's own memory at its peak")
      .def_readonly("min_cost", &SearchStats::min_cost, "the smallest passable cost");
  py::class_<StepValues>(m, "StepValues", "What a model reports per step (None: not reported)")
      .def_property_readonly("setting", [](const StepValues& s) { return optional_array(s.setting); })
      .def_property_readonly("hours", [](const StepValues& s) { return optional_array(s.hours); })
      .def_property_readonly("fuel_t", [](const StepValues& s) { return optional_array(s.fuel_t); })
      .def_property_readonly("depart_h", [](const StepValues& s) { return optional_array(s.depart_h); })
      .def_property_readonly("wait_h", [](const StepValues& s) { return optional_array(s.wait_h); });
  py::class_<QueryResult>(m, "QueryResult", "A search's answer: cost (inf if unreachable), path, figures")
      .def_property_readonly("cost", [](const QueryResult& q) { return q.route.cost; })
      .def_property_readonly("path", [](const QueryResult& q) { return as_array(q.route.path); },
                             "flat pixel indices, start first")
      .def_property_readonly("cumulative", [](const QueryResult& q) { return as_array(q.route.cumulative); },
                             "the cost from the start to each pixel of the path")
      .def_property_readonly("stats", [](const QueryResult& q) { return q.route.stats; })
      .def_property_readonly("steps", [](const QueryResult& q) { return q.steps; });
}

}  // namespace seaway
