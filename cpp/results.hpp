// Search results as Python objects, shared by the binding files.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "models.hpp"

namespace seaway {

inline pybind11::dict stats_dict(const SearchStats& s) {
  pybind11::dict d;
  d["settled"] = s.settled;
  d["heap_peak"] = s.heap_peak;
  d["state_bytes"] = s.state_bytes;
  d["min_cost"] = s.min_cost;
  return d;
}

// (cost, flat path, stats, cost to each path pixel, {name: value per step}), as
// seaway.PreparedChart expects.
inline pybind11::tuple route_tuple(const RouteResult& out, const StepValues& steps) {
  namespace py = pybind11;
  py::dict per_step;
  for (const auto& [name, v] : steps) per_step[name.c_str()] = py::array_t<double>(py::ssize_t(v.size()), v.data());
  return py::make_tuple(out.cost, py::array_t<std::int64_t>(py::ssize_t(out.path.size()), out.path.data()),
                        stats_dict(out.stats),
                        py::array_t<double>(py::ssize_t(out.cumulative.size()), out.cumulative.data()),
                        per_step);
}

}  // namespace seaway
