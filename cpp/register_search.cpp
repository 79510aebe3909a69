// Bindings for the raster search: convert arguments, release the GIL, run, return arrays.
// Python (seaway/_engine.py) validates everything first; errors here are last-line guards.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>

#include "results.hpp"
#include "seaway/many_targets.hpp"

namespace py = pybind11;
using namespace seaway;

namespace {

template <class T>
using Raster = Eigen::Ref<const Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>;
using Mask = Raster<std::uint8_t>;

Directions parse_directions(const std::string& s) {
  if (s == "full") return Directions::full;
  if (s == "unique") return Directions::unique;
  if (s == "axis") return Directions::axis;
  throw std::invalid_argument("directions must be 'full', 'unique' or 'axis', got '" + s + "'");
}

LandRule parse_land_rule(const std::string& s) {
  if (s == "segment") return LandRule::segment;
  if (s == "ends") return LandRule::ends;
  throw std::invalid_argument("land_rule must be 'segment' or 'ends', got '" + s + "'");
}

template <class T>
void check_shape(const Geometry& g, const Raster<T>& a, const char* what) {
  if (a.rows() != g.rows || a.cols() != g.cols || a.outerStride() != g.cols)
    throw std::invalid_argument(std::string(what) + " must be a C-contiguous array of the grid's shape");
}


template <class T>
std::unique_ptr<PreparedChart> make_router(const Raster<T>& cost, const std::optional<Mask>& land, const Geometry& g, int k,
                   const std::string& directions, const std::string& land_rule) {
  check_shape(g, cost, "cost");
  if (land) check_shape(g, *land, "land");
  if (g.size() >= std::int64_t(0xffffffffu)) throw std::invalid_argument("the chart has 2**32 pixels or more");
  const Directions dirs = parse_directions(directions);
  const LandRule rule = parse_land_rule(land_rule);
  const T* u = cost.data();
  const std::uint8_t* l = land ? land->data() : nullptr;
  py::gil_scoped_release release;
  return std::make_unique<PreparedChart>(g, u, l, k, dirs, rule);
}

// PreparedChart.route(model, ...) and PreparedChart.field(model, ...) for one model type.
template <class M>
void def_queries(ChartClass& router) {
  router.def("route",
             [](PreparedChart& chart, const M& m, std::int64_t start, std::int64_t target, double weight,
                const CancelToken* cancel) {
               return query(chart, m, [&](const auto& model) {
                 return chart.route(model, start, target, weight, flag_of(cancel));
               });
             },
             py::arg("model"), py::arg("start"), py::arg("target"), py::arg("heuristic_weight"),
             py::arg("cancel") = nullptr,
             "The QueryResult (cost, path, figures, values per step); weight 0: Dijkstra, 1: A*, "
             "> 1: weighted A*");
  router.def("routes",
             [](PreparedChart& chart, const M& m, std::int64_t start, const std::vector<std::int64_t>& targets,
                const CancelToken* cancel) {
               std::vector<QueryResult> out(targets.size());
               py::gil_scoped_release release;
               m.visit(chart, [&](const auto& model) {
                 routes_to(chart, model, start, targets, flag_of(cancel), [&](std::size_t i, RouteResult&& r) {
                   out[i].route = std::move(r);
                   out[i].steps = m.step_values(model, chart, out[i].route);
                 });
                 return 0;
               });
               return out;
             },
             py::arg("model"), py::arg("start"), py::arg("targets"), py::arg("cancel") = nullptr,
             "[QueryResult per target] of one Dijkstra search from start until every target is "
             "settled: each the route a Dijkstra search to that target alone finds");
  router.def("prune_collinear",
             [](PreparedChart& chart, const M& m) {
               py::gil_scoped_release release;
               return m.visit(chart, [&](const auto& model) {
                 using F = std::decay_t<decltype(model)>;
                 if constexpr (PrunableModel<F>::value) chart.prune_collinear(model);
                 return PrunableModel<F>::value;
               });
             },
             py::arg("model"),
             "Leave out, in later landmark queries under this model, the doubled steps two unit "
             "steps replace at no more cost (collinear.hpp): every least cost the same, fewer steps "
             "(the other searches read no table). False (and "
             "nothing done) for a model whose costs change with time. Each model keeps its own table; "
             "the caller keeps the model's raster alive and unchanged until forget_pruned(model): "
             "its address is the key.");
  router.def("forget_pruned",
             [](PreparedChart& chart, const M& m) {
               m.visit(chart, [&](const auto& model) { chart.forget_pruned(model); });
             },
             py::arg("model"), "Drop the table prune_collinear(model) built, if any");
  router.def(
      "skip_table",
      [](const PreparedChart& chart, const M& m) -> py::object {
        const std::vector<std::uint16_t>* t =
            m.visit(chart, [&](const auto& model) { return chart.skip_table(model); });
        if (!t) return py::none();
        const Geometry& g = chart.geometry();
        py::array_t<std::uint16_t> out({g.rows, g.cols});
        std::copy(t->begin(), t->end(), out.mutable_data());
        return std::move(out);
      },
      py::arg("model"),
      "The doubled steps prune_collinear(model) left out, per pixel (bit b: the b-th of (-2,-2), "
      "(-2,0), (-2,2), (0,-2), (0,2), (2,-2), (2,0), (2,2) from the pixel; bit 8 + b: the one "
      "ending there), or None");
  router.def("field",
             [](PreparedChart& chart, const M& m, std::int64_t start, const CancelToken* cancel) {
               const Geometry& g = chart.geometry();
               py::array_t<double> out({g.rows, g.cols});
               double* d = out.mutable_data();
               SearchStats stats;
               {
                 py::gil_scoped_release release;
                 stats = m.visit(chart, [&](const auto& model) {
                   return chart.field(model, start, d, flag_of(cancel));
                 });
               }
               return py::make_tuple(out, stats);
             },
             py::arg("model"), py::arg("start"), py::arg("cancel") = nullptr,
             "(accumulated cost from start to every pixel, stats)");
}

template <class... M>
void def_all_queries(ChartClass& router, ModelList<M...>) {
  (def_queries<M>(router), ...);
}

}  // namespace

void register_search(py::module_& m) {
  register_results(m);
  py::class_<Geometry>(m, "Geometry", "Raster geometry: planar (dx, dy) or regular lat/lon on a sphere")
      .def(py::init<>())
      .def_readwrite("rows", &Geometry::rows)
      .def_readwrite("cols", &Geometry::cols)
      .def_readwrite("geographic", &Geometry::geographic)
      .def_readwrite("dx", &Geometry::dx)
      .def_readwrite("dy", &Geometry::dy)
      .def_readwrite("lat0", &Geometry::lat0)
      .def_readwrite("dlat", &Geometry::dlat)
      .def_readwrite("lon0", &Geometry::lon0)
      .def_readwrite("dlon", &Geometry::dlon)
      .def_readwrite("wrap", &Geometry::wrap);

  py::class_<CancelToken>(m, "CancelToken", "Set it to stop the searches that were given it")
      .def(py::init<>())
      .def("set", [](CancelToken& t) { t.cancel = true; })
      .def_property_readonly("is_set", [](const CancelToken& t) { return t.cancel.load(); })
      .def_property_readonly(
          "settled", [](const CancelToken& t) { return t.settled.load(std::memory_order_relaxed); },
          "pixels settled so far by the search given this token (updated every 4096)");
  py::register_exception<Cancelled>(m, "SearchCancelled", PyExc_KeyboardInterrupt);

  ChartClass router(m, "PreparedChart", "A chart prepared for routing: shared, thread-safe");
  router.def_property_readonly(
      "workspaces", [](const PreparedChart& chart) { return chart.workspaces_made(); },
      "search workspaces allocated so far (8-13 bytes per pixel each; reused across queries)");
  def_all_queries(router, Models{});
  auto bind = [&](auto tag) {
    using T = decltype(tag);
    m.def("make_router", &make_router<T>, py::arg("cost").noconvert(), py::arg("land").noconvert(),
          py::arg("grid"), py::arg("neighbourhood"), py::arg("directions"), py::arg("land_rule"),
          "Prepare a chart for routing (builds the land clearance once). The caller keeps the "
          "cost and land arrays alive and unchanged while the router is in use.");
  };
  bind(double{});
  bind(float{});

  m.def("stencil", [](int k, const std::string& directions) {
    py::list out;
    for (const Offset& o : make_stencil(k, parse_directions(directions))) {
      py::list touched, shares;
      for (const CellShare& t : o.touched) touched.append(py::make_tuple(t.di, t.dj));
      for (const CellShare& t : o.shares) shares.append(py::make_tuple(t.di, t.dj, t.fraction));
      out.append(py::make_tuple(o.di, o.dj, touched, shares));
    }
    return out;
  }, "The stencil's offsets as (di, dj, touched pixels, length shares).");

  m.def("haversine_km", &haversine_km, "Great-circle distance in km (sphere of R = 6371.0088 km).");
}
