// Bindings for leg pricing and smoothing (seaway.chart.legs, seaway.smoothing): a static
// smoothable model (caps.smoothable: its raster, read in place and kept alive here, and its own
// rule), the chart's land mask and its grid; a time model's legs on the clock (TimedLegs, on a
// prepared chart and the chart's impassable pixels).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "models.hpp"
#include "seaway/smooth.hpp"
#include "seaway/timed_legs.hpp"
#include "seaway/timed_smooth.hpp"

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

// A time model's legs on a prepared chart: the model's functor is built for each call (visit),
// so the two are kept (keep_alive) and the calls are type-erased here.
struct Timed {
  py::array_t<std::uint8_t> closed;
  std::function<double(Point, Point, double)> arrive;
  std::function<TimedSmoothed(const std::vector<Point>&, const std::vector<double>&,
                              const std::vector<double>&, const std::vector<char>&,
                              const std::vector<std::int64_t>&)>
      smooth;
};

template <class M>
Timed make_timed(const PreparedChart& chart, const M& model,
                 const py::array_t<std::uint8_t, py::array::c_style>& closed) {
  const Geometry& g = chart.geometry();
  if (closed.ndim() != 2 || closed.shape(0) != g.rows || closed.shape(1) != g.cols)
    throw std::invalid_argument("the impassable pixels must be a mask of the chart's shape");
  const std::uint8_t* c = closed.data();
  auto with_legs = [&chart, &model, c](auto&& f) {
    return model.visit(chart, [&](const auto& fn) { return f(TimedLegs<std::decay_t<decltype(fn)>>(chart, fn, c)); });
  };
  Timed t{closed, {}, {}};
  t.arrive = [with_legs](Point p, Point q, double t_h) {
    return with_legs([&](const auto& legs) { return legs.arrive(p, q, t_h); });
  };
  t.smooth = [with_legs](const auto& v, const auto& arrive, const auto& leave, const auto& fixed, const auto& cand) {
    return with_legs([&](const auto& legs) { return smooth_timed(legs, v, arrive, leave, fixed, cand); });
  };
  return t;
}

using Ints = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

std::vector<double> doubles_of(const Array& a, std::size_t n, const char* what) {
  if (a.ndim() != 1 || std::size_t(a.size()) != n)
    throw std::invalid_argument(std::string("give one ") + what + " per vertex");
  return {a.data(), a.data() + n};
}

void register_timed(py::module_& m) {
  py::class_<Timed> cls(m, "TimedLegs", "Legs sailed on the clock under a time model (timed_legs.hpp)");
  for_each_model(Models{}, [&](auto* tag) {
    using M = std::remove_pointer_t<decltype(tag)>;
    if constexpr (M::caps.smoothable && M::caps.time_dependent)
      cls.def(py::init(&make_timed<M>), py::arg("router"), py::arg("model"), py::arg("closed"),
              py::keep_alive<1, 2>(), py::keep_alive<1, 3>(),
              "Legs sailed under a time model of seaway._core on a prepared chart (_core.PreparedChart); "
              "closed: the chart's impassable pixels (uint8)");
  });
  cls.def("arrive", [](const Timed& t, double r0, double c0, double r1, double c1, double depart_h) {
       py::gil_scoped_release release;
       return t.arrive({r0, c0}, {r1, c1}, depart_h);
     }, py::arg("r0"), py::arg("c0"), py::arg("r1"), py::arg("c1"), py::arg("depart_h"),
     "Hours after departure at which the leg (r0, c0) -> (r1, c1) left at depart_h arrives; inf if forbidden");
  cls.def("smooth", [](const Timed& t, const Array& v, const Array& arrive_h, const Array& leave_h,
                       const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>& fixed,
                       const Ints& candidates) {
       const std::vector<Point> pts = points_of(v, "vertices");
       const std::size_t n = pts.size();
       const std::vector<double> arrive = doubles_of(arrive_h, n, "arrival"), leave = doubles_of(leave_h, n, "departure");
       if (fixed.ndim() != 1 || std::size_t(fixed.size()) != n || n == 0 || !fixed.data()[n - 1])
         throw std::invalid_argument("fixed: one flag per vertex, the last one set");
       const std::vector<char> keep(fixed.data(), fixed.data() + n);
       const std::vector<std::int64_t> cand(candidates.data(), candidates.data() + candidates.size());
       for (std::size_t i = 0; i < cand.size(); ++i)
         if (cand[i] < 0 || cand[i] >= std::int64_t(n) || (i && cand[i] <= cand[i - 1]))
           throw std::invalid_argument("candidates must be ascending vertex indices");
       for (std::size_t i = 0; i < n; ++i)
         if (keep[i] && !std::binary_search(cand.begin(), cand.end(), std::int64_t(i)))
           throw std::invalid_argument("every fixed vertex must be a candidate");
       TimedSmoothed out;
       {
         py::gil_scoped_release release;
         out = t.smooth(pts, arrive, leave, keep, cand);
       }
       return py::make_tuple(py::array_t<std::int64_t>(py::ssize_t(out.kept.size()), out.kept.data()),
                             py::array_t<double>(py::ssize_t(out.depart_h.size()), out.depart_h.data()),
                             py::array_t<double>(py::ssize_t(out.arrive_h.size()), out.arrive_h.data()),
                             out.waits_added);
     }, py::arg("vertices"), py::arg("arrive_h"), py::arg("leave_h"), py::arg("fixed"), py::arg("candidates"),
     "(kept vertex indices, each leg's departure and arrival in hours, waits added): see seaway.smooth");
}

}  // namespace

void register_smooth(py::module_& m) {
  register_timed(m);
  py::class_<Pricer> cls(m, "LegPricer", "Cost and land test of arbitrary straight legs (legs.hpp)");
  for_each_model(Models{}, [&](auto* tag) {
    using M = std::remove_pointer_t<decltype(tag)>;
    if constexpr (M::caps.smoothable && M::caps.is_static)
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
