// Which pixels a ship may enter, and how far (Chebyshev, in pixels) each pixel is from the
// nearest one it may not. A pixel whose clearance exceeds the stencil's half-width has no
// forbidden step, so the search skips the land test for it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <thread>

#include "geometry.hpp"
#include "compat.hpp"

namespace seaway {

struct Passability {
  double min_cost = std::numeric_limits<double>::infinity();  // over passable pixels
  double max_cost = 0;
  std::int64_t passable = 0;                                  // how many there are
};

// clearance[v] = min(distance to the nearest impassable pixel, cap); 0 marks impassable.
// A pixel is impassable when its cost is NaN, infinite or negative, or land[v] is set.
// `scratch` holds one byte per pixel during the call. Rows are independent within each of the
// two passes, so on a chart of a million pixels or more each pass runs on two threads (the
// preparation is a tenth of a fresh chart's route otherwise); the result does not depend on it.
template <class T>
Passability compute_clearance(const Geometry& g, const T* cost, const std::uint8_t* land, int cap,
                              std::uint8_t* clearance, std::uint8_t* scratch) {
  const std::int64_t R = g.rows, C = g.cols;
  // Pass 1: distance along the row to the nearest impassable pixel of that row.
  auto rows_pass1 = [&](std::int64_t r_begin, std::int64_t r_end, Passability& out) {
    double lo = out.min_cost, hi = out.max_cost;  // locals: kept in registers (a byte store
    std::int64_t passable = 0;                    // could alias what the lambda captured)
    const std::int64_t cols = g.cols;  // a local: see above
    for (std::int64_t r = r_begin; r < r_end; ++r) {
      const T* u = cost + r * cols;
      const std::uint8_t* l = land ? land + r * cols : nullptr;
      std::uint8_t* h = scratch + r * cols;
      auto blocked = [&](std::int64_t c) {
        const double x = double(u[c]);
        return !(x >= 0 && x < std::numeric_limits<double>::infinity()) || (l && l[c]);
      };
      // With periodic columns the distance may run across the seam: start from the last
      // blocked pixel of the row, one period back.
      std::int64_t last = -4 * std::int64_t(cap);
      if (g.wrap)
        for (std::int64_t c = cols - 1; c >= 0; --c)
          if (blocked(c)) { last = c - cols; break; }
      for (std::int64_t c = 0; c < cols; ++c) {
        if (blocked(c)) {
          last = c;
        } else {
          const double x = double(u[c]);
          lo = std::min(lo, x);
          hi = std::max(hi, x);
          ++passable;
        }
        h[c] = std::uint8_t(std::min<std::int64_t>(c - last, cap));
      }
      last = 4 * std::int64_t(cap) + cols;
      if (g.wrap)
        for (std::int64_t c = 0; c < cols; ++c)
          if (h[c] == 0) { last = c + cols; break; }
      for (std::int64_t c = cols - 1; c >= 0; --c) {
        if (h[c] == 0) last = c;
        h[c] = std::uint8_t(std::min<std::int64_t>(h[c], last - c));
      }
    }
    out.min_cost = lo;
    out.max_cost = hi;
    out.passable += passable;
  };
  // Pass 2: Chebyshev distance = min over nearby rows of max(row gap, distance in that row).
  // (restrict: the rows do not overlap, so the compiler may vectorise the byte loop)
  auto rows_pass2 = [&](std::int64_t r_begin, std::int64_t r_end) {
    for (std::int64_t r = r_begin; r < r_end; ++r) {
      std::uint8_t* SEAWAY_RESTRICT out_row = clearance + r * C;
      std::copy(scratch + r * C, scratch + (r + 1) * C, out_row);
      for (int d = 1; d < cap; ++d)
        for (std::int64_t rr : {r - d, r + d}) {
          if (rr < 0 || rr >= R) continue;
          const std::uint8_t* SEAWAY_RESTRICT h = scratch + rr * C;
          const std::uint8_t gap = std::uint8_t(d);
          const std::int64_t n = C;  // a local: a byte store could alias the captured C
          for (std::int64_t c = 0; c < n; ++c)
            out_row[c] = std::min(out_row[c], std::max(gap, h[c]));
        }
    }
  };
  Passability out, second;
  if (g.size() < (1 << 20)) {
    rows_pass1(0, R, out);
    rows_pass2(0, R);
    return out;
  }
  const std::int64_t half = R / 2;
  {
    std::thread helper([&] { rows_pass1(half, R, second); });
    rows_pass1(0, half, out);
    helper.join();
  }
  {
    std::thread helper([&] { rows_pass2(half, R); });
    rows_pass2(0, half);
    helper.join();
  }
  out.min_cost = std::min(out.min_cost, second.min_cost);
  out.max_cost = std::max(out.max_cost, second.max_cost);
  out.passable += second.passable;
  return out;
}

}  // namespace seaway
