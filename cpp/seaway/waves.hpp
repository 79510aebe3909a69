// Wave danger by heading (Grinyak et al. 2018), built from IMO MSC.1/Circ.1228's criteria because the
// paper's storm diagram is only a figure. For a ship of length L (m) at speed V (kn), the
// danger u of meeting waves of significant height Hs, mean length lambda (deep water,
// g T^2 / 2 pi) from an encounter angle alpha (0 head seas, 180 following seas) is
//   u = 1 + 9 d,  d = max(successive high waves, surf-riding) in [0, 1], where
//   successive high waves = sector(alpha) * ramp(lambda / 0.8 L) * ramp(Hs / 0.04 L),
//   surf-riding         = sector(alpha) * ramp(V cos(180 - alpha) / 1.8 sqrt(L)),
// sector = 1 within 135-225 degrees, falling linearly to 0 ten degrees outside, and
// ramp(x) = 0 below 0.8, 1 above 1, linear between: u = 10 inside the Circular's dangerous
// zones, 1 well outside, linear in between (the paper's inner and outer polygons).
// A step costs (u_i + u_j) / 2 * r (Grinyak et al. 2018), u evaluated at each end for the step's course.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "cost_models.hpp"
#include "geometry.hpp"

namespace seaway {

inline double ramp08(double x) { return std::clamp((x - 0.8) / 0.2, 0.0, 1.0); }

// The danger u in [1, 10]; alpha in radians.
inline double wave_danger(double hs_m, double length_m, double alpha, double ship_length_m,
                          double speed_kn) {
  const double off = std::fabs(std::fabs(std::remainder(alpha, 2 * pi)) -
                               pi) / deg;  // degrees away from following
  const double sector = std::clamp((55.0 - off) / 10.0, 0.0, 1.0);
  if (sector == 0) return 1;
  const double high = ramp08(length_m / (0.8 * ship_length_m)) * ramp08(hs_m / (0.04 * ship_length_m));
  const double surf = ramp08(speed_kn * std::cos(pi - alpha) /
                             (1.8 * std::sqrt(ship_length_m)));
  return 1 + 9 * sector * std::max(high, surf);
}

class WaveDangerCost {
 public:
  static constexpr Capabilities caps = on_one_frame;
  // Fields (rows x cols, float32): significant height (m), direction the waves come from
  // (degrees true), mean period (s).
  WaveDangerCost(const Geometry& g, const std::vector<Offset>& st, const float* hs,
                 const float* from, const float* period, double ship_length_m, double speed_kn)
      : g_(g), course_(g.step_courses(st)), n_off_(std::int64_t(st.size())), hs_(hs),
        from_(from), period_(period), L_(ship_length_m), v_(speed_kn) {}

  StepBounds bounds(const Passability&) const { return {1.0, 10.0, true}; }

  template <class Cell>
  double operator()(std::int64_t v, std::int64_t w, int o, double r, double, Cell&&) const {
    const double course = course_[std::size_t((v / g_.cols) * n_off_ + o)];
    return 0.5 * (danger(v, course) + danger(w, course)) * r;
  }

 private:
  double danger(std::int64_t p, double course) const {
    const double length = 9.80665 * period_[p] * period_[p] / (2 * pi);
    return wave_danger(hs_[p], length, from_[p] * deg - course, L_, v_);
  }

  const Geometry& g_;
  std::vector<double> course_;
  std::int64_t n_off_;
  const float *hs_, *from_, *period_;
  double L_, v_;
};

}  // namespace seaway
