// The landmark (ALT) tables and the bounds read from them: one landmark's lower bound
// |D_L(t) - D_L(v)| on the cost from v to t, the max over landmarks, and the average potential
// of the bounds to the target and from the start for the bidirectional search, both read in one
// pass over the pixel's row of the tables.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "constants.hpp"
#include "geometry.hpp"

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

// p(v) = scale x (h_t(v) - h_s(v)) / 2, the consistent average potential (potentials.hpp) of
// the lower bounds h_t(v) = max(max_l |D_l(t) - D_l(v)|, straight-line bound to t) and h_s the
// same from s (a max of consistent bounds is consistent; the straight line is the better bound
// in open water of uniform cost), over the landmarks that reach both ends (the others reach no
// pixel of this search). One pass over the pixel's row; kept per pixel by the search
// (CachedBound): a pixel is pushed about three times.
class LandmarkPotential {
 public:
  static constexpr bool worth_caching = true;
  static constexpr bool sparse_keys = true;  // buckets a small share of a step wide
  static constexpr bool prunes = true;  // leaves out the steps of the chart's skip table
  // rate: the least cost per unit length (0: no straight-line bound).
  LandmarkPotential(const Landmarks& lm, const Geometry& g, std::int64_t start, std::int64_t target,
                    double rate, double scale)
      : table_(lm.table.data()), n_(lm.count()), scale_(0.5 * scale), to_t_(g, target, rate),
        from_s_(g, start, rate) {
    for (std::size_t l = 0; l < n_; ++l) {
      const float t = lm.table[std::size_t(target) * n_ + l], s = lm.table[std::size_t(start) * n_ + l];
      if (std::isfinite(t) && std::isfinite(s)) {
        use_.push_back(l);
        at_t_.push_back(t);
        at_s_.push_back(s);
      }
    }
    all_ = use_.size() == n_;
  }
  bool active() const { return true; }
  double operator()(std::int64_t v) const {
    const float* d = table_ + std::size_t(v) * n_;
    double bt = 0, bs = 0;
    if (all_) {
      for (std::size_t l = 0; l < n_; ++l) {
        const double x = double(d[l]);
        const double gt = std::fabs(double(at_t_[l]) - x), gs = std::fabs(double(at_s_[l]) - x);
        bt = gt > bt ? gt : bt;
        bs = gs > bs ? gs : bs;
      }
    } else {
      for (std::size_t i = 0; i < use_.size(); ++i) {
        const double x = double(d[use_[i]]);
        const double gt = std::fabs(double(at_t_[i]) - x), gs = std::fabs(double(at_s_[i]) - x);
        bt = gt > bt ? gt : bt;
        bs = gs > bs ? gs : bs;
      }
    }
    if (to_t_.active()) {
      const double dt = to_t_(v), ds = from_s_(v);
      bt = dt > bt ? dt : bt;
      bs = ds > bs ? ds : bs;
    }
    return scale_ * (bt - bs);
  }
  // scale x h_t(v): the one-way A* bound (the forward side's solo phase).
  double one_way(std::int64_t v) const {
    const float* d = table_ + std::size_t(v) * n_;
    double bt = to_t_.active() ? to_t_(v) : 0.0;
    for (std::size_t i = 0; i < use_.size(); ++i) {
      const double gt = std::fabs(double(at_t_[i]) - double(d[use_[i]]));
      bt = gt > bt ? gt : bt;
    }
    return 2 * scale_ * bt;
  }

 private:
  const float* table_;
  std::size_t n_;
  double scale_;
  bool all_ = false;
  std::vector<std::size_t> use_;
  std::vector<float> at_t_, at_s_;
  DistanceBound to_t_, from_s_;
};

}  // namespace seaway
