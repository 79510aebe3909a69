// The steps of the raster graph at one pixel, for every search (plain, bidirectional, turn
// penalty, least danger): written once here. A step along offset o runs from pixel `from` to
// `from + o`. It exists when both ends lie on the chart (columns wrap on 360-degree charts),
// both are passable and, under LandRule::segment, no pixel its closed segment touches is
// impassable. A pixel away from the border whose land clearance exceeds the stencil's
// half-width has every step (the fast path: no test at all), less, for a search that asks
// (each<..., Prune>), those a skip table (collinear.hpp) leaves out there.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry.hpp"
#include "compat.hpp"
#include "stencil.hpp"

namespace seaway {

class StepEnumerator {
 public:
  // `clear` comes from compute_clearance() with cap = half-width + 1. The arguments are read
  // in place and must outlive the enumerator.
  StepEnumerator(const Geometry& g, const std::vector<Offset>& st, const Geometry::Lengths& lengths,
                 const std::uint8_t* clear, LandRule rule)
      : g_(&g), st_(&st), lengths_(&lengths), clear_(clear), rule_(rule), half_(half_width(st)),
        row_of_(g.cols) {
    for (const Offset& o : st) flat_.push_back(o.di * g.cols + o.dj);
  }

  const Geometry& geometry() const { return *g_; }
  const std::vector<Offset>& stencil() const { return *st_; }
  const std::uint8_t* clearance() const { return clear_; }

  // This enumerator leaving out, on the fast path, the doubled steps `skip` marks (bit b of
  // skip[v]: doubled[b] from v; bit 8 + b: doubled[b] ending at v). `skip` must outlive it.
  StepEnumerator with_skips(const std::uint16_t* skip, const std::vector<int>& doubled) const {
    StepEnumerator e = *this;
    e.skip_ = skip;
    for (unsigned byte = 0; byte < 256; ++byte) {
      std::uint64_t m = 0;
      for (std::size_t b = 0; b < doubled.size(); ++b)
        if (byte >> b & 1u) m |= std::uint64_t(1) << doubled[b];
      e.expand_[byte] = m;
    }
    return e;
  }

  // Calls f(w, o, from, to, r, cell) for every step with v at its start (Backward: at its end):
  // w its other end, o its offset, from -> to the step as the model prices it, r its length and
  // cell(m) the flat index of the m-th pixel of the offset's length shares.
  // Prune: leave out the steps a skip table marks (with_skips). A template flag, not a test: the
  // fast path's loop with the test made the searches that need none 1.15-1.3 x slower (2026-12-08).
  template <bool Backward = false, bool Prune = false, class F>
  SEAWAY_ALWAYS_INLINE void each(std::int64_t v, F&& f) const {
    // Locals, not members: the callback's byte stores could alias members, locals stay in registers.
    const std::int64_t R = g_->rows, C = g_->cols, K = std::int64_t(flat_.size());
    const int h = half_;
    const Offset* st = st_->data();
    const std::int64_t* flat = flat_.data();
    const std::uint8_t* clear = clear_;
    const std::int64_t row = row_of_(v), col = v - row * C;
    if (row >= h && row < R - h && col >= h && col < C - h && clear[v] > h) {
      const double* len = lengths_->row(row);
      const std::uint64_t skip = Prune && skip_ ? expand_[Backward ? skip_[v] >> 8 : skip_[v] & 0xffu] : 0;
      for (std::int64_t o = 0; o < K; ++o) {
        if constexpr (Prune)
          if (o < 64 && (skip >> o & 1u)) continue;
        const auto& shares = st[o].shares;
        const std::int64_t from = Backward ? v - flat[o] : v, w = Backward ? from : v + flat[o];
        const double r = Backward ? lengths_->row(row - st[o].di)[o] : len[o];
        f(w, o, from, Backward ? v : w, r,
          [&](std::size_t m) { return from + shares[m].di * C + shares[m].dj; });
      }
      return;
    }
    const bool wrap = g_->wrap;
    for (std::int64_t o = 0; o < K; ++o) {
      const Offset& off = st[o];
      // The step runs from (r0, c0) to (r0 + di, c0 + dj); w is its end other than v.
      const std::int64_t r0 = Backward ? row - off.di : row;
      std::int64_t c0 = Backward ? col - off.dj : col;
      const std::int64_t rw = Backward ? r0 : row + off.di;
      std::int64_t cw = Backward ? c0 : col + off.dj;
      if (rw < 0 || rw >= R) continue;
      if (wrap) cw = g_->wrap_col(cw);
      else if (cw < 0 || cw >= C) continue;
      if (wrap) c0 = g_->wrap_col(c0);
      const std::int64_t w = rw * C + cw;
      if (clear[w] == 0) continue;
      auto at = [&](int di, int dj) { return (r0 + di) * C + (wrap ? g_->wrap_col(c0 + dj) : c0 + dj); };
      if (rule_ == LandRule::segment) {
        bool blocked = false;
        for (const CellShare& t : off.touched)
          if (clear[at(t.di, t.dj)] == 0) { blocked = true; break; }
        if (blocked) continue;
      }
      f(w, o, r0 * C + c0, Backward ? v : w, lengths_->row(r0)[o],
        [&](std::size_t m) { return at(off.shares[m].di, off.shares[m].dj); });
    }
  }

 private:
  const Geometry* g_;
  const std::vector<Offset>* st_;
  const Geometry::Lengths* lengths_;
  const std::uint8_t* clear_;
  LandRule rule_;
  int half_;
  FastDiv row_of_;  // v / cols
  std::vector<std::int64_t> flat_;  // each offset's step in flat pixel index
  const std::uint16_t* skip_ = nullptr;  // with_skips()
  std::array<std::uint64_t, 256> expand_{};  // a skip byte as a mask of offsets
};

}  // namespace seaway
