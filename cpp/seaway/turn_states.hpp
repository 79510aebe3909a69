// The turn search's labels (turns.hpp): per state (pixel x incoming offset) a cost and a
// predecessor code, and per pixel the best label any of its states holds so far and that state's
// offset (what a relaxation checks first: a pixel's neighbours' best labels share cache lines,
// their states do not), and which of its states were expanded (a bit mask, up to 64 offsets).
// Memory: 8 bytes of cost + 1 of predecessor per state, 9 x (number of stencil offsets) bytes per
// pixel of address space (k=3: 72, k=5: 216, k=7: 432), plus 9 per pixel for its best state and
// 8 for its mask. All zero-filled (calloc): pages are mapped when first written.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "compat.hpp"
#include "geometry.hpp"
#include "lazy_labels.hpp"
#include "route_result.hpp"

namespace seaway {

class TurnStates {
 public:
  // A state's predecessor code: 0 for a first step from the start, 1 + the incoming offset of
  // the state it came from, or `dropped` for a state taken off the queue but not expanded.
  static constexpr std::uint8_t dropped = 255;

  TurnStates(std::int64_t pixels, std::int64_t offsets)
      : n_(std::size_t(pixels)), k_(std::size_t(offsets)), cost_(detail::zeroed<std::uint64_t>(n_ * k_)),
        pred_(detail::zeroed<std::uint8_t>(n_ * k_)), best_(detail::zeroed<std::uint64_t>(n_)),
        best_in_(detail::zeroed<std::uint8_t>(n_)),
        expanded_(detail::zeroed<std::uint64_t>(k_ <= 64 ? n_ : 0)) {}

  // A state's label: inf if never labelled, negative once settled (taken off the queue).
  double get(std::int64_t s) const { return decode(cost_[std::size_t(s)]); }
  void set(std::int64_t s, double d, std::uint8_t code) {
    cost_[std::size_t(s)] = encode(d);
    pred_[std::size_t(s)] = code;
  }
  void settle(std::int64_t s) { cost_[std::size_t(s)] = encode(-get(s)); }
  void drop(std::int64_t s) { pred_[std::size_t(s)] = dropped; }
  void prefetch(std::uint32_t s) const {
    if (s != 0xffffffffu) compat::prefetch(&cost_[s]);
  }
  int pred(std::int64_t s) const { return pred_[std::size_t(s)]; }
  bool expanded(std::int64_t s) const { return std::signbit(get(s)) && pred_[std::size_t(s)] != dropped; }
  // With 64 offsets or fewer, a pixel's expanded states as a bit mask (bit o: offset o), so
  // checking them reads one word instead of every state of the pixel.
  bool masks() const { return k_ <= 64; }
  void mark(std::int64_t v, std::int64_t in) {
    if (masks()) expanded_[std::size_t(v)] |= std::uint64_t(1) << in;
  }
  // Whether a state of v expanded before dominates (v, in) with label d: an expanded (v, o)
  // with |label| + margin(o, in) <= d (turn_penalty.hpp's margins).
  template <class Margin>
  bool dominated(std::int64_t v, std::int64_t in, double d, Margin&& margin) const {
    const std::int64_t k = std::int64_t(k_);
    if (masks()) {
      for (std::uint64_t m = expanded_[std::size_t(v)]; m;) {
        const std::int64_t o = 63 - compat::clz64(m);
        m ^= std::uint64_t(1) << o;
        if (-get(v * k + o) + margin(o, in) <= d) return true;
      }
      return false;
    }
    for (std::int64_t o = 0; o < k; ++o)
      if (o != in && expanded(v * k + o) && -get(v * k + o) + margin(o, in) <= d) return true;
    return false;
  }
  // Up to 4 states of v expanded before, other than (v, in): their offsets and labels (masks()
  // only; none otherwise). Returns how many.
  int expanded_before(std::int64_t v, std::int64_t in, std::int64_t* offsets, double* labels) const {
    int n = 0;
    if (!masks()) return 0;
    for (std::uint64_t m = expanded_[std::size_t(v)] & ~(std::uint64_t(1) << in); m && n < 4; ++n) {
      offsets[n] = 63 - compat::clz64(m);
      m ^= std::uint64_t(1) << offsets[n];
      labels[n] = -get(v * std::int64_t(k_) + offsets[n]);
    }
    return n;
  }

  // The best label of pixel v's states so far, and the offset of the state holding it (-1: none).
  double best(std::int64_t v) const { return decode(best_[std::size_t(v)]); }
  std::int64_t best_in(std::int64_t v) const { return std::int64_t(best_in_[std::size_t(v)]) - 1; }
  void offer(std::int64_t v, std::int64_t in, double d) {
    if (d < best(v)) {
      best_[std::size_t(v)] = encode(d);
      best_in_[std::size_t(v)] = std::uint8_t(in + 1);
    }
  }

  std::size_t bytes() const { return n_ * k_ * 9 + n_ * 9 + (masks() ? n_ * 8 : 0); }

 private:
  // Stored as bits(d) ^ bits(inf): zero-filled memory reads as inf.
  static std::uint64_t encode(double d) { return detail::bits_of(d) ^ detail::bits_of(inf); }
  static double decode(std::uint64_t b) { return detail::from_bits(b ^ detail::bits_of(inf)); }
  std::size_t n_, k_;
  std::unique_ptr<std::uint64_t[], detail::FreeDeleter> cost_;
  std::unique_ptr<std::uint8_t[], detail::FreeDeleter> pred_;
  std::unique_ptr<std::uint64_t[], detail::FreeDeleter> best_;
  std::unique_ptr<std::uint8_t[], detail::FreeDeleter> best_in_;
  std::unique_ptr<std::uint64_t[], detail::FreeDeleter> expanded_;
};

// The route into `out` (path, cumulative costs, offsets), back along the predecessors from the
// state `reached` at the target: state (w, o) came from pixel w - offset o, in state pred - 1.
inline void trace_back(const TurnStates& S, const Geometry& g, const std::vector<Offset>& st, std::int64_t reached,
                       RouteResult& out) {
  const std::int64_t K = std::int64_t(st.size());
  const std::size_t states = std::size_t(g.size() * K);
  std::int64_t s = reached;
  for (;;) {
    const std::int64_t v = s / K, o = s - v * K;
    out.path.push_back(v);
    out.cumulative.push_back(std::fabs(S.get(s)));
    out.offsets.push_back(int(o));
    const std::int64_t u = g.step(v, st[std::size_t(o)], -1);
    const int p = S.pred(s);
    if (p == 0) { out.path.push_back(u); out.cumulative.push_back(0.0); break; }
    s = u * K + (p - 1);
    if (out.path.size() > states) throw std::logic_error("predecessor cycle");
  }
  std::reverse(out.path.begin(), out.path.end());
  std::reverse(out.cumulative.begin(), out.cumulative.end());
  std::reverse(out.offsets.begin(), out.offsets.end());
}

}  // namespace seaway
