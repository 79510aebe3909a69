// One Dijkstra search from a start to many targets (a batch of voyages from one port, one
// origin's row of an origin-destination matrix): it runs until every target is settled and
// traces each route from the labels it leaves. Each route is the one a Dijkstra search to
// that target alone finds, step for step: the searches pop the same pixels in the same order
// up to the target, and a settled pixel's label never changes again.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "prepared_chart.hpp"

namespace seaway {

// Settles pixels until the last of the targets is settled.
class TargetSet {
 public:
  explicit TargetSet(std::vector<std::int64_t> targets) : sorted_(std::move(targets)) {
    std::sort(sorted_.begin(), sorted_.end());
    sorted_.erase(std::unique(sorted_.begin(), sorted_.end()), sorted_.end());
    left_ = sorted_.size();
  }
  bool operator()(std::int64_t v) const {
    return std::binary_search(sorted_.begin(), sorted_.end(), v) && --left_ == 0;
  }

 private:
  std::vector<std::int64_t> sorted_;
  mutable std::size_t left_ = 0;
};

// The Dijkstra routes from `start` to each of `targets` (cost inf where unreachable), from one
// search; `each(i, route)` receives them in the targets' order.
template <class Model, class Each>
void routes_to(PreparedChart& chart, const Model& model, std::int64_t start,
               const std::vector<std::int64_t>& targets, const SearchControl* control, Each&& each) {
  chart.check(start);
  for (std::int64_t t : targets) chart.check(t);
  PreparedChart::Lease ws(chart);
  const StepBounds b = model.bounds(chart.passability());
  const QueueChoice q = choose_queue(b, chart.shortest_step(), chart.longest_step(), 1.0, 0.0);
  const DistanceBound none(chart.geometry(), 0, 0.0);
  const TargetSet stop(targets);
  SearchStats stats = with_queue<true, false, Model::caps.time_dependent>(q, [&](auto heap) {
    return search_with_bound(chart.steps(), model, start, -1, *ws, std::move(heap), none, control, stop);
  });
  stats.min_cost = b.min_rate;
  stats.state_bytes += chart.clearance_bytes();
  for (std::size_t i = 0; i < targets.size(); ++i) each(i, chart.result(*ws, start, targets[i], stats));
}

}  // namespace seaway
