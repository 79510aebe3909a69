// The steps out of one pixel, for searches other than search.hpp's (the turn penalty's
// expanded states, the least-danger labels), under the same rules as search.hpp.
#pragma once

#include <cstdint>
#include <vector>

#include "router.hpp"

namespace seaway {

// Calls f(w, o, cell) for every step the chart allows out of pixel v: w the pixel reached along
// stencil offset o, cell(m) the flat index of the m-th pixel of the offset's length shares.
// The same rules as search.hpp: inside the grid (columns wrap on global charts), both ends
// passable and, under LandRule::segment, no touched pixel impassable.
template <class F>
void for_each_step(const PreparedGrid& pg, std::int64_t v, F&& f) {
  const Grid& g = pg.grid();
  const std::vector<Offset>& st = pg.stencil();
  const std::uint8_t* clear = pg.clearance();
  const std::int64_t R = g.rows, C = g.cols, K = std::int64_t(st.size());
  const std::int64_t row = v / C, col = v - row * C;
  const int h = pg.half_width();
  if (row >= h && row < R - h && col >= h && col < C - h && clear[v] > h) {
    for (std::int64_t o = 0; o < K; ++o) {
      const Offset& off = st[std::size_t(o)];
      f(v + off.di * C + off.dj, o, [&](std::size_t m) { return v + off.shares[m].di * C + off.shares[m].dj; });
    }
    return;
  }
  auto wrap_col = [&](std::int64_t c) { return c < 0 ? c + C : (c >= C ? c - C : c); };
  for (std::int64_t o = 0; o < K; ++o) {
    const Offset& off = st[std::size_t(o)];
    const std::int64_t r2 = row + off.di;
    std::int64_t c2 = col + off.dj;
    if (r2 < 0 || r2 >= R) continue;
    if (g.wrap) c2 = wrap_col(c2);
    else if (c2 < 0 || c2 >= C) continue;
    const std::int64_t w = r2 * C + c2;
    if (clear[w] == 0) continue;
    auto at = [&](int di, int dj) { return (row + di) * C + (g.wrap ? wrap_col(col + dj) : col + dj); };
    if (pg.land_rule() == LandRule::segment) {
      bool blocked = false;
      for (const CellShare& t : off.touched)
        if (clear[at(t.di, t.dj)] == 0) { blocked = true; break; }
      if (blocked) continue;
    }
    f(w, o, [&](std::size_t m) { return at(off.shares[m].di, off.shares[m].dj); });
  }
}

}  // namespace seaway
