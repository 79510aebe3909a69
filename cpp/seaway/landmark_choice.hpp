// Where landmarks go (landmarks.hpp builds their tables): largest_water() gives a pixel of the
// largest body of water (8-connected passable pixels), so that the landmarks serve the water
// most voyages cross, not a lake or cove the chart's centre happens to lie in (their bound is
// 0 for any pixel they cannot reach: a chart whose landmarks sit in a cove gets no pruning).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "prepared_chart.hpp"

namespace seaway {

inline std::int64_t largest_water(const PreparedChart& pg, std::int64_t fallback) {
  const Geometry& g = pg.geometry();
  const std::uint8_t* clear = pg.clearance();
  std::vector<std::uint32_t> label(std::size_t(g.size()), 0), queue;
  std::uint32_t next = 0;
  std::size_t best = 0;
  std::int64_t best_pixel = fallback;
  for (std::int64_t p = 0; p < g.size(); ++p) {
    if (clear[p] == 0 || label[std::size_t(p)]) continue;
    label[std::size_t(p)] = ++next;
    queue.assign(1, std::uint32_t(p));
    for (std::size_t i = 0; i < queue.size(); ++i) {
      const std::int64_t v = queue[i], r = v / g.cols, c = v % g.cols;
      for (int di = -1; di <= 1; ++di)
        for (int dj = -1; dj <= 1; ++dj) {
          std::int64_t rr = r + di, cc = c + dj;
          if (rr < 0 || rr >= g.rows) continue;
          if (g.wrap) cc = g.wrap_col(cc);
          else if (cc < 0 || cc >= g.cols) continue;
          const std::int64_t w = rr * g.cols + cc;
          if (clear[w] && !label[std::size_t(w)]) {
            label[std::size_t(w)] = next;
            queue.push_back(std::uint32_t(w));
          }
        }
    }
    if (queue.size() > best) {
      best = queue.size();
      best_pixel = p;
    }
  }
  return best_pixel;
}

}  // namespace seaway
