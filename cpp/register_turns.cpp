// Bindings for the turn-penalty search (seaway/turns.hpp) on a prepared static chart.
// Python (seaway/_engine.py) validates the penalty table first; errors here are last-line guards.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "results.hpp"
#include "seaway/turns.hpp"
#include "static_router.hpp"

namespace py = pybind11;
using namespace seaway;

void register_turns(py::module_& m) {
  m.def(
      "route_turns",
      [](StaticRouter& r, std::int64_t start, std::int64_t target, double weight,
         std::vector<double> angle_deg, std::vector<double> cost, int incoming,
         const CancelToken* cancel) {
        if (angle_deg.size() < 2 || angle_deg.size() != cost.size())
          throw std::invalid_argument("the turn penalty needs matching angle and cost lists of 2+ points");
        const TurnPenalty turn{std::move(angle_deg), std::move(cost)};
        RouteResult out;
        {
          py::gil_scoped_release release;
          out = r.with_model([&](const auto& model) {
            return route_with_turns(*r.grid, model, turn, start, target, incoming, weight,
                                    flag_of(cancel));
          });
        }
        return route_tuple(out);
      },
      py::arg("router"), py::arg("start"), py::arg("target"), py::arg("heuristic_weight"),
      py::arg("angle_deg"), py::arg("cost"), py::arg("incoming") = -1, py::arg("cancel") = nullptr,
      "Least-cost route with a piecewise-linear penalty per course change (degrees -> cost): "
      "(cost, flat path, stats, cost to each path pixel). incoming: the offset index of the step "
      "that reached the start, or -1.");
  m.def(
      "offset_index",
      [](StaticRouter& r, int di, int dj) { return r.grid->offset_index(di, dj); },
      py::arg("router"), py::arg("di"), py::arg("dj"), "Index of the stencil offset (di, dj), or -1.");
}
