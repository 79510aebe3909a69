// Edge-cost models: functors the search is templated on. Each is called for a step from pixel
// v to pixel w along stencil offset o of length r, with the cost accumulated so far (g, for
// models that depend on time) and `cell(m)`, the flat index of the m-th pixel in the offset's
// length shares. Every model returns a cost >= 0, or +inf for a step the ship may not take,
// and gives bounds() on its costs, which pick the search's queue and A*'s bound.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "capabilities.hpp"
#include "passability.hpp"
#include "stencil.hpp"

namespace seaway {

// Every step costs between min_rate and max_rate times its length (per_length) or, if not
// per_length, between min_rate and max_rate whatever its length. max_rate may be inf.
struct StepBounds {
  double min_rate, max_rate;
  bool per_length;
  // With max_rate inf (a step may wait without limit): the most a step costs when it does not
  // wait, so the search can keep its buckets and set the rare waits aside (queue_choice.hpp).
  double usual_max_rate = inf;
};

// The static models cost u per unit length, u from the chart's passable pixels.
inline StepBounds raster_bounds(const Passability& p, bool per_length = true) {
  return {p.passable ? p.min_cost : 0.0, p.max_cost, per_length};
}

// A rule on the two ends of a step: d = pair(u_i, u_j) * r, Rule::pair per unit length (also
// along legs: legs.hpp).
template <class T, class Rule>
struct PairCost {
  static constexpr Capabilities caps = raster_rule;
  static double pair(double a, double b) { return Rule::pair(a, b); }
  const T* u;
  StepBounds bounds(const Passability& p) const { return raster_bounds(p); }
  template <class Cell>
  double operator()(std::int64_t v, std::int64_t w, int, double r, double, Cell&&) const {
    return pair(double(u[v]), double(u[w])) * r;
  }
};

// Grinyak et al. 2022: d = max(u_i, u_j) * r.
struct MaxRule {
  static double pair(double a, double b) { return std::max(a, b); }
};
template <class T>
using MaxCost = PairCost<T, MaxRule>;

// Grinyak et al. 2018: d = (u_i + u_j) / 2 * r.
struct MeanRule {
  static double pair(double a, double b) { return 0.5 * (a + b); }
};
template <class T>
using MeanCost = PairCost<T, MeanRule>;

// The exact line integral of the piecewise-constant field along the straight step.
template <class T>
struct IntegralCost {
  static constexpr Capabilities caps = raster_rule;
  // Legs are priced by the same rule: the sum of length x cost over the pixels crossed.
  static constexpr bool line_integral = true;
  const T* u;
  const std::vector<Offset>* stencil;
  StepBounds bounds(const Passability& p) const { return raster_bounds(p); }
  template <class Cell>
  double operator()(std::int64_t, std::int64_t, int o, double r, double, Cell&& cell) const {
    const std::vector<CellShare>& s = (*stencil)[std::size_t(o)].shares;
    double sum = 0;
    for (std::size_t m = 0; m < s.size(); ++m) sum += s[m].fraction * double(u[cell(m)]);
    return sum * r;
  }
};

// The step's length alone: the shortest route through the passable pixels (the raster decides
// only where the ship may go). The smallest complete model, the worked example of
// docs/dev/cost-models.md: the search, the bidirectional and landmark searches, the turn
// penalty and smoothing all take it because of its caps.
template <class T>
struct LengthCost {
  static constexpr Capabilities caps = raster_rule;
  static double pair(double, double) { return 1.0; }
  const T* u;
  StepBounds bounds(const Passability& p) const { return {p.passable ? 1.0 : 0.0, 1.0, true}; }
  template <class Cell>
  double operator()(std::int64_t, std::int64_t, int, double r, double, Cell&&) const {
    return r;
  }
};

// scikit-image's MCP (non-geometric): the cost of the pixel entered, whatever the step.
template <class T>
struct EnteredPixelCost {
  // Static, but a step costs the pixel it enters: not symmetric, not per unit length.
  static constexpr Capabilities caps{true, false, false, false, false};
  const T* u;
  StepBounds bounds(const Passability& p) const { return raster_bounds(p, false); }
  template <class Cell>
  double operator()(std::int64_t, std::int64_t w, int, double, double, Cell&&) const {
    return double(u[w]);
  }
};

}  // namespace seaway
