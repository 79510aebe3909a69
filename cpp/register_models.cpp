// Bindings for the cost models (models.hpp): one typed class per model, built from arrays and
// numbers that seaway/models.py has validated; the arrays are read in place and kept alive.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "models.hpp"

namespace py = pybind11;
using namespace seaway;

namespace {

template <class T>
using Raster = py::array_t<T, py::array::c_style>;
using Field = py::array_t<float, py::array::c_style>;
using Closed = py::array_t<std::int16_t, py::array::c_style>;
using Values = py::array_t<double, py::array::c_style | py::array::forcecast>;

template <class Model, class T>
Model raster_model(const Raster<T>& cost) {
  if (cost.ndim() != 2) throw std::invalid_argument("the cost raster must be 2-D");
  Model m;
  m.keep = cost;
  m.u = cost.data();
  m.single = std::is_same_v<T, float>;
  m.rows = cost.shape(0);
  m.cols = cost.shape(1);
  return m;
}

// A static model class taking a float32 or float64 C-contiguous raster (never copied).
template <template <class> class Functor>
void bind_raster_model(py::module_& m, const char* name, const char* doc) {
  using Model = RasterModel<Functor>;
  py::class_<Model>(m, name, doc)
      .def(py::init(&raster_model<Model, double>), py::arg("cost").noconvert())
      .def(py::init(&raster_model<Model, float>), py::arg("cost").noconvert());
}

// The cost of steps between pixel pairs under a model that reads only the step's two ends:
// lengths x the model's rule on (a, b); used by graphs that are not rasters (corridors).
template <template <class> class Functor>
py::array_t<double> pair_costs(const Values& a, const Values& b, const Values& length) {
  if (a.size() != b.size() || a.size() != length.size())
    throw std::invalid_argument("a, b and length must have one value per step");
  py::array_t<double> out(a.size());
  const double *pa = a.data(), *pb = b.data(), *pl = length.data();
  double* o = out.mutable_data();
  for (py::ssize_t i = 0; i < a.size(); ++i) {
    const double u[2] = {pa[i], pb[i]};
    o[i] = Functor<double>{u}(0, 1, 0, pl[i], 0.0, [](std::size_t) { return 0; });
  }
  return out;
}

std::shared_ptr<ForecastFields> forecast(double first_h, double step_h, const py::kwargs& fields) {
  static const char* roles[] = {"current_east", "current_north", "wave_height", "wave_from",
                                "wind_speed", "wave_period"};
  auto out = std::make_shared<ForecastFields>();
  if (!(step_h > 0)) throw std::invalid_argument("the forecast needs a positive time step");
  out->f.first_h = first_h;
  out->f.step_h = step_h;
  const float** slots[] = {&out->f.current_east, &out->f.current_north, &out->f.wave_height,
                           &out->f.wave_from, &out->f.wind_speed, &out->wave_period};
  bool first = true;
  for (const auto& item : fields) {
    const std::string role = item.first.cast<std::string>();
    std::size_t k = 0;
    while (k < 6 && role != roles[k]) ++k;
    if (k == 6) throw std::invalid_argument("unknown forecast field '" + role + "'");
    if (item.second.is_none()) continue;
    if (!py::isinstance<Field>(item.second))
      throw std::invalid_argument(role + " must be a C-contiguous float32 array");
    const Field f = item.second.cast<Field>();
    if (f.ndim() != 3) throw std::invalid_argument(role + " must be a (time, rows, cols) array");
    if (first) {
      out->f.frames = f.shape(0);
      out->rows = f.shape(1);
      out->cols = f.shape(2);
      first = false;
    } else if (f.shape(0) != out->f.frames || f.shape(1) != out->rows || f.shape(2) != out->cols) {
      throw std::invalid_argument(role + " must have the shape of the other forecast fields");
    }
    *slots[k] = f.data();
    out->keep.push_back(f);
  }
  if (first) throw std::invalid_argument("the forecast has no field");
  if (bool(out->f.current_east) != bool(out->f.current_north))
    throw std::invalid_argument("give both current components or neither");
  return out;
}

// A season of ice charts as hours per km (read in place, kept alive) and validity times.
IceSeasonModel ice_season(const Field& hours_per_km, std::vector<double> valid_from_h,
                          double min_hours_per_km, double max_hours_per_km,
                          const std::optional<Closed>& closed_for) {
  if (hours_per_km.ndim() != 3 || hours_per_km.shape(0) < 1)
    throw std::invalid_argument("hours_per_km must be a (time, rows, cols) array");
  if (std::int64_t(valid_from_h.size()) != hours_per_km.shape(0))
    throw std::invalid_argument("give one validity time per chart");
  for (std::size_t k = 1; k < valid_from_h.size(); ++k)
    if (!(valid_from_h[k] > valid_from_h[k - 1])) throw std::invalid_argument("chart times must increase");
  if (!(valid_from_h[0] <= 0)) throw std::invalid_argument("the first chart must be valid at departure");
  if (!(min_hours_per_km > 0 && min_hours_per_km < inf))
    throw std::invalid_argument("min_hours_per_km must be positive and finite");
  IceSeasonModel m;
  m.keep = hours_per_km;
  // The largest finite hours per km: a step that does not wait (queue choice); when not given.
  double slowest = max_hours_per_km;
  if (!(slowest >= 0 && slowest < inf)) {
    slowest = 0;
    const float* h = hours_per_km.data();
    const py::ssize_t n = hours_per_km.size();
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < n; ++i)
      if (double(h[i]) < inf && double(h[i]) > slowest) slowest = double(h[i]);
  }
  m.series = {hours_per_km.shape(0), nullptr, hours_per_km.data(), min_hours_per_km,
              slowest > 0 ? slowest : inf};
  if (closed_for) {
    if (closed_for->ndim() != 3 || closed_for->shape(0) != hours_per_km.shape(0) ||
        closed_for->shape(1) != hours_per_km.shape(1) || closed_for->shape(2) != hours_per_km.shape(2))
      throw std::invalid_argument("closed_for must have the shape of hours_per_km");
    m.keep_closed = *closed_for;
    m.series.closed_for = closed_for->data();
  }
  m.valid_from_h = std::move(valid_from_h);
  m.rows = hours_per_km.shape(1);
  m.cols = hours_per_km.shape(2);
  return m;
}

}  // namespace

void register_models(py::module_& m) {
  bind_raster_model<MaxCost>(m, "MaxCost", "Grinyak et al. 2022: a step costs max(u_i, u_j) x length");
  bind_raster_model<MeanCost>(m, "MeanCost", "Grinyak et al. 2018: a step costs (u_i + u_j) / 2 x length");
  bind_raster_model<IntegralCost>(m, "IntegralCost", "A step costs the line integral of u");
  bind_raster_model<LengthCost>(m, "LengthCost", "A step costs its length (the raster: passability)");
  bind_raster_model<EnteredPixelCost>(m, "EnteredPixelCost", "skimage's MCP: the pixel entered");
  m.def("max_pair_costs", &pair_costs<MaxCost>, py::arg("a"), py::arg("b"), py::arg("length"));
  m.def("mean_pair_costs", &pair_costs<MeanCost>, py::arg("a"), py::arg("b"), py::arg("length"));
  m.def("length_pair_costs", &pair_costs<LengthCost>, py::arg("a"), py::arg("b"), py::arg("length"));

  py::enum_<SpeedLoss>(m, "SpeedLoss")
      .value("none", SpeedLoss::none)
      .value("khokhlov", SpeedLoss::khokhlov)
      .value("stawave1", SpeedLoss::stawave1);
  py::class_<Vessel>(m, "Vessel", "A ship's speed, speed-loss formula and weather limits")
      .def(py::init<>())
      .def_readwrite("speed_kn", &Vessel::speed_kn)
      .def_readwrite("displacement_t", &Vessel::displacement_t)
      .def_readwrite("speed_loss", &Vessel::speed_loss)
      .def_readwrite("beam_m", &Vessel::beam_m)
      .def_readwrite("length_m", &Vessel::length_m)
      .def_readwrite("calm_resistance_kn", &Vessel::calm_resistance_kn)
      .def_readwrite("max_wind_ms", &Vessel::max_wind_ms)
      .def_readwrite("max_wave_m", &Vessel::max_wave_m);
  py::class_<ForecastFields, std::shared_ptr<ForecastFields>>(
      m, "Forecast", "Forecast fields, float32 (frames, rows, cols), frame k valid first_h + k step_h")
      .def(py::init(&forecast), py::arg("first_h"), py::arg("step_h"));

  py::class_<TravelTimeModel>(m, "TravelTimeModel", "Hours through a forecast")
      .def(py::init([](std::shared_ptr<ForecastFields> f, const Vessel& v, double best_speed_kn) {
             return TravelTimeModel{{}, f, v, best_speed_kn};
           }),
           py::arg("forecast"), py::arg("vessel"), py::arg("best_speed_kn"));
  py::class_<FuelModel>(m, "FuelModel", "Fuel + lambda x time with an engine setting per step")
      .def(py::init([](std::shared_ptr<ForecastFields> f, const Vessel& v, std::vector<double> settings,
                       std::vector<double> rates, double lambda, double best_extra_kn) {
             if (settings.empty() || settings.size() != rates.size())
               throw std::invalid_argument("give one fuel rate per engine setting");
             return FuelModel{f, v, settings, rates, lambda, best_extra_kn};
           }),
           py::arg("forecast"), py::arg("vessel"), py::arg("settings_kn"), py::arg("rate_t_per_h"),
           py::arg("lambda_t_per_h"), py::arg("best_extra_kn"));
  py::class_<WaveDangerModel>(m, "WaveDangerModel", "Wave danger x km by heading")
      .def(py::init([](std::shared_ptr<ForecastFields> f, double ship_length_m, double speed_kn) {
             if (!f->f.wave_height || !f->f.wave_from || !f->wave_period)
               throw std::invalid_argument("wave danger needs wave_height, wave_from and wave_period");
             return WaveDangerModel{{}, f, ship_length_m, speed_kn};
           }),
           py::arg("forecast"), py::arg("ship_length_m"), py::arg("speed_kn"));
  py::class_<IceSeasonModel>(m, "IceSeasonModel", "Hours through a season of ice charts (waiting allowed)")
      .def(py::init(&ice_season), py::arg("hours_per_km").noconvert(), py::arg("valid_from_h"),
           py::arg("min_hours_per_km"), py::arg("max_hours_per_km") = -1.0,
           py::arg("closed_for").noconvert() = py::none(),
           "max_hours_per_km: the largest finite value of hours_per_km, when known (else found); "
           "closed_for: int16 charts each pixel stays closed from each chart on (ice_time.hpp)");
  py::class_<IceWeatherModel>(m, "IceWeatherModel", "Hours through ice and weather at once (waiting allowed)")
      .def(py::init([](const IceSeasonModel& ice, std::shared_ptr<ForecastFields> f, const Vessel& v,
                       double min_hours_per_km) {
             if (!(min_hours_per_km > 0 && min_hours_per_km < inf))
               throw std::invalid_argument("min_hours_per_km must be positive and finite");
             return IceWeatherModel{ice, f, v, min_hours_per_km};
           }),
           py::arg("ice"), py::arg("forecast"), py::arg("vessel"), py::arg("min_hours_per_km"));
}

// Each bound model class's `capabilities` (a dict of its Capabilities), once every model class
// is registered: seaway.models' flags are tested against them.
void register_capabilities(py::module_&) {
  for_each_model(Models{}, [](auto* tag) {
    using M = std::remove_pointer_t<decltype(tag)>;
    constexpr Capabilities c = M::caps;
    py::dict d;
    d["static"] = c.is_static;
    d["symmetric"] = c.symmetric;
    d["turn_penalty"] = c.turn_penalty;
    d["time_dependent"] = c.time_dependent;
    d["smoothable"] = c.smoothable;
    py::type::of<M>().attr("capabilities") = d;
  });
}
