// Bindings for the turn-penalty search (seaway/turns.hpp): route_turns(router, model, ...) for
// the models with caps.turn_penalty (a cost per unit length in the penalty's units; not a
// clock). Python (seaway.engine.constrained) validates the penalty table first; errors here are
// last-line guards.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "results.hpp"
#include "seaway/turns.hpp"

namespace py = pybind11;
using namespace seaway;

namespace {

template <class M>
void def_route_turns(py::module_& m) {
  m.def(
      "route_turns",
      [](PreparedChart& chart, const M& model, std::int64_t start, std::int64_t target, double weight,
         std::vector<double> angle_deg, std::vector<double> cost, int incoming,
         const CancelToken* cancel) {
        if (angle_deg.size() < 2 || angle_deg.size() != cost.size())
          throw std::invalid_argument("the turn penalty needs matching angle and cost lists of 2+ points");
        const TurnPenalty turn{std::move(angle_deg), std::move(cost)};
        return query(chart, model, [&](const auto& f) {
          return route_with_turns(chart, f, turn, start, target, incoming, weight, flag_of(cancel));
        });
      },
      py::arg("router"), py::arg("model"), py::arg("start"), py::arg("target"),
      py::arg("heuristic_weight"), py::arg("angle_deg"), py::arg("cost"), py::arg("incoming") = -1,
      py::arg("cancel") = nullptr,
      "Least-cost route with a piecewise-linear penalty per course change (degrees -> cost), as "
      "PreparedChart.route returns it. incoming: the offset index of the step that reached the start, "
      "or -1.");
}

}  // namespace

void register_turns(py::module_& m) {
  for_each_model(Models{}, [&](auto* tag) {
    using M = std::remove_pointer_t<decltype(tag)>;
    if constexpr (M::caps.turn_penalty) def_route_turns<M>(m);
  });
  m.def(
      "offset_index", [](PreparedChart& chart, int di, int dj) { return chart.offset_index(di, dj); },
      py::arg("router"), py::arg("di"), py::arg("dj"), "Index of the stencil offset (di, dj), or -1.");
}
