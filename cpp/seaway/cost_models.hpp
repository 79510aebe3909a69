// Edge-cost models: functors the search is templated on. Each is called for a step from pixel
// v to pixel w along stencil offset o of length r, with the cost accumulated so far (g, for
// models that depend on time) and `cell(m)`, the flat index of the m-th pixel in the offset's
// length shares. Every model returns a cost >= 0, or +inf for a step the ship may not take,
// and gives bounds() on its costs, which pick the search's queue and A*'s bound.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "passability.hpp"
#include "stencil.hpp"

namespace seaway {

// Every step costs between min_rate and max_rate times its length (per_length) or, if not
// per_length, between min_rate and max_rate whatever its length. max_rate may be inf.
struct StepBounds {
  double min_rate, max_rate;
  bool per_length;
};

// The static models cost u per unit length, u from the chart's passable pixels.
inline StepBounds raster_bounds(const Passability& p, bool per_length = true) {
  return {p.passable ? p.min_cost : 0.0, p.max_cost, per_length};
}

// Grinyak et al. 2022: d = max(u_i, u_j) * r.
template <class T>
struct MaxCost {
  const T* u;
  StepBounds bounds(const Passability& p) const { return raster_bounds(p); }
  template <class Cell>
  double operator()(std::int64_t v, std::int64_t w, int, double r, double, Cell&&) const {
    return std::max(double(u[v]), double(u[w])) * r;
  }
};

// Grinyak et al. 2018: d = (u_i + u_j) / 2 * r.
template <class T>
struct MeanCost {
  const T* u;
  StepBounds bounds(const Passability& p) const { return raster_bounds(p); }
  template <class Cell>
  double operator()(std::int64_t v, std::int64_t w, int, double r, double, Cell&&) const {
    return 0.5 * (double(u[v]) + double(u[w])) * r;
  }
};

// The exact line integral of the piecewise-constant field along the straight step.
template <class T>
struct IntegralCost {
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

// scikit-image's MCP (non-geometric): the cost of the pixel entered, whatever the step.
template <class T>
struct EnteredPixelCost {
  const T* u;
  StepBounds bounds(const Passability& p) const { return raster_bounds(p, false); }
  template <class Cell>
  double operator()(std::int64_t, std::int64_t w, int, double, double, Cell&&) const {
    return double(u[w]);
  }
};

}  // namespace seaway
