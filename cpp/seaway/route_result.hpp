// What a search returns: its figures, and the route read back from its predecessor steps.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "geometry.hpp"

namespace seaway {

struct SearchStats {
  std::int64_t settled = 0;     // pixels (or states) taken off the queue
  std::size_t heap_peak = 0;    // largest frontier
  std::size_t state_bytes = 0;  // the search's own memory at its peak
  double min_cost = inf;        // smallest passable cost (the A* bound's factor)
};

struct RouteResult {
  double cost = inf;               // inf when the target was not reached
  std::vector<std::int64_t> path;  // flat pixel indices, start first
  std::vector<double> cumulative;  // the cost from the start to each pixel of the path
  std::vector<int> offsets;        // the stencil offset of each step (path.size() - 1)
  SearchStats stats;
};

// The pixels from `start` to `target`, start first, read back along pred(v): the stencil offset
// of the step that reached v (negative or past the stencil: none). The offsets of the steps are
// appended to *offsets in route order.
template <class Pred>
std::vector<std::int64_t> trace_back(const Geometry& g, const std::vector<Offset>& st,
                                     std::int64_t start, std::int64_t target, Pred&& pred,
                                     std::vector<int>* offsets = nullptr) {
  std::vector<std::int64_t> path{target};
  const std::size_t first = offsets ? offsets->size() : 0;
  for (std::int64_t v = target; v != start;) {
    const int o = pred(v);
    if (o < 0 || o >= int(st.size())) throw std::logic_error("broken predecessor chain");
    if (offsets) offsets->push_back(o);
    v = g.step(v, st[std::size_t(o)], -1);
    path.push_back(v);
    if (path.size() > std::size_t(g.size())) throw std::logic_error("predecessor cycle");
  }
  if (offsets) std::reverse(offsets->begin() + std::ptrdiff_t(first), offsets->end());
  return {path.rbegin(), path.rend()};
}

}  // namespace seaway
