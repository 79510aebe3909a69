// Potentials for the bidirectional search: none (plain bidirectional Dijkstra), or the average
// of two lower bounds (bidirectional A*, with straight-line or landmark bounds).
#pragma once

#include <cstdint>
#include <type_traits>

#include "geometry.hpp"

namespace seaway {

// No potential: plain bidirectional Dijkstra.
struct NoPotential {
  static constexpr bool worth_caching = false, sparse_keys = false, prunes = false;
  bool active() const { return false; }
  double operator()(std::int64_t) const { return 0; }
  double one_way(std::int64_t) const { return 0; }
};

// The consistent average potential of two lower bounds (to the target, from the start):
// p(v) = scale x (to_target(v) - from_start(v)) / 2. With scale = 1 - eps, every step's reduced
// cost c - p(v) + p(w) is at least eps x c (less the bounds' rounding), forward and backward.
template <class Bound>
struct AveragePotential {
  // Kept per pixel when the bounds read tables, recomputed when they are arithmetic; buckets a
  // small share of a step wide (sparse keys) when the bounds are scaled close to 1.
  static constexpr bool worth_caching = !std::is_same_v<Bound, DistanceBound>;
  static constexpr bool sparse_keys = worth_caching, prunes = false;
  Bound to_target, from_start;
  double scale;
  bool active() const { return true; }
  double operator()(std::int64_t v) const { return scale * 0.5 * (to_target(v) - from_start(v)); }
  // The one-way A* bound to the target at the same scale (the forward side's solo phase).
  double one_way(std::int64_t v) const { return scale * to_target(v); }
};

// A potential's one-way bound to the target as a bound of its own (for CachedBound).
template <class Potential>
struct OneWay {
  const Potential& pot;
  bool active() const { return pot.active(); }
  double operator()(std::int64_t v) const { return pot.one_way(v); }
};

}  // namespace seaway
