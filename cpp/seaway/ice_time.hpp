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
#include "geometry.hpp"
#include "stencil.hpp"

namespace seaway {

// A season of charts on the chart grid: frames x rows x cols hours per km (float32, C order;
// +inf where the ship may not go), frame k valid from valid_from_h[k].
struct IceSeries {
  std::int64_t frames = 1;
  const double* valid_from_h = nullptr;  // increasing; frame 0 valid at departure (<= 0)
  const float* hours_per_km = nullptr;
  double min_hours_per_km = 0;  // the least finite value of any frame (> 0): A*'s bound
  double max_hours_per_km = inf;  // the largest finite value of any frame: a step without a wait
  // Optional, frames x rows x cols like hours_per_km: how many charts from this one on the
  // pixel stays closed (0: open in this chart; at most 32767): a step closed in chart j cannot
  // open before chart j + closed_for of any pixel it crosses, so those charts are skipped.
  const std::int16_t* closed_for = nullptr;
};

class IceSeasonTime {
 public:
  static constexpr Capabilities caps = on_the_clock;
  IceSeasonTime(const Geometry& g, const std::vector<Offset>& st, const IceSeries& s)
      : g_(g), st_(st), s_(s) {
    corners_.resize(st.size());
    for (std::size_t o = 0; o < st.size(); ++o)
      for (const CellShare& t : st[o].touched)
        if (t.fraction == 0) corners_[o].push_back(t);
  }

  // Hours per km: at least the fastest ice of the season; waiting has no upper bound, a step
  // that does not wait costs at most the slowest ice's hours.
  StepBounds bounds(const Passability&) const {
    return {s_.min_hours_per_km, inf, true, s_.max_hours_per_km};
  }

  template <class Cell>
  double operator()(std::int64_t v, std::int64_t, int o, double r_km, double t_h, Cell&& cell) const {
    return step(v, o, r_km, t_h, cell).arrive_h - t_h;
  }

  struct Step {
    double depart_h, arrive_h;  // the best departure at or after the arrival at v, and its arrival
  };

  // The earliest arrival of the step v -> v + offset o (length r_km) for a ship at v at t_h;
  // cell(m) is the flat index of the step's m-th length share (the search's, or at()'s).
  template <class Cell>
  Step step(std::int64_t v, int o, double r_km, double t_h, Cell&& cell) const {
    const double* from = s_.valid_from_h;
    const std::int64_t k = chart_at(t_h);
    Step best{t_h, t_h + duration(v, o, r_km, k, cell)};
    // Later charts can only help if they start before the best arrival so far.
    for (std::int64_t j = k + 1; j < s_.frames && from[j] < best.arrive_h; ++j) {
      if (const std::int64_t skip = closed_charts(j, o, cell); skip > 0) {
        j += skip - 1;
        continue;
      }
      const double a = from[j] + duration(v, o, r_km, j, cell);
      if (a < best.arrive_h) best = {from[j], a};
    }
    return best;
  }
  // The cell(m) of step o from v outside the search: the flat index of its m-th length share.
  auto shares_of(std::int64_t v, int o) const {
    return [this, v, o](std::size_t m) {
      const CellShare& c = st_[std::size_t(o)].shares[m];
      return at(v, c.di, c.dj);
    };
  }
  Step step(std::int64_t v, int o, double r_km, double t_h) const {
    return step(v, o, r_km, t_h, shares_of(v, o));
  }

  // The index of the chart valid at t_h (the first before departure). The search relaxes a
  // pixel's steps one after another at the same time: the chart is found once.
  std::int64_t chart_at(double t_h) const {
    if (t_h != memo_t_) {
      const double* from = s_.valid_from_h;
      memo_t_ = t_h;
      memo_k_ = std::max<std::int64_t>(std::int64_t(std::upper_bound(from, from + s_.frames, t_h) - from) - 1, 0);
    }
    return memo_k_;
  }
  const IceSeries& series() const { return s_; }

  // Legs on the clock (timed_legs.hpp): the step v -> w sailed from t_h without waiting, and a
  // move of la km in pixel a then lb km in pixel b started at t_h (the line integral through
  // the chart valid then), in hours (inf where closed); whether pixel c is open in every chart
  // valid from t0_h to t1_h.
  double sail(std::int64_t v, std::int64_t, int o, double r_km, double t_h) const {
    return duration(v, o, r_km, chart_at(t_h), shares_of(v, o));
  }
  template <class Course>
  double move_hours(std::int64_t a, std::int64_t b, double la, double lb, const Course&, double t_h) const {
    const float* h = s_.hours_per_km + chart_at(t_h) * g_.size();
    return la * double(h[a]) + (lb > 0 ? lb * double(h[b]) : 0.0);
  }
  bool open(std::int64_t c, double t0_h, double t1_h) const {
    const std::int64_t k0 = chart_at(t0_h);
    for (std::int64_t k = k0; k < s_.frames && (k == k0 || s_.valid_from_h[k] <= t1_h); ++k)
      if (!(double(s_.hours_per_km[k * g_.size() + c]) < inf)) return false;
    return true;
  }

  // The flat index of the pixel (di, dj) from v, across the antimeridian on wrapping grids.
  std::int64_t at(std::int64_t v, int di, int dj) const {
    const std::int64_t row = v / g_.cols;
    std::int64_t c = v - row * g_.cols + dj;
    if (g_.wrap) c = c < 0 ? c + g_.cols : (c >= g_.cols ? c - g_.cols : c);
    return (row + di) * g_.cols + c;
  }

  // How many charts from chart j on the step's own pixels keep it closed (0: it may be open).
  template <class Cell>
  std::int64_t closed_charts(std::int64_t j, int o, Cell&& cell) const {
    if (!s_.closed_for) return 0;
    const std::int16_t* c = s_.closed_for + j * g_.size();
    std::int64_t most = 0;
    const auto& shares = st_[std::size_t(o)].shares;
    for (std::size_t m = 0; m < shares.size(); ++m) most = std::max<std::int64_t>(most, c[cell(m)]);
    return most;
  }

  // Hours to sail the step through chart k; inf when the step touches closed ice or land.
  template <class Cell>
  double duration(std::int64_t v, int o, double r_km, std::int64_t k, Cell&& cell) const {
    const float* h = s_.hours_per_km + k * g_.size();
    const auto& shares = st_[std::size_t(o)].shares;
    double sum = 0;
    for (std::size_t m = 0; m < shares.size(); ++m) sum += shares[m].fraction * double(h[cell(m)]);
    if (!(sum < inf)) return inf;
    for (const CellShare& t : corners_[std::size_t(o)]) {
      const std::int64_t c = g_.wrap ? at(v, t.di, t.dj) : v + t.di * g_.cols + t.dj;
      if (!(double(h[c]) < inf)) return inf;
    }
    return sum * r_km;
  }

 private:
  const Geometry& g_;
  const std::vector<Offset>& st_;
  IceSeries s_;
  std::vector<std::vector<CellShare>> corners_;  // pixels each step meets only at a corner
  mutable double memo_t_ = -inf;  // one functor per query (models.hpp): not shared by threads
  mutable std::int64_t memo_k_ = 0;
};

}  // namespace seaway
