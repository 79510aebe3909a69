// Time-optimal steps through ice and weather at once: a season of ice charts (ice_time.hpp) and
// a forecast of currents, wind and waves (weather.hpp) on one grid.
//
// A step started at t through the chart valid then (k): the ice gives its time through calm
// water, T_ice = r * sum_c share_c * hours_per_km_c (the class's speed in each pixel's ice:
// Andreeva 2021's V = F * V0, or POLARIS speed limits), i.e. a speed through the ice
// V_ice = r / T_ice; the weather at t then acts on V_ice as on a calm-water speed
// (WeatherTime::speed_over_ground: Khokhlov's or STAWAVE-1's loss in waves, the wind and wave
// limits, the current holding the track), and the step takes r / speed over ground. It is
// closed where the ice closes it (any pixel its closed segment touches is closed in chart k:
// the class's limits, land) or where the weather does. Without weather it takes T_ice exactly.
//
// Waiting: as in ice_time.hpp the ship may wait where it is for a later chart, so a step
// started at t arrives at
//   A(t) = min(t + d_k(t), min over later charts j of valid_from_h[j] + d_j(valid_from_h[j])).
// Within one chart's validity d_k(t) changes only with the weather, which weather routing
// takes as FIFO (t + d_k(t) never decreases), so there the earliest departure is the best one;
// A(t) never decreases and the search's earliest-arrival labels are exact.
#pragma once

#include <cstdint>
#include <vector>

#include "ice_time.hpp"
#include "weather.hpp"

namespace seaway {

class IceWeatherTime {
 public:
  static constexpr Capabilities caps = on_the_clock;
  // min_hours_per_km: at most 1 / the fastest speed the ice and the weather allow (A*'s bound).
  IceWeatherTime(const Geometry& g, const std::vector<Offset>& st, const IceSeries& ice,
                 const Forecast& f, const Vessel& v, double min_hours_per_km)
      : st_(st), ice_(g, st, ice), weather_(g, st, f, v, 1.0), min_h_(min_hours_per_km) {}

  StepBounds bounds(const Passability&) const { return {min_h_, inf, true}; }

  template <class Cell>
  double operator()(std::int64_t v, std::int64_t w, int o, double r_km, double t_h, Cell&& cell) const {
    return step(v, w, o, r_km, t_h, cell).arrive_h - t_h;
  }

  using Step = IceSeasonTime::Step;

  // The earliest arrival of the step v -> w (offset o, length r_km) for a ship at v at t_h.
  template <class Cell>
  Step step(std::int64_t v, std::int64_t w, int o, double r_km, double t_h, Cell&& cell) const {
    const IceSeries& s = ice_.series();
    const std::int64_t k = ice_.chart_at(t_h);
    Step best{t_h, t_h + duration(v, w, o, r_km, k, t_h, cell)};
    // Later charts can only help if they start before the best arrival so far.
    for (std::int64_t j = k + 1; j < s.frames && s.valid_from_h[j] < best.arrive_h; ++j) {
      const double a = s.valid_from_h[j] + duration(v, w, o, r_km, j, s.valid_from_h[j], cell);
      if (a < best.arrive_h) best = {s.valid_from_h[j], a};
    }
    return best;
  }
  // The same outside the search (per-step values of a found route).
  Step step(std::int64_t v, int o, double r_km, double t_h) const {
    const Offset& d = st_[std::size_t(o)];
    return step(v, ice_.at(v, d.di, d.dj), o, r_km, t_h, ice_.shares_of(v, o));
  }

  // Legs on the clock (timed_legs.hpp), as IceSeasonTime's and WeatherTime's: the step sailed
  // from t_h without waiting; a move of la km in pixel a then lb km in pixel b as the step
  // between them (its time through the ice of the chart valid at t_h, that speed changed by
  // the weather then on `heading`); pixel c open in the ice and within the weather's limits
  // from t0_h to t1_h.
  double sail(std::int64_t v, std::int64_t w, int o, double r_km, double t_h) const {
    return duration(v, w, o, r_km, ice_.chart_at(t_h), t_h, ice_.shares_of(v, o));
  }
  double move_hours(std::int64_t a, std::int64_t b, double la, double lb, const Course& heading, double t_h) const {
    const double ice_h = ice_.move_hours(a, b, la, lb, heading, t_h), r_km = la + lb;
    if (!(ice_h < inf)) return inf;
    const double sog = weather_.speed_on_course(a, b, heading, t_h, r_km / km_per_nm / ice_h);
    return sog > 1e-9 ? r_km / km_per_nm / sog : inf;
  }
  bool open(std::int64_t c, double t0_h, double t1_h) const {
    return ice_.open(c, t0_h, t1_h) && weather_.open(c, t0_h, t1_h);
  }

 private:
  // Hours to sail the step through chart k starting at t_h; inf when the ice or the weather
  // closes it.
  template <class Cell>
  double duration(std::int64_t v, std::int64_t w, int o, double r_km, std::int64_t k, double t_h,
                  Cell&& cell) const {
    const double ice_h = ice_.duration(v, o, r_km, k, cell);
    if (!(ice_h < inf)) return inf;
    const double through_ice_kn = r_km / km_per_nm / ice_h;
    const double sog = weather_.speed_over_ground(v, w, o, t_h, through_ice_kn);
    return sog > 1e-9 ? r_km / km_per_nm / sog : inf;
  }

  const std::vector<Offset>& st_;
  IceSeasonTime ice_;
  WeatherTime weather_;
  double min_h_;
};

}  // namespace seaway
