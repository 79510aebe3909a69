// One side of the exact bidirectional search (bidirectional.hpp); what the two sides exchange
// at their barriers is in rounds.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "heap.hpp"
#include "lazy_labels.hpp"
#include "rekeyed.hpp"
#include "rounds.hpp"
#include "route_result.hpp"
#include "search_control.hpp"
#include "steps.hpp"

namespace seaway {

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
template <bool Backward, bool Prune, class Queue, class Model, class Potential, class Solo, class StartOther>
SearchStats bidirectional_side(const StepEnumerator& steps, const Model& model, std::int64_t origin,
                               std::int64_t target, LazyLabels& mine, const LazyLabels& other, Queue heap,
                               const Potential& pot, const Solo& solo, double shift,
                               detail::Rounds& rounds, Meeting& meet, const SearchControl* cancel,
                               StartOther&& start_other) {
  constexpr int self = Backward ? 1 : 0;
  SearchStats stats;
  RoundLog now(is_cached<Potential>);  // this round's settled and relabelled pixels
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
  now.pushed(origin);
  // Rounds of a count of settled pixels, the same on both sides (round_pixels, later 1/16 of
  // what the side has settled): the two threads get equal work whatever the ends' surroundings, and the
  // last round overshoots the stop by at most 1/16. The count depends on nothing but this
  // side's own search, so the rounds are the same on every run.
  double mu = inf;
  std::int64_t mu_pixel = -1;  // the best meeting so far: cost mu, this pixel
  int passed = 0;

  auto settle = [&](std::int64_t v, double dv) {
    mine.set(v, -dv);  // settled
    now.settled(v);
    count_settled(stats.settled, cancel, !Backward);  // the forward side reports progress
    steps.template each<Backward, Prune>(v, [&](std::int64_t w, std::int64_t o, std::int64_t from,
                                                std::int64_t to, double r, auto&& cell) {
      const double nd = dv + model(from, to, int(o), r, 0.0, cell);
      if (nd < mine.get(w)) {  // false for settled pixels: their label is negative
        mine.set(w, nd, int(o));
        now.pushed(w);
        heap.push({key(w, nd), std::uint32_t(w)});
      }
    });
  };

  if constexpr (!Backward) {
    // Alone: the pixels settled here join the first round's (checked at its barrier).
    while (stats.settled < solo_pixels && !heap.empty()) {
      const HeapEntry top = heap.pop();
      now.popped();
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
      stats.state_bytes = heap.capacity_bytes() + now.capacity_bytes();
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
    if (Backward || passed > 0) now.start();
    const std::int64_t quota = std::max<std::int64_t>(round_pixels, stats.settled / 16);
    while (std::int64_t(now.settled_count()) < quota && (later.feed(heap), !heap.empty())) {
      const HeapEntry top = heap.pop();
      now.popped();
      const double dv = mine.get(top.id);
      if (std::signbit(dv)) continue;  // an older entry of a settled pixel
      settle(top.id, dv);
    }
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
    now.for_each_changed(check, heap, later);
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
  stats.state_bytes = heap.capacity_bytes() + now.capacity_bytes() + later.capacity_bytes();
  return stats;
}

}  // namespace seaway
