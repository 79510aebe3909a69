// Time-optimal steps through currents, wind and waves that change in time (Olovyannikov 2025 and Sotnikova 2009).
// A step's cost is its duration in hours; the weather is read at both ends of the step at
// the time the ship starts it (the search's label), linearly interpolated between forecast
// frames. The search is label-setting, which is exact when the weather is FIFO: leaving a
// pixel later never means arriving earlier.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "cost_models.hpp"
#include "geometry.hpp"
#include "stencil.hpp"

namespace seaway {

// Fields on the chart grid, frames of rows x cols each (C order), float32; any may be null.
struct Forecast {
  std::int64_t frames = 1;
  double first_h = 0, step_h = 1;  // frame k is valid first_h + k * step_h hours after departure
  const float* current_east = nullptr;  // m/s, towards east
  const float* current_north = nullptr;
  const float* wave_height = nullptr;   // significant height, m
  const float* wave_from = nullptr;     // direction the waves come from, degrees true
  const float* wind_speed = nullptr;    // m/s
};

enum class SpeedLoss { none, khokhlov, stawave1 };

struct Vessel {
  double speed_kn = 12;           // speed through calm water
  double displacement_t = 15000;  // for Khokhlov's formula
  SpeedLoss speed_loss = SpeedLoss::khokhlov;
  // For STAWAVE-1: waterline breadth and length (m), calm-water resistance (kN) at speed_kn.
  double beam_m = 0, length_m = 0, calm_resistance_kn = 0;
  double max_wind_ms = 25, max_wave_m = 5;  // limits (Olovyannikov 2025); also danger-zone winds (Sotnikova 2009)
};

// Speed through water in wind waves, Khokhlov (Olovyannikov 2025, eq. 8): h3 the 3 % wave height (m),
// q the waves' bearing from the bow in radians (0: head seas, pi: following seas).
inline double khokhlov_speed_kn(double v0, double h3, double q, double displacement_t) {
  return v0 - (0.745 * h3 - 0.275 * q * h3) * (1 - 1.35e-6 * displacement_t * v0);
}

// Speed at constant delivered power in head waves, from STAWAVE-1 (ITTC 7.5-04-01-01.1, ISO
// 15016): added resistance R_aw = rho g Hs^2 B sqrt(B / L) / 16 (sea water rho = 1025 kg/m^3),
// valid for waves within 45 degrees of the bow and Hs <= 2.25 sqrt(L / 100); with calm
// resistance R0 at v0 growing as V^2, power R0 v0 = R0 (V/v0)^2 V + R_aw V gives V = x v0, x
// the real root of x^3 + (R_aw / R0) x - 1 = 0.
inline double stawave1_speed_kn(double v0, double hs_m, double beam_m, double length_m,
                                double calm_resistance_kn) {
  const double raw_kn = 1025.0 * 9.80665 * hs_m * hs_m * beam_m * std::sqrt(beam_m / length_m) / 16 / 1000;
  const double a = raw_kn / calm_resistance_kn;
  const double d = std::sqrt(0.25 + a * a * a / 27);
  return v0 * (std::cbrt(0.5 + d) + std::cbrt(0.5 - d));
}

// Speed over ground holding the track through a current of speed vt at angle q to the
// course (Olovyannikov 2025, eq. 6 with the crabbing sign); <= 0 or NaN when the track cannot be held.
inline double speed_over_ground_kn(double v, double vt, double q) {
  const double along = vt * std::cos(q), cross = vt * std::sin(q);
  if (std::fabs(cross) >= v) return 0;
  return along + std::sqrt(v * v - cross * cross);
}

// A course (radians from north, clockwise) with its sine and cosine.
struct Course {
  double rad, sin, cos;
};

class WeatherTime {
 public:
  static constexpr Capabilities caps = on_the_clock;
  WeatherTime(const Geometry& g, const std::vector<Offset>& st, const Forecast& f, const Vessel& v,
              double best_speed_kn)
      : g_(g), f_(f), v_(v), n_off_(std::int64_t(st.size())), best_kn_(best_speed_kn) {
    course_ = g.step_courses(st);
    for (double c : course_) {
      course_sin_.push_back(std::sin(c));
      course_cos_.push_back(std::cos(c));
    }
  }

  // Hours per km: at least 1 / the best attainable speed; no finite upper bound.
  StepBounds bounds(const Passability&) const { return {1.0 / (km_per_nm * best_kn_), inf, true}; }

  template <class Cell>
  double operator()(std::int64_t v, std::int64_t w, int o, double r_km, double t_h, Cell&&) const {
    const double speed = speed_over_ground(v, w, o, t_h, v_.speed_kn);
    return speed > 1e-9 ? r_km / km_per_nm / speed : inf;
  }

  // Speed over ground (kn) of the step v -> w along offset o started at t_h hours after
  // departure, with the engine set for v0_kn in calm water; 0 where the step is forbidden.
  double speed_over_ground(std::int64_t v, std::int64_t w, int o, double t_h, double v0_kn) const {
    const std::size_t ro = std::size_t((v / g_.cols) * n_off_ + o);
    return speed_on_course(v, w, {course_[ro], course_sin_[ro], course_cos_[ro]}, t_h, v0_kn);
  }

  // The same between pixels v and w (the weather the mean of theirs) on `course`.
  double speed_on_course(std::int64_t v, std::int64_t w, const Course& heading, double t_h, double v0_kn) const {
    const auto at = fields_at(t_h);
    if (f_.wind_speed && std::max(at(f_.wind_speed, v), at(f_.wind_speed, w)) > v_.max_wind_ms) return 0;
    const double course = heading.rad;

    double speed = v0_kn;
    if (f_.wave_height) {
      const double hv = at(f_.wave_height, v), hw = at(f_.wave_height, w);
      if (std::max(hv, hw) > v_.max_wave_m) return 0;
      if (v_.speed_loss != SpeedLoss::none) {
        double q = 0;  // waves of unknown direction: head seas, the largest loss
        if (f_.wave_from) {
          const double dv = at(f_.wave_from, v) * deg, dw = at(f_.wave_from, w) * deg;
          const double from = std::atan2(std::sin(dv) + std::sin(dw), std::cos(dv) + std::cos(dw));
          q = std::fabs(std::remainder(from - course, 2 * pi));
        }
        const double hs = 0.5 * (hv + hw);
        if (v_.speed_loss == SpeedLoss::khokhlov)
          speed = khokhlov_speed_kn(speed, 1.32 * hs, q, v_.displacement_t);
        else if (q <= pi / 4)  // STAWAVE-1 covers bow waves only; the calm resistance scales as v0^2
          speed = stawave1_speed_kn(speed, hs, v_.beam_m, v_.length_m,
                                    v_.calm_resistance_kn * (speed / v_.speed_kn) * (speed / v_.speed_kn));
      }
    }
    if (f_.current_east) {
      const double ce = 0.5 * (at(f_.current_east, v) + at(f_.current_east, w)) * knots_per_ms;
      const double cn = 0.5 * (at(f_.current_north, v) + at(f_.current_north, w)) * knots_per_ms;
      // The current along and across the course (course from north, clockwise): the same as
      // speed_over_ground_kn(speed, |c|, angle(c) - course), without the angles.
      const double along = cn * heading.cos + ce * heading.sin;
      const double cross = ce * heading.cos - cn * heading.sin;
      if (ce != 0 || cn != 0)
        speed = std::fabs(cross) >= speed ? 0 : along + std::sqrt(speed * speed - cross * cross);
    }
    return speed > 1e-9 ? speed : 0;
  }

  // Legs on the clock (timed_legs.hpp): the step v -> w sailed from t_h, and a move of la km
  // in pixel a then lb km in pixel b on `heading` from t_h (the step's rule between a and b),
  // in hours (inf where forbidden); whether pixel c stays within the wind and wave limits from
  // t0_h to t1_h (the fields are linear between frames: largest at the ends or a frame's time).
  double sail(std::int64_t v, std::int64_t w, int o, double r_km, double t_h) const {
    const double speed = speed_over_ground(v, w, o, t_h, v_.speed_kn);
    return speed > 1e-9 ? r_km / km_per_nm / speed : inf;
  }
  double move_hours(std::int64_t a, std::int64_t b, double la, double lb, const Course& heading, double t_h) const {
    const double speed = speed_on_course(a, b, heading, t_h, v_.speed_kn);
    return speed > 1e-9 ? (la + lb) / km_per_nm / speed : inf;
  }
  bool open(std::int64_t c, double t0_h, double t1_h) const {
    auto calm = [&](double t) {
      const auto at = fields_at(t);
      return !(f_.wind_speed && !(at(f_.wind_speed, c) <= v_.max_wind_ms)) &&
             !(f_.wave_height && !(at(f_.wave_height, c) <= v_.max_wave_m));
    };
    if (!calm(t0_h) || !calm(t1_h)) return false;
    const double first = std::floor((t0_h - f_.first_h) / f_.step_h) + 1;
    for (std::int64_t k = std::int64_t(std::max(first, 0.0)); k < f_.frames; ++k) {
      const double tk = f_.first_h + double(k) * f_.step_h;
      if (tk >= t1_h) break;
      if (tk > t0_h && !calm(tk)) return false;
    }
    return true;
  }

 private:
  // The fields at t_h, linear between frames (held at the ends of the forecast): at(field, p).
  struct FieldsAt {
    std::int64_t i0, i1, n;
    double a;
    double operator()(const float* field, std::int64_t p) const {
      return (1 - a) * double(field[i0 * n + p]) + a * double(field[i1 * n + p]);
    }
  };
  FieldsAt fields_at(double t_h) const {
    const double x = std::clamp((t_h - f_.first_h) / f_.step_h, 0.0, double(f_.frames - 1));
    const std::int64_t i0 = std::int64_t(x);
    return {i0, std::min(i0 + 1, f_.frames - 1), g_.size(), x - double(i0)};
  }

  const Geometry& g_;
  Forecast f_;
  Vessel v_;
  std::int64_t n_off_;
  double best_kn_;
  std::vector<double> course_, course_sin_, course_cos_;  // per row and offset
};

}  // namespace seaway
