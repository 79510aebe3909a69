// Landmarks (ALT: A*, landmarks, triangle inequality) for many exact queries on one chart.
// Each landmark L stores D_L(v), the least cost from L to every pixel, as float32 (4 bytes per
// pixel per landmark, pixel-major so one pixel's distances share a cache line). On a symmetric
// graph (the max, mean and integral models: a step costs the same both ways) the triangle
// inequality gives the consistent bound |D_L(t) - D_L(v)| <= cost(v -> t).
// Rounding to float32 moves each D by at most ulp/2, which could break consistency by up to one
// ulp; the bound is therefore scaled by (1 - eps) with eps x (cheapest step) > 2 x ulp of the
// largest stored cost, so every step's reduced cost c + h(w) - h(v) stays positive and A*
// (with the bucket queue or the radix heap) stays exact.
// Landmarks are picked farthest-first in the largest body of water (landmark_choice.hpp): the
// usual choice on road networks; the avoid rule (Goldberg and Werneck 2005) was measured and
// not kept (benchmarks/README.md).
#pragma once


#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <utility>
#include <stdexcept>
#include <vector>

#include "bidirectional.hpp"
#include "landmark_bound.hpp"
#include "landmark_choice.hpp"
#include "prepared_chart.hpp"
#include "pages.hpp"

namespace seaway {

// Distances from `count` landmarks picked farthest-first in the largest body of water
// (landmark_choice.hpp; `seed` only if the chart has no larger one): the pixel farthest from
// it, then repeatedly the pixel farthest from every landmark so far. The model must be
// symmetric (max, mean, integral).
template <class Model>
Landmarks build_landmarks(PreparedChart& pg, const Model& model, int count, std::int64_t seed,
                          const SearchControl* cancel = nullptr) {
  pg.check(seed);
  if (count < 1 || count > 64) throw std::invalid_argument("landmark count must be 1 to 64");
  const std::int64_t n = pg.geometry().size();
  std::vector<double> field(static_cast<std::size_t>(n)), nearest(static_cast<std::size_t>(n), inf);
  Landmarks lm;
  lm.table.reserve(std::size_t(n) * std::size_t(count));
  {  // huge pages before the first write: a query reads one row per pixel, scattered over the chart
    const std::uintptr_t a = reinterpret_cast<std::uintptr_t>(lm.table.data()), huge = 2u << 20;
    const std::uintptr_t lo = (a + huge - 1) & ~(huge - 1), hi = (a + lm.table.capacity() * 4) & ~(huge - 1);
    if (hi > lo) pages::prefer_huge(reinterpret_cast<void*>(lo), hi - lo);
  }
  lm.table.resize(std::size_t(n) * std::size_t(count));
  auto farthest = [&](const std::vector<double>& d) {
    std::int64_t best = -1;
    double far = -1;
    for (std::int64_t v = 0; v < n; ++v)
      if (d[std::size_t(v)] < inf && d[std::size_t(v)] > far) { far = d[std::size_t(v)]; best = v; }
    return best;
  };
  pg.field(model, largest_water(pg, seed), field.data(), cancel);
  std::int64_t next = farthest(field);
  for (int l = 0; l < count; ++l) {
    lm.pixels.push_back(next);
    pg.field(model, next, field.data(), cancel);
    for (std::int64_t v = 0; v < n; ++v) {
      const double d = field[std::size_t(v)];
      if (d < inf) {
        if (d > 3e38) throw std::invalid_argument("costs too large for float32 landmark tables");
        lm.largest = std::max(lm.largest, d);
      }
      lm.table[std::size_t(v) * std::size_t(count) + std::size_t(l)] = float(d);
      nearest[std::size_t(v)] = std::min(nearest[std::size_t(v)], d);
    }
    next = farthest(nearest);
  }
  return lm;
}

// What both landmark searches need of a query, after checking its ends and tables: the model's
// step bounds, the share of the bound given up (eps) and the float32 rounding allowance (ulp);
// eps >= 0.5: the tables cannot give an exact bound here.
struct LandmarkQuery {
  StepBounds b;
  double eps, ulp, cheapest, rmax;
  template <class Model>
  LandmarkQuery(const PreparedChart& pg, const Landmarks& lm, const Model& model, std::int64_t start,
                std::int64_t target)
      : b(model.bounds(pg.passability())) {
    pg.check(start);
    pg.check(target);
    if (lm.table.size() != std::size_t(pg.geometry().size()) * lm.count())
      throw std::invalid_argument("the landmarks were built for another chart");
    const double rmin = b.per_length ? pg.shortest_step() : 1.0;
    rmax = b.per_length ? pg.longest_step() : 1.0;
    cheapest = b.min_rate * rmin;
    ulp = lm.largest * std::ldexp(1.0, -23);  // >= one float32 ulp of any entry
    // As little as the float32 rounding allows (0.01 settled 35 % fewer pixels than 0.05 on
    // the benchmark chart; below, the rounding floor decides).
    eps = cheapest > 0 ? std::max(0.01, 4 * ulp / cheapest) : 1.0;
  }
};

// Least-cost route by A* with the landmark bound (exact). When the bound cannot be made exact
// in float32 (zero-cost pixels, or steps far cheaper than the tables' rounding), it runs
// Dijkstra instead; stats.min_cost is then reported as is.
template <class Model>
RouteResult route_landmarks(PreparedChart& pg, const Landmarks& lm, const Model& model,
                            std::int64_t start, std::int64_t target,
                            const SearchControl* cancel = nullptr) {
  const LandmarkQuery sl(pg, lm, model, start, target);
  const StepBounds& b = sl.b;
  const double eps = sl.eps;
  if (!(eps < 0.5)) return pg.route(model, start, target, 0.0, cancel);
  // Every step's reduced cost is at least eps x cheapest - ulp >= cheapest x eps / 2; its key
  // rises by at most twice its cost plus the rounding.
  QueueChoice q = choose_queue(b, pg.shortest_step(), pg.longest_step(), 0.5 * eps,
                               b.max_rate + sl.ulp / sl.rmax);
  if (q.kind == QueueKind::buckets) q.kind = QueueKind::chunked_buckets;  // many sparse buckets
  const LandmarkBound exact_bound(lm, start, target, 1 - eps, lm.count());
  LabelLease cache(pg.labels(), true);
  const CachedBound<LandmarkBound> bound(exact_bound, &*cache);
  PreparedChart::Lease ws(pg);
  std::shared_ptr<const void> keep;
  const StepEnumerator& steps = pg.steps_for(model, keep);
  SearchStats stats = with_queue<false, true>(q, [&](auto heap) {
    return search_with_bound<true>(steps, model, start, target, *ws, std::move(heap), bound, cancel);
  });
  stats.min_cost = b.min_rate;
  stats.state_bytes += pg.clearance_bytes() + pg.pruned_bytes() + bound.resident_bytes();
  return pg.result(*ws, start, target, stats);
}

// The same query by bidirectional A* on two threads (bidirectional.hpp) with the average
// potential of the landmark bounds to the target and from the start (scaled by 1 - eps). Each
// bound moves by at most a step's cost plus one ulp across a step, so every reduced cost lies
// between eps x cheapest - ulp >= eps x cheapest / 2 and 2 x the step's cost + ulp.
template <class Model>
RouteResult route_landmarks_bidirectional(PreparedChart& pg, const Landmarks& lm, const Model& model,
                                          std::int64_t start, std::int64_t target,
                                          const SearchControl* cancel = nullptr) {
  const LandmarkQuery sl(pg, lm, model, start, target);
  if (!(sl.eps < 0.5)) return route_bidirectional(pg, model, start, target, cancel);
  const LandmarkPotential pot(lm, pg.geometry(), start, target, sl.b.per_length ? sl.b.min_rate : 0.0,
                              1 - sl.eps);
  return route_bidirectional(pg, model, start, target, cancel, pot, 0.5 * sl.eps,
                             sl.b.max_rate + sl.ulp / sl.rmax);
}

}  // namespace seaway
