// Dijkstra / A* / weighted A* on the implicit raster graph. Vertices are pixels; the edges of a
// pixel are generated from the stencil when it is settled; nothing about adjacency is stored.
// The search is a template over the edge-cost model, so new costs are new functors.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "grid.hpp"
#include "heap.hpp"
#include "passability.hpp"
#include "stencil.hpp"

namespace seaway {

constexpr std::uint8_t no_pred = 255;
// Which pixels a step must keep clear of. `segment`: both ends and every pixel whose closed
// square the closed straight segment touches (the papers' rule: no leaking through diagonal
// coastlines, no jumping over land). `ends`: only the two ends (scikit-image's rule).
enum class LandRule { segment, ends };

// Search state, kept by a thread across queries: 8 bytes of accumulated cost and 1 of
// predecessor step per pixel. The next query resets only the pixels this one reached, listed
// while they are few (up to 1/8 of the chart, half a byte per pixel); past that, the whole
// cost array is reset, which then costs no more than the query that touched them did. An
// expanded pixel has its cost's sign bit set: the relaxation test `new < dist` then fails
// for it without a separate flag.
struct Workspace {
  std::vector<double> dist;
  std::vector<std::uint8_t> pred;
  std::vector<std::uint32_t> touched;
  bool overflowed = false;

  void reset(std::int64_t n) {
    if (dist.size() != std::size_t(n)) {
      dist.assign(std::size_t(n), inf);
      pred.assign(std::size_t(n), no_pred);
      touched = {};
      touched.reserve(std::size_t(n / 8 + 1));
    } else if (overflowed) {
      std::fill(dist.begin(), dist.end(), inf);
    } else {
      for (std::uint32_t v : touched) dist[v] = inf;
    }
    touched.clear();
    overflowed = false;
  }
  void reached(std::int64_t v) {  // v's cost was inf until now
    if (touched.size() < touched.capacity()) touched.push_back(std::uint32_t(v));
    else overflowed = true;
  }
  double cost(std::int64_t v) const { return std::fabs(dist[std::size_t(v)]); }
  std::size_t bytes() const {
    return dist.capacity() * sizeof(double) + pred.capacity() + touched.capacity() * sizeof(std::uint32_t);
  }
};

struct SearchStats {
  std::int64_t settled = 0;     // pixels taken off the heap
  std::size_t heap_peak = 0;    // largest frontier
  std::size_t state_bytes = 0;  // the search's own memory at its peak
  double min_cost = inf;        // smallest passable cost (the A* bound's factor)
};

// Shared with whoever started a search (e.g. Python's waiting main thread): every 4096
// expansions the search publishes how many pixels it has settled and stops (throws Cancelled)
// if `cancel` was set. Without a control the search polls nothing.
struct SearchControl {
  std::atomic<bool> cancel{false};
  mutable std::atomic<std::int64_t> settled{0};
};

struct SearchSpec {
  const Grid* grid;
  const std::vector<Offset>* stencil;
  LandRule land_rule = LandRule::segment;
  double heuristic_weight = 0;  // 0: Dijkstra; 1: A*; w > 1: weighted A* (cost <= w * optimum)
  const SearchControl* control = nullptr;  // polled every 4096 expansions
};

// Thrown out of a search whose cancel flag was set (e.g. Ctrl-C in Python).
struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("search cancelled") {}
};

// Runs from `start` until `target` is settled (target < 0: until every reachable pixel is).
// ws.cost(v) ends as the accumulated cost of v (exact for settled pixels), inf if not reached.
// `clear` comes from compute_clearance() with cap = half-width + 1.
// `bound(v)` is A*'s lower bound on the cost from v to target (used when bound.active()).
template <class Queue, class Model, class Bound>
SearchStats search_with_bound(const SearchSpec& spec, const Model& model,
                              const Grid::Lengths& lengths, const std::uint8_t* clear,
                              double min_cost, std::int64_t start, std::int64_t target,
                              Workspace& ws, Queue heap, const Bound& bound) {
  const Grid& g = *spec.grid;
  const std::vector<Offset>& st = *spec.stencil;
  const std::int64_t R = g.rows, C = g.cols, n_off = std::int64_t(st.size());
  int h = 0;
  for (const Offset& o : st) h = std::max({h, std::abs(o.di), std::abs(o.dj)});

  std::vector<std::int64_t> flat(st.size());
  for (std::size_t k = 0; k < st.size(); ++k) flat[k] = st[k].di * C + st[k].dj;

  const bool use_bound = bound.active() && target >= 0;

  ws.reset(g.size());
  double* dist = ws.dist.data();
  std::uint8_t* pred = ws.pred.data();
  SearchStats stats;
  stats.min_cost = min_cost;

  dist[start] = 0;
  ws.reached(start);
  heap.push({use_bound ? bound(start) : 0.0, std::uint32_t(start)});

  auto wrap_col = [&](std::int64_t c) { return c < 0 ? c + C : (c >= C ? c - C : c); };

  while (!heap.empty()) {
    const HeapEntry top = heap.pop();
    const std::int64_t v = top.id;
    const double dv = dist[v];
    if (std::signbit(dv)) continue;  // an older, costlier entry of an expanded pixel
    dist[v] = -dv;                   // expanded: never reopened (weighted A* keeps its bound)
    if ((++stats.settled & 4095) == 0 && spec.control) {
      spec.control->settled.store(stats.settled, std::memory_order_relaxed);
      if (spec.control->cancel.load(std::memory_order_relaxed)) throw Cancelled();
    }
    if (v == target) break;
    const std::int64_t row = v / C, col = v - row * C;
    const double* len = lengths.row(row);
    const bool interior = row >= h && row < R - h && col >= h && col < C - h;

    auto relax = [&](std::int64_t w, double c, std::int64_t o) {
      const double nd = dv + c;
      const double old = dist[w];
      if (nd < old) {  // false for expanded pixels: their cost is negative
        if (old == inf) ws.reached(w);
        dist[w] = nd;
        pred[w] = std::uint8_t(o);
        heap.push({use_bound ? nd + bound(w) : nd, std::uint32_t(w)});
      }
    };

    if (interior && clear[v] > h) {
      // The common case: away from the border and from land, every step exists and is free.
      for (std::int64_t o = 0; o < n_off; ++o) {
        const std::int64_t w = v + flat[std::size_t(o)];
        const auto& shares = st[std::size_t(o)].shares;
        relax(w, model(v, w, int(o), len[o], dv,
                       [&](std::size_t m) { return v + shares[m].di * C + shares[m].dj; }),
              o);
      }
      continue;
    }

    // Near land or the border: check each step's existence and the land rule.
    for (std::int64_t o = 0; o < n_off; ++o) {
      const Offset& off = st[std::size_t(o)];
      const std::int64_t r2 = row + off.di;
      std::int64_t c2 = col + off.dj;
      if (r2 < 0 || r2 >= R) continue;
      if (g.wrap) c2 = wrap_col(c2);
      else if (c2 < 0 || c2 >= C) continue;
      const std::int64_t w = r2 * C + c2;
      if (clear[w] == 0) continue;
      // Flat index of a pixel met by this step, given relative to v.
      auto at = [&](int di, int dj) {
        return (row + di) * C + (g.wrap ? wrap_col(col + dj) : col + dj);
      };
      if (spec.land_rule == LandRule::segment) {
        bool blocked = false;
        for (const CellShare& t : off.touched)
          if (clear[at(t.di, t.dj)] == 0) { blocked = true; break; }
        if (blocked) continue;
      }
      relax(w, model(v, w, int(o), len[o], dv,
                     [&](std::size_t m) { return at(off.shares[m].di, off.shares[m].dj); }),
            o);
    }
  }
  stats.heap_peak = heap.peak();
  stats.state_bytes = ws.bytes() + heap.capacity_bytes();
  return stats;
}

// The straight-line (great-circle) bound, times spec.heuristic_weight x min_cost.
template <class Queue, class Model>
SearchStats search(const SearchSpec& spec, const Model& model, const Grid::Lengths& lengths,
                   const std::uint8_t* clear, double min_cost, std::int64_t start,
                   std::int64_t target, Workspace& ws, Queue heap) {
  const bool use_bound = spec.heuristic_weight > 0 && target >= 0;
  const DistanceBound bound(*spec.grid, use_bound ? target : 0,
                            use_bound ? spec.heuristic_weight * min_cost : 0);
  return search_with_bound(spec, model, lengths, clear, min_cost, start, target, ws,
                           std::move(heap), bound);
}

// The pixels of the route from start to `target`, start first, read back from the predecessors.
inline std::vector<std::int64_t> trace_path(const Grid& g, const std::vector<Offset>& st,
                                            const Workspace& s, std::int64_t start,
                                            std::int64_t target,
                                            std::vector<int>* offsets = nullptr) {
  std::vector<std::int64_t> path{target};
  std::int64_t v = target;
  while (v != start) {
    const std::uint8_t o = s.pred[std::size_t(v)];
    if (o == no_pred) throw std::logic_error("broken predecessor chain");
    if (offsets) offsets->push_back(o);
    std::int64_t r = v / g.cols - st[o].di, c = v % g.cols - st[o].dj;
    if (g.wrap) c = (c + g.cols) % g.cols;
    v = r * g.cols + c;
    path.push_back(v);
    if (path.size() > std::size_t(g.size())) throw std::logic_error("predecessor cycle");
  }
  if (offsets) std::reverse(offsets->begin(), offsets->end());
  return {path.rbegin(), path.rend()};
}

}  // namespace seaway
