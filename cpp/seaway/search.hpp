// Dijkstra / A* / weighted A* on the implicit raster graph. Vertices are pixels; the edges of a
// pixel are generated from the stencil when it is settled (steps.hpp); nothing about adjacency
// is stored. The search is a template over the edge-cost model, so new costs are new functors.
#pragma once

#include <cmath>
#include <cstdint>
#include <utility>

#include "geometry.hpp"
#include "heap.hpp"
#include "route_result.hpp"
#include "search_control.hpp"
#include "steps.hpp"
#include "workspace.hpp"

namespace seaway {

// A search that stops only at its target.
struct NeverStop {
  bool operator()(std::int64_t) const { return false; }
};

// Runs from `start` until `target` is settled (target < 0: until every reachable pixel is),
// or `stop(v)` says so for a settled pixel v (many targets: many_targets.hpp).
// ws.cost(v) ends as the accumulated cost of v (exact for settled pixels), inf if not reached.
// `bound(v)` is A*'s lower bound on the cost from v to target (used when bound.active()).
// Prune: leave out the steps `steps` skips (StepEnumerator::each).
template <bool Prune = false, class Queue, class Model, class Bound, class Stop = NeverStop>
SearchStats search_with_bound(const StepEnumerator& steps, const Model& model, std::int64_t start,
                              std::int64_t target, Workspace& ws, Queue heap, const Bound& bound,
                              const SearchControl* control, const Stop& stop = Stop{}) {
  const bool use_bound = bound.active() && target >= 0;
  ws.reset(steps.geometry().size());
  double* dist = ws.dist.data();
  std::uint8_t* pred = ws.pred.data();
  SearchStats stats;

  dist[start] = 0;
  ws.reached(start);
  heap.push({use_bound ? bound(start) : 0.0, std::uint32_t(start)});

  while (!heap.empty()) {
    const HeapEntry top = heap.pop();
    const std::int64_t v = top.id;
    const double dv = dist[v];
    if (std::signbit(dv)) continue;  // an older, costlier entry of an expanded pixel
    dist[v] = -dv;                   // expanded: never reopened (weighted A* keeps its bound)
    count_settled(stats.settled, control);
    if (v == target || stop(v)) break;
    steps.template each<false, Prune>(v, [&](std::int64_t w, std::int64_t o, std::int64_t from, std::int64_t to, double r, auto&& cell) {
      const double nd = dv + model(from, to, int(o), r, dv, cell);
      const double old = dist[w];
      if (nd < old) {  // false for expanded pixels: their cost is negative
        if (old == inf) ws.reached(w);
        dist[w] = nd;
        pred[w] = std::uint8_t(o);
        heap.push({use_bound ? nd + bound(w) : nd, std::uint32_t(w)});
      }
    });
  }
  stats.heap_peak = heap.peak();
  stats.state_bytes = ws.bytes() + heap.capacity_bytes();
  return stats;
}

// With the straight-line (great-circle) bound times `bound_factor` (0: Dijkstra).
template <class Queue, class Model>
SearchStats search(const StepEnumerator& steps, const Model& model, std::int64_t start,
                   std::int64_t target, Workspace& ws, Queue heap, double bound_factor,
                   const SearchControl* control) {
  const bool use_bound = bound_factor > 0 && target >= 0;
  const DistanceBound bound(steps.geometry(), use_bound ? target : 0, use_bound ? bound_factor : 0);
  return search_with_bound(steps, model, start, target, ws, std::move(heap), bound, control);
}

// The route to `target` a search from `start` left in `ws`.
inline RouteResult route_from(const StepEnumerator& steps, const Workspace& ws, std::int64_t start,
                              std::int64_t target, const SearchStats& stats) {
  RouteResult out;
  out.stats = stats;
  out.cost = ws.cost(target);
  if (out.cost < inf) {
    out.path = trace_back(steps.geometry(), steps.stencil(), start, target,
                          [&](std::int64_t v) { return int(ws.pred[std::size_t(v)]); }, &out.offsets);
    for (std::int64_t p : out.path) out.cumulative.push_back(ws.cost(p));
  }
  return out;
}

}  // namespace seaway
