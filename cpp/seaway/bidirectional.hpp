// Exact bidirectional Dijkstra on two threads: a forward search from the start and a backward
// search from the target run at once, each with its own labels and queue. The backward search
// walks the same directed steps from their far end and charges each the model's cost of the
// forward step (same function, same arguments, so the same double), so it needs no symmetry of
// the model; the model must be static (a step's cost may not depend on the arrival time).
//
// Meeting: when a side scans a settled pixel v, every step between v and a pixel w the other
// side has labelled gives a route of cost d_this(v) + c + d_other(w); mu is the least.
// Stopping rule: a side stops once top_f + top_b >= mu (top: no key left in a queue is lower);
// then mu is optimal: on an optimal route of cost L < top_f + top_b there is a step (x, y) with
// x settled forward and y settled backward, both scanned before the stop. With two threads the
// later of the two scans must see the other side's label: each side stores its pixel's
// settled mark, issues a seq_cst fence, then reads the other side's labels (Dekker's pattern),
// so at least one of the two scans sees the other's label (labels only fall, and a settled
// label is final). The published tops and mu are read relaxed: a stale top is lower and a stale
// mu higher, so a stale read only delays the stop.
// A side reads the other's labels only for pixels in 16 x 16 blocks the other has flagged (it
// flags every block within the stencil's reach of each pixel it labels), so the two searches
// add no memory traffic while they are apart.
//
// Memory: each side's labels live in anonymous zero-filled pages that the kernel maps only
// when first written (lazy_labels.hpp); the two sides together touch about the pixels one
// Dijkstra settles, so the search stays within the 9 B/pixel of one workspace plus the
// frontier; stats.state_bytes counts the resident pages.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

#include "lazy_labels.hpp"
#include "router.hpp"

namespace seaway {

namespace detail {

// What the two sides share: the best meeting found, the least key of each queue, the block
// flags and the stop signal.
struct Meeting {
  static constexpr int block_shift = 4;  // 16 x 16 pixel blocks: wider than any stencil (k <= 15)
  std::atomic<double> mu{inf};
  std::atomic<double> top[2];
  std::atomic<bool> stop{false};
  std::int64_t block_cols, blocks;
  std::unique_ptr<std::atomic<std::uint8_t>[]> flags[2];  // per side, per block
  std::mutex best_mutex;
  std::int64_t from = -1, to = -1;  // the crossing step's forward-side and backward-side pixels
  double step_cost = inf;
  int step_offset = -1;

  Meeting(std::int64_t rows, std::int64_t cols)
      : block_cols((cols >> block_shift) + 1), blocks(((rows >> block_shift) + 1) * block_cols) {
    for (int s = 0; s < 2; ++s) {
      flags[s].reset(new std::atomic<std::uint8_t>[std::size_t(blocks)]());
      top[s].store(0.0);
    }
  }
  std::size_t bytes() const { return 2 * std::size_t(blocks); }
  std::atomic<std::uint8_t>& flag(int side, std::int64_t r, std::int64_t c) {
    return flags[side][std::size_t((r >> block_shift) * block_cols + (c >> block_shift))];
  }
  // Flag the blocks within reach h of a pixel `side` has just labelled. A block is wider than
  // the reach, so the corners' blocks cover them all, except across a wrapping grid's seam
  // (whose last block may be narrow), where every column's block is flagged.
  void flag_around(int side, const Grid& g, int h, std::int64_t v) {
    const std::int64_t C = g.cols, r = v / C, c = v - r * C;
    const bool seam = g.wrap && (c - h < 0 || c + h >= C);
    const int step = seam ? 1 : 2 * h;
    for (std::int64_t rr : {std::max<std::int64_t>(r - h, 0), std::min(r + h, g.rows - 1)})
      for (std::int64_t cc = c - h; cc <= c + h; cc += step) {
        const std::int64_t col = seam ? (cc + C) % C : std::min(std::max<std::int64_t>(cc, 0), C - 1);
        auto& f = flag(side, rr, col);
        if (!f.load(std::memory_order_relaxed)) f.store(1, std::memory_order_relaxed);
      }
  }
  void offer(double total, std::int64_t f, std::int64_t b, double c, int o) {
    if (!(total < mu.load(std::memory_order_relaxed))) return;
    std::lock_guard<std::mutex> lock(best_mutex);
    if (!(total < mu.load(std::memory_order_relaxed))) return;
    mu.store(total, std::memory_order_relaxed);
    from = f;
    to = b;
    step_cost = c;
    step_offset = o;
  }
};

inline int half_width(const std::vector<Offset>& st) {
  int h = 0;
  for (const Offset& o : st) h = std::max({h, std::abs(o.di), std::abs(o.dj)});
  return h;
}

}  // namespace detail

// One side of the search. Backward == true walks the steps into each pixel.
template <bool Backward, class Queue, class Model>
SearchStats bidirectional_side(const PreparedGrid& pg, const Model& model, std::int64_t origin,
                               LazyLabels& mine, const LazyLabels& other, Queue heap, double ahead,
                               detail::Meeting& meet, const std::atomic<bool>* cancel) {
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
  heap.push({0.0, std::uint32_t(origin)});
  while (!heap.empty()) {
    const HeapEntry top = heap.pop();
    const std::int64_t v = top.id;
    const double dv = mine.get(v);
    if (std::signbit(dv)) continue;  // an older entry of a settled pixel
    const double lb = heap.empty() ? top.key : std::min(top.key, heap.lower_bound());
    meet.top[self].store(lb, std::memory_order_relaxed);
    // Balance: a side that is `ahead` of the other waits for it, so each side covers about half
    // the route whatever the scheduler does (else, with the other thread descheduled on a busy
    // machine, one side would redo most of a Dijkstra and the other's work would be wasted).
    while (lb > meet.top[1 - self].load(std::memory_order_relaxed) + ahead &&
           !meet.stop.load(std::memory_order_relaxed))
      std::this_thread::yield();
    if (meet.stop.load(std::memory_order_relaxed) ||
        lb + meet.top[1 - self].load(std::memory_order_relaxed) >= meet.mu.load(std::memory_order_relaxed))
      break;
    mine.set(v, -dv);  // settled
    std::atomic_thread_fence(std::memory_order_seq_cst);  // the mark before the reads below
    if ((++stats.settled & 4095) == 0 && cancel && cancel->load(std::memory_order_relaxed)) {
      meet.stop.store(true);
      throw Cancelled();
    }
    const std::int64_t row = v / C, col = v - row * C;
    const bool near_other = meet.flag(1 - self, row, col).load(std::memory_order_relaxed) != 0;
    const bool interior = row >= h && row < R - h && col >= h && col < C - h;

    // w: the neighbour; c: the step's cost; o: its offset (forward: v -> w; backward: w -> v).
    auto relax = [&](std::int64_t w, double c, std::int64_t o) {
      const double nd = dv + c;
      if (near_other) {
        const double dw = std::fabs(other.get(w));
        if (dw < inf) meet.offer(nd + dw, Backward ? w : v, Backward ? v : w, c, int(o));
      }
      const double old = mine.get(w);
      if (nd < old) {  // false for settled pixels: their label is negative
        if (old == inf) meet.flag_around(self, g, h, w);
        mine.set(w, nd, int(o));
        heap.push({nd, std::uint32_t(w)});
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
      continue;
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
      auto at = [&](int di, int dj) {
        return (r0 + di) * C + (g.wrap ? wrap_col(c0 + dj) : c0 + dj);
      };
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
  }
  // Both ways out end both sides: a stop (the rule, or the other side's) or an exhausted queue
  // (every pixel this side can reach is settled; every meeting has been offered).
  meet.stop.store(true);
  stats.heap_peak = heap.peak();
  stats.state_bytes = heap.capacity_bytes();
  return stats;
}

// Least-cost route from start to target by bidirectional Dijkstra on two threads, for static
// models only (the caller checks).
template <class Model>
RouteResult route_bidirectional(PreparedGrid& pg, const Model& model, std::int64_t start,
                                std::int64_t target, const std::atomic<bool>* cancel = nullptr) {
  pg.check(start);
  pg.check(target);
  if (start == target || pg.clearance()[start] == 0 || pg.clearance()[target] == 0)
    return pg.route(model, start, target, 0.0, cancel);
  const Grid& g = pg.grid();
  const std::vector<Offset>& st = pg.stencil();
  const StepBounds b = model.bounds(pg.passability());
  const double rmin = b.per_length ? pg.shortest_step() : 1.0;
  const double rmax = b.per_length ? pg.longest_step() : 1.0;
  const double width = 0.999999 * b.min_rate * rmin;
  const double span = 1.000001 * b.max_rate * rmax + 1e-300;
  const bool buckets = width > 0 && span < inf && BucketQueue::buckets_needed(width, span) < 65536;
  const double ahead = 8 * span;  // how far (in cost) one side may run ahead of the other

  LazyLabels fw(g.size()), bw(g.size());
  fw.set(start, 0.0);
  bw.set(target, 0.0);
  // Both origins' labels and flags are set before the threads start, so either side that
  // reaches the other's origin sees it.
  detail::Meeting meet(g.rows, g.cols);
  const int h = detail::half_width(st);
  meet.flag_around(0, g, h, start);
  meet.flag_around(1, g, h, target);

  SearchStats sides[2];
  std::exception_ptr errors[2];
  auto side = [&](auto backward) {
    constexpr bool B = decltype(backward)::value;
    LazyLabels& mine = B ? bw : fw;
    const LazyLabels& theirs = B ? fw : bw;
    const std::int64_t origin = B ? target : start;
    try {
      sides[B] = buckets
          ? bidirectional_side<B>(pg, model, origin, mine, theirs, BucketQueue(width, span), ahead, meet, cancel)
          : bidirectional_side<B>(pg, model, origin, mine, theirs, RadixHeap{}, ahead, meet, cancel);
    } catch (...) {
      errors[B] = std::current_exception();
      meet.stop.store(true);
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
                          bw.resident_bytes() + pg.clearance_bytes() + meet.bytes();
  out.stats.min_cost = b.min_rate;
  if (meet.from < 0) return out;  // no route: cost stays inf

  // Forward labels: the start to `from`; then the crossing step; then the backward side's
  // predecessor steps (each the offset of the forward step out of its pixel) to the target.
  auto move = [&](std::int64_t v, int o, int sign) {
    std::int64_t r = v / g.cols + sign * st[std::size_t(o)].di;
    std::int64_t c = v % g.cols + sign * st[std::size_t(o)].dj;
    if (g.wrap) c = (c + g.cols) % g.cols;
    return r * g.cols + c;
  };
  for (std::int64_t v = meet.from;; v = move(v, out.offsets.back(), -1)) {
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
  out.cost = std::fabs(fw.get(meet.from)) + meet.step_cost + std::fabs(bw.get(meet.to));
  out.offsets.push_back(meet.step_offset);
  for (std::int64_t v = meet.to;; ) {
    out.path.push_back(v);
    out.cumulative.push_back(out.cost - std::fabs(bw.get(v)));
    if (v == target) break;
    const int o = bw.pred(v);
    if (o < 0 || out.path.size() > std::size_t(g.size()))
      throw std::logic_error("broken backward predecessor chain");
    out.offsets.push_back(o);
    v = move(v, o, +1);
  }
  out.cumulative.back() = out.cost;
  return out;
}

}  // namespace seaway
