// Bindings for the faster exact searches on a PreparedChart: bidirectional Dijkstra on two threads
// (the models with caps.is_static), and A* with landmark tables built once per chart and model
// (static and symmetric models). Python (seaway.engine.methods) picks and validates.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <mutex>
#include <type_traits>
#include <utility>

#include "results.hpp"
#include "seaway/bidirectional.hpp"
#include "seaway/landmarks.hpp"

namespace py = pybind11;
using namespace seaway;

namespace {

template <class M>
void def_bidirectional(ChartClass& router) {
  router.def("route_bidirectional",
             [](PreparedChart& chart, const M& m, std::int64_t start, std::int64_t target, bool astar,
                const CancelToken* cancel) {
               return query(chart, m, [&](const auto& model) {
                 return astar ? route_bidirectional_astar(chart, model, start, target, flag_of(cancel))
                              : route_bidirectional(chart, model, start, target, flag_of(cancel));
               });
             },
             py::arg("model"), py::arg("start"), py::arg("target"), py::arg("astar"),
             py::arg("cancel") = nullptr,
             "Exact bidirectional Dijkstra (astar: A* with the distance bound) on two threads; "
             "returns what PreparedChart.route does");
}

template <class M>
void def_landmarks(ChartClass& router) {
  router.def("build_landmarks",
             [](PreparedChart& chart, const M& m, int count, std::int64_t seed, const CancelToken* cancel) {
               py::gil_scoped_release release;
               return m.visit(chart, [&](const auto& model) {
                 return build_landmarks(chart, model, count, seed, flag_of(cancel));
               });
             },
             py::arg("model"), py::arg("count"), py::arg("seed"), py::arg("cancel") = nullptr,
             "Pick `count` landmarks farthest-first in the largest body of water and tabulate "
             "their costs (float32)");
  router.def("route_landmarks",
             [](PreparedChart& chart, const M& m, const Landmarks& lm, std::int64_t start, std::int64_t target,
                bool bidirectional, const CancelToken* cancel) {
               return query(chart, m, [&](const auto& model) {
                 return bidirectional
                            ? route_landmarks_bidirectional(chart, lm, model, start, target, flag_of(cancel))
                            : route_landmarks(chart, lm, model, start, target, flag_of(cancel));
               });
             },
             py::arg("model"), py::arg("landmarks"), py::arg("start"), py::arg("target"),
             py::arg("bidirectional"), py::arg("cancel") = nullptr,
             "Exact A* with the landmark bound (bidirectional: on two threads, with the average "
             "potential); returns what PreparedChart.route does");
}

}  // namespace

void register_exact(py::module_& m) {
  py::class_<Landmarks>(m, "Landmarks", "Float32 least-cost tables from landmark pixels (ALT)")
      .def_property_readonly("pixels", [](const Landmarks& l) { return l.pixels; })
      .def_property_readonly("bytes", &Landmarks::bytes)
      .def_property_readonly("largest", [](const Landmarks& l) { return l.largest; })
      .def_property_readonly(
          "table",
          [](py::object self) {
            const Landmarks& l = self.cast<const Landmarks&>();
            const py::ssize_t n = py::ssize_t(l.table.size() / std::max<std::size_t>(l.count(), 1));
            py::array_t<float> a({n, py::ssize_t(l.count())}, l.table.data(), self);
            a.attr("flags").attr("writeable") = false;
            return a;
          },
          "The tables as a read-only (pixels, landmarks) float32 view: the least cost from each "
          "landmark to each pixel (inf where unreachable)");
  m.def("label_spares", [] {
    detail::LabelSpares& s = detail::label_spares();
    std::lock_guard<std::mutex> lock(s.mutex);
    std::vector<std::int64_t> sizes;
    for (const auto& l : s.kept) sizes.push_back(l->size());
    return py::make_tuple(sizes, s.bytes);
  }, "(pixels of each kept set of labels, their resident bytes): the bidirectional labels gone "
     "charts left for the next chart of their size");
  ChartClass router = py::reinterpret_borrow<ChartClass>(m.attr("PreparedChart"));
  router.def_property_readonly("cost_range", [](const PreparedChart& chart) {
    const Passability& p = chart.passability();
    return py::make_tuple(p.passable ? p.min_cost : 0.0, p.max_cost, p.passable);
  }, "(smallest, largest passable cost, passable pixels), from the preparation");
  router.def_property_readonly("clearance", [](const PreparedChart& chart) {
    const Geometry& g = chart.geometry();
    py::array_t<std::uint8_t> out({py::ssize_t(g.rows), py::ssize_t(g.cols)});
    std::copy(chart.clearance(), chart.clearance() + g.size(), out.mutable_data());
    return out;
  }, "A copy of the land clearance: Chebyshev pixels to the nearest impassable pixel, capped at "
     "the stencil's half-width + 1; 0 on impassable pixels");
  router.def_property_readonly("least_cost_share", [](const PreparedChart& chart) {
    return chart.passability().least_share;
  }, "Share of a fixed sample of 4096 passable pixels whose cost is within 1 % of the least "
     "(auto's one-way A* rule), from the preparation");
  for_each_model(Models{}, [&](auto* tag) {
    using M = std::remove_pointer_t<decltype(tag)>;
    if constexpr (M::caps.is_static) def_bidirectional<M>(router);  // the backward side prices steps
    if constexpr (M::caps.is_static && M::caps.symmetric) def_landmarks<M>(router);
  });
}
