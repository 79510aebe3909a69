// One side of the exact bidirectional search (bidirectional.hpp) and what the two sides
// exchange at their barriers.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <thread>
#include <vector>

#include "heap.hpp"
#include "lazy_labels.hpp"
#include "rekeyed.hpp"
#include "route_result.hpp"
#include "search_control.hpp"
#include "steps.hpp"

namespace seaway {

namespace detail {

// What the two sides exchange at the barriers (written before one, read after it).
struct Rounds {
  std::atomic<int> arrived[2] = {0, 0};
  std::atomic<bool> abort{false};  // a side failed (cancel, error): the other leaves too
  // [round parity][side]: a side writes round k + 1's while the other may still read round k's.
  double top[2][2] = {};
  double mu_part[2][2] = {};
  std::int64_t meet_part[2][2] = {};
  bool empty[2][2] = {};
  // With a potential the keys are reduced: stop once top_f + top_b >= mu + p(t) - p(s) (plus a
  // relative 1e-12 against the potentials' rounding).
  double mu_offset = 0, mu_slack = 0;

  // Wait until the other side has passed as many barriers as this one; false on abort.
  bool barrier(int self, int& passed) {
    arrived[self].store(++passed, std::memory_order_release);
    while (arrived[1 - self].load(std::memory_order_acquire) < passed)
      if (abort.load(std::memory_order_relaxed)) return false;
      else std::this_thread::yield();
    return !abort.load(std::memory_order_relaxed);
  }
};

}  // namespace detail

struct Meeting {
  std::int64_t pixel = -1;  // labelled by both sides on an optimal route; -1: no route
  double cost = inf;
};

// The forward side searches alone first, as a one-way search (Dijkstra, or with a potential A*
// with the bound to the target), until it settles the target (then its label is the answer) or this
// many pixels; only then does the backward side start: a short voyage costs no thread and no
// rounds, a long one loses about this many pixels' time on one core.
constexpr std::int64_t solo_pixels = 4096;
// The least count of pixels a side settles in a round (later 1/16 of what it has settled): the
// stop is decided only at the barriers, so a search overshoots by up to a round per side.
constexpr std::int64_t round_pixels = 1024;

// One side of the search. Backward == true walks the steps into each pixel; each step is priced
// as the forward step it is (from -> to), with no time (the model is static). The forward side
// first searches alone (solo_pixels above) towards `target`, then calls start_other() to start
// the backward side. With a potential it searches alone as one-way A* with `solo` (the bound to
// the target at the potential's scale, which pulls twice as hard as the average potential),
// then re-keys its queue to the potential (rekeyed.hpp).
template <bool Backward, class Queue, class Model, class Potential, class Solo, class StartOther>
SearchStats bidirectional_side(const StepEnumerator& steps, const Model& model, std::int64_t origin,
                               std::int64_t target, LazyLabels& mine, const LazyLabels& other, Queue heap,
                               const Potential& pot, const Solo& solo, double shift,
                               detail::Rounds& rounds, Meeting& meet, const SearchControl* cancel,
                               StartOther&& start_other) {
  constexpr int self = Backward ? 1 : 0;
  SearchStats stats;
  std::vector<std::uint32_t> settled_now;  // settled in this round
  std::size_t round_peak = 0;
  bool alone = !Backward && pot.active();
  // The key: the label, or with a potential p the reduced label d + p(v) - p(s) forward and
  // d - p(v) + p(t) backward (>= 0; clamped against rounding); alone, d + solo(v).
  auto key = [&](std::int64_t v, double d) {
    if (!pot.active()) return d;
    if (alone) return d + solo(v);
    return std::max(0.0, Backward ? d - pot(v) + shift : d + pot(v) - shift);
  };
  Rekeyed later;  // the forward side's queue after searching alone, re-keyed
  heap.push({key(origin, 0.0), std::uint32_t(origin)});
  // Rounds of a count of settled pixels, the same on both sides (round_pixels, later 1/16 of
  // what the side has settled): the two threads get equal work whatever the ends' surroundings, and the
  // last round overshoots the stop by at most 1/16. The count depends on nothing but this
  // side's own search, so the rounds are the same on every run.
  double mu = inf;
  std::int64_t mu_pixel = -1;  // the best meeting so far: cost mu, this pixel
  int passed = 0;

  auto settle = [&](std::int64_t v, double dv) {
    mine.set(v, -dv);  // settled
    settled_now.push_back(std::uint32_t(v));
    count_settled(stats.settled, cancel, !Backward);  // the forward side reports progress
    steps.each<Backward>(v, [&](std::int64_t w, std::int64_t o, std::int64_t from,
                                 std::int64_t to, double r, auto&& cell) {
      const double nd = dv + model(from, to, int(o), r, 0.0, cell);
      if (nd < mine.get(w)) {  // false for settled pixels: their label is negative
        mine.set(w, nd, int(o));
        heap.push({key(w, nd), std::uint32_t(w)});
      }
    });
  };

  if constexpr (!Backward) {
    // Alone: the pixels settled here join the first round's (checked at its barrier).
    while (stats.settled < solo_pixels && !heap.empty()) {
      const HeapEntry top = heap.pop();
      const double dv = mine.get(top.id);
      if (std::signbit(dv)) continue;
      settle(top.id, dv);
      if (std::int64_t(top.id) == target) {  // settled by a one-way search: exact
        meet.pixel = target;
        meet.cost = dv;
        break;
      }
    }
    if (meet.pixel >= 0 || heap.empty()) {  // done, or nothing left to reach (no route)
      stats.heap_peak = heap.peak();
      stats.state_bytes = heap.capacity_bytes() + settled_now.capacity() * sizeof(std::uint32_t);
      return stats;
    }
    start_other();
    if (alone) {
      alone = false;  // key() now gives the reduced keys
      later.take(heap, mine, key);
    }
  }
  for (;;) {
    // Search: settle this round's count of pixels (the forward side's first round adds to the
    // pixels it settled alone).
    if (Backward || passed > 0) settled_now.clear();
    const std::int64_t quota = std::max<std::int64_t>(round_pixels, stats.settled / 16);
    while (std::int64_t(settled_now.size()) < quota && (later.feed(heap), !heap.empty())) {
      const HeapEntry top = heap.pop();
      const double dv = mine.get(top.id);
      if (std::signbit(dv)) continue;  // an older entry of a settled pixel
      settle(top.id, dv);
    }
    round_peak = std::max(round_peak, settled_now.capacity());
    if (!rounds.barrier(self, passed)) break;
    // Meet: the pixels this side relabelled in the round against the other's still labels.
    double best = inf;
    std::int64_t at = -1;
    auto check = [&](std::int64_t w) {
      const double dw = other.get(w);
      if (dw == inf) return;
      const double total = std::fabs(mine.get(w)) + std::fabs(dw);
      if (total < best || (total == best && w < at)) { best = total; at = w; }
    };
    for (std::uint32_t v : settled_now) check(v);
    heap.for_each([&](const HeapEntry& e) { check(e.id); });
    later.for_each([&](const HeapEntry& e) { check(e.id); });
    const int k = passed / 2 % 2;  // this round's slot
    rounds.mu_part[k][self] = best;
    rounds.meet_part[k][self] = at;
    rounds.top[k][self] = std::min(heap.empty() ? inf : heap.lower_bound(), later.least());
    rounds.empty[k][self] = heap.empty() && later.empty();
    if (!rounds.barrier(self, passed)) break;
    // Decide, on the same values on both sides.
    for (int s = 0; s < 2; ++s)
      if (rounds.mu_part[k][s] < mu || (rounds.mu_part[k][s] == mu && rounds.meet_part[k][s] < mu_pixel)) {
        mu = rounds.mu_part[k][s];
        mu_pixel = rounds.meet_part[k][s];
      }
    if (!Backward) {  // the forward side keeps the answer (the same on both sides)
      meet.pixel = mu_pixel;
      meet.cost = mu;
    }
    if (rounds.empty[k][0] || rounds.empty[k][1] ||
        rounds.top[k][0] + rounds.top[k][1] >= mu + rounds.mu_offset + rounds.mu_slack * mu)
      break;
  }
  stats.heap_peak = heap.peak();
  stats.state_bytes = heap.capacity_bytes() + round_peak * sizeof(std::uint32_t) + later.capacity_bytes();
  return stats;
}

}  // namespace seaway
