// Bindings for the raster search: convert arguments, release the GIL, run, return arrays.
// Python (seaway/_engine.py) validates everything first; errors here are last-line guards.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Eigen/Core>
#include <algorithm>
#include <memory>
#include <optional>
#include <string>

#include "seaway/cost_models.hpp"
#include "seaway/search.hpp"

namespace py = pybind11;
using namespace seaway;

namespace {

// Share of the A* bound given up so that A* can use the bucket queue (see run()); 0.05 settled
// the fewest pixels per second on the benchmark charts (0.02 to 0.25 tried).
constexpr double astar_bucket_eps = 0.05;

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
void check_shape(const Grid& g, const Raster<T>& a, const char* what) {
  if (a.rows() != g.rows || a.cols() != g.cols || a.outerStride() != g.cols)
    throw std::invalid_argument(std::string(what) + " must be a C-contiguous array of the grid's shape");
}

struct Outcome {
  SearchStats stats;
  std::vector<std::int64_t> path;
};

// Fill the clearance, then run the search with the chosen cost model.
template <class T>
Outcome run(const Grid& g, const Raster<T>& cost, const std::optional<Mask>& land, int k,
            const std::string& directions, const std::string& edge_cost,
            const std::string& land_rule, double weight, std::int64_t start, std::int64_t target,
            double* dist) {
  if (start < 0 || start >= g.size() || target >= g.size())
    throw std::out_of_range("start or target outside the grid");
  if (g.wrap && g.cols <= k - 1)
    throw std::invalid_argument("a wrapping grid needs more columns than the neighbourhood size");
  const std::vector<Offset> st = make_stencil(k, parse_directions(directions));
  SearchSpec spec{&g, &st, parse_land_rule(land_rule), weight};
  const Grid::Lengths lengths = g.step_lengths(st);
  SearchState s;
  s.resize(g.size());
  const Passability pass = compute_clearance(g, cost.data(), land ? land->data() : nullptr,
                                             (k - 1) / 2 + 1, s.clearance.data(), s.pred.data());
  std::fill(s.pred.begin(), s.pred.end(), no_pred);
  const double min_cost = pass.passable ? pass.min_cost : 0.0;
  const T* u = cost.data();
  Outcome out;
  // Bounds on a step's cost, which pick the queue for Dijkstra.
  const bool per_pixel = edge_cost == "entered";
  const auto [rmin, rmax] = std::minmax_element(lengths.table.begin(), lengths.table.end());
  // Exact A* in buckets: with the bound scaled by (1 - eps), every step's reduced cost
  // c + h(w) - h(v) is at least eps x the cheapest step, which then serves as bucket width.
  const double eps = weight == 1 ? astar_bucket_eps : 1.0;
  const double width = 0.999999 * eps * min_cost * (per_pixel ? 1.0 : *rmin);
  // The largest key increase of one step: its cost, plus for A* the bound's largest drop.
  const double span = 1.000001 * (pass.max_cost + (weight == 1 ? min_cost : 0.0)) *
                      (per_pixel ? 1.0 : *rmax) + 1e-300;
  const bool buckets = weight <= 1 && width > 0 && BucketQueue::buckets_needed(width, span) < 65536;
  if (buckets && weight == 1) spec.heuristic_weight = 1 - eps;
  auto go = [&](const auto& model) {
    if (weight > 1)  // weighted A* keys are not monotone: they need a comparison heap
      out.stats = search(spec, model, lengths, min_cost, start, target, dist, s, QuaternaryHeap{});
    else if (buckets)
      out.stats = search(spec, model, lengths, min_cost, start, target, dist, s, BucketQueue(width, span));
    else
      out.stats = search(spec, model, lengths, min_cost, start, target, dist, s, RadixHeap{});
  };
  if (edge_cost == "max") go(MaxCost<T>{u});
  else if (edge_cost == "mean") go(MeanCost<T>{u});
  else if (edge_cost == "integral") go(IntegralCost<T>{u, &st});
  else if (edge_cost == "entered") go(EnteredPixelCost<T>{u});
  else throw std::invalid_argument("edge_cost must be 'max', 'mean' or 'integral', got '" + edge_cost + "'");
  if (target >= 0 && dist[target] < inf) out.path = trace_path(g, st, s, start, target);
  return out;
}

template <class T>
py::tuple search_py(const Raster<T>& cost, const std::optional<Mask>& land, const Grid& g,
                    std::int64_t start, std::int64_t target, int k, const std::string& directions,
                    const std::string& edge_cost, const std::string& land_rule, double weight,
                    bool field) {
  check_shape(g, cost, "cost");
  if (land) check_shape(g, *land, "land");
  py::array_t<double> dist;
  std::unique_ptr<double[]> own;  // left uninitialised: the search fills it
  double* d;
  if (field) {
    dist = py::array_t<double>({g.rows, g.cols});
    d = dist.mutable_data();
  } else {
    own.reset(new double[std::size_t(g.size())]);
    d = own.get();
  }
  Outcome out;
  {
    py::gil_scoped_release release;
    out = run<T>(g, cost, land, k, directions, edge_cost, land_rule, weight, start, target, d);
  }
  const double total = target >= 0 ? d[target] : 0.0;
  py::dict stats;
  stats["settled"] = out.stats.settled;
  stats["heap_peak"] = out.stats.heap_peak;
  stats["state_bytes"] = out.stats.state_bytes;
  stats["min_cost"] = out.stats.min_cost;
  return py::make_tuple(total, py::array_t<std::int64_t>(py::ssize_t(out.path.size()), out.path.data()),
                        stats, field ? py::object(dist) : py::none());
}

}  // namespace

void register_search(py::module_& m) {
  py::class_<Grid>(m, "Grid", "Raster geometry: planar (dx, dy) or regular lat/lon on a sphere")
      .def(py::init<>())
      .def_readwrite("rows", &Grid::rows)
      .def_readwrite("cols", &Grid::cols)
      .def_readwrite("geographic", &Grid::geographic)
      .def_readwrite("dx", &Grid::dx)
      .def_readwrite("dy", &Grid::dy)
      .def_readwrite("lat0", &Grid::lat0)
      .def_readwrite("dlat", &Grid::dlat)
      .def_readwrite("lon0", &Grid::lon0)
      .def_readwrite("dlon", &Grid::dlon)
      .def_readwrite("wrap", &Grid::wrap);

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

  auto bind = [&](auto tag) {
    using T = decltype(tag);
    m.def("search", &search_py<T>, py::arg("cost").noconvert(), py::arg("land").noconvert(),
          py::arg("grid"), py::arg("start"), py::arg("target"), py::arg("neighbourhood"),
          py::arg("directions"), py::arg("edge_cost"), py::arg("land_rule"),
          py::arg("heuristic_weight"), py::arg("field"),
          "Route search on the implicit raster graph; returns (cost, path, stats, field).");
  };
  bind(double{});
  bind(float{});
}
