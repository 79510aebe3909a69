// A leg's path (leg_path.hpp) cut at pixel borders into pieces, each inside one pixel, with the
// pixels its closed path touches: what legs.hpp prices on a chart's raster and timed_legs.hpp
// on a clock. Pixel (i, j) is the closed square [i - 1/2, i + 1/2] x [j - 1/2, j + 1/2].
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "leg_path.hpp"

namespace seaway {

// The pixels whose closed squares hold a point: rows r0..r1 and columns c0..c1 (1, 2 or 4
// pixels; r1 = r0 or r0 + 1, likewise c1), as raw indices: off the chart, or past its last
// column on a chart that wraps.
struct Touch {
  std::int64_t r0, r1, c0, c1;
};

inline Touch touch_of(Point x) {
  constexpr double eps = 1e-9;
  return {std::int64_t(std::floor(x.r + 0.5 - eps)), std::int64_t(std::floor(x.r + 0.5 + eps)),
          std::int64_t(std::floor(x.c + 0.5 - eps)), std::int64_t(std::floor(x.c + 0.5 + eps))};
}

// Calls f(r, c) for each pixel of t (raw indices).
template <class F>
void for_each_pixel(const Touch& t, F&& f) {
  for (std::int64_t r = t.r0; r <= t.r1; ++r)
    for (std::int64_t c = t.c0; c <= t.c1; ++c) f(r, c);
}

struct LegPiece {
  double len;    // km on geographic charts, chart units on planar ones
  Point from, to;  // its ends in index space
  Touch start;   // the pixels its first point touches
  Touch inside;  // the pixels holding it (one; two for a piece along a border)
};

// Splits paths; one per thread (it keeps its scratch).
class LegSplitter {
 public:
  explicit LegSplitter(const Geometry& g) : g_(g) {}

  // The pieces of `path` in order (consecutive pieces may lie in one pixel: a path vertex cuts
  // them); end() is the touch of the path's last point.
  const std::vector<LegPiece>& split(const std::vector<Point>& path) const {
    constexpr double eps = 1e-9;
    pieces_.clear();
    end_ = touch_of(path.back());
    for (std::size_t s = 0; s + 1 < path.size(); ++s) {
      const Point a = path[s], b = path[s + 1];
      // The border crossings of each axis, each list ascending in t, then merged.
      ts_.assign({0.0});
      std::size_t mid = 1;
      for (int axis = 0; axis < 2; ++axis) {
        const double xa = axis ? a.c : a.r, xb = axis ? b.c : b.r;
        const double lo = std::min(xa, xb), hi = std::max(xa, xb);
        if (hi - lo > eps) {
          const double k0 = std::ceil(lo - 0.5 - eps), k1 = std::floor(hi - 0.5 + eps);
          const std::size_t from = ts_.size();
          for (double k = k0; k <= k1; ++k) ts_.push_back(std::clamp((k + 0.5 - xa) / (xb - xa), 0.0, 1.0));
          if (xb < xa) std::reverse(ts_.begin() + std::ptrdiff_t(from), ts_.end());
        }
        if (axis == 0) mid = ts_.size();
      }
      std::inplace_merge(ts_.begin() + 1, ts_.begin() + std::ptrdiff_t(mid), ts_.end());
      ts_.push_back(1.0);
      kept_.clear();
      for (std::size_t i = 0; i < ts_.size(); ++i)
        if (i == 0 || ts_[i] - ts_[i - 1] > eps) kept_.push_back(ts_[i]);
      const double seg = leg_length(g_, a, b);
      auto point = [&](double t) { return Point{a.r + t * (b.r - a.r), a.c + t * (b.c - a.c)}; };
      for (std::size_t i = 0; i + 1 < kept_.size(); ++i) {
        const Point p = point(kept_[i]), q = point(kept_[i + 1]);
        pieces_.push_back({(kept_[i + 1] - kept_[i]) * seg, p, q, touch_of(p),
                           touch_of(point((kept_[i] + kept_[i + 1]) / 2))});
      }
      // A segment's last point starts the next segment's first piece, or ends the path.
      if (s + 2 == path.size() && !kept_.empty()) end_ = touch_of(point(kept_.back()));
    }
    return pieces_;
  }
  const Touch& end() const { return end_; }
  const std::vector<LegPiece>& pieces() const { return pieces_; }

 private:
  Geometry g_;
  mutable std::vector<LegPiece> pieces_;
  mutable std::vector<double> ts_, kept_;
  mutable Touch end_{0, 0, 0, 0};
};

}  // namespace seaway
