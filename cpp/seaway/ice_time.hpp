// Time-optimal steps through a season of ice charts: the ice changes during the voyage.
//
// Chart k is valid from valid_from_h[k] (hours after departure, increasing) until the next
// chart's time, the last one for ever after: piecewise constant, which is what ice services
// mean by a chart "valid at" a date. A step started at time t crosses the ice of the chart
// valid at t; its duration is the exact time of the straight step through that chart,
// r * sum_c share_c * hours_per_km_c over the pixels c the segment crosses (the line integral
// of 1 / speed), and the step is closed when any pixel its closed segment touches is closed
// (hours_per_km inf) in that chart: the engine's land rule applied to the ice of the moment.
//
// A duration that is constant between chart times and jumps down when the ice clears is not
// FIFO (leaving just before a chart change can arrive later than leaving at it), so
// label-setting alone would not be exact. The ship may wait at any pixel it has reached, and
// a step started at t arrives at
//   A(t) = min over departures t' >= t of t' + duration(t')
//        = min(t + duration_k(t), min over later charts j of valid_from_h[j] + duration_j),
// since within a chart's validity the earliest departure is the best one. A(t) never
// decreases with t (FIFO), so the search's earliest-arrival labels are exact for this model.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "cost_models.hpp"
#include "grid.hpp"
#include "stencil.hpp"

namespace seaway {

// A season of charts on the chart grid: frames x rows x cols hours per km (float32, C order;
// +inf where the ship may not go), frame k valid from valid_from_h[k].
struct IceSeries {
  std::int64_t frames = 1;
  const double* valid_from_h = nullptr;  // increasing; frame 0 valid at departure (<= 0)
  const float* hours_per_km = nullptr;
  double min_hours_per_km = 0;  // the least finite value of any frame (> 0): A*'s bound
};

class IceSeasonTime {
 public:
  IceSeasonTime(const Grid& g, const std::vector<Offset>& st, const IceSeries& s)
      : g_(g), st_(st), s_(s) {
    corners_.resize(st.size());
    for (std::size_t o = 0; o < st.size(); ++o)
      for (const CellShare& t : st[o].touched)
        if (t.fraction == 0) corners_[o].push_back(t);
  }

  // Hours per km: at least the fastest ice of the season; waiting has no upper bound.
  StepBounds bounds(const Passability&) const { return {s_.min_hours_per_km, inf, true}; }

  template <class Cell>
  double operator()(std::int64_t v, std::int64_t, int o, double r_km, double t_h, Cell&&) const {
    return step(v, o, r_km, t_h).arrive_h - t_h;
  }

  struct Step {
    double depart_h, arrive_h;  // the best departure at or after the arrival at v, and its arrival
  };

  // The earliest arrival of the step v -> v + offset o (length r_km) for a ship at v at t_h.
  Step step(std::int64_t v, int o, double r_km, double t_h) const {
    const double* from = s_.valid_from_h;
    std::int64_t k = std::int64_t(std::upper_bound(from, from + s_.frames, t_h) - from) - 1;
    k = std::max<std::int64_t>(k, 0);
    Step best{t_h, t_h + duration(v, o, r_km, k)};
    // Later charts can only help if they start before the best arrival so far.
    for (std::int64_t j = k + 1; j < s_.frames && from[j] < best.arrive_h; ++j) {
      const double a = from[j] + duration(v, o, r_km, j);
      if (a < best.arrive_h) best = {from[j], a};
    }
    return best;
  }

  // Hours to sail the step through chart k; inf when the step touches closed ice or land.
  double duration(std::int64_t v, int o, double r_km, std::int64_t k) const {
    const float* h = s_.hours_per_km + k * g_.size();
    const std::int64_t row = v / g_.cols, col = v - row * g_.cols;
    auto at = [&](int di, int dj) {
      std::int64_t c = col + dj;
      if (g_.wrap) c = c < 0 ? c + g_.cols : (c >= g_.cols ? c - g_.cols : c);
      return h[(row + di) * g_.cols + c];
    };
    double sum = 0;
    for (const CellShare& s : st_[std::size_t(o)].shares) sum += s.fraction * double(at(s.di, s.dj));
    if (!(sum < inf)) return inf;
    for (const CellShare& t : corners_[std::size_t(o)])
      if (!(double(at(t.di, t.dj)) < inf)) return inf;
    return sum * r_km;
  }

 private:
  const Grid& g_;
  const std::vector<Offset>& st_;
  IceSeries s_;
  std::vector<std::vector<CellShare>> corners_;  // pixels each step meets only at a corner
};

}  // namespace seaway
