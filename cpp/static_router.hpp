// The Python-facing router: a prepared chart plus its static cost model (shared by the
// binding files of each area).
#pragma once

#include <atomic>
#include <memory>

#include "seaway/cost_models.hpp"
#include "seaway/router.hpp"

namespace seaway {

enum class EdgeCost { max, mean, integral, entered };

// Set from Python (e.g. on Ctrl-C) to stop a running search (it throws Cancelled); it also
// reports the pixels settled so far (progress).
using CancelToken = SearchControl;
inline const SearchControl* flag_of(const CancelToken* t) { return t; }

// A prepared chart with its static cost model. The raster is read in place:
// seaway.PreparedChart keeps the arrays alive beside the router.
struct StaticRouter {
  std::unique_ptr<PreparedGrid> grid;
  const void* cost;
  bool single;  // float32 costs
  EdgeCost edge_cost;

  template <class F>
  auto with_model(F&& f) const {
    return single ? with<float>(f) : with<double>(f);
  }
  template <class T, class F>
  auto with(F& f) const {
    const T* u = static_cast<const T*>(cost);
    switch (edge_cost) {
      case EdgeCost::mean: return f(MeanCost<T>{u});
      case EdgeCost::integral: return f(IntegralCost<T>{u, &grid->stencil()});
      case EdgeCost::entered: return f(EnteredPixelCost<T>{u});
      default: return f(MaxCost<T>{u});
    }
  }
};

}  // namespace seaway
