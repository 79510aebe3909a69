// Landmarks (ALT: A*, landmarks, triangle inequality) for many exact queries on one chart.
// Each landmark L stores D_L(v), the least cost from L to every pixel, as float32 (4 bytes per
// pixel per landmark, pixel-major so one pixel's distances share a cache line). On a symmetric
// graph (the max, mean and integral models: a step costs the same both ways) the triangle
// inequality gives the consistent bound |D_L(t) - D_L(v)| <= cost(v -> t).
// Rounding to float32 moves each D by at most ulp/2, which could break consistency by up to one
// ulp; the bound is therefore scaled by (1 - eps) with eps x (cheapest step) > 2 x ulp of the
// largest stored cost, so every step's reduced cost c + h(w) - h(v) stays positive and A*
// (with the bucket queue or the radix heap) stays exact.
// Landmarks are picked farthest-first: the pixel farthest from a seed, then repeatedly the
// pixel farthest from every landmark so far (the usual choice on road networks).
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <utility>
#include <stdexcept>
#include <vector>

#include "bidirectional.hpp"
#include "prepared_chart.hpp"

namespace seaway {

struct Landmarks {
  std::vector<std::int64_t> pixels;  // the landmarks' flat indices
  std::vector<float> table;          // table[v * count + l] = D_l(v); inf if unreachable
  double largest = 0;                // largest finite stored cost
  std::size_t count() const { return pixels.size(); }
  std::size_t bytes() const { return table.capacity() * sizeof(float); }
};

// max over landmarks of |D_l(t) - D_l(v)|, times `scale`; 0 for landmarks that reach only one
// of the two (they lie in another water body than v or t).
class LandmarkBound {
 public:
  // Uses the `active` landmarks with the largest bound at `start` (all if active >= count;
  // fewer made each push cheaper but settled more pixels: all 8 were fastest on the benchmark).
  LandmarkBound(const Landmarks& lm, std::int64_t start, std::int64_t target, double scale, std::size_t active)
      : lm_(lm), n_(lm.count()), scale_(scale) {
    std::vector<std::pair<double, std::size_t>> gain;
    for (std::size_t l = 0; l < n_; ++l) {
      const double gap = std::fabs(double(lm.table[std::size_t(target) * n_ + l]) -
                                   double(lm.table[std::size_t(start) * n_ + l]));
      gain.push_back({gap < inf ? -gap : 0.0, l});
    }
    std::stable_sort(gain.begin(), gain.end());
    for (std::size_t i = 0; i < std::min(active, n_); ++i) {
      use_.push_back(gain[i].second);
      at_target_.push_back(lm.table[std::size_t(target) * n_ + gain[i].second]);
    }
  }
  bool active() const { return scale_ > 0; }
  double operator()(std::int64_t v) const {
    const float* d = lm_.table.data() + std::size_t(v) * n_;
    double best = 0;
    for (std::size_t i = 0; i < use_.size(); ++i) {
      const double gap = std::fabs(double(at_target_[i]) - double(d[use_[i]]));  // exact; NaN if both inf
      if (gap < inf && gap > best) best = gap;
    }
    return scale_ * best;
  }

 private:
  const Landmarks& lm_;
  std::size_t n_;
  double scale_;
  std::vector<std::size_t> use_;
  std::vector<float> at_target_;
};

// Distances from `count` landmarks picked farthest-first from `seed`. The model must be
// symmetric (max, mean, integral).
template <class Model>
Landmarks build_landmarks(PreparedChart& pg, const Model& model, int count, std::int64_t seed,
                          const SearchControl* cancel = nullptr) {
  pg.check(seed);
  if (count < 1 || count > 64) throw std::invalid_argument("landmark count must be 1 to 64");
  const std::int64_t n = pg.geometry().size();
  std::vector<double> field(static_cast<std::size_t>(n)), nearest(static_cast<std::size_t>(n), inf);
  Landmarks lm;
  lm.table.resize(std::size_t(n) * std::size_t(count));
  auto farthest = [&](const std::vector<double>& d) {
    std::int64_t best = -1;
    double far = -1;
    for (std::int64_t v = 0; v < n; ++v)
      if (d[std::size_t(v)] < inf && d[std::size_t(v)] > far) { far = d[std::size_t(v)]; best = v; }
    return best;
  };
  pg.field(model, seed, field.data(), cancel);
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
  const CachedBound<LandmarkBound> bound(exact_bound, pg.geometry().size());
  PreparedChart::Lease ws(pg);
  SearchStats stats = with_queue<false, true>(q, [&](auto heap) {
    return search_with_bound(pg.steps(), model, start, target, *ws, std::move(heap), bound, cancel);
  });
  stats.min_cost = b.min_rate;
  stats.state_bytes += pg.clearance_bytes() + bound.resident_bytes();
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
  const AveragePotential<LandmarkBound> pot{LandmarkBound(lm, start, target, 1.0, lm.count()),
                                            LandmarkBound(lm, target, start, 1.0, lm.count()), 1 - sl.eps};
  return route_bidirectional(pg, model, start, target, cancel, pot, 0.5 * sl.eps,
                             sl.b.max_rate + sl.ulp / sl.rmax);
}

}  // namespace seaway
