// A chart prepared for many queries (_core.PreparedChart, held by seaway.PreparedChart): the
// stencil, step lengths, land clearance and step enumerator are built once and shared (read-only)
// by every query; each query borrows a Workspace from a pool, so threads route on one chart at
// once and a repeated query allocates nothing large. Queries take an edge-cost model
// (cost_models.hpp, weather.hpp): one prepared chart serves every model.
#pragma once

#include <algorithm>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "collinear.hpp"
#include "cost_models.hpp"
#include "label_spares.hpp"
#include "passability.hpp"
#include "queue_choice.hpp"
#include "search.hpp"

namespace seaway {

class PreparedChart {
 public:
  // `cost` marks impassable pixels (NaN, inf, negative) and gives the static cost range.
  template <class T>
  PreparedChart(const Geometry& g, const T* cost, const std::uint8_t* land, int k, Directions dirs,
               LandRule rule)
      : g_(g), stencil_(make_stencil(k, dirs)), lengths_(g.step_lengths(stencil_)), rule_(rule),
        half_(seaway::half_width(stencil_)) {
    if (g.wrap && g.cols <= k - 1)
      throw std::invalid_argument("a wrapping grid needs more columns than the neighbourhood size");
    clearance_.resize(std::size_t(g.size()));
    std::vector<std::uint8_t> scratch(std::size_t(g.size()));
    pass_ = compute_clearance(g, cost, land, (k - 1) / 2 + 1, clearance_.data(), scratch.data());
    pass_.least_share = least_cost_share(cost, clearance_.data(), g.size(), pass_.min_cost);
    const auto [rmin, rmax] = std::minmax_element(lengths_.table.begin(), lengths_.table.end());
    rmin_ = *rmin;
    rmax_ = *rmax;
    steps_.emplace(g_, stencil_, lengths_, clearance_.data(), rule_);
  }
  PreparedChart(const PreparedChart&) = delete;  // the enumerator points into it
  PreparedChart& operator=(const PreparedChart&) = delete;

  const Geometry& geometry() const { return g_; }
  std::size_t workspaces_made() const {  // search workspaces allocated (one per concurrent query)
    std::lock_guard<std::mutex> lock(pool_mutex_);
    return workspaces_made_;
  }
  const std::vector<Offset>& stencil() const { return stencil_; }
  const Geometry::Lengths& lengths() const { return lengths_; }
  int half_width() const { return half_; }  // largest |di| or |dj| of the stencil
  // Index of the stencil offset (di, dj), or -1.
  int offset_index(int di, int dj) const { return offset_of(stencil_, di, dj); }

  // Least-cost route under `model`; weight 0: Dijkstra, 1: A*, > 1: weighted A*.
  template <class Model>
  RouteResult route(const Model& model, std::int64_t start, std::int64_t target, double weight,
                    const SearchControl* control = nullptr) {
    check(start);
    check(target);
    Lease ws(*this);
    return result(*ws, start, target, run(model, start, target, weight, *ws, control));
  }

  // The route to `target` a search from `start` left in `ws`.
  RouteResult result(const Workspace& ws, std::int64_t start, std::int64_t target,
                     const SearchStats& stats) const {
    return route_from(*steps_, ws, start, target, stats);
  }

  // Accumulated cost from start to every pixel (inf where unreachable) into out[size].
  template <class Model>
  SearchStats field(const Model& model, std::int64_t start, double* out,
                    const SearchControl* control = nullptr) {
    check(start);
    Lease ws(*this);
    SearchStats stats = run(model, start, -1, 0.0, *ws, control);
    for (std::int64_t v = 0; v < g_.size(); ++v) out[v] = ws->cost(v);
    return stats;
  }

  // Dijkstra from `from` into `ws` until `stop` is settled (stop < 0: every reachable pixel),
  // for a search that reads the costs it leaves (the turn search's bound, turns.hpp).
  template <class Model>
  SearchStats search_into(const Model& model, std::int64_t from, std::int64_t stop, Workspace& ws,
                          const SearchControl* control = nullptr) const {
    check(from);
    return run(model, from, stop, 0.0, ws, control);
  }

  // What the other searches (bidirectional, landmarks, turns, least danger) need: every step,
  // or for the landmark searches under a static model those left after prune_collinear(model)
  // (collinear.hpp); the other searches gain nothing from the table (benchmarks/README.md).
  const StepEnumerator& steps() const { return *steps_; }
  template <class Model>
  const StepEnumerator& steps_for(const Model& model, std::shared_ptr<const void>& keep) const {
    return pruned_.get(*steps_, model, keep);
  }
  template <class Model>
  void prune_collinear(const Model& model) { pruned_.build(*steps_, model); }
  template <class Model>
  void forget_pruned(const Model& model) { pruned_.forget(model); }
  std::size_t pruned_bytes() const { return pruned_.bytes(); }
  template <class Model>
  const std::vector<std::uint16_t>* skip_table(const Model& model) const { return pruned_.table(model); }
  const std::uint8_t* clearance() const { return clearance_.data(); }
  std::size_t clearance_bytes() const { return clearance_.capacity(); }
  const Passability& passability() const { return pass_; }
  LandRule land_rule() const { return rule_; }
  double shortest_step() const { return rmin_; }  // step lengths on this grid
  double longest_step() const { return rmax_; }
  void check(std::int64_t p) const {
    if (p < 0 || p >= g_.size()) throw std::out_of_range("pixel index outside the grid");
  }

  // The labels the two-sided searches and the bound caches borrow (label_spares.hpp).
  LabelPool& labels() { return labels_; }

  // A workspace borrowed from the pool for one query, returned when the query ends.
  class Lease {
   public:
    explicit Lease(PreparedChart& p) : p_(p) {
      std::lock_guard<std::mutex> lock(p_.pool_mutex_);
      if (p_.pool_.empty()) {
        ws_ = std::make_unique<Workspace>();
        ++p_.workspaces_made_;
      } else {
        ws_ = std::move(p_.pool_.back());
        p_.pool_.pop_back();
      }
    }
    ~Lease() {
      std::lock_guard<std::mutex> lock(p_.pool_mutex_);
      p_.pool_.push_back(std::move(ws_));
    }
    Workspace& operator*() { return *ws_; }
    Workspace* operator->() { return ws_.get(); }

   private:
    PreparedChart& p_;
    std::unique_ptr<Workspace> ws_;
  };

 private:
  // Weight 0: Dijkstra, 1: A* (exact: buckets, the bound scaled by 1 - astar_bucket_eps), > 1: weighted A*.
  template <class Model>
  SearchStats run(const Model& model, std::int64_t start, std::int64_t target, double weight,
                  Workspace& ws, const SearchControl* control) const {
    const StepBounds b = model.bounds(pass_);
    const bool astar = weight == 1 && target >= 0 && b.per_length;
    const double eps = astar ? astar_bucket_eps : 1.0;
    // The largest key increase of one step: its cost, plus for A* the bound's largest drop.
    QueueChoice q = choose_queue(b, rmin_, rmax_, eps, astar ? b.min_rate : 0.0);
    if (weight > 1) q.kind = QueueKind::quaternary;
    double hw = target >= 0 && b.per_length ? weight : 0.0;
    if ((q.kind == QueueKind::buckets || q.kind == QueueKind::overflow_buckets) && astar) hw = 1 - eps;
    if (q.kind == QueueKind::buckets && astar && g_.size() <= chunked_astar_pixels) q.kind = QueueKind::chunked_buckets;
    SearchStats stats = with_queue<true, true, Model::caps.time_dependent>(q, [&](auto heap) {
      return search(*steps_, model, start, target, ws, std::move(heap), hw * b.min_rate, control);
    });
    stats.min_cost = b.min_rate;
    stats.state_bytes += clearance_.capacity();
    return stats;
  }

  Geometry g_;
  std::vector<Offset> stencil_;
  Geometry::Lengths lengths_;
  LandRule rule_;
  std::vector<std::uint8_t> clearance_;
  Passability pass_;
  double rmin_ = 0, rmax_ = 0;
  int half_ = 0;
  std::optional<StepEnumerator> steps_;  // built once the clearance is
  PrunedSteps pruned_;
  mutable std::mutex pool_mutex_;
  std::vector<std::unique_ptr<Workspace>> pool_;
  LabelPool labels_{g_.size()};  // after g_
  std::size_t workspaces_made_ = 0;
};

}  // namespace seaway
