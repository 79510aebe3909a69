// Which pixels a ship may enter, and how far (Chebyshev, in pixels) each pixel is from the
// nearest one it may not. A pixel whose clearance exceeds the stencil's half-width has no
// forbidden step, so the search skips the land test for it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <thread>
#include <vector>

#include "geometry.hpp"
#include "compat.hpp"
#include "threads.hpp"

namespace seaway {

struct Passability {
  double min_cost = std::numeric_limits<double>::infinity();  // over passable pixels
  double max_cost = 0;
  std::int64_t passable = 0;                                  // how many there are
  // Share of the passable pixels of a fixed sample (least_share_sample) whose cost is within
  // 1 % of min_cost (0 when no pixel of the sample is passable or min_cost is 0): what auto
  // reads to choose one-way A* (seaway.engine.methods.mostly_least_cost).
  double least_share = 0;
};

// The sample behind Passability::least_share: pixel (i * 2654435761) mod n for i < this (a fixed
// multiplicative-hash stride over the flat raster: the same pixels, and share, on every run).
constexpr std::int64_t least_share_sample = 4096;

// Passability::least_share of a chart whose clearance (0: impassable) is computed.
template <class T>
double least_cost_share(const T* cost, const std::uint8_t* clearance, std::int64_t n, double min_cost) {
  if (!(min_cost > 0) || n <= 0) return 0.0;
  const double limit = min_cost * 1.01;
  std::int64_t ok = 0, least = 0;
  for (std::int64_t i = 0; i < std::min(least_share_sample, n); ++i) {
    const std::int64_t v = std::int64_t(std::uint64_t(i) * 2654435761ull % std::uint64_t(n));
    if (clearance[v] == 0) continue;
    ++ok;
    least += double(cost[v]) <= limit;
  }
  return ok ? double(least) / double(ok) : 0.0;
}

// clearance[v] = min(distance to the nearest impassable pixel, cap); 0 marks impassable.
// A pixel is impassable when its cost is NaN, infinite or negative, or land[v] is set.
// `scratch` holds one byte per pixel during the call. Rows are independent within each of the
// two passes, so on a chart of a million pixels or more each pass runs on two threads (the
// preparation is a tenth of a fresh chart's route otherwise); the result does not depend on it.
template <class T>
Passability compute_clearance(const Geometry& g, const T* cost, const std::uint8_t* land, int cap,
                              std::uint8_t* clearance, std::uint8_t* scratch) {
  const std::int64_t R = g.rows, C = g.cols;
  // Pass 1: distance along the row to the nearest impassable pixel of that row (capped), and the
  // range and count of the row's passable costs. The distance is a min over the cap's window of
  // byte rows, as pass 2 does across rows: loops without a carried chain, which vectorise.
  // (Locals throughout: a byte store could alias what the lambda captured by reference. The
  // range is kept in four lanes: one min/max chain costs several cycles a pixel.)
  auto rows_pass1 = [&](std::int64_t r_begin, std::int64_t r_end, Passability& out) {
    const std::int64_t cols = g.cols;
    const std::uint8_t far = std::uint8_t(cap);
    const bool wrap = g.wrap;
    double lo[4] = {out.min_cost, inf, inf, inf}, hi[4] = {out.max_cost, 0, 0, 0};
    std::int64_t passable = 0;
    std::vector<std::uint8_t> open_row(std::size_t(cols), 0);  // far: passable, 0: blocked
    std::uint8_t* SEAWAY_RESTRICT b = open_row.data();
    for (std::int64_t r = r_begin; r < r_end; ++r) {
      const T* u = cost + r * cols;
      const std::uint8_t* l = land ? land + r * cols : nullptr;
      std::uint8_t* SEAWAY_RESTRICT h = scratch + r * cols;
      for (std::int64_t c = 0; c < cols; ++c) {
        const double x = double(u[c]);
        b[c] = (x >= 0 && x < inf) ? far : 0;
      }
      if (l)
        for (std::int64_t c = 0; c < cols; ++c) b[c] = l[c] ? 0 : b[c];
      std::int64_t c = 0;
      for (; c + 4 <= cols; c += 4)
        for (int k = 0; k < 4; ++k) {
          const bool ok = b[c + k] != 0;
          const double x = double(u[c + k]);
          lo[k] = std::min(lo[k], ok ? x : inf);
          hi[k] = std::max(hi[k], ok ? x : 0.0);
          passable += ok;
        }
      for (; c < cols; ++c) {
        const bool ok = b[c] != 0;
        lo[0] = std::min(lo[0], ok ? double(u[c]) : inf);
        hi[0] = std::max(hi[0], ok ? double(u[c]) : 0.0);
        passable += ok;
      }
      // h[c] = min over |d| < cap of (blocked(c + d) ? |d| : cap); across the seam if periodic.
      std::copy(b, b + cols, h);
      for (std::int64_t d = 1; d < cap; ++d) {
        const std::uint8_t gap = std::uint8_t(d);
        for (std::int64_t c2 = d; c2 < cols; ++c2) h[c2] = std::min(h[c2], std::max(gap, b[c2 - d]));
        for (std::int64_t c2 = 0; c2 + d < cols; ++c2) h[c2] = std::min(h[c2], std::max(gap, b[c2 + d]));
        if (wrap)
          for (std::int64_t c2 = 0; c2 < std::min(d, cols); ++c2) {
            h[c2] = std::min(h[c2], std::max(gap, b[c2 - d + cols]));
            h[cols - 1 - c2] = std::min(h[cols - 1 - c2], std::max(gap, b[d - 1 - c2]));
          }
      }
    }
    out.min_cost = std::min(std::min(lo[0], lo[1]), std::min(lo[2], lo[3]));
    out.max_cost = std::max(std::max(hi[0], hi[1]), std::max(hi[2], hi[3]));
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
    std::thread helper = thread_on_other_core([&] { rows_pass1(half, R, second); });
    rows_pass1(0, half, out);
    helper.join();
  }
  {
    std::thread helper = thread_on_other_core([&] { rows_pass2(half, R); });
    rows_pass2(0, half);
    helper.join();
  }
  out.min_cost = std::min(out.min_cost, second.min_cost);
  out.max_cost = std::max(out.max_cost, second.max_cost);
  out.passable += second.passable;
  return out;
}

}  // namespace seaway
