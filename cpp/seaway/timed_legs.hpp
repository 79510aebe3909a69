// The arrival time of an arbitrary straight leg sailed on the clock under a time model
// (weather.hpp, ice_time.hpp, ice_weather.hpp, timed_zones.hpp), from a departure time, without
// waiting: what smoothing a time route (timed_smooth.hpp) needs.
//
// The leg's path is the static smoothing's (leg_path.hpp: the great circle on lat/lon charts)
// cut at pixel borders (leg_pieces.hpp). A leg that is one of the engine's stencil steps is
// sailed by the model's own step (Model::sail: exactly what the engine charges for that step
// started then, without a wait). Any other leg is sailed piece by piece: the piece inside pixel
// c, entered at time t, takes Model::piece_hours(c, length, course, t) — the model's rule for
// that pixel at that time (the ice chart valid then, the weather then on the piece's course),
// as the engine reads a step's at the time the ship starts it — and the ship enters the next
// pixel when it leaves this one. A piece along a pixel border is charged the slower side.
//
// Forbidden (inf): a leg whose closed path touches a pixel closed on the chart (land, or the
// chart's own impassable pixels) or leaves it; a piece whose pixels are not Model::open for the
// whole time the ship is in them (closed ice in any chart valid then, wind or waves beyond the
// vessel's limits, a zone closed then); a border point touching a pixel not open when the ship
// is there.
#pragma once

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
    double t = t_h, entered = t_h;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const LegPiece& k = pieces[i];
      if (!open(k.start, t, t)) return inf;
      if (i == 0 || !same(k.inside, pieces[i - 1].inside)) entered = t;  // a path vertex cut it
      const Course heading = course(k.from, k.to);
      double h = 0;
      for_each_pixel(k.inside, [&](std::int64_t r, std::int64_t c) {
        h = std::max(h, m_.piece_hours(flat(r, c), k.len, heading, entered));
      });
      if (!(h < inf) || !open(k.inside, t, t + h)) return inf;
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
};

}  // namespace seaway
