// Any-angle smoothing of a raster route (seaway/smooth.py documents the method and binds it):
// 1. string pulling: from each anchor, one straight leg to the farthest waypoint ahead whose
//    leg is allowed and costs no more than the part of the route it replaces;
// 2. refinement: each turning point in turn moves by compass search (steps of 1 pixel halved to
//    1/32) while its two legs get cheaper; then pulling again; sweeps until the cost stops
//    falling. Every accepted change keeps or lowers the cost (to a relative 1e-12 for
//    rounding), and legs are priced and land-tested by LegPricer, so the smoothed route never
//    costs more than the route it came from and never touches an impassable pixel.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "legs.hpp"

namespace seaway {

struct Smoothed {
  std::vector<Point> points;
  std::vector<double> costs;  // of each leg
  int sweeps = 0;
};

namespace detail {

constexpr double smooth_rtol = 1e-12;

// String pulling over the chain v (step_cost[i]: v[i] -> v[i + 1]) trying the vertices of
// `candidates` (ascending) as leg ends; returns the kept indices and the new legs' costs.
inline void pull(const LegPricer& seg, const std::vector<Point>& v, const std::vector<double>& step_cost,
                 const std::vector<std::int64_t>& candidates, std::vector<std::int64_t>& keep,
                 std::vector<double>& costs) {
  const std::int64_t n = std::int64_t(v.size());
  std::vector<double> cum(std::size_t(n), 0.0);
  for (std::int64_t i = 1; i < n; ++i) cum[std::size_t(i)] = cum[std::size_t(i - 1)] + step_cost[std::size_t(i - 1)];
  keep.assign({0});
  costs.clear();
  std::int64_t i = 0;
  auto fits = [&](std::int64_t j, double* c) {
    *c = seg.leg(v[std::size_t(i)], v[std::size_t(j)]).first;
    return *c <= (cum[std::size_t(j)] - cum[std::size_t(i)]) * (1 + smooth_rtol);
  };
  while (i < n - 1) {
    std::int64_t best = i + 1, fail = -1;
    double best_cost = step_cost[std::size_t(i)], c;
    auto it = std::upper_bound(candidates.begin(), candidates.end(), i + 1);
    for (; it != candidates.end(); ++it) {
      if (fits(*it, &c)) {
        best = *it;
        best_cost = c;
      } else {
        fail = *it;
        break;
      }
    }
    if (fail >= 0) {  // the farthest vertex before the blocked turning point
      std::int64_t lo = best, hi = fail;
      while (hi - lo > 1) {
        const std::int64_t mid = (lo + hi) / 2;
        if (fits(mid, &c)) {
          lo = mid;
          best_cost = c;
        } else {
          hi = mid;
        }
      }
      best = lo;
    }
    keep.push_back(best);
    costs.push_back(best_cost);
    i = best;
  }
}

// One sweep of compass search on each active interior waypoint; returns the improvement.
inline double refine(const LegPricer& seg, std::vector<Point>& w, std::vector<double>& costs,
                     const std::vector<char>& active, std::vector<char>& moved_any) {
  static const double dirs[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
  double gained = 0;
  moved_any.assign(w.size(), 0);
  for (std::size_t k = 1; k + 1 < w.size(); ++k) {
    if (!active[k]) continue;
    double here = costs[k - 1] + costs[k];
    for (double step = 1.0; step >= 1.0 / 32;) {
      bool moved = false;
      for (const auto& d : dirs) {
        const Point p{w[k].r + step * d[0], w[k].c + step * d[1]};
        const double a = seg.leg(w[k - 1], p).first;
        if (!(a < inf) || a >= here) continue;
        const double b = seg.leg(p, w[k + 1]).first;
        if (a + b < here * (1 - smooth_rtol)) {
          gained += here - (a + b);
          w[k] = p;
          costs[k - 1] = a;
          costs[k] = b;
          here = a + b;
          moved_any[k] = true;
          moved = true;
          break;
        }
      }
      if (!moved) step /= 2;
    }
  }
  return gained;
}

}  // namespace detail

// The smoothed chain of the route's vertices v (costs step_cost), the shortcut pass trying
// the waypoints `candidates` (both ends and every course change, ascending).
inline Smoothed smooth_route(const LegPricer& seg, const std::vector<Point>& v,
                             const std::vector<double>& step_cost,
                             const std::vector<std::int64_t>& candidates, bool refine, int max_sweeps) {
  Smoothed out;
  std::vector<std::int64_t> idx;
  std::vector<double> costs;
  detail::pull(seg, v, step_cost, candidates, idx, costs);
  std::vector<Point> w;
  for (std::int64_t i : idx) w.push_back(v[std::size_t(i)]);
  std::vector<char> active(w.size(), 1), moved;
  std::vector<std::int64_t> all;
  while (refine && w.size() > 2 && out.sweeps < max_sweeps) {
    ++out.sweeps;
    const double gained = detail::refine(seg, w, costs, active, moved);
    all.resize(w.size());
    for (std::size_t i = 0; i < w.size(); ++i) all[i] = std::int64_t(i);
    const std::vector<double> legs = costs;
    detail::pull(seg, w, legs, all, idx, costs);
    // Next sweep: the waypoints that moved, their neighbours, and those next to a removal.
    const std::size_t n = w.size();
    std::vector<char> near(n, 0), kept(n, 0);
    for (std::size_t i = 0; i < n; ++i)
      near[i] = moved[i] || (i > 0 && moved[i - 1]) || (i + 1 < n && moved[i + 1]);
    for (std::int64_t i : idx) kept[std::size_t(i)] = 1;
    for (std::size_t i = 0; i < n; ++i)
      if (!kept[i]) {
        near[i - 1] = 1;  // i > 0: the first vertex is always kept
        near[std::min(i + 1, n - 1)] = 1;
      }
    std::vector<Point> next;
    active.clear();
    for (std::int64_t i : idx) {
      next.push_back(w[std::size_t(i)]);
      active.push_back(near[std::size_t(i)]);
    }
    w.swap(next);
    double total = 0;
    for (double c : costs) total += c;
    bool any = false;
    for (std::size_t i = 1; i + 1 < active.size(); ++i) any = any || active[i];
    if (gained <= detail::smooth_rtol * std::max(total, 1e-300) || !any) break;
  }
  out.points = std::move(w);
  out.costs = std::move(costs);
  return out;
}

}  // namespace seaway
