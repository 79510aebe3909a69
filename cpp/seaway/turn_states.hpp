// The turn search's labels (turns.hpp): per state (pixel x incoming offset) a cost and a
// predecessor code, and per pixel the best label any of its states holds so far and that state's
// offset (what a relaxation checks first: a pixel's neighbours' best labels share cache lines,
// their states do not). All zero-filled (calloc): pages are mapped when first written.
#pragma once

#include <cstdint>
#include <cstdlib>

#include "lazy_labels.hpp"
#include "compat.hpp"

namespace seaway {

class TurnStates {
 public:
  // A state's predecessor code: 0 for a first step from the start, 1 + the incoming offset of
  // the state it came from, or `dropped` for a state taken off the queue but not expanded.
  static constexpr std::uint8_t dropped = 255;

  TurnStates(std::int64_t pixels, std::int64_t offsets)
      : n_(std::size_t(pixels)), k_(std::size_t(offsets)), cost_(detail::zeroed<std::uint64_t>(n_ * k_)),
        pred_(detail::zeroed<std::uint8_t>(n_ * k_)), best_(detail::zeroed<std::uint64_t>(n_)),
        best_in_(detail::zeroed<std::uint8_t>(n_)) {}

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

  // The best label of pixel v's states so far, and the offset of the state holding it (-1: none).
  double best(std::int64_t v) const { return decode(best_[std::size_t(v)]); }
  std::int64_t best_in(std::int64_t v) const { return std::int64_t(best_in_[std::size_t(v)]) - 1; }
  void offer(std::int64_t v, std::int64_t in, double d) {
    if (d < best(v)) {
      best_[std::size_t(v)] = encode(d);
      best_in_[std::size_t(v)] = std::uint8_t(in + 1);
    }
  }

  std::size_t bytes() const { return n_ * k_ * 9 + n_ * 9; }

 private:
  // Stored as bits(d) ^ bits(inf): zero-filled memory reads as inf.
  static std::uint64_t encode(double d) { return detail::bits_of(d) ^ detail::bits_of(inf); }
  static double decode(std::uint64_t b) { return detail::from_bits(b ^ detail::bits_of(inf)); }
  std::size_t n_, k_;
  std::unique_ptr<std::uint64_t[], detail::FreeDeleter> cost_;
  std::unique_ptr<std::uint8_t[], detail::FreeDeleter> pred_;
  std::unique_ptr<std::uint64_t[], detail::FreeDeleter> best_;
  std::unique_ptr<std::uint8_t[], detail::FreeDeleter> best_in_;
};

}  // namespace seaway
