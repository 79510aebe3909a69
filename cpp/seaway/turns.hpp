// Turn penalty: a cost per course change, by an expanded-state search over (pixel, incoming
// step). A state's label is the least cost of reaching the pixel by its last step along offset
// o; leaving it along offset o2 costs the model's step cost plus penalty(angle(o, o2)). The plain
// search (search.hpp) is untouched: this one runs only when a penalty is asked for.
//
// Turn angle at pixel v: the angle between the two steps' directions in the local metric at
// v's row, (di*dy, dj*dx) on planar grids and (di*dlat, dj*dlon*cos(lat_v)) on lat/lon grids,
// 0..180 degrees. The first step from the start pays no penalty unless the start is given an
// incoming step (a via-point continues the previous leg).
//
// Dominated states are dropped (turn_penalty.hpp: the margin of two incoming offsets): a state
// (w, o) is not labelled when w's best state so far, reached along b, has d_b + margin(b, o) <= its
// label, and a state taken off the queue is not expanded when a state of the same pixel expanded
// before it dominates it the same way; whatever route continues from the dropped state continues
// at no more cost from the other. A pixel then expands about two states instead of all of them
// (A winter's corner voyage: 14.9 M states settled without, benchmarks/README.md).
//
// A state expanded at a pixel where another was expanded before skips the steps the other took
// at no dearer label plus turn. Memory: turn_states.hpp (k=5: 233 bytes per pixel of address space).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "prepared_chart.hpp"
#include "turn_penalty.hpp"
#include "turn_states.hpp"

namespace seaway {

// Least-cost route from `start` to `target` with turn penalties under `model`. `incoming`: the
// offset of the step that reached the start (charged at the first turn), or -1 for none.
// weight 0: Dijkstra, 1: A*, > 1: weighted A*. The queue is chosen as in PreparedChart::run
// (every step plus a penalty >= 0 costs at least a step): exact A* in buckets with its bound
// scaled by 1 - turn_bucket_eps (1 - astar_bucket_eps when the finer buckets would be too many).
template <class Model>
RouteResult route_with_turns(PreparedChart& pg, const Model& model, const TurnPenalty& turn,
                             std::int64_t start, std::int64_t target, int incoming, double weight,
                             const SearchControl* control = nullptr) {
  const Geometry& g = pg.geometry();
  const std::vector<Offset>& st = pg.stencil();
  const std::int64_t K = std::int64_t(st.size()), n = g.size();
  if (start < 0 || start >= n || target < 0 || target >= n)
    throw std::out_of_range("pixel index outside the grid");
  if (incoming >= K) throw std::invalid_argument("incoming step is not a stencil offset");
  if (double(n) * double(K) >= 4294967295.0)
    throw std::invalid_argument("pixels x stencil offsets must stay below 2**32 for the turn penalty");
  const TurnCosts penalty(g, st, turn);
  const StepBounds b = model.bounds(pg.passability());
  const bool astar = weight == 1 && b.per_length;
  // The largest key increase of one step: its cost and penalty, plus the bound's largest drop
  // (exact A*'s bound below drops by at most a step's cost).
  double eps = astar ? turn_bucket_eps : 1.0;
  auto choose = [&] {
    return choose_queue(b, pg.shortest_step(), pg.longest_step(), eps, astar ? b.max_rate : 0.0,
                        penalty.largest());
  };
  QueueChoice q = choose();
  if (astar && q.kind != QueueKind::buckets) q = (eps = astar_bucket_eps, choose());
  if (weight > 1) q.kind = QueueKind::quaternary;
  const bool buckets = q.kind == QueueKind::buckets;
  const bool use_bound = weight > 0 && b.per_length;
  // A* in a heap: the bound is consistent; shave it by 1e-9 against rounding. In buckets: 1 - eps.
  const double scale = weight != 1 ? weight : (buckets ? 1 - eps : 1 - 1e-9);
  const DistanceBound bound(g, target, use_bound ? b.min_rate * scale : 0);
  // Exact A*'s bound: the least cost to the target without turn penalties, by one plain search
  // from the target (these models cost a step the same both ways, so costs from the target are
  // costs to it), stopped once it settles the start. A pixel it settled has its exact cost to
  // go d(v); any other costs at least R = d(start). So h = d where settled, R elsewhere, is
  // consistent (penalties are >= 0), far tighter than the straight-line bound in ice (the
  // default chart: 40 s -> 6 s), and costs a short search for a short leg. It holds one more
  // workspace while the search runs.
  std::optional<PreparedChart::Lease> field;
  const double* to_go = nullptr;
  double radius = 0;
  std::size_t field_bytes = 0;
  if (astar && start != target && pg.clearance()[start] > 0) {
    field.emplace(pg);
    pg.search_into(model, target, start, **field, control);
    radius = (*field)->cost(start);
    if (!(radius < inf)) {  // the target is out of reach: no route
      RouteResult none;
      none.stats.min_cost = b.min_rate;
      return none;
    }
    to_go = (*field)->dist.data();
    field_bytes = (*field)->bytes();
  }
  auto h = [&](std::int64_t w) {
    if (!to_go) return bound(w);
    const double d = to_go[std::size_t(w)];
    return scale * (std::signbit(d) ? -d : radius);  // settled pixels have a negative cost
  };

  TurnStates S(n, K);
  const bool prune = penalty.prunes();

  SearchStats stats;
  stats.min_cost = b.min_rate;
  std::int64_t reached = -1;  // the state at the target
  std::size_t queue_bytes = 0;
  // Every step out of pixel v (reached by offset `in`, -1: none) with label dv; `code` is what
  // the new states record as their predecessor (0 from the start, else 1 + in).
  auto run = [&](auto heap) {
    auto expand = [&](std::int64_t v, std::int64_t in, double dv, std::uint8_t code) {
      const std::int64_t row = v / g.cols;
      const double* leave = penalty.leaving(row, in);  // nullptr: computed per step
      // A step an earlier expanded state of v took at no dearer label plus turn is skipped: it
      // offered w the same state at no more cost (the step costs are static).
      std::int64_t e[4];
      double before[4];
      const int nb = prune && leave && in >= 0 ? S.expanded_before(v, in, e, before) : 0;
      const double* turns_before[4];
      for (int i = 0; i < nb; ++i) {
        before[i] -= dv;
        turns_before[i] = penalty.leaving(row, e[i]);
      }
      pg.steps().each(v, [&](std::int64_t w, std::int64_t o, std::int64_t, std::int64_t, double r, auto&& cell) {
        const double pen_o = leave ? leave[o] : penalty(row, in, o);
        for (int i = 0; i < nb; ++i)
          if (before[i] + turns_before[i][o] <= pen_o) return;
        const double c = model(v, w, int(o), r, dv, cell);
        if (!(c < inf)) return;
        const double nd = dv + c + pen_o;
        if (prune) {  // dominated on arrival by w's best state so far
          const std::int64_t bw = S.best_in(w);
          if (bw >= 0 && bw != o && S.best(w) + penalty.margin(row + st[std::size_t(o)].di, bw, o) <= nd) return;
        }
        const std::int64_t s = w * K + o;
        if (nd < S.get(s)) {  // false for settled states: their cost is negative
          S.set(s, nd, code);
          if (prune) S.offer(w, o, nd);
          heap.push({use_bound ? nd + h(w) : nd, std::uint32_t(s)});
        }
      });
    };
    // A first entry at the least key any state can have (the start's bound): the bucket queue
    // starts its ring at the first key it is given. Popped, it is skipped.
    constexpr std::uint32_t sentinel = 0xffffffffu;
    heap.push({use_bound ? h(start) : 0.0, sentinel});
    expand(start, incoming, 0.0, 0);
    while (!heap.empty()) {
      const HeapEntry top = heap.pop();
      if (top.id == sentinel) continue;
      const std::int64_t s = top.id;
      if constexpr (std::is_same_v<decltype(heap), BucketQueue>) S.prefetch(heap.peek());
      const double ds = S.get(s);
      if (std::signbit(ds)) continue;
      S.settle(s);
      count_settled(stats.settled, control);
      const std::int64_t v = s / K, in = s - v * K;
      if (v == target) { reached = s; break; }
      const std::int64_t row = v / g.cols;
      auto margin = [&](std::int64_t o1, std::int64_t o2) { return penalty.margin(row, o1, o2); };
      if (prune && S.dominated(v, in, ds, margin)) {
        S.drop(s);
        continue;
      }
      S.mark(v, in);
      expand(v, in, ds, std::uint8_t(in + 1));
    }
    stats.heap_peak = heap.peak();
    queue_bytes = heap.capacity_bytes();
  };

  RouteResult out;
  if (start == target) {
    out.cost = 0;
    out.path = {start};
    out.cumulative = {0.0};
    return out;
  }
  with_queue<true, false>(q, run);
  stats.state_bytes = S.bytes() + queue_bytes + penalty.bytes() + field_bytes;
  out.stats = stats;
  if (reached < 0) return out;
  // The target has one state per incoming step. A bucket empties in any order, so another of
  // them may be cheaper than the first one popped; those in the same bucket are final already
  // (no step is cheaper than a bucket's width) and later buckets hold only dearer labels.
  for (std::int64_t o = 0; o < K; ++o)
    if (std::fabs(S.get(target * K + o)) < std::fabs(S.get(reached))) reached = target * K + o;
  out.cost = std::fabs(S.get(reached));
  trace_back(S, g, st, reached, out);
  return out;
}

}  // namespace seaway
