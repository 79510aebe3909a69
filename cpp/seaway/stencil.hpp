// The k x k stencil of a raster graph: which offsets join a pixel to its neighbours, which
// pixels each step's straight segment touches (for the land rule) and how its length is split
// between pixels (for the line-integral cost). Pure geometry in pixel-index space.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace seaway {

enum class Directions { full, unique, axis };

// Which pixels a step must keep clear of. `segment`: both ends and every pixel whose closed
// square the closed straight segment touches (the papers' rule: no leaking through diagonal
// coastlines, no jumping over land). `ends`: only the two ends (scikit-image's rule).
enum class LandRule { segment, ends };

struct CellShare {
  int di, dj;       // pixel relative to the step's origin
  double fraction;  // share of the segment's length inside it (0 for a corner touch)
};

struct Offset {
  int di, dj;
  std::vector<CellShare> touched;  // pixels met by the closed segment, ends excluded
  std::vector<CellShare> shares;   // pixels holding a positive length, ends included
};

namespace detail {

// An exact rational t = n / d (d > 0); the segment's parameter where it crosses a pixel border.
struct Ratio {
  std::int64_t n, d;
  bool operator<(const Ratio& o) const { return n * o.d < o.n * d; }
  double value() const { return double(n) / double(d); }
};

// The closed interval of t in [0, 1] for which coordinate t*step lies within half a pixel
// of `centre`; empty when lo > hi.
inline void clip(int step, int centre, Ratio& lo, Ratio& hi) {
  if (step == 0) {
    if (centre != 0) hi = Ratio{-1, 1};  // never inside: make the interval empty
    return;
  }
  Ratio a{2 * centre - 1, 2 * step}, b{2 * centre + 1, 2 * step};
  if (step < 0) { a = Ratio{-a.n, -a.d}; b = Ratio{-b.n, -b.d}; std::swap(a, b); }
  if (lo < a) lo = a;
  if (b < hi) hi = b;
}

}  // namespace detail

// Offsets of the stencil with their touched pixels and length shares, in a fixed order.
inline std::vector<Offset> make_stencil(int k, Directions dirs) {
  if (k < 3 || k > 15 || k % 2 == 0)
    throw std::invalid_argument("neighbourhood must be odd and between 3 and 15, got " +
                                std::to_string(k));
  const int h = (k - 1) / 2;
  std::vector<Offset> out;
  for (int di = -h; di <= h; ++di)
    for (int dj = -h; dj <= h; ++dj) {
      if (di == 0 && dj == 0) continue;
      if (dirs == Directions::unique && std::gcd(std::abs(di), std::abs(dj)) != 1) continue;
      if (dirs == Directions::axis && (std::abs(di) + std::abs(dj) != 1)) continue;
      Offset off{di, dj, {}, {}};
      for (int a = std::min(0, di); a <= std::max(0, di); ++a)
        for (int b = std::min(0, dj); b <= std::max(0, dj); ++b) {
          detail::Ratio lo{0, 1}, hi{1, 1};
          detail::clip(di, a, lo, hi);
          detail::clip(dj, b, lo, hi);
          if (hi < lo) continue;
          const double frac = hi.value() - lo.value();
          const bool end = (a == 0 && b == 0) || (a == di && b == dj);
          if (!end) off.touched.push_back({a, b, frac});
          if (frac > 0) off.shares.push_back({a, b, frac});
        }
      out.push_back(std::move(off));
    }
  return out;
}

// The index, in the stencil, of the offset (di, dj), or -1.
inline int offset_of(const std::vector<Offset>& st, int di, int dj) {
  for (std::size_t o = 0; o < st.size(); ++o)
    if (st[o].di == di && st[o].dj == dj) return int(o);
  return -1;
}

// Largest |di| or |dj| of the stencil's offsets.
inline int half_width(const std::vector<Offset>& st) {
  int h = 0;
  for (const Offset& o : st) h = std::max({h, std::abs(o.di), std::abs(o.dj)});
  return h;
}

}  // namespace seaway
