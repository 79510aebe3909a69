// Doubled steps a pair of unit steps replaces at no more cost. In the 5 x 5 stencil the steps
// (±2, 0), (0, ±2) and (±2, ±2) run straight through the middle pixel m of a unit step: where
// the two unit steps v -> m -> w cost no more than the step v -> w, that step can never make a
// route cheaper, and a search may leave it out (every least cost stays the same; a route that
// took it takes the two unit steps instead, the same track). Under the papers' max rule that
// holds wherever m costs no more than the dearer end, so on most of a chart a search makes 16
// steps per pixel instead of 24. Only for static models over a raster (PrunableModel: a step's
// cost depends on the step alone); the turn search keeps every step (its state is the step).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <type_traits>
#include <typeindex>
#include <utility>
#include <vector>

#include "capabilities.hpp"
#include "steps.hpp"

namespace seaway {

// A relative slack for the rounding of the two sums (the search adds the two unit steps to a
// cost, not to each other): a route may come out at most this share dearer than the least.
inline constexpr double collinear_slack = 1e-12;

// For the stencil `st`: the indices of the 8 doubled unit offsets (bit b of a skip byte) and of
// their halves, or empty when the stencil has none or they lie beyond bit 63 of a step mask.
struct DoubledSteps {
  std::vector<int> doubled, half;
  explicit DoubledSteps(const std::vector<Offset>& st) {
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj) {
        if (di == 0 && dj == 0) continue;
        const int d = offset_of(st, 2 * di, 2 * dj), h = offset_of(st, di, dj);
        if (d < 0 || h < 0 || d > 63) {
          doubled.clear();
          half.clear();
          return;
        }
        doubled.push_back(d);
        half.push_back(h);
      }
  }
  bool any() const { return !doubled.empty(); }
};

// Per pixel v a 16-bit word: bit b (b < 8) set when the doubled step of DoubledSteps b from v
// may be left out, bit 8 + b when the one ending at v may (the backward search's view of the
// same step). Costs every step of every pixel once (three rows of step costs kept at a time).
template <class Model>
std::vector<std::uint16_t> collinear_skips(const StepEnumerator& steps, const Model& model,
                                           const DoubledSteps& ds) {
  const Geometry& g = steps.geometry();
  const std::vector<Offset>& st = steps.stencil();
  const std::int64_t R = g.rows, C = g.cols, K = std::int64_t(st.size());
  std::vector<std::uint16_t> skip(std::size_t(g.size()), 0);
  if (!ds.any()) return skip;
  constexpr double none = std::numeric_limits<double>::infinity();
  // Step costs of rows r - 1, r, r + 1 (ring of three), K per pixel, inf where no step.
  std::vector<double> ring(std::size_t(3 * C * K));
  auto fill = [&](std::int64_t r) {
    double* out = ring.data() + (r % 3) * C * K;
    std::fill(out, out + C * K, none);
    for (std::int64_t c = 0; c < C; ++c) {
      const std::int64_t v = r * C + c;
      if (steps.clearance()[v] == 0) continue;
      double* cv = out + c * K;
      steps.each(v, [&](std::int64_t, std::int64_t o, std::int64_t from, std::int64_t to, double len, auto&& cell) {
        cv[o] = model(from, to, int(o), len, 0.0, cell);
      });
    }
  };
  auto cost = [&](std::int64_t r, std::int64_t c, int o) { return ring[std::size_t(((r % 3) * C + c) * K + o)]; };
  fill(0);
  if (R > 1) fill(1);
  for (std::int64_t r = 0; r < R; ++r) {
    if (r + 1 < R && r > 0) fill(r + 1);
    for (std::int64_t c = 0; c < C; ++c) {
      for (std::size_t b = 0; b < ds.doubled.size(); ++b) {
        const int d = ds.doubled[b], h = ds.half[b];
        const double direct = cost(r, c, d);
        if (!(direct < none)) continue;  // no such step
        const std::int64_t rm = r + st[std::size_t(h)].di;
        std::int64_t cm = c + st[std::size_t(h)].dj;
        if (g.wrap) cm = g.wrap_col(cm);
        const double two = cost(r, c, h) + cost(rm, cm, h);
        if (!(two <= direct * (1 + collinear_slack))) continue;
        skip[std::size_t(r * C + c)] |= std::uint16_t(1u << b);
        std::int64_t cw = c + st[std::size_t(d)].dj;
        if (g.wrap) cw = g.wrap_col(cw);
        skip[std::size_t((r + st[std::size_t(d)].di) * C + cw)] |= std::uint16_t(1u << (8 + b));
      }
    }
  }
  return skip;
}

// A static model over a raster `u` (cost_models.hpp): the models a skip table serves.
template <class Model, class = void>
struct PrunableModel : std::false_type {};
template <class Model>
struct PrunableModel<Model, std::void_t<decltype(std::declval<const Model&>().u)>>
    : std::bool_constant<Model::caps.is_static && !Model::caps.time_dependent> {};

// A chart's pruned enumerators, one per model (the functor's type and its raster), published
// atomically so that threads querying meanwhile see the old list or the new, both exact. The
// caller keeps each model's raster alive while its table is listed (forget() drops it).
class PrunedSteps {
 public:
  template <class Model>
  void build(const StepEnumerator& all, const Model& model) {
    static_assert(PrunableModel<Model>::value, "only a static raster model's steps can be left out");
    auto p = std::make_shared<Table>();
    const Key k = key(model);
    p->key = k;
    const DoubledSteps ds(all.stencil());
    p->skip = collinear_skips(all, model, ds);
    p->steps.emplace(all.with_skips(p->skip.data(), ds.doubled));
    publish(k, std::move(p));
  }
  // Drops the table of `model` (before its raster goes: a new raster could take the address).
  template <class Model>
  void forget(const Model& model) {
    if constexpr (PrunableModel<Model>::value) publish(key(model), nullptr);
  }
  // The steps for a query under `model`: the pruned ones if built for it, else `all`. `keep`
  // holds them for the query's length.
  template <class Model>
  const StepEnumerator& get(const StepEnumerator& all, const Model& model, std::shared_ptr<const void>& keep) const {
    if constexpr (PrunableModel<Model>::value) {
      if (auto p = find(key(model))) {
        const StepEnumerator& e = *p->steps;
        keep = std::move(p);
        return e;
      }
    }
    return all;
  }
  std::size_t bytes() const {
    std::size_t n = 0;
    if (const auto list = std::atomic_load(&list_))
      for (const auto& t : *list) n += t->skip.capacity() * sizeof(std::uint16_t);
    return n;
  }
  // The skip table (collinear_skips) of `model`, or null; valid until the next build or forget.
  template <class Model>
  const std::vector<std::uint16_t>* table(const Model& model) const {
    if constexpr (PrunableModel<Model>::value) {
      if (const auto p = find(key(model))) return &p->skip;
    }
    return nullptr;
  }

 private:
  using Key = std::pair<std::type_index, const void*>;
  template <class Model>
  static Key key(const Model& m) { return {std::type_index(typeid(Model)), static_cast<const void*>(m.u)}; }
  struct Table {
    Key key{std::type_index(typeid(void)), nullptr};
    std::vector<std::uint16_t> skip;
    std::optional<StepEnumerator> steps;  // reads skip
  };
  using List = std::vector<std::shared_ptr<const Table>>;
  std::shared_ptr<const Table> find(const Key& k) const {
    if (const auto list = std::atomic_load(&list_))
      for (const auto& t : *list)
        if (t->key == k) return t;
    return nullptr;
  }
  // The list with `k`'s table replaced by `t` (dropped if null), swapped in unless another
  // thread published first (then again on its list).
  void publish(const Key& k, std::shared_ptr<const Table> t) {
    auto old = std::atomic_load(&list_);
    std::shared_ptr<const List> next;
    do {
      auto l = std::make_shared<List>();
      if (old)
        for (const auto& e : *old)
          if (e->key != k) l->push_back(e);
      if (t) l->push_back(t);
      next = std::move(l);
    } while (!std::atomic_compare_exchange_weak(&list_, &old, next));
  }
  std::shared_ptr<const List> list_;
};

}  // namespace seaway
