// Cost models as Python objects. Each bound model is a small struct that keeps its data alive
// and, for one query, builds its C++ functor (seaway/cost_models.hpp, weather.hpp, waves.hpp)
// on a prepared chart:
//   template <class F> auto visit(const PreparedChart&, F&& f) const;  // calls f(functor)
//   template <class Fn> StepValues step_values(const Fn&, const PreparedChart&,
//                                              const RouteResult&) const;  // per-step extras
// visit() runs without the GIL: it must not touch Python objects.
// Adding a model: a functor in cpp/seaway/ (with its Capabilities), a struct here, its name in
// the Models list below, its class in register_models.cpp, and a Python class in seaway.models.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "model_values.hpp"
#include "seaway/cost_models.hpp"
#include "seaway/fuel.hpp"
#include "seaway/ice_time.hpp"
#include "seaway/ice_weather.hpp"
#include "seaway/prepared_chart.hpp"
#include "seaway/timed_zones.hpp"
#include "seaway/waves.hpp"
#include "seaway/weather.hpp"

namespace seaway {

// A static cost per unit length (float32 or float64 raster), priced by Functor (max, mean,
// integral, entered pixel).
template <template <class> class Functor>
struct RasterModel : NoStepValues {
  static constexpr Capabilities caps = Functor<double>::caps;
  template <class T>
  using Rule = Functor<T>;
  pybind11::object keep;  // the raster
  const void* u = nullptr;
  bool single = false;
  std::int64_t rows = 0, cols = 0;

  template <class F>
  auto visit(const PreparedChart& g, F&& f) const {
    check_on_grid(g, rows, cols, "the cost raster");
    return single ? f(make<float>(g)) : f(make<double>(g));
  }
  template <class T>
  Functor<T> make(const PreparedChart& g) const {
    const T* p = static_cast<const T*>(u);
    if constexpr (std::is_same_v<Functor<T>, IntegralCost<T>>)
      return {p, &g.stencil()};
    else
      return {p};
  }
};

// Forecast fields on the chart grid, float32 (frames, rows, cols); kept alive here.
struct ForecastFields {
  Forecast f;
  const float* wave_period = nullptr;
  std::int64_t rows = 0, cols = 0;
  std::vector<pybind11::object> keep;
};
using ForecastPtr = std::shared_ptr<const ForecastFields>;

// Hours through a forecast (Olovyannikov 2025 and Sotnikova 2009).
struct TravelTimeModel : NoStepValues {
  static constexpr Capabilities caps = WeatherTime::caps;
  ForecastPtr forecast;
  Vessel vessel;
  double best_speed_kn;

  template <class F>
  auto visit(const PreparedChart& g, F&& f) const {
    check_on_grid(g, forecast->rows, forecast->cols, "the forecast");
    return f(WeatherTime(g.geometry(), g.stencil(), forecast->f, vessel, best_speed_kn));
  }
};

// Fuel + lambda x time with an engine setting per step (Sotnikova 2009), on the forecast's first frame.
struct FuelModel {
  static constexpr Capabilities caps = FuelLagrangian::caps;
  ForecastPtr forecast;
  Vessel vessel;
  std::vector<double> settings_kn, rate_t_per_h;
  double lambda_t_per_h, best_extra_kn;

  template <class F>
  auto visit(const PreparedChart& g, F&& f) const {
    check_on_grid(g, forecast->rows, forecast->cols, "the forecast");
    const WeatherTime physics(g.geometry(), g.stencil(), forecast->f, vessel, 1.0);
    return f(FuelLagrangian(physics, settings_kn, rate_t_per_h, lambda_t_per_h, best_extra_kn));
  }
  // The chosen setting (index), hours and fuel (t) of each step.
  StepValues step_values(const FuelLagrangian& m, const PreparedChart& g, const RouteResult& out) const {
    std::vector<double> setting, hours, fuel;
    for (std::size_t i = 0; i < out.offsets.size(); ++i) {
      const std::int64_t a = out.path[i], row = a / g.geometry().cols;
      const int o = out.offsets[i];
      const auto c = m.best(a, out.path[i + 1], o, g.lengths().row(row)[o]);
      setting.push_back(c.setting);
      hours.push_back(c.hours);
      fuel.push_back(c.fuel_t);
    }
    StepValues out_values;
    out_values.setting = std::move(setting);
    out_values.hours = std::move(hours);
    out_values.fuel_t = std::move(fuel);
    return out_values;
  }
};

// Wave danger by heading (Grinyak et al. 2018, MSC.1/Circ.1228) on the forecast's first frame.
struct WaveDangerModel : NoStepValues {
  static constexpr Capabilities caps = WaveDangerCost::caps;
  ForecastPtr forecast;
  double ship_length_m, speed_kn;

  template <class F>
  auto visit(const PreparedChart& g, F&& f) const {
    check_on_grid(g, forecast->rows, forecast->cols, "the forecast");
    const ForecastFields& w = *forecast;
    return f(WaveDangerCost(g.geometry(), g.stencil(), w.f.wave_height, w.f.wave_from, w.wave_period,
                            ship_length_m, speed_kn));
  }
};

// Hours through a season of ice charts: hours per km, float32 (frames, rows, cols),
// frame k valid from valid_from_h[k] hours after departure; waiting allowed (ice_time.hpp).
struct IceSeasonModel {
  static constexpr Capabilities caps = IceSeasonTime::caps;
  pybind11::object keep;  // the hours-per-km frames
  pybind11::object keep_closed;  // their closed_for table, when given
  IceSeries series;
  std::vector<double> valid_from_h;
  std::int64_t rows = 0, cols = 0;

  template <class F>
  auto visit(const PreparedChart& g, F&& f) const {
    check_on_grid(g, rows, cols, "the season of ice charts");
    IceSeries s = series;
    s.valid_from_h = valid_from_h.data();
    return f(IceSeasonTime(g.geometry(), g.stencil(), s));
  }
  // The hour each step leaves its first pixel: after the arrival there, by any wait.
  StepValues step_values(const IceSeasonTime& m, const PreparedChart& g, const RouteResult& out) const {
    return departures(m, g, out);
  }
};

// Hours through ice and weather at once (ice_weather.hpp): a season of ice charts and a
// forecast on one grid, the vessel's speed in each chart's ice changed by the weather.
struct IceWeatherModel {
  static constexpr Capabilities caps = IceWeatherTime::caps;
  IceSeasonModel ice;
  ForecastPtr forecast;
  Vessel vessel;
  double min_hours_per_km;

  template <class F>
  auto visit(const PreparedChart& g, F&& f) const {
    check_on_grid(g, ice.rows, ice.cols, "the season of ice charts");
    check_on_grid(g, forecast->rows, forecast->cols, "the forecast");
    IceSeries s = ice.series;
    s.valid_from_h = ice.valid_from_h.data();
    return f(IceWeatherTime(g.geometry(), g.stencil(), s, forecast->f, vessel, min_hours_per_km));
  }
  StepValues step_values(const IceWeatherTime& m, const PreparedChart& g, const RouteResult& out) const {
    return departures(m, g, out);
  }
};

// Every model a query takes: PreparedChart.route and PreparedChart.field get one overload each; the other
// searches one for each model whose capabilities they need (for_each_model).
template <class... M>
struct ModelList {};
using Models = ModelList<RasterModel<MaxCost>, RasterModel<MeanCost>, RasterModel<IntegralCost>,
                         RasterModel<LengthCost>, RasterModel<EnteredPixelCost>, TravelTimeModel, FuelModel, WaveDangerModel,
                         IceSeasonModel, IceWeatherModel, Zoned<TravelTimeModel>>;

// Calls f(static_cast<M*>(nullptr)) for every model M of the list: a binding folds over the
// models and keeps those whose M::caps have what its search needs (if constexpr).
template <class F, class... M>
void for_each_model(ModelList<M...>, F&& f) {
  (f(static_cast<M*>(nullptr)), ...);
}

}  // namespace seaway
