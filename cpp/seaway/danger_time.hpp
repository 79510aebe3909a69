// When every route crosses danger (Sotnikova 2009): the route that spends the least time in the
// forecast's danger zones, then the least total time. Labels are pairs (hours in danger, hours)
// compared lexicographically; a step's weather is read at the time the ship starts it, as in
// WeatherTime. Label-setting, so exact when leaving a pixel with a lexicographically smaller
// label never arrives with a larger one (static zones always; moving zones when they do not
// overtake the ship, the same FIFO premise as the time search).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <queue>
#include <tuple>
#include <vector>

#include "prepared_chart.hpp"
#include "timed_zones.hpp"
#include "weather.hpp"

namespace seaway {

// A step is in danger when the wind (m/s) or the significant wave height (m) at either end,
// at the time the step starts, exceeds its threshold (inf: not used).
struct DangerZones {
  const Geometry* g;
  Forecast f;
  double wind_ms = inf, wave_m = inf;

  bool operator()(std::int64_t v, std::int64_t w, double t_h) const {
    double x = std::clamp((t_h - f.first_h) / f.step_h, 0.0, double(f.frames - 1));
    const std::int64_t i0 = std::int64_t(x), i1 = std::min(i0 + 1, f.frames - 1);
    const double a = x - double(i0);
    const std::int64_t n = g->size();
    auto at = [&](const float* field, std::int64_t p) {
      return (1 - a) * double(field[i0 * n + p]) + a * double(field[i1 * n + p]);
    };
    if (f.wind_speed && std::max(at(f.wind_speed, v), at(f.wind_speed, w)) > wind_ms) return true;
    if (f.wave_height && std::max(at(f.wave_height, v), at(f.wave_height, w)) > wave_m) return true;
    return false;
  }
};

struct DangerRoute {
  RouteResult route;              // cost and cumulative: hours; path: pixels
  std::vector<double> danger_h;   // hours in danger of each step
};

// weight 0: Dijkstra; 1: A* on the time component (remaining distance / best speed). The queue
// orders (hours in danger, hours + bound) lexicographically, exactly (no scalarised key).
// `time` prices a step in hours (WeatherTime, or ZonedTime when zones close in time windows:
// a wait for a zone counts as danger when the step it waits for is in danger).
template <class Time>
DangerRoute route_least_danger(const PreparedChart& pg, const Time& time, const DangerZones& danger,
                               double best_speed_kn, std::int64_t start, std::int64_t target,
                               double weight, const SearchControl* control = nullptr) {
  const Geometry& g = pg.geometry();
  const std::vector<Offset>& st = pg.stencil();
  const std::int64_t n = g.size();
  if (start < 0 || start >= n || target < 0 || target >= n)
    throw std::out_of_range("pixel index outside the grid");
  const DistanceBound bound(g, target, weight > 0 ? (1 - 1e-9) / (km_per_nm * best_speed_kn) : 0);
  std::vector<double> dng(std::size_t(n), inf), hrs(std::size_t(n), inf);
  std::vector<std::uint8_t> pred(std::size_t(n), no_pred), closed(std::size_t(n), 0);
  using Key = std::tuple<double, double, std::uint32_t>;
  std::priority_queue<Key, std::vector<Key>, std::greater<Key>> heap;
  SearchStats stats;
  dng[std::size_t(start)] = hrs[std::size_t(start)] = 0;
  heap.push({0.0, bound(start), std::uint32_t(start)});
  std::size_t peak = 1;
  while (!heap.empty()) {
    const std::int64_t v = std::get<2>(heap.top());
    heap.pop();
    if (closed[std::size_t(v)]) continue;
    closed[std::size_t(v)] = 1;
    count_settled(stats.settled, control);
    if (v == target) break;
    const double dv = dng[std::size_t(v)], tv = hrs[std::size_t(v)];
    pg.steps().each(v, [&](std::int64_t w, std::int64_t o, std::int64_t, std::int64_t, double r, auto&& cell) {
      if (closed[std::size_t(w)]) return;
      const double h = time(v, w, int(o), r, tv, cell);
      if (!(h < inf)) return;
      const double nd = dv + (danger(v, w, tv) ? h : 0.0), nt = tv + h;
      double& od = dng[std::size_t(w)];
      double& ot = hrs[std::size_t(w)];
      if (nd < od || (nd == od && nt < ot)) {
        od = nd;
        ot = nt;
        pred[std::size_t(w)] = std::uint8_t(o);
        heap.push({nd, nt + bound(w), std::uint32_t(w)});
        peak = std::max(peak, heap.size());
      }
    });
  }
  stats.heap_peak = peak;
  stats.state_bytes = std::size_t(n) * 18 + peak * sizeof(Key);
  DangerRoute out;
  out.route.stats = stats;
  if (!closed[std::size_t(target)]) return out;
  out.route.cost = hrs[std::size_t(target)];
  out.route.path = trace_back(g, st, start, target, [&](std::int64_t v) { return int(pred[std::size_t(v)]); },
                              &out.route.offsets);
  for (std::size_t i = 0; i < out.route.path.size(); ++i) {
    const std::int64_t p = out.route.path[i];
    out.route.cumulative.push_back(hrs[std::size_t(p)]);
    if (i > 0) out.danger_h.push_back(dng[std::size_t(p)] - dng[std::size_t(out.route.path[i - 1])]);
  }
  return out;
}

}  // namespace seaway
