// Bindings for leg pricing and smoothing (seaway.chart.legs, seaway.smoothing): a smoothable
// model (caps.smoothable: its raster, read in place and kept alive here, and its own rule), the
// chart's land mask and its grid.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "models.hpp"
#include "seaway/smooth.hpp"

namespace py = pybind11;
using namespace seaway;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

struct Pricer {
  py::object keep_values;
  py::array keep_land;
  LegPricer pricer;
};

std::vector<Point> points_of(const Array& a, const char* what) {
  if (a.ndim() != 2 || a.shape(1) != 2) throw std::invalid_argument(std::string(what) + " must be an (n, 2) array of (row, col)");
  std::vector<Point> out(std::size_t(a.shape(0)));
  const double* p = a.data();
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {p[2 * i], p[2 * i + 1]};
  return out;
}

template <class M>
Pricer make(const M& model, const std::optional<py::array_t<std::uint8_t, py::array::c_style>>& land,
            const Geometry& g, int half) {
  if (model.rows != g.rows || model.cols != g.cols)
    throw std::invalid_argument("the model's cost raster must have the grid's shape");
  if (land && (land->ndim() != 2 || land->shape(0) != g.rows || land->shape(1) != g.cols))
    throw std::invalid_argument("the land mask must have the grid's shape");
  const float* uf = model.single ? static_cast<const float*>(model.u) : nullptr;
  const double* ud = model.single ? nullptr : static_cast<const double*>(model.u);
  const std::uint8_t* l = land ? land->data() : nullptr;
  const LegRule rule = LegRule::of<typename M::template Rule<double>>();
  return Pricer{model.keep, land ? py::array(*land) : py::array(), LegPricer(uf, ud, l, g, rule, half)};
}

}  // namespace

void register_smooth(py::module_& m) {
  py::class_<Pricer> cls(m, "LegPricer", "Cost and land test of arbitrary straight legs (legs.hpp)");
  for_each_model(Models{}, [&](auto* tag) {
    using M = std::remove_pointer_t<decltype(tag)>;
    if constexpr (M::caps.smoothable)
      cls.def(py::init(&make<M>), py::arg("model"), py::arg("land"), py::arg("grid"), py::arg("half"),
                 "Legs priced by the model's own rule (a smoothable model of seaway._core)");
  });
  cls
      .def("leg", [](const Pricer& s, double r0, double c0, double r1, double c1) {
             const auto [cost, length] = s.pricer.leg({r0, c0}, {r1, c1});
             return py::make_tuple(cost, length);
           }, "(cost, length) of the leg (r0, c0) -> (r1, c1); cost inf if forbidden")
      .def("smooth", [](const Pricer& s, const Array& v, const Array& step_cost,
                        const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& candidates,
                        bool refine, int max_sweeps) {
             const std::vector<Point> pts = points_of(v, "vertices");
             if (step_cost.ndim() != 1 || std::size_t(step_cost.size()) + 1 != pts.size())
               throw std::invalid_argument("give one step cost per step between vertices");
             const std::vector<double> steps(step_cost.data(), step_cost.data() + step_cost.size());
             const std::vector<std::int64_t> cand(candidates.data(), candidates.data() + candidates.size());
             for (std::size_t i = 0; i < cand.size(); ++i)
               if (cand[i] < 0 || cand[i] >= std::int64_t(pts.size()) || (i && cand[i] <= cand[i - 1]))
                 throw std::invalid_argument("candidates must be ascending vertex indices");
             Smoothed out;
             {
               py::gil_scoped_release release;
               const LegPricer pricer = s.pricer;  // its own scratch: calls may run in parallel
               out = smooth_route(pricer, pts, steps, cand, refine, max_sweeps);
             }
             py::array_t<double> points({py::ssize_t(out.points.size()), py::ssize_t(2)});
             double* p = points.mutable_data();
             for (std::size_t i = 0; i < out.points.size(); ++i) {
               p[2 * i] = out.points[i].r;
               p[2 * i + 1] = out.points[i].c;
             }
             return py::make_tuple(points, py::array_t<double>(py::ssize_t(out.costs.size()), out.costs.data()),
                                   out.sweeps);
           },
           py::arg("vertices"), py::arg("step_cost"), py::arg("candidates"), py::arg("refine"),
           py::arg("max_sweeps"), "(waypoints, cost of each leg, sweeps): see seaway.smooth");
}
