// Exact bidirectional Dijkstra on two threads: a forward search from the start and a backward
// search from the target, each with its own labels and queue, run at once in rounds.
// The backward search walks the same directed steps from their far end and charges each the
// model's cost of the forward step (same function, same arguments, so the same double): it
// needs no symmetry of the model, but the model must be static (a step's cost may not depend
// on the arrival time; the caller checks).
//
// Rounds: in each round each side settles the same count of pixels (so the two threads get
// equal work whatever the scheduler does), then the two meet at a barrier. There, labels are
// still: each side checks the pixels it relabelled in the round (a list of them, or those it
// settled and its whole queue: rounds.hpp, RoundLog) against the other's labels, and mu = min
// over pixels labelled by both of d_f + d_b (a real route's cost) is updated.
// The forward side first searches alone (bidirectional_side.hpp: solo_pixels): a voyage it
// finishes alone is a one-way search's, on one thread; its pixels then join its first round.
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
// for the next one (PreparedChart::labels()), which then writes them without page faults.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <functional>
#include <optional>
#include <thread>
#include <type_traits>
#include <vector>

#include "bidirectional_side.hpp"
#include "potentials.hpp"
#include "prepared_chart.hpp"
#include "threads.hpp"

namespace seaway {

// Least-cost route from start to target by bidirectional search on two threads, for static
// models only (the caller checks). `reduced_floor`: every step's reduced cost is at least this
// share of the cheapest step (1 without a potential); `extra_rate`: the most a step's key may
// rise above its cost, per unit length (0 without a potential).
template <class Model, class Potential = NoPotential>
RouteResult route_bidirectional(PreparedChart& pg, const Model& model, std::int64_t start,
                                std::int64_t target, const SearchControl* cancel = nullptr,
                                const Potential& pot = {}, double reduced_floor = 1.0,
                                double extra_rate = 0.0) {
  pg.check(start);
  pg.check(target);
  if (start == target || pg.clearance()[start] == 0 || pg.clearance()[target] == 0)
    return pg.route(model, start, target, 0.0, cancel);
  const Geometry& g = pg.geometry();
  const StepBounds b = model.bounds(pg.passability());
  QueueChoice q = choose_queue(b, pg.shortest_step(), pg.longest_step(), reduced_floor, extra_rate);
  // Landmark potentials need buckets a small share of a step wide: many, sparsely filled. Pooled
  // chunks, as one-way A* on charts of up to chunked_astar_pixels: a vector per bucket costs
  // allocations in every bucket a query fills (the DMI 2013 chart, a ring of <= 4096 buckets:
  // 0.80 x the time, the maze 0.92 x).
  if (Potential::sparse_keys && q.kind == QueueKind::buckets &&
      (q.buckets() > chunked_above || g.size() <= chunked_astar_pixels))
    q.kind = QueueKind::chunked_buckets;
  const double shift_f = pot.active() ? pot(start) : 0.0, shift_b = pot.active() ? pot(target) : 0.0;

  LabelLease fw_lease(pg.labels()), bw_lease(pg.labels());  // pooled: no page faults when reused
  LazyLabels &fw = *fw_lease, &bw = *bw_lease;
  detail::Rounds rounds;
  if (pot.active()) {
    rounds.mu_offset = shift_b - shift_f;
    rounds.mu_slack = 1e-12;
  }
  Meeting meet;
  SearchStats sides[2];
  std::exception_ptr errors[2];
  std::thread helper;  // the backward side, started by the forward side after its solo phase
  std::function<void()> start_backward;
  std::shared_ptr<const void> keep;
  // Only the landmark search reads a chart's skip table (a chart with landmarks has one).
  const StepEnumerator& steps = Potential::prunes ? pg.steps_for(model, keep) : pg.steps();
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
      const OneWay<Potential> one_way{pot};  // the forward side's solo phase
      auto run = [&](const auto& p, const auto& solo) {
        return with_queue<false, Potential::sparse_keys>(q, [&](auto heap) {
          return bidirectional_side<B, Potential::prunes>(steps, model, origin, target, mine, theirs,
                                                          std::move(heap), p, solo, shift, rounds,
                                                          meet, cancel, start_backward);
        });
      };
      // A potential is asked for at every push: each side keeps the values it computed.
      if constexpr (!Potential::worth_caching) {
        sides[B] = run(pot, one_way);
      } else {
        LabelLease cache(pg.labels(), true);
        std::optional<LabelLease> solo_cache;  // the backward side has no solo phase
        if (!B) solo_cache.emplace(pg.labels(), true);
        const CachedBound<Potential> cached(pot, &*cache);
        const CachedBound<OneWay<Potential>> solo(one_way, B ? nullptr : &**solo_cache);
        sides[B] = run(cached, solo);
        sides[B].state_bytes += cached.resident_bytes() + solo.resident_bytes();
      }
    } catch (...) {
      errors[B] = std::current_exception();
      rounds.abort.store(true);
    }
  };
  start_backward = [&] { helper = thread_on_other_core([&] { side(std::true_type{}); }); };
  side(std::false_type{});
  if (helper.joinable()) helper.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);

  RouteResult out;
  out.stats.settled = sides[0].settled + sides[1].settled;
  out.stats.heap_peak = sides[0].heap_peak + sides[1].heap_peak;
  out.stats.state_bytes = sides[0].state_bytes + sides[1].state_bytes + fw.resident_bytes() +
                          bw.resident_bytes() + pg.clearance_bytes() + (Potential::prunes ? pg.pruned_bytes() : 0);
  out.stats.min_cost = b.min_rate;
  if (meet.pixel < 0) return out;  // no route: cost stays inf

  // Forward labels from the start to the meeting pixel, then the backward side's predecessor
  // steps (each the offset of the forward step out of its pixel) to the target.
  const std::vector<Offset>& st = pg.stencil();
  out.path = trace_back(g, st, start, meet.pixel, [&](std::int64_t v) { return fw.pred(v); }, &out.offsets);
  for (std::int64_t p : out.path) out.cumulative.push_back(std::fabs(fw.get(p)));
  out.cost = meet.cost;
  for (std::int64_t v = meet.pixel; v != target;) {
    const int o = bw.pred(v);
    if (o < 0 || out.path.size() > std::size_t(g.size()))
      throw std::logic_error("broken predecessor chain");
    out.offsets.push_back(o);
    v = g.step(v, st[std::size_t(o)], +1);
    out.path.push_back(v);
    out.cumulative.push_back(out.cost - std::fabs(bw.get(v)));
  }
  out.cumulative.back() = out.cost;
  return out;
}

// Bidirectional A*: the average potential of the straight-line (great-circle) bounds to the
// target and from the start, times the chart's smallest cost per unit length, scaled by 0.95
// so that the bucket queue stays exact (as exact A* in PreparedChart::run). Models priced per length
// only (max, mean, integral); others run plain bidirectional Dijkstra.
template <class Model>
RouteResult route_bidirectional_astar(PreparedChart& pg, const Model& model, std::int64_t start,
                                      std::int64_t target, const SearchControl* cancel = nullptr) {
  pg.check(start);
  pg.check(target);
  const StepBounds b = model.bounds(pg.passability());
  if (!b.per_length || !(b.min_rate > 0)) return route_bidirectional(pg, model, start, target, cancel);
  constexpr double eps = astar_bucket_eps;
  const AveragePotential<DistanceBound> pot{DistanceBound(pg.geometry(), target, b.min_rate),
                                            DistanceBound(pg.geometry(), start, b.min_rate), 1 - eps};
  return route_bidirectional(pg, model, start, target, cancel, pot, eps, b.min_rate);
}
}  // namespace seaway
