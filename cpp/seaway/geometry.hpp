// Raster geometry (bound to Python as _core.Geometry): a planar grid (cell sizes dx, dy) or a
// regular lat/lon grid on a sphere, optionally wrapping at the antimeridian. Gives each stencil step's length and the
// straight-line (or great-circle) lower bound that A* uses.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <vector>

#include "constants.hpp"
#include "stencil.hpp"

namespace seaway {

// a / d for a, d < 2^32 by a multiply (Lemire et al. 2019: m = floor((2^64 - 1) / d) + 1, then
// a / d = (m a) >> 64, exact for 32-bit a and d): the searches find a pixel's row at every
// settle and every bound, and a 64-bit division costs tens of cycles. d = 1 is its own case.
class FastDiv {
 public:
  explicit FastDiv(std::int64_t d = 1) : m_(d > 1 ? ~std::uint64_t(0) / std::uint64_t(d) + 1 : 0) {}
  std::int64_t operator()(std::int64_t a) const {
    return m_ ? std::int64_t((static_cast<unsigned __int128>(m_) * std::uint64_t(a)) >> 64) : a;
  }

 private:
  std::uint64_t m_;
};

// Great-circle distance in km between two points given in degrees (haversine form).
inline double haversine_km(double lat1, double lon1, double lat2, double lon2) {
  const double s1 = std::sin((lat2 - lat1) * deg / 2), s2 = std::sin((lon2 - lon1) * deg / 2);
  const double a = s1 * s1 + std::cos(lat1 * deg) * std::cos(lat2 * deg) * s2 * s2;
  return 2 * earth_radius_km * std::asin(std::min(1.0, std::sqrt(a)));
}

struct Geometry {
  std::int64_t rows = 0, cols = 0;
  bool geographic = false;
  double dx = 1, dy = 1;                    // planar cell sizes (columns, rows)
  double lat0 = 0, dlat = 1, lon0 = 0, dlon = 1;  // centre of pixel (0, 0) and steps, degrees
  bool wrap = false;                        // columns are periodic (360 degrees of longitude)

  std::int64_t size() const { return rows * cols; }
  // A column index one period off (c in [-cols, 2 cols)) brought back onto the chart.
  std::int64_t wrap_col(std::int64_t c) const { return c < 0 ? c + cols : (c >= cols ? c - cols : c); }
  // The pixel one stencil step from v: along the offset (sign +1) or back along it (sign -1).
  std::int64_t step(std::int64_t v, const Offset& o, int sign) const {
    const std::int64_t r = v / cols + sign * o.di;
    std::int64_t c = v % cols + sign * o.dj;
    if (wrap) c = (c + cols) % cols;
    return r * cols + c;
  }
  double lat(std::int64_t r) const { return lat0 + double(r) * dlat; }

  // Length of every step from every row: table[row * stride + o]; stride 0 on planar grids,
  // where a step's length does not depend on the row.
  struct Lengths {
    std::vector<double> table;
    std::int64_t stride;
    const double* row(std::int64_t r) const { return table.data() + r * stride; }
  };

  Lengths step_lengths(const std::vector<Offset>& st) const {
    const std::int64_t n = std::int64_t(st.size());
    Lengths out{{}, geographic ? n : 0};
    if (!geographic) {
      for (const Offset& o : st) out.table.push_back(std::hypot(o.di * dy, o.dj * dx));
      return out;
    }
    // The haversine of each step with its trigonometry read from tables (a chart's preparation
    // made rows x n_offsets calls of sin, cos and asin): cos(lat) of every row a step reaches,
    // sin^2 of half of each offset's latitude and longitude angles (the grid is regular).
    std::int64_t reach = 0;
    std::vector<double> half_lat(static_cast<std::size_t>(n)), half_lon(static_cast<std::size_t>(n));
    for (std::int64_t k = 0; k < n; ++k) {
      const Offset& o = st[std::size_t(k)];
      reach = std::max<std::int64_t>(reach, std::abs(o.di));
      half_lat[std::size_t(k)] = std::pow(std::sin(o.di * dlat * deg / 2), 2);
      half_lon[std::size_t(k)] = std::pow(std::sin(o.dj * dlon * deg / 2), 2);
    }
    std::vector<double> cos_lat(std::size_t(rows + 2 * reach));
    for (std::int64_t r = -reach; r < rows + reach; ++r) cos_lat[std::size_t(r + reach)] = std::cos(lat(r) * deg);
    out.table.resize(std::size_t(rows * n));
    for (std::int64_t r = 0; r < rows; ++r)
      for (std::int64_t k = 0; k < n; ++k) {
        const std::int64_t to = r + st[std::size_t(k)].di + reach;
        const double a = half_lat[std::size_t(k)] +
                         cos_lat[std::size_t(r + reach)] * cos_lat[std::size_t(to)] * half_lon[std::size_t(k)];
        out.table[std::size_t(r * n + k)] = 2 * earth_radius_km * std::asin(std::min(1.0, std::sqrt(a)));
      }
    return out;
  }

  // Initial great-circle course (radians from north, clockwise) of every step from every row:
  // table[row * n_offsets + o]; it does not depend on the column. Geographic grids only.
  std::vector<double> step_courses(const std::vector<Offset>& st) const {
    const std::int64_t n = std::int64_t(st.size());
    std::vector<double> out(std::size_t(rows * n));
    for (std::int64_t r = 0; r < rows; ++r)
      for (std::int64_t k = 0; k < n; ++k) {
        const double p1 = lat(r) * deg, p2 = lat(r + st[std::size_t(k)].di) * deg;
        const double dl = st[std::size_t(k)].dj * dlon * deg;
        out[std::size_t(r * n + k)] =
            std::atan2(std::sin(dl) * std::cos(p2),
                       std::cos(p1) * std::sin(p2) - std::sin(p1) * std::cos(p2) * std::cos(dl));
      }
    return out;
  }
};

// The trigonometry of a lat/lon chart's chord bounds, made once per chart and thread (the
// last chart's tables are kept): sin^2 of half of k rows' and k columns' angles, cos(lat) of
// every row. Each DistanceBound made its own (rows + cols sines, rows cosines: about 30 us of a
// bidirectional landmark query, which makes two, on the 273 x 668 DMI SW chart).
struct ChordTables {
  Geometry g;
  std::vector<double> half_lat, half_lon, cos_lat;
  explicit ChordTables(const Geometry& geo) : g(geo) {
    for (std::int64_t k = 0; k < g.rows; ++k) half_lat.push_back(std::pow(std::sin(double(k) * g.dlat * deg / 2), 2));
    for (std::int64_t k = 0; k < g.cols; ++k) half_lon.push_back(std::pow(std::sin(double(k) * g.dlon * deg / 2), 2));
    for (std::int64_t r = 0; r < g.rows; ++r) cos_lat.push_back(std::cos(g.lat(r) * deg));
  }
  bool fits(const Geometry& o) const {
    return g.rows == o.rows && g.cols == o.cols && g.lat0 == o.lat0 && g.dlat == o.dlat && g.dlon == o.dlon;
  }
  static std::shared_ptr<const ChordTables> of(const Geometry& g) {
    thread_local std::shared_ptr<const ChordTables> last;
    if (!last || !last->fits(g)) last = std::make_shared<const ChordTables>(g);
    return last;
  }
};

// Admissible distance-to-target bound: straight-line or chord (great-circle) distance from a
// pixel to the target times a factor (the smallest cost per unit length, times the A* inflation).
class DistanceBound {
 public:
  DistanceBound(const Geometry& g, std::int64_t target, double factor)
      : g_(g), factor_(factor), row_of_(g.cols) {
    tr_ = target / g.cols;
    tc_ = target % g.cols;
    if (!g.geographic || factor == 0) return;
    trig_ = ChordTables::of(g);
    cos_t_ = trig_->cos_lat[std::size_t(tr_)];
  }

  bool active() const { return factor_ != 0; }
  double operator()(std::int64_t v) const {
    if (factor_ == 0) return 0;
    const std::int64_t r = row_of_(v), c = v - r * g_.cols;
    if (!g_.geographic) {  // sqrt, not hypot (several times slower): no overflow at chart sizes
      const double y = double(r - tr_) * g_.dy, x = double(c - tc_) * g_.dx;
      return factor_ * std::sqrt(x * x + y * y);
    }
    // The chord 2R sqrt(a), not the arc 2R asin(sqrt(a)): a metric of its own (straight lines in
    // space), never longer than a step's great-circle length, so the bound stays consistent;
    // within 0.2 % of the arc up to 1000 km, and without asin at every push.
    const ChordTables& t = *trig_;
    const double a = t.half_lat[std::size_t(std::abs(r - tr_))] +
                     t.cos_lat[std::size_t(r)] * cos_t_ * t.half_lon[std::size_t(std::abs(c - tc_))];
    return factor_ * 2 * earth_radius_km * std::sqrt(a);
  }

 private:
  const Geometry& g_;
  double factor_;
  FastDiv row_of_;
  std::int64_t tr_ = 0, tc_ = 0;
  std::shared_ptr<const ChordTables> trig_;
  double cos_t_ = 0;
};

}  // namespace seaway
