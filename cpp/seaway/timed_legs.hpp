// The arrival time of an arbitrary straight leg sailed on the clock under a time model
// (weather.hpp, ice_time.hpp, ice_weather.hpp, timed_zones.hpp), from a departure time, without
// waiting: what smoothing a time route (timed_smooth.hpp) needs.
//
// The leg's path is the static smoothing's (leg_path.hpp: the great circle on lat/lon charts)
// cut at pixel borders (leg_pieces.hpp). A leg that is one of the engine's stencil steps is
// sailed by the model's own step (Model::sail: exactly what the engine charges for that step
// started then, without a wait). Any other leg is sailed as the chain of the pixels it crosses
// (as legs.hpp prices the max and mean rules): the move from pixel a to the next, b, covers the
// second half of the leg's length in a and the first half in b (the first move all of the first
// pixel's, the last all of the last's), on the great-circle course from the middle of a to the
// middle of b, and takes Model::move_hours(a, b, length in a, length in b, course, t): the
// model's own step rule between a and b started at t, the time the ship starts that move (the
// ice chart valid then, the weather then, the mean of a's and b's as the engine reads a step's
// two ends). A straight run of axis or diagonal steps is so priced as the engine prices its
// steps one by one (on lat/lon charts along the great circle, a little shorter). A piece along
// a pixel border is charged as the slower side.
//
// Forbidden (inf): a leg whose closed path touches a pixel closed on the chart (land, or the
// chart's own impassable pixels) or leaves it; a move whose pixels, or a border point between
// them, are not Model::open for the whole time the move takes (closed ice in any chart valid
// then, wind or waves beyond the vessel's limits, a zone closed then).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "leg_pieces.hpp"
#include "prepared_chart.hpp"
#include "weather.hpp"

namespace seaway {

template <class Model>
class TimedLegs {
 public:
  // closed[p] != 0: pixel p is impassable whatever the time (the chart's land and its own
  // impassable pixels), one byte per pixel of the chart.
  TimedLegs(const PreparedChart& chart, const Model& model, const std::uint8_t* closed)
      : chart_(chart), g_(chart.geometry()), m_(model), closed_(closed), split_(chart.geometry()) {}

  // Hours after departure at which the leg p -> q (fractional (row, col); columns may run past
  // the chart's last on a chart that wraps) started at t_h reaches q; inf if it is forbidden.
  double arrive(Point p, Point q, double t_h) const {
    const std::int64_t o = step_offset(p, q);
    leg_path(g_, p, q, o >= 0, path_);
    const std::vector<LegPiece>& pieces = split_.split(path_);
    for (const LegPiece& k : pieces)
      if (!on_water(k.start) || !on_water(k.inside)) return inf;
    if (!on_water(split_.end())) return inf;
    if (o >= 0) {
      const std::int64_t v = flat(std::int64_t(p.r), std::int64_t(p.c));
      const double r_km = chart_.lengths().row(std::int64_t(p.r))[o];
      return t_h + m_.sail(v, flat(std::int64_t(q.r), std::int64_t(q.c)), int(o), r_km, t_h);
    }
    // The pixels the path crosses in order ("cells": consecutive pieces inside one pixel).
    cells_.clear();
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (i == 0 || !same(pieces[i].inside, pieces[i - 1].inside)) cells_.push_back({i, i, 0.0});
      cells_.back().last = i;
      cells_.back().len += pieces[i].len;
    }
    const std::size_t n = cells_.size();
    double t = t_h;
    for (std::size_t i = 0; i + 1 < std::max<std::size_t>(n, 2) && n > 0; ++i) {
      // The move from cell a to cell b: a's second half (all of it for the first) and b's
      // first half (all of it for the last), read as a step from a to b.
      const Cell& a = cells_[i];
      const Cell& b = cells_[std::min(i + 1, n - 1)];
      const double la = i == 0 ? a.len : a.len / 2;
      const double lb = n == 1 ? 0.0 : (i + 2 == n ? b.len : b.len / 2);
      const Course heading = course(i == 0 ? path_.front() : middle(a), i + 2 >= n ? path_.back() : middle(b));
      double h = 0;
      for_each_pixel(pieces[a.first].inside, [&](std::int64_t ra, std::int64_t ca) {
        for_each_pixel(pieces[b.first].inside, [&](std::int64_t rb, std::int64_t cb) {
          h = std::max(h, m_.move_hours(flat(ra, ca), flat(rb, cb), la, lb, heading, t));
        });
      });
      if (!(h < inf)) return inf;
      for (std::size_t k = a.first; k <= b.last; ++k)  // the border before a is the last move's
        if ((k > a.first || i == 0) && !open(pieces[k].start, t, t + h)) return inf;
      for (std::size_t k = a.first; k <= b.last; ++k)
        if (!open(pieces[k].inside, t, t + h)) return inf;
      t += h;
    }
    return open(split_.end(), t, t) ? t : inf;
  }

 private:
  // The stencil offset of p -> q when the leg is an engine step (pixel centres within the
  // stencil's reach), else -1.
  std::int64_t step_offset(Point p, Point q) const {
    const bool centres = p.r == std::round(p.r) && p.c == std::round(p.c) && q.r == std::round(q.r) &&
                         q.c == std::round(q.c);
    const int half = chart_.half_width();
    if (!centres || std::fabs(q.r - p.r) > half || std::fabs(q.c - p.c) > half) return -1;
    return chart_.offset_index(int(q.r - p.r), int(q.c - p.c));
  }

  // The flat index of pixel (r, c) (c brought onto a wrapping chart), or -1 off the chart.
  std::int64_t flat(std::int64_t r, std::int64_t c) const {
    if (g_.wrap) c = ((c % g_.cols) + g_.cols) % g_.cols;
    if (r < 0 || r >= g_.rows || c < 0 || c >= g_.cols) return -1;
    return r * g_.cols + c;
  }
  struct Cell {
    std::size_t first, last;  // its pieces
    double len;
  };
  // The point of the path halfway along cell c.
  Point middle(const Cell& c) const {
    const std::vector<LegPiece>& pieces = split_.pieces();
    std::size_t k = c.first;
    double left = c.len / 2;
    for (; k < c.last && left > pieces[k].len; ++k) left -= pieces[k].len;
    const LegPiece& piece = pieces[k];
    const double f = piece.len > 0 ? std::clamp(left / piece.len, 0.0, 1.0) : 0.0;
    return {piece.from.r + f * (piece.to.r - piece.from.r), piece.from.c + f * (piece.to.c - piece.from.c)};
  }
  static bool same(const Touch& a, const Touch& b) {
    return a.r0 == b.r0 && a.r1 == b.r1 && a.c0 == b.c0 && a.c1 == b.c1;
  }
  bool on_water(const Touch& t) const {
    bool ok = true;
    for_each_pixel(t, [&](std::int64_t r, std::int64_t c) {
      const std::int64_t p = flat(r, c);
      ok = ok && p >= 0 && !closed_[p];
    });
    return ok;
  }
  // Every pixel of t open under the model from t0_h to t1_h (on_water checked them already).
  bool open(const Touch& t, double t0_h, double t1_h) const {
    bool ok = true;
    for_each_pixel(t, [&](std::int64_t r, std::int64_t c) { ok = ok && m_.open(flat(r, c), t0_h, t1_h); });
    return ok;
  }

  // The initial great-circle course from a to b (index space), as Geometry::step_courses gives
  // a step's; 0 on planar charts (no model there reads a course).
  Course course(Point a, Point b) const {
    if (!g_.geographic) return {0.0, 0.0, 1.0};
    const double p1 = (g_.lat0 + a.r * g_.dlat) * deg, p2 = (g_.lat0 + b.r * g_.dlat) * deg;
    const double dl = (b.c - a.c) * g_.dlon * deg;
    const double c = std::atan2(std::sin(dl) * std::cos(p2),
                                std::cos(p1) * std::sin(p2) - std::sin(p1) * std::cos(p2) * std::cos(dl));
    return {c, std::sin(c), std::cos(c)};
  }

  const PreparedChart& chart_;
  const Geometry& g_;
  const Model& m_;
  const std::uint8_t* closed_;
  LegSplitter split_;
  mutable std::vector<Point> path_;
  mutable std::vector<Cell> cells_;
};

}  // namespace seaway
