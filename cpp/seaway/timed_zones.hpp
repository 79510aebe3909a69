// Zones closed during a time window, for time routes: a step that touches a closed
// zone (either end inside) must end by the time the zone closes or start once it has opened
// again; otherwise the ship waits at the step's start until the zone opens. A step touches a
// zone when one of its ends or any pixel its closed segment meets lies in it (the land rule's
// pixels, so no long step jumps over a thin closed zone). A step's cost is
// then wait + sailing time at the new departure. Waiting keeps the search exact: if the
// weather is FIFO, leaving later never arrives earlier, so the earliest allowed departure is
// the best one, and arrival stays monotone in departure (the premise of the label-setting
// time search). A zone without a window is closed from -inf to +inf (an exclusion).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "cost_models.hpp"
#include "geometry.hpp"
#include "stencil.hpp"

namespace seaway {

// Bit z of mask[p] is set when pixel p lies in zone z (at most 8 zones), closed on
// [closes_h[z], opens_h[z]) in hours after departure.
// near[p] is set when a zone pixel lies within 7 pixels (the widest stencil's reach) of p, so
// that steps far from every zone cost one byte read.
struct TimeWindows {
  std::vector<std::uint8_t> mask, near;
  std::vector<double> closes_h, opens_h;
};

template <class Inner>
class ZonedTime {
 public:
  static constexpr Capabilities caps = Inner::caps;
  ZonedTime(const Inner& inner, const TimeWindows& z, const Geometry& g, const std::vector<Offset>& st)
      : inner_(inner), z_(z), g_(g), st_(st) {}

  auto bounds(const Passability& p) const { return inner_.bounds(p); }

  // The zones the step v -> w along offset o touches, one bit each.
  std::uint8_t bits(std::int64_t v, std::int64_t w, int o) const {
    if (!z_.near[std::size_t(v)]) return 0;
    std::uint8_t b = std::uint8_t(z_.mask[std::size_t(v)] | z_.mask[std::size_t(w)]);
    const std::int64_t C = g_.cols, row = v / C, col = v - row * C;
    for (const CellShare& t : st_[std::size_t(o)].touched) {
      std::int64_t c = col + t.dj;
      if (g_.wrap) c = c < 0 ? c + C : (c >= C ? c - C : c);
      b = std::uint8_t(b | z_.mask[std::size_t((row + t.di) * C + c)]);
    }
    return b;
  }

  template <class Cell>
  double operator()(std::int64_t v, std::int64_t w, int o, double r, double t_h, Cell&& cell) const {
    double h = inner_(v, w, o, r, t_h, cell);
    const std::uint8_t bits = this->bits(v, w, o);
    if (!bits || !(h < inf)) return h;
    const double dep = departure(v, w, o, r, t_h, h, bits, cell);
    if (dep == t_h) return h;
    return dep < inf ? dep - t_h + inner_(v, w, o, r, dep, cell) : inf;
  }

  // Hours after departure at which the step is started (>= t_h: the ship waits until then).
  template <class Cell>
  double departure(std::int64_t v, std::int64_t w, int o, double r, double t_h, double h,
                   std::uint8_t bits, Cell&& cell) const {
    double dep = t_h;
    // Each zone can push the departure once (to its opening), so 8 rounds settle it.
    for (int round = 0; round < 9; ++round) {
      bool moved = false;
      for (std::size_t z = 0; z < z_.closes_h.size(); ++z) {
        if (!((bits >> z) & 1u)) continue;
        if (dep < z_.opens_h[z] && dep + h > z_.closes_h[z]) {
          dep = z_.opens_h[z];
          if (!(dep < inf)) return inf;
          h = inner_(v, w, o, r, dep, cell);
          if (!(h < inf)) return inf;
          moved = true;
        }
      }
      if (!moved) break;
    }
    return dep;
  }

  // Legs on the clock (timed_legs.hpp): the inner model's, and no zone touched while it is
  // closed (the step between its start and its arrival, as above; a pixel from t0_h to t1_h).
  double sail(std::int64_t v, std::int64_t w, int o, double r, double t_h) const {
    const double h = inner_.sail(v, w, o, r, t_h);
    return h < inf && closed_during(bits(v, w, o), t_h, t_h + h) ? inf : h;
  }
  template <class Course>
  double move_hours(std::int64_t a, std::int64_t b, double la, double lb, const Course& heading, double t_h) const {
    return inner_.move_hours(a, b, la, lb, heading, t_h);
  }
  bool open(std::int64_t c, double t0_h, double t1_h) const {
    return inner_.open(c, t0_h, t1_h) && !closed_during(z_.mask[std::size_t(c)], t0_h, t1_h);
  }
  bool closed_during(std::uint8_t bits, double t0_h, double t1_h) const {
    for (std::size_t z = 0; z < z_.closes_h.size(); ++z)
      if (((bits >> z) & 1u) && t0_h < z_.opens_h[z] && t1_h > z_.closes_h[z]) return true;
    return false;
  }

  const Inner& inner() const { return inner_; }
  const TimeWindows& windows() const { return z_; }

 private:
  const Inner& inner_;
  const TimeWindows& z_;
  const Geometry& g_;
  const std::vector<Offset>& st_;
};

// Base (a time model struct of models.hpp) with zones closed in time windows on its grid.
template <class Base>
struct Zoned {
  static constexpr Capabilities caps = Base::caps;
  Base base;
  TimeWindows zones;

  template <class G, class F>
  auto visit(const G& g, F&& f) const {
    if (std::int64_t(zones.mask.size()) != g.geometry().size() || zones.near.size() != zones.mask.size())
      throw std::invalid_argument("the zone mask must have one value per pixel of the chart");
    return base.visit(g, [&](const auto& inner) {
      return f(ZonedTime<std::decay_t<decltype(inner)>>(inner, zones, g.geometry(), g.stencil()));
    });
  }

  // The hours each step waits for a zone to open ("wait_h"), beside the base model's values.
  template <class Fn, class G, class R>
  auto step_values(const Fn& m, const G& g, const R& out) const {
    auto values = base.step_values(m.inner(), g, out);
    std::vector<double> wait;
    for (std::size_t i = 0; i < out.offsets.size(); ++i) {
      const std::int64_t v = out.path[i], w = out.path[i + 1];
      const int o = out.offsets[i];
      const double r = g.lengths().row(v / g.geometry().cols)[o], t = out.cumulative[i];
      auto no_cell = [](std::size_t) { return std::int64_t(0); };
      const double h = m.inner()(v, w, o, r, t, no_cell);
      const std::uint8_t bits = m.bits(v, w, o);
      wait.push_back(bits && h < inf ? m.departure(v, w, o, r, t, h, bits, no_cell) - t : 0.0);
    }
    values.wait_h = std::move(wait);
    return values;
  }
};

}  // namespace seaway
