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
// (the benchmark chart's corner voyage: 14.9 M states settled without, benchmarks/README.md).
//
// Memory (turn_states.hpp): 8 bytes of cost + 1 byte of predecessor per state, i.e. 9 x (number
// of stencil offsets) bytes per pixel of address space (k=3: 72, k=5: 216, k=7: 432), and 9
// bytes per pixel for its best state. It is allocated zero-filled (calloc: the kernel maps pages
// only when they are first written, so a search that reaches a small part of the chart uses
// physical memory only there).
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
// scaled by 1 - astar_bucket_eps.
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
  const double eps = astar ? astar_bucket_eps : 1.0;
  // The largest key increase of one step: its cost and penalty, plus the bound's largest drop
  // (exact A*'s bound below drops by at most a step's cost).
  QueueChoice q = choose_queue(b, pg.shortest_step(), pg.longest_step(), eps, astar ? b.max_rate : 0.0,
                               penalty.largest());
  if (weight > 1) q.kind = QueueKind::quaternary;
  const bool buckets = q.kind == QueueKind::buckets;
  const bool use_bound = weight > 0 && b.per_length;
  // A* in a heap: the bound is consistent; shave it by 1e-9 against rounding. In buckets: 0.95.
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

  const std::size_t states = std::size_t(n * K);
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
      pg.steps().each(v, [&](std::int64_t w, std::int64_t o, std::int64_t, std::int64_t, double r, auto&& cell) {
        const double c = model(v, w, int(o), r, dv, cell);
        if (!(c < inf)) return;
        const double nd = dv + c + (leave ? leave[o] : penalty(row, in, o));
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
    // Whether a state of v expanded before (v, in) dominates it.
    auto dominated = [&](std::int64_t v, std::int64_t in, double dv) {
      const std::int64_t row = v / g.cols;
      for (std::int64_t o = 0; o < K; ++o)
        if (o != in && S.expanded(v * K + o) && -S.get(v * K + o) + penalty.margin(row, o, in) <= dv) return true;
      return false;
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
      if (prune && dominated(v, in, ds)) { S.drop(s); continue; }
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
  // Back along the predecessors: state (w, o) came from pixel w - offset o, in state pred - 1.
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
  return out;
}

}  // namespace seaway
