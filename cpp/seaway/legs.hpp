// The cost and land test of an arbitrary straight leg on a chart, consistent with the engine
// (the rules are documented in seaway.chart.legs, which binds this class).
// Points are fractional (row, col) pixel indices; pixel (i, j) is the closed square
// [i - 1/2, i + 1/2] x [j - 1/2, j + 1/2]. A leg is forbidden when its closed path touches the
// closed square of an impassable pixel or leaves the chart. On geographic charts the path is
// the great circle, followed through index space as a polyline with a vertex every <= 4
// pixels; a leg that is one of the engine's stencil steps is the engine's straight segment.
// Cost: split the path at pixel borders into pieces (length l_k in pixel of cost u_k);
// the model's own rule prices them (LegRule::of<Functor>, from cost_models.hpp): a line integral
// sums l_k u_k; a pair rule (max, mean) is applied to the chain of pixels crossed, each move
// between consecutive pixels of length (l_k + l_k+1) / 2 (the end half-pieces go to the end
// moves); a stencil step costs exactly what the engine charges.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "leg_pieces.hpp"

namespace seaway {

class LegPricer {
 public:
  // The chart's cost per unit length, float32 (uf) or float64 (ud), read in place, and its
  // land mask (or null): a pixel is impassable where land is set or its cost is NaN, inf or
  // negative (the engine's rule).
  LegPricer(const float* uf, const double* ud, const std::uint8_t* land, const Geometry& g, LegRule rule,
            int half)
      : uf_(uf), ud_(ud), land_(land), g_(g), rule_(rule), half_(half), split_(g) {}

  // (cost, length) of the leg p -> q; cost inf if the leg is forbidden.
  std::pair<double, double> leg(Point p, Point q) const {
    const bool step = is_step(p, q);
    std::vector<Point>& path = path_;
    make_path(p, q, step, path);
    if (!pieces(path)) {
      double total = 0;
      for (std::size_t i = 0; i + 1 < path.size(); ++i) total += length(path[i], path[i + 1]);
      return {inf, total};
    }
    double total = 0;
    for (const Piece& k : pieces_) total += k.len;
    if (!rule_.pair) {
      double s = 0;
      for (const Piece& k : pieces_) s += k.len * k.u;
      return {s, total};
    }
    if (step) {
      const double a = at(std::int64_t(p.r), std::int64_t(p.c)), b = at(std::int64_t(q.r), std::int64_t(q.c));
      return {rule_.pair(a, b) * total, total};
    }
    // One entry per pixel crossed (consecutive pieces in the same pixel merged).
    merged_.clear();
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
      if (i > 0 && pieces_[i].id == pieces_[i - 1].id) merged_.back().len += pieces_[i].len;
      else merged_.push_back(pieces_[i]);
    }
    const std::size_t n = merged_.size();
    if (n == 1) return {merged_[0].len * rule_.pair(merged_[0].u, merged_[0].u), total};
    double s = 0;
    for (std::size_t i = 0; i + 1 < n; ++i) {
      double move = (merged_[i].len + merged_[i + 1].len) / 2;
      if (i == 0) move += merged_[0].len / 2;
      if (i + 2 == n) move += merged_[n - 1].len / 2;
      const double a = merged_[i].u, b = merged_[i + 1].u;
      s += move * rule_.pair(a, b);
    }
    return {s, total};
  }

  double cost(const std::vector<Point>& pts) const {
    double s = 0;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) s += leg(pts[i], pts[i + 1]).first;
    return s;
  }

 private:
  struct Piece {
    double len, u;
    std::int64_t id;
  };

  bool is_step(Point p, Point q) const {
    return p.r == std::round(p.r) && p.c == std::round(p.c) && q.r == std::round(q.r) &&
           q.c == std::round(q.c) && std::max(std::fabs(q.r - p.r), std::fabs(q.c - p.c)) <= half_;
  }

  double length(Point a, Point b) const { return leg_length(g_, a, b); }
  void make_path(Point p, Point q, bool straight, std::vector<Point>& path) const {
    leg_path(g_, p, q, straight, path);
  }

  // Cost of pixel (r, c): inf outside the chart; columns wrap on a 360-degree chart.
  double at(std::int64_t r, std::int64_t c) const {
    if (g_.wrap) c = ((c % g_.cols) + g_.cols) % g_.cols;
    if (r < 0 || r >= g_.rows || c < 0 || c >= g_.cols) return inf;
    const std::int64_t i = r * g_.cols + c;
    const double x = uf_ ? double(uf_[i]) : ud_[i];
    return (x >= 0 && x < inf && !(land_ && land_[i])) ? x : inf;
  }
  // The largest cost among the pixels of t (1, 2 or 4 of them), and the id of the first.
  double around(const Touch& t, std::int64_t* id = nullptr) const {
    if (id) *id = t.r0 * (g_.cols + 1) + t.c0;
    return std::max({at(t.r0, t.c0), at(t.r0, t.c1), at(t.r1, t.c0), at(t.r1, t.c1)});
  }

  // Pieces of the polyline inside single pixels into pieces_; false if the closed polyline
  // touches an impassable pixel or leaves the chart.
  bool pieces(const std::vector<Point>& path) const {
    pieces_.clear();
    for (const LegPiece& k : split_.split(path)) {
      std::int64_t id;
      const double u = around(k.inside, &id);
      if (!(around(k.start) < inf) || !(u < inf)) return false;
      pieces_.push_back({k.len, u, id});
    }
    return around(split_.end()) < inf;
  }

  const float* uf_;
  const double* ud_;
  const std::uint8_t* land_;
  Geometry g_;
  LegRule rule_;
  int half_;
  // Scratch reused across calls (one pricer per thread).
  LegSplitter split_;
  mutable std::vector<Point> path_;
  mutable std::vector<Piece> pieces_, merged_;
};

}  // namespace seaway
