// A chart prepared for many queries: the stencil, step lengths and land clearance are built
// once and shared (read-only) by every query; each query borrows a Workspace from a pool, so
// threads route on one chart at once and a repeated query allocates nothing large.
#pragma once

#include <algorithm>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "cost_models.hpp"
#include "heap.hpp"
#include "passability.hpp"
#include "search.hpp"

namespace seaway {

enum class EdgeCost { max, mean, integral, entered };

struct RouteResult {
  double cost = inf;                // inf when the target was not reached
  std::vector<std::int64_t> path;   // flat pixel indices, start first
  SearchStats stats;
};

class RouterBase {
 public:
  virtual ~RouterBase() = default;
  // Least-cost route; weight 0: Dijkstra, 1: A*, > 1: weighted A*.
  virtual RouteResult route(std::int64_t start, std::int64_t target, double weight) = 0;
  // Accumulated cost from start to every pixel (inf where unreachable) into out[size].
  virtual SearchStats field(std::int64_t start, double* out) = 0;
  virtual std::size_t shared_bytes() const = 0;
};

template <class T>
class Router : public RouterBase {
 public:
  Router(const Grid& g, const T* cost, const std::uint8_t* land, int k, Directions dirs,
         EdgeCost ec, LandRule rule)
      : g_(g), u_(cost), stencil_(make_stencil(k, dirs)), lengths_(g.step_lengths(stencil_)),
        ec_(ec), rule_(rule) {
    if (g.wrap && g.cols <= k - 1)
      throw std::invalid_argument("a wrapping grid needs more columns than the neighbourhood size");
    clearance_.resize(std::size_t(g.size()));
    std::vector<std::uint8_t> scratch(std::size_t(g.size()));
    pass_ = compute_clearance(g, cost, land, (k - 1) / 2 + 1, clearance_.data(), scratch.data());
  }

  RouteResult route(std::int64_t start, std::int64_t target, double weight) override {
    check(start);
    check(target);
    Lease ws(*this);
    RouteResult out;
    out.stats = run(start, target, weight, *ws);
    out.cost = ws->cost(target);
    if (out.cost < inf) out.path = trace_path(g_, stencil_, *ws, start, target);
    return out;
  }

  SearchStats field(std::int64_t start, double* out) override {
    check(start);
    Lease ws(*this);
    SearchStats stats = run(start, -1, 0.0, *ws);
    for (std::int64_t v = 0; v < g_.size(); ++v) out[v] = ws->cost(v);
    return stats;
  }

  std::size_t shared_bytes() const override {
    return clearance_.capacity() + lengths_.table.capacity() * sizeof(double);
  }

 private:
  // A workspace borrowed from the pool for one query, returned when the query ends.
  class Lease {
   public:
    explicit Lease(Router& r) : r_(r) {
      std::lock_guard<std::mutex> lock(r_.pool_mutex_);
      if (r_.pool_.empty()) {
        ws_ = std::make_unique<Workspace>();
      } else {
        ws_ = std::move(r_.pool_.back());
        r_.pool_.pop_back();
      }
    }
    ~Lease() {
      std::lock_guard<std::mutex> lock(r_.pool_mutex_);
      r_.pool_.push_back(std::move(ws_));
    }
    Workspace& operator*() { return *ws_; }
    Workspace* operator->() { return ws_.get(); }

   private:
    Router& r_;
    std::unique_ptr<Workspace> ws_;
  };

  void check(std::int64_t p) const {
    if (p < 0 || p >= g_.size()) throw std::out_of_range("pixel index outside the grid");
  }

  // Pick the queue: buckets when every step's (reduced) cost has a positive floor and the
  // range of step costs needs few buckets; a radix heap otherwise; a 4-ary heap for weighted
  // A*, whose keys are not monotone.
  SearchStats run(std::int64_t start, std::int64_t target, double weight, Workspace& ws) const {
    const double min_cost = pass_.passable ? pass_.min_cost : 0.0;
    const bool per_pixel = ec_ == EdgeCost::entered;
    const auto [rmin, rmax] = std::minmax_element(lengths_.table.begin(), lengths_.table.end());
    const bool astar = weight == 1 && target >= 0;
    // Exact A* in buckets: with the bound scaled by (1 - eps), every step's reduced cost
    // c + h(w) - h(v) is at least eps x the cheapest step, which then serves as bucket width.
    const double eps = astar ? astar_bucket_eps : 1.0;
    const double width = 0.999999 * eps * min_cost * (per_pixel ? 1.0 : *rmin);
    // The largest key increase of one step: its cost, plus for A* the bound's largest drop.
    const double span =
        1.000001 * (pass_.max_cost + (astar ? min_cost : 0.0)) * (per_pixel ? 1.0 : *rmax) + 1e-300;
    const bool buckets = weight <= 1 && width > 0 && BucketQueue::buckets_needed(width, span) < 65536;
    SearchSpec spec{&g_, &stencil_, rule_, target >= 0 ? weight : 0.0};
    if (buckets && astar) spec.heuristic_weight = 1 - eps;

    auto go = [&](const auto& model) {
      const std::uint8_t* clear = clearance_.data();
      if (weight > 1)
        return search(spec, model, lengths_, clear, min_cost, start, target, ws, QuaternaryHeap{});
      if (buckets)
        return search(spec, model, lengths_, clear, min_cost, start, target, ws, BucketQueue(width, span));
      return search(spec, model, lengths_, clear, min_cost, start, target, ws, RadixHeap{});
    };
    SearchStats stats;
    switch (ec_) {
      case EdgeCost::max: stats = go(MaxCost<T>{u_}); break;
      case EdgeCost::mean: stats = go(MeanCost<T>{u_}); break;
      case EdgeCost::integral: stats = go(IntegralCost<T>{u_, &stencil_}); break;
      case EdgeCost::entered: stats = go(EnteredPixelCost<T>{u_}); break;
    }
    stats.state_bytes += clearance_.capacity();
    return stats;
  }

  // Share of the A* bound given up so that A* can use the bucket queue; 0.05 settled the
  // fewest pixels per second on the benchmark charts (0.02 to 0.25 tried).
  static constexpr double astar_bucket_eps = 0.05;

  Grid g_;
  const T* u_;
  std::vector<Offset> stencil_;
  Grid::Lengths lengths_;
  EdgeCost ec_;
  LandRule rule_;
  std::vector<std::uint8_t> clearance_;
  Passability pass_;
  std::mutex pool_mutex_;
  std::vector<std::unique_ptr<Workspace>> pool_;
};

}  // namespace seaway
