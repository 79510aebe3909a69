// The turn penalty's prices (turns.hpp): a piecewise-linear cost of the course change, the
// angle between two stencil steps in the local metric, and their table per row.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "compat.hpp"
#include "geometry.hpp"

namespace seaway {

// Share of the bound the turn search gives up for its bucket queue (astar_bucket_eps for the
// plain search): the states it explores grow faster with it (A winter's voyages: 0.01 settled
// 10-35 % fewer states than 0.05; 0.003 needs more buckets than the ring holds).
constexpr double turn_bucket_eps = 0.01;

// Piecewise-linear penalty of the course change: cost[i] at angle_deg[i] (ascending, from 0 to
// 180), linear between, in the route's cost units. Per degree p: {0, 180} -> {0, 180 p}.
struct TurnPenalty {
  std::vector<double> angle_deg, cost;

  double operator()(double a) const {
    if (a <= angle_deg.front()) return cost.front();
    for (std::size_t i = 1; i < angle_deg.size(); ++i)
      if (a <= angle_deg[i]) {
        const double slope = (cost[i] - cost[i - 1]) / (angle_deg[i] - angle_deg[i - 1]);
        return slope * (a - angle_deg[i - 1]) + cost[i - 1];
      }
    return cost.back();
  }
};

// Unit direction of every offset at every row (one row on planar grids), for turn angles.
class TurnAngles {
 public:
  TurnAngles(const Geometry& g, const std::vector<Offset>& st) : n_(std::int64_t(st.size())) {
    rows_ = g.geographic ? g.rows : 1;
    dir_.resize(std::size_t(rows_ * n_ * 2));
    for (std::int64_t r = 0; r < rows_; ++r)
      for (std::int64_t o = 0; o < n_; ++o) {
        const Offset& s = st[std::size_t(o)];
        const double y = g.geographic ? s.di * g.dlat : s.di * g.dy;
        const double x = g.geographic ? s.dj * g.dlon * std::cos(g.lat(r) * deg) : s.dj * g.dx;
        const double len = std::hypot(y, x);
        dir_[std::size_t((r * n_ + o) * 2)] = y / len;
        dir_[std::size_t((r * n_ + o) * 2 + 1)] = x / len;
      }
  }
  // Degrees between offsets o1 and o2 at row r.
  double operator()(std::int64_t r, std::int64_t o1, std::int64_t o2) const {
    if (o1 == o2) return 0;
    const double* a = &dir_[std::size_t(((rows_ == 1 ? 0 : r) * n_ + o1) * 2)];
    const double* b = &dir_[std::size_t(((rows_ == 1 ? 0 : r) * n_ + o2) * 2)];
    return std::acos(std::clamp(a[0] * b[0] + a[1] * b[1], -1.0, 1.0)) / deg;
  }
  std::size_t bytes() const { return dir_.capacity() * sizeof(double); }

 private:
  std::int64_t n_, rows_;
  std::vector<double> dir_;
};

// The penalty of every (incoming, outgoing) offset pair per row (one row on planar grids), so
// a relaxation reads a number instead of taking an arccosine; computed on the fly when the
// table would pass 64 MB (lat/lon grids with wide stencils).
// With the table comes the dominance margin of every pair of incoming offsets a, b at a pixel:
// margin(a, b) = max over outgoing o of penalty(a, o) - penalty(b, o). A state reached along a
// with label d_a can continue however a state reached along b with d_b can, at no more cost,
// once d_a + margin(a, b) <= d_b (the turn search then drops the second state: turns.hpp). For a
// penalty that grows with the angle and is concave in it (per degree, for one), the margin is
// the penalty of the turn from a to b.
class TurnCosts {
 public:
  TurnCosts(const Geometry& g, const std::vector<Offset>& st, const TurnPenalty& p)
      : angles_(g, st), p_(p), k_(std::int64_t(st.size())), rows_(g.geographic ? g.rows : 1) {
    zeros_.assign(std::size_t(k_), 0.0);
    if (double(rows_) * double(k_ * k_) * sizeof(double) > 32e6) return;
    table_.resize(std::size_t(rows_ * k_ * k_));
    for (std::int64_t r = 0; r < rows_; ++r)
      for (std::int64_t a = 0; a < k_; ++a)
        for (std::int64_t b = 0; b < k_; ++b) table_[std::size_t((r * k_ + a) * k_ + b)] = p(angles_(r, a, b));
    margin_.resize(table_.size());
    margin_ready_.assign(std::size_t(rows_), 0);
    if (rows_ == 1) fill_margins(0);
  }
  double operator()(std::int64_t row, std::int64_t in, std::int64_t o) const {
    if (table_.empty()) return p_(angles_(row, in, o));
    return table_[std::size_t(((rows_ == 1 ? 0 : row) * k_ + in) * k_ + o)];
  }
  // The penalties of leaving a pixel of row `row` reached along `in` (-1: none, all zero), by
  // outgoing offset; nullptr when they are computed on the fly.
  const double* leaving(std::int64_t row, std::int64_t in) const {
    if (in < 0) return zeros_.data();
    return table_.empty() ? nullptr : &table_[std::size_t(((rows_ == 1 ? 0 : row) * k_ + in) * k_)];
  }
  // Whether states may be dropped by their margins (the tables exist).
  bool prunes() const { return !margin_.empty(); }
  // margin(a, b) at a pixel of row `row` (prunes() only); a row's margins are worked out when
  // first asked for (k^3 steps: a search reaches few rows of a large lat/lon chart).
  SEAWAY_ALWAYS_INLINE double margin(std::int64_t row, std::int64_t a, std::int64_t b) const {
    const std::int64_t r = rows_ == 1 ? 0 : row;
    if (!margin_ready_[std::size_t(r)]) fill_margins(r);
    return margin_[std::size_t((r * k_ + a) * k_ + b)];
  }
  double largest() const { return *std::max_element(p_.cost.begin(), p_.cost.end()); }
  std::size_t bytes() const {
    return angles_.bytes() + (table_.capacity() + margin_.capacity() + zeros_.capacity()) * sizeof(double);
  }

 private:
#if defined(__GNUC__)
  __attribute__((noinline, cold))
#endif
  void fill_margins(std::int64_t r) const {
    const double* t = &table_[std::size_t(r * k_ * k_)];
    double* m = &margin_[std::size_t(r * k_ * k_)];
    for (std::int64_t a = 0; a < k_; ++a)
      for (std::int64_t b = 0; b < k_; ++b) {
        double worst = -inf;
        for (std::int64_t o = 0; o < k_; ++o) worst = std::max(worst, t[a * k_ + o] - t[b * k_ + o]);
        m[a * k_ + b] = worst;
      }
    margin_ready_[std::size_t(r)] = 1;
  }
  TurnAngles angles_;
  const TurnPenalty& p_;
  std::int64_t k_, rows_;
  std::vector<double> table_, zeros_;
  mutable std::vector<double> margin_;
  mutable std::vector<std::uint8_t> margin_ready_;
};

}  // namespace seaway
