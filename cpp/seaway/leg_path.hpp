// The geometry of an arbitrary straight leg in a chart's index space (legs.hpp prices it): its
// length and its path (on geographic charts the great circle, as a polyline with a vertex every
// <= 4 pixels; the engine's own steps are straight in index space), and the rule that prices
// its pieces, taken from the model's functor.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry.hpp"

namespace seaway {

struct Point {
  double r, c;
};

// How a leg's pieces are priced: the model's own rule, taken from its functor. pair(a, b) is
// the cost per unit length between pixels of costs a and b (max, mean, length); null: the line
// integral (the functor declares line_integral).
struct LegRule {
  double (*pair)(double, double) = nullptr;

  template <class Functor>
  static LegRule of() {
    if constexpr (line_integral<Functor>(0)) return {nullptr};
    else return {&Functor::pair};
  }

 private:
  template <class F>
  static constexpr auto line_integral(int) -> decltype(bool(F::line_integral)) { return F::line_integral; }
  template <class F>
  static constexpr bool line_integral(long) { return false; }
};

// Great-circle km (geographic) or planar units between two index-space points.
inline double leg_length(const Geometry& g, Point a, Point b) {
  if (!g.geographic) return std::hypot((b.r - a.r) * g.dy, (b.c - a.c) * g.dx);
  const double p1 = (g.lat0 + a.r * g.dlat) * deg, p2 = (g.lat0 + b.r * g.dlat) * deg;
  const double dl = (b.c - a.c) * g.dlon * deg;
  const double s1 = std::sin((p2 - p1) / 2), s2 = std::sin(dl / 2);
  const double x = std::clamp(s1 * s1 + std::cos(p1) * std::cos(p2) * s2 * s2, 0.0, 1.0);
  return 2 * earth_radius_km * std::asin(std::sqrt(x));
}

// The path's vertices in index space into `path`: the segment p-q (planar charts, `straight`
// legs, short legs), or the great circle as a polyline with a vertex every <= 4 pixels.
inline void leg_path(const Geometry& g, Point p, Point q, bool straight, std::vector<Point>& path) {
  constexpr double subdivide = 4.0;  // index-space length of a great-circle leg's pieces
  auto lat = [&](double r) { return g.lat0 + r * g.dlat; };
  auto lon = [&](double c) { return g.lon0 + c * g.dlon; };
  path.clear();
  const double n_index = std::hypot(q.r - p.r, q.c - p.c);
  if (!g.geographic || straight || n_index <= subdivide) {
    path = {p, q};
    return;
  }
  const int m = int(std::ceil(n_index / subdivide));
  const double la1 = lat(p.r) * deg, lo1 = lon(p.c) * deg, la2 = lat(q.r) * deg, lo2 = lon(q.c) * deg;
  const double a[3] = {std::cos(la1) * std::cos(lo1), std::cos(la1) * std::sin(lo1), std::sin(la1)};
  const double b[3] = {std::cos(la2) * std::cos(lo2), std::cos(la2) * std::sin(lo2), std::sin(la2)};
  const double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2], cz = a[0] * b[1] - a[1] * b[0];
  const double omega = std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
  double prev = lon(p.c), unwrapped = prev, first = 0;
  for (int i = 0; i <= m; ++i) {
    const double f = double(i) / m;
    double v[3];
    for (int k = 0; k < 3; ++k)
      v[k] = omega < 1e-12 ? a[k] : (std::sin((1 - f) * omega) * a[k] + std::sin(f * omega) * b[k]) / std::sin(omega);
    const double la = std::atan2(v[2], std::hypot(v[0], v[1])) / deg;
    const double lo = std::atan2(v[1], v[0]) / deg;
    // Continuous longitudes (no jump over 180 degrees), then shifted so the first is lon(p).
    double d = std::fmod(lo - prev + 180.0, 360.0);
    if (d < 0) d += 360.0;
    unwrapped += d - 180.0;
    prev = lo;
    if (i == 0) first = unwrapped;
    path.push_back({(la - g.lat0) / g.dlat, (unwrapped + (lon(p.c) - first) - g.lon0) / g.dlon});
  }
  path.front() = p;
  // Across the seam of a 360-degree chart the path ends at q's column plus a whole turn.
  const double turns = g.wrap ? std::round((path.back().c - q.c) / double(g.cols)) : 0.0;
  path.back() = {q.r, q.c + turns * double(g.cols)};
}

}  // namespace seaway
