// Exact bidirectional Dijkstra on two threads: a forward search from the start and a backward
// search from the target, each with its own labels and queue, run at once in rounds.
// The backward search walks the same directed steps from their far end and charges each the
// model's cost of the forward step (same function, same arguments, so the same double): it
// needs no symmetry of the model, but the model must be static (a step's cost may not depend
// on the arrival time; the caller checks).
//
// Rounds: in each round each side settles the same count of pixels (so the two threads get
// equal work whatever the scheduler does), then the two meet at a barrier. There, labels are
// still: each side scans the pixels it relabelled in the round (those it settled, and its
// queue) against the other's labels, and mu = min over pixels labelled by both of d_f + d_b
// (a real route's cost) is updated.
// Stop when top_f + top_b >= mu (top: no key left in a queue is lower) or a queue is empty:
// then mu is optimal. On an optimal route of cost L < top_f + top_b there is a step (x, y)
// with x settled forward and y settled backward; relaxing x labelled y forward, so y is
// labelled by both and d_f(y) + d_b(y) <= L. If a queue is empty, its side has settled every
// pixel it can reach, the other's origin among them.
// Each side's search does not depend on the other's, and the stop is decided on the state at
// a barrier, so the route and its cost are the same on every run (bit for bit), whatever the
// threads' timing: threaded queries give the serial answers.
//
// Memory: each side's labels live in anonymous zero-filled pages that the kernel maps only when
// first written (lazy_labels.hpp); the two sides together touch about the pixels one Dijkstra
// reaches, so the search needs about one workspace's 9 B per reached pixel plus the frontier;
// stats.state_bytes counts the resident pages. The chart keeps the labels of the last query
// for the next one (PreparedGrid::LabelLease), which then writes them without page faults.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <thread>
#include <type_traits>
#include <vector>

#include "lazy_labels.hpp"
#include "router.hpp"

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

inline int half_width(const std::vector<Offset>& st) {
  int h = 0;
  for (const Offset& o : st) h = std::max({h, std::abs(o.di), std::abs(o.dj)});
  return h;
}

}  // namespace detail

struct Meeting {
  std::int64_t pixel = -1;  // labelled by both sides on an optimal route; -1: no route
  double cost = inf;
};

// One side of the search. Backward == true walks the steps into each pixel.
template <bool Backward, class Queue, class Model, class Potential>
SearchStats bidirectional_side(const PreparedGrid& pg, const Model& model, std::int64_t origin,
                               LazyLabels& mine, const LazyLabels& other, Queue heap,
                               const Potential& pot, double shift, detail::Rounds& rounds,
                               Meeting& meet, const SearchControl* cancel) {
  constexpr int self = Backward ? 1 : 0;
  const Grid& g = pg.grid();
  const std::vector<Offset>& st = pg.stencil();
  const Grid::Lengths& lengths = pg.lengths();
  const std::uint8_t* clear = pg.clearance();
  const LandRule rule = pg.land_rule();
  const std::int64_t R = g.rows, C = g.cols, n_off = std::int64_t(st.size());
  const int h = detail::half_width(st);
  std::vector<std::int64_t> flat(st.size());
  for (std::size_t k = 0; k < st.size(); ++k) flat[k] = st[k].di * C + st[k].dj;
  auto wrap_col = [&](std::int64_t c) { return c < 0 ? c + C : (c >= C ? c - C : c); };

  SearchStats stats;
  std::vector<std::uint32_t> settled_now;  // settled in this round
  std::size_t round_peak = 0;
  // The key: the label, or with a potential p the reduced label d + p(v) - p(s) forward and
  // d - p(v) + p(t) backward (>= 0; clamped against rounding).
  auto key = [&](std::int64_t v, double d) {
    if (!pot.active()) return d;
    return std::max(0.0, Backward ? d - pot(v) + shift : d + pot(v) - shift);
  };
  heap.push({0.0, std::uint32_t(origin)});
  // Rounds of a count of settled pixels, the same on both sides (4096, later 1/16 of what the
  // side has settled): the two threads get equal work whatever the ends' surroundings, and the
  // last round overshoots the stop by at most 1/16. The count depends on nothing but this
  // side's own search, so the rounds are the same on every run.
  double mu = inf;
  std::int64_t mu_pixel = -1;  // the best meeting so far: cost mu, this pixel
  int passed = 0;

  auto settle = [&](std::int64_t v, double dv) {
    mine.set(v, -dv);  // settled
    settled_now.push_back(std::uint32_t(v));
    if ((++stats.settled & 4095) == 0 && cancel) {
      if (!Backward) cancel->settled.store(stats.settled, std::memory_order_relaxed);  // progress
      if (cancel->cancel.load(std::memory_order_relaxed)) {
        rounds.abort.store(true);
        throw Cancelled();
      }
    }
    const std::int64_t row = v / C, col = v - row * C;
    const bool interior = row >= h && row < R - h && col >= h && col < C - h;
    // w: the neighbour; c: the step's cost; o: its offset (forward: v -> w; backward: w -> v).
    auto relax = [&](std::int64_t w, double c, std::int64_t o) {
      const double nd = dv + c;
      if (nd < mine.get(w)) {  // false for settled pixels: their label is negative
        mine.set(w, nd, int(o));
        heap.push({key(w, nd), std::uint32_t(w)});
      }
    };
    if (interior && clear[v] > h) {  // every step to or from v exists and is free
      for (std::int64_t o = 0; o < n_off; ++o) {
        const auto& shares = st[std::size_t(o)].shares;
        if constexpr (Backward) {
          const std::int64_t p = v - flat[std::size_t(o)];
          relax(p, model(p, v, int(o), lengths.row(p / C)[o], 0.0,
                         [&](std::size_t m) { return p + shares[m].di * C + shares[m].dj; }), o);
        } else {
          const std::int64_t w = v + flat[std::size_t(o)];
          relax(w, model(v, w, int(o), lengths.row(row)[o], 0.0,
                         [&](std::size_t m) { return v + shares[m].di * C + shares[m].dj; }), o);
        }
      }
      return;
    }
    for (std::int64_t o = 0; o < n_off; ++o) {
      const Offset& off = st[std::size_t(o)];
      // The step runs from (r0, c0) to (r0 + di, c0 + dj); w is its end other than v.
      const std::int64_t r0 = Backward ? row - off.di : row;
      std::int64_t c0 = Backward ? col - off.dj : col;
      const std::int64_t rw = Backward ? r0 : row + off.di;
      std::int64_t cw = Backward ? c0 : col + off.dj;
      if (rw < 0 || rw >= R) continue;
      if (g.wrap) cw = wrap_col(cw);
      else if (cw < 0 || cw >= C) continue;
      if (g.wrap) c0 = wrap_col(c0);
      const std::int64_t w = rw * C + cw;
      if (clear[w] == 0) continue;
      auto at = [&](int di, int dj) { return (r0 + di) * C + (g.wrap ? wrap_col(c0 + dj) : c0 + dj); };
      if (rule == LandRule::segment) {
        bool blocked = false;
        for (const CellShare& t : off.touched)
          if (clear[at(t.di, t.dj)] == 0) { blocked = true; break; }
        if (blocked) continue;
      }
      const std::int64_t from = r0 * C + c0, to = Backward ? v : w;
      relax(w, model(from, to, int(o), lengths.row(r0)[o], 0.0,
                     [&](std::size_t m) { return at(off.shares[m].di, off.shares[m].dj); }),
            o);
    }
  };

  for (;;) {
    // Search: settle this round's count of pixels.
    settled_now.clear();
    const std::int64_t quota = std::max<std::int64_t>(4096, stats.settled / 16);
    while (std::int64_t(settled_now.size()) < quota && !heap.empty()) {
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
    const int k = passed / 2 % 2;  // this round's slot
    rounds.mu_part[k][self] = best;
    rounds.meet_part[k][self] = at;
    rounds.top[k][self] = heap.empty() ? inf : heap.lower_bound();
    rounds.empty[k][self] = heap.empty();
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
  stats.state_bytes = heap.capacity_bytes() + round_peak * sizeof(std::uint32_t);
  return stats;
}

// No potential: plain bidirectional Dijkstra.
struct NoPotential {
  static constexpr bool worth_caching = false;
  bool active() const { return false; }
  double operator()(std::int64_t) const { return 0; }
};

// The consistent average potential of two lower bounds (to the target, from the start):
// p(v) = scale x (to_target(v) - from_start(v)) / 2. With scale = 1 - eps, every step's reduced
// cost c - p(v) + p(w) is at least eps x c (less the bounds' rounding), forward and backward.
template <class Bound>
struct AveragePotential {
  // Kept per pixel when the bounds read tables (landmarks), recomputed when they are arithmetic.
  static constexpr bool worth_caching = !std::is_same_v<Bound, DistanceBound>;
  Bound to_target, from_start;
  double scale;
  bool active() const { return true; }
  double operator()(std::int64_t v) const { return scale * 0.5 * (to_target(v) - from_start(v)); }
};

// Least-cost route from start to target by bidirectional search on two threads, for static
// models only (the caller checks). `reduced_floor`: every step's reduced cost is at least this
// share of the cheapest step (1 without a potential); `extra_span`: the most a step's key may
// rise above its cost (0 without a potential).
template <class Model, class Potential = NoPotential>
RouteResult route_bidirectional(PreparedGrid& pg, const Model& model, std::int64_t start,
                                std::int64_t target, const SearchControl* cancel = nullptr,
                                const Potential& pot = {}, double reduced_floor = 1.0,
                                double extra_rate = 0.0) {
  pg.check(start);
  pg.check(target);
  if (start == target || pg.clearance()[start] == 0 || pg.clearance()[target] == 0)
    return pg.route(model, start, target, 0.0, cancel);
  const Grid& g = pg.grid();
  const std::vector<Offset>& st = pg.stencil();
  const StepBounds b = model.bounds(pg.passability());
  const double rmin = b.per_length ? pg.shortest_step() : 1.0;
  const double rmax = b.per_length ? pg.longest_step() : 1.0;
  const double width = 0.999999 * reduced_floor * b.min_rate * rmin;
  const double span = 1.000001 * (b.max_rate + extra_rate) * rmax + 1e-300;
  const bool buckets = width > 0 && span < inf && BucketQueue::buckets_needed(width, span) < 65536;
  const double shift_f = pot.active() ? pot(start) : 0.0, shift_b = pot.active() ? pot(target) : 0.0;

  PreparedGrid::LabelLease fw_lease(pg), bw_lease(pg);  // pooled: no page faults when reused
  LazyLabels &fw = *fw_lease, &bw = *bw_lease;
  detail::Rounds rounds;
  if (pot.active()) {
    rounds.mu_offset = shift_b - shift_f;
    rounds.mu_slack = 1e-12;
  }
  Meeting meet;
  SearchStats sides[2];
  std::exception_ptr errors[2];
  auto side = [&](auto backward) {
    constexpr bool B = decltype(backward)::value;
    LazyLabels& mine = B ? bw : fw;
    const LazyLabels& theirs = B ? fw : bw;
    const std::int64_t origin = B ? target : start;
    try {
      // A pooled side's pages from the last query are zeroed here, each side on its own thread;
      // the other side reads these labels only after the first round's barrier.
      mine.clear();
      mine.set(origin, 0.0);
      const double shift = B ? shift_b : shift_f;
      auto run = [&](const auto& p) {
        // Landmark potentials need buckets a small share of a step wide: many, sparsely filled.
        if constexpr (Potential::worth_caching)
          if (buckets && BucketQueue::buckets_needed(width, span) > 4096)
            return bidirectional_side<B>(pg, model, origin, mine, theirs, ChunkedBucketQueue(width, span),
                                         p, shift, rounds, meet, cancel);
        return buckets ? bidirectional_side<B>(pg, model, origin, mine, theirs, BucketQueue(width, span),
                                               p, shift, rounds, meet, cancel)
                       : bidirectional_side<B>(pg, model, origin, mine, theirs, RadixHeap{}, p, shift,
                                               rounds, meet, cancel);
      };
      // A potential is asked for at every push: each side keeps the values it computed.
      if constexpr (!Potential::worth_caching) {
        sides[B] = run(pot);
      } else {
        const CachedBound<Potential> cached(pot, g.size());
        sides[B] = run(cached);
        sides[B].state_bytes += cached.resident_bytes();
      }
    } catch (...) {
      errors[B] = std::current_exception();
      rounds.abort.store(true);
    }
  };
  {
    std::thread helper([&] { side(std::true_type{}); });
    side(std::false_type{});
    helper.join();
  }
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);

  RouteResult out;
  out.stats.settled = sides[0].settled + sides[1].settled;
  out.stats.heap_peak = sides[0].heap_peak + sides[1].heap_peak;
  out.stats.state_bytes = sides[0].state_bytes + sides[1].state_bytes + fw.resident_bytes() +
                          bw.resident_bytes() + pg.clearance_bytes();
  out.stats.min_cost = b.min_rate;
  if (meet.pixel < 0) return out;  // no route: cost stays inf

  // Forward labels from the start to the meeting pixel, then the backward side's predecessor
  // steps (each the offset of the forward step out of its pixel) to the target.
  auto move = [&](std::int64_t v, int o, int sign) {
    std::int64_t r = v / g.cols + sign * st[std::size_t(o)].di;
    std::int64_t c = v % g.cols + sign * st[std::size_t(o)].dj;
    if (g.wrap) c = (c + g.cols) % g.cols;
    return r * g.cols + c;
  };
  for (std::int64_t v = meet.pixel;; v = move(v, out.offsets.back(), -1)) {
    out.path.push_back(v);
    if (v == start) break;
    const int o = fw.pred(v);
    if (o < 0 || out.path.size() > std::size_t(g.size()))
      throw std::logic_error("broken forward predecessor chain");
    out.offsets.push_back(o);
  }
  std::reverse(out.path.begin(), out.path.end());
  std::reverse(out.offsets.begin(), out.offsets.end());
  for (std::int64_t p : out.path) out.cumulative.push_back(std::fabs(fw.get(p)));
  out.cost = meet.cost;
  for (std::int64_t v = meet.pixel; v != target;) {
    const int o = bw.pred(v);
    if (o < 0 || out.path.size() > std::size_t(g.size()))
      throw std::logic_error("broken backward predecessor chain");
    out.offsets.push_back(o);
    v = move(v, o, +1);
    out.path.push_back(v);
    out.cumulative.push_back(out.cost - std::fabs(bw.get(v)));
  }
  out.cumulative.back() = out.cost;
  return out;
}

// Bidirectional A*: the average potential of the straight-line (great-circle) bounds to the
// target and from the start, times the chart's smallest cost per unit length, scaled by 0.95
// so that the bucket queue stays exact (as exact A* in router.hpp). Models priced per length
// only (max, mean, integral); others run plain bidirectional Dijkstra.
template <class Model>
RouteResult route_bidirectional_astar(PreparedGrid& pg, const Model& model, std::int64_t start,
                                      std::int64_t target, const SearchControl* cancel = nullptr) {
  pg.check(start);
  pg.check(target);
  const StepBounds b = model.bounds(pg.passability());
  if (!b.per_length || !(b.min_rate > 0)) return route_bidirectional(pg, model, start, target, cancel);
  constexpr double eps = 0.05;
  const AveragePotential<DistanceBound> pot{DistanceBound(pg.grid(), target, b.min_rate),
                                            DistanceBound(pg.grid(), start, b.min_rate), 1 - eps};
  return route_bidirectional(pg, model, start, target, cancel, pot, eps, b.min_rate);
}

}  // namespace seaway
