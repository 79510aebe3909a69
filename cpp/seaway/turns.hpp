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
// Memory: 8 bytes of cost + 1 byte of predecessor per state, i.e. 9 x (number of stencil
// offsets) bytes per pixel of address space (k=3: 72, k=5: 216, k=7: 432). It is allocated
// zero-filled (calloc: the kernel maps pages only when they are first written, so a search
// that reaches a small part of the chart uses physical memory only there).
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
#include <vector>

#include "router.hpp"
#include "steps.hpp"

namespace seaway {

// Piecewise-linear penalty of the course change: cost[i] at angle_deg[i] (ascending, from 0 to
// 180), linear between, in the route's cost units. Per degree p: {0, 180} -> {0, 180 p}.
struct TurnPenalty {
  std::vector<double> angle_deg, cost;

  double operator()(double a) const {
    if (a <= angle_deg.front()) return cost.front();
    for (std::size_t i = 1; i < angle_deg.size(); ++i)
      if (a <= angle_deg[i]) {
        const double slope = (cost[i] - cost[i - 1]) / (angle_deg[i] - angle_deg[i - 1]);
        return slope * (a - angle_deg[i - 1]) + cost[i - 1];
      }
    return cost.back();
  }
};

// Unit direction of every offset at every row (one row on planar grids), for turn angles.
class TurnAngles {
 public:
  TurnAngles(const Grid& g, const std::vector<Offset>& st) : n_(std::int64_t(st.size())) {
    rows_ = g.geographic ? g.rows : 1;
    dir_.resize(std::size_t(rows_ * n_ * 2));
    for (std::int64_t r = 0; r < rows_; ++r)
      for (std::int64_t o = 0; o < n_; ++o) {
        const Offset& s = st[std::size_t(o)];
        const double y = g.geographic ? s.di * g.dlat : s.di * g.dy;
        const double x = g.geographic ? s.dj * g.dlon * std::cos(g.lat(r) * deg) : s.dj * g.dx;
        const double len = std::hypot(y, x);
        dir_[std::size_t((r * n_ + o) * 2)] = y / len;
        dir_[std::size_t((r * n_ + o) * 2 + 1)] = x / len;
      }
  }
  // Degrees between offsets o1 and o2 at row r.
  double operator()(std::int64_t r, std::int64_t o1, std::int64_t o2) const {
    if (o1 == o2) return 0;
    const double* a = &dir_[std::size_t(((rows_ == 1 ? 0 : r) * n_ + o1) * 2)];
    const double* b = &dir_[std::size_t(((rows_ == 1 ? 0 : r) * n_ + o2) * 2)];
    return std::acos(std::clamp(a[0] * b[0] + a[1] * b[1], -1.0, 1.0)) / deg;
  }
  std::size_t bytes() const { return dir_.capacity() * sizeof(double); }

 private:
  std::int64_t n_, rows_;
  std::vector<double> dir_;
};

// The penalty of every (incoming, outgoing) offset pair per row (one row on planar grids), so
// a relaxation reads a number instead of taking an arccosine; computed on the fly when the
// table would pass 64 MB (lat/lon grids with wide stencils).
class TurnCosts {
 public:
  TurnCosts(const Grid& g, const std::vector<Offset>& st, const TurnPenalty& p)
      : angles_(g, st), p_(p), k_(std::int64_t(st.size())), rows_(g.geographic ? g.rows : 1) {
    if (double(rows_) * double(k_ * k_) * sizeof(double) > 64e6) return;
    table_.resize(std::size_t(rows_ * k_ * k_));
    for (std::int64_t r = 0; r < rows_; ++r)
      for (std::int64_t a = 0; a < k_; ++a)
        for (std::int64_t b = 0; b < k_; ++b) table_[std::size_t((r * k_ + a) * k_ + b)] = p(angles_(r, a, b));
  }
  double operator()(std::int64_t row, std::int64_t in, std::int64_t o) const {
    if (table_.empty()) return p_(angles_(row, in, o));
    return table_[std::size_t(((rows_ == 1 ? 0 : row) * k_ + in) * k_ + o)];
  }
  double largest() const { return *std::max_element(p_.cost.begin(), p_.cost.end()); }
  std::size_t bytes() const { return angles_.bytes() + table_.capacity() * sizeof(double); }

 private:
  TurnAngles angles_;
  const TurnPenalty& p_;
  std::int64_t k_, rows_;
  std::vector<double> table_;
};

namespace detail {
struct FreeDeleter {
  void operator()(void* p) const { std::free(p); }
};
template <class T>
std::unique_ptr<T[], FreeDeleter> zeroed(std::size_t n) {
  void* p = std::calloc(n, sizeof(T));
  if (!p) throw std::bad_alloc();
  return std::unique_ptr<T[], FreeDeleter>(static_cast<T*>(p));
}
// Costs are stored as bits(d) ^ bits(inf), so zero-filled memory reads as inf.
inline std::uint64_t bits_of(double d) {
  std::uint64_t b;
  std::memcpy(&b, &d, 8);
  return b;
}
inline double from_bits(std::uint64_t b) {
  double d;
  std::memcpy(&d, &b, 8);
  return d;
}
}  // namespace detail

// Least-cost route from `start` to `target` with turn penalties under `model`. `incoming`: the
// offset of the step that reached the start (charged at the first turn), or -1 for none.
// weight 0: Dijkstra, 1: A*, > 1: weighted A*. The queue is chosen as in PreparedGrid::run:
// buckets when every step (and so every step plus a penalty >= 0) costs at least a bucket's
// width, exact A* then with its bound scaled by 0.95; a radix heap for other monotone keys; a
// 4-ary heap for weighted A*.
template <class Model>
RouteResult route_with_turns(PreparedGrid& pg, const Model& model, const TurnPenalty& turn,
                             std::int64_t start, std::int64_t target, int incoming, double weight,
                             const SearchControl* control = nullptr) {
  const Grid& g = pg.grid();
  const std::vector<Offset>& st = pg.stencil();
  const Grid::Lengths& lengths = pg.lengths();
  const std::int64_t C = g.cols, K = std::int64_t(st.size()), n = g.size();
  if (start < 0 || start >= n || target < 0 || target >= n)
    throw std::out_of_range("pixel index outside the grid");
  if (incoming >= K) throw std::invalid_argument("incoming step is not a stencil offset");
  if (double(n) * double(K) >= 4294967295.0)
    throw std::invalid_argument("pixels x stencil offsets must stay below 2**32 for the turn penalty");
  const TurnCosts penalty(g, st, turn);
  const StepBounds b = model.bounds(pg.passability());
  const auto [rmin_it, rmax_it] = std::minmax_element(lengths.table.begin(), lengths.table.end());
  const double rmin = b.per_length ? *rmin_it : 1.0, rmax = b.per_length ? *rmax_it : 1.0;
  const bool astar = weight == 1 && b.per_length;
  const double eps = astar ? 0.05 : 1.0;
  const double width = 0.999999 * eps * b.min_rate * rmin;
  // The largest key increase of one step: its cost and penalty, plus the bound's largest drop
  // (exact A*'s bound below drops by at most a step's cost).
  const double span = 1.000001 * (b.max_rate + (astar ? b.max_rate : 0.0)) * rmax + penalty.largest() + 1e-300;
  const bool buckets = weight <= 1 && width > 0 && span < inf && BucketQueue::buckets_needed(width, span) < 65536;
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
  std::optional<PreparedGrid::Lease> field;
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
  auto cost_bits = detail::zeroed<std::uint64_t>(states);
  auto pred = detail::zeroed<std::uint8_t>(states);  // 1 + offset into the predecessor; 0: start
  const std::uint64_t inf_bits = detail::bits_of(inf);
  auto dist = [&](std::int64_t s) { return detail::from_bits(cost_bits[std::size_t(s)] ^ inf_bits); };
  auto set = [&](std::int64_t s, double d) { cost_bits[std::size_t(s)] = detail::bits_of(d) ^ inf_bits; };

  SearchStats stats;
  stats.min_cost = b.min_rate;
  std::int64_t reached = -1;  // the state at the target
  std::size_t queue_bytes = 0;
  // Every step out of pixel v (reached by offset `in`, -1: none) with label dv; `code` is what
  // the new states record as their predecessor (0 from the start, else 1 + in).
  auto run = [&](auto heap) {
    auto expand = [&](std::int64_t v, std::int64_t in, double dv, std::uint8_t code) {
      const std::int64_t row = v / C;
      const double* len = lengths.row(row);
      for_each_step(pg, v, [&](std::int64_t w, std::int64_t o, auto&& cell) {
        const double c = model(v, w, int(o), len[o], dv, cell);
        if (!(c < inf)) return;
        const double nd = dv + c + (in >= 0 ? penalty(row, in, o) : 0.0);
        const std::int64_t s = w * K + o;
        if (nd < dist(s)) {  // false for expanded states: their cost is negative
          set(s, nd);
          pred[std::size_t(s)] = code;
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
      const double ds = dist(s);
      if (std::signbit(ds)) continue;
      set(s, -ds);
      if ((++stats.settled & 4095) == 0 && control) {  // progress and Ctrl-C, as search.hpp
        control->settled.store(stats.settled, std::memory_order_relaxed);
        if (control->cancel.load(std::memory_order_relaxed)) throw Cancelled();
      }
      const std::int64_t v = s / K;
      if (v == target) { reached = s; break; }
      expand(v, s - v * K, ds, std::uint8_t(s - v * K + 1));
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
  if (weight > 1) run(QuaternaryHeap{});
  else if (buckets) run(BucketQueue(width, span));
  else run(RadixHeap{});
  stats.state_bytes = states * 9 + queue_bytes + penalty.bytes() + field_bytes;
  out.stats = stats;
  if (reached < 0) return out;
  // The target has one state per incoming step. A bucket empties in any order, so another of
  // them may be cheaper than the first one popped; those in the same bucket are final already
  // (no step is cheaper than a bucket's width) and later buckets hold only dearer labels.
  for (std::int64_t o = 0; o < K; ++o)
    if (std::fabs(dist(target * K + o)) < std::fabs(dist(reached))) reached = target * K + o;
  out.cost = std::fabs(dist(reached));
  // Back along the predecessors: state (w, o) came from pixel w - offset o, in state pred - 1.
  std::int64_t s = reached;
  for (;;) {
    const std::int64_t v = s / K, o = s - v * K;
    out.path.push_back(v);
    out.cumulative.push_back(std::fabs(dist(s)));
    out.offsets.push_back(int(o));
    std::int64_t r = v / C - st[std::size_t(o)].di, c = v % C - st[std::size_t(o)].dj;
    if (g.wrap) c = (c + C) % C;
    const std::int64_t u = r * C + c;
    const int p = pred[std::size_t(s)];
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
