// A lower bound on the turn penalties a route still pays (turns.hpp's A*), on planar grids.
//
// The steps of any route from pixel w to the target add up to the displacement D = target - w
// (in the metric (di*dy, dj*dx) the turn angles use), so some step has a direction within the
// arc the route's headings sweep; a route entering w along offset o turns, in all, at least the
// angle between o and D. Priced by the chord of that angle, |u_o - D/|D|| (a metric on the unit
// circle, below the angle in radians), times the least penalty per chord of any pair of stencil
// directions, slope = min over a, b of penalty(a, b) / |u_a - u_b|, the bound
//   H(w, o) = slope |u_o - D_w/|D_w||   (0 at the target)
// is consistent: H(v, a) <= slope |u_a - u_o| + slope |u_o - D_v/|D_v|| <= penalty(a, o) + H(w, o),
// since w = v + o turns D away from o (D_w = D_v - o: its angle to o only grows). Added to the
// bound without penalties (consistent in the step costs), the sum is consistent in step cost +
// penalty. Off on lat/lon grids (a step's direction changes with the row).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "compat.hpp"
#include "geometry.hpp"
#include "turn_penalty.hpp"

namespace seaway {

// Share of the bound the turn search gives up for its bucket queue (astar_bucket_eps for the
// plain search): the states it explores grow faster with it (A winter's voyages: 0.01 settled
// 10-35 % fewer states than 0.05; 0.003 needs more buckets than the ring holds).
constexpr double turn_bucket_eps = 0.01;

class HeadingBound {
 public:
  // `on`: whether to bound at all (A* only).
  HeadingBound(const Geometry& g, const std::vector<Offset>& st, const TurnCosts& pen, std::int64_t target,
               bool on)
      : cols_(g.cols), ti_(target / g.cols), tj_(target % g.cols), dy_(g.dy), dx_(g.dx), div_(g.cols) {
    if (g.geographic || g.wrap || !on) return;
    const std::size_t k = st.size();
    for (const Offset& o : st) {
      const double y = o.di * g.dy, x = o.dj * g.dx, len = std::sqrt(y * y + x * x);
      uy_.push_back(y / len);
      ux_.push_back(x / len);
    }
    double slope = inf;
    for (std::size_t a = 0; a < k; ++a)
      for (std::size_t b = 0; b < k; ++b) {
        const double chord = std::hypot(uy_[a] - uy_[b], ux_[a] - ux_[b]);
        if (chord > 1e-9) slope = std::min(slope, pen(0, std::int64_t(a), std::int64_t(b)) / chord);
      }
    // Below the slope by a hair: the chords above are rounded, and so is the bound.
    slope_ = slope < inf ? slope * (1 - 1e-12) : 0;
  }
  bool on() const { return slope_ > 0; }
  // The largest rise of the bound over one step (it lies in [0, 2 slope]).
  double largest_rise() const { return 2 * slope_; }
  SEAWAY_ALWAYS_INLINE double operator()(std::int64_t w, std::int64_t o) const {
    const std::int64_t r = div_(w);
    const double y = double(ti_ - r) * dy_, x = double(tj_ - (w - r * cols_)) * dx_;
    const double len = std::sqrt(y * y + x * x);
    if (len == 0) return 0;
    const double ey = uy_[std::size_t(o)] - y / len, ex = ux_[std::size_t(o)] - x / len;
    return slope_ * std::sqrt(ey * ey + ex * ex);
  }

 private:
  std::int64_t cols_, ti_, tj_;
  double dy_, dx_;
  FastDiv div_;
  std::vector<double> uy_, ux_;
  double slope_ = 0;
};

}  // namespace seaway
