// The doubled steps of a stencil, (±2, 0), (0, ±2) and (±2, ±2), each running straight through
// the middle pixel of a unit step, and the lengths that let a search leave one out where its two
// halves cost no more: collinear.hpp's tables and StepEnumerator::with_max_rule read them.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "geometry.hpp"
#include "stencil.hpp"

namespace seaway {

// A relative slack for the rounding of the two sums (the search adds the two unit steps to a
// cost, not to each other): a route may come out at most this share dearer than the least.
inline constexpr double collinear_slack = 1e-12;

// For the stencil `st`: the indices of the 8 doubled unit offsets (bit b of a skip byte) and of
// their halves, or empty when the stencil has none or they lie beyond bit 63 of a step mask.
struct DoubledSteps {
  std::vector<int> doubled, half;
  explicit DoubledSteps(const std::vector<Offset>& st) {
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj) {
        if (di == 0 && dj == 0) continue;
        const int d = offset_of(st, 2 * di, 2 * dj), h = offset_of(st, di, dj);
        if (d < 0 || h < 0 || d > 63) {
          doubled.clear();
          half.clear();
          return;
        }
        doubled.push_back(d);
        half.push_back(h);
      }
  }
  bool any() const { return !doubled.empty(); }
};

// The bits b of `ds` whose doubled step is, on every row it starts from, no shorter than its two
// halves (to half the slack): where the middle pixel costs no more than the dearer end, the max
// rule then prices the halves at no more than the doubled step (StepEnumerator::with_max_rule).
// Planar pixels: every doubled step; lat/lon pixels: those along a meridian (elsewhere the great
// circle is a little shorter than its halves).
inline unsigned collinear_lengths(const Geometry& g, const std::vector<Offset>& st,
                                  const Geometry::Lengths& len, const DoubledSteps& ds) {
  unsigned bits = 0;
  for (std::size_t b = 0; b < ds.doubled.size(); ++b) {
    const int d = ds.doubled[b], h = ds.half[b], di = st[std::size_t(h)].di;
    bool ok = true;
    for (std::int64_t r = std::max(0, -2 * di); ok && r < g.rows - std::max(0, 2 * di); ++r)
      ok = len.row(r)[h] + len.row(r + di)[h] <= len.row(r)[d] * (1 + collinear_slack / 2);
    if (ok) bits |= 1u << b;
  }
  return bits;
}

}  // namespace seaway
