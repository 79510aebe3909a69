// A search's queue re-keyed under another consistent potential, labels kept: the forward side
// of the bidirectional search (bidirectional_side.hpp) searches alone as one-way A*, then joins
// the two-sided search under the average potential. A consistent potential then orders the
// remaining pixels as a search by it from the start would: every unsettled pixel on an optimal
// route lies behind a queued pixel, labelled exactly, whose key is no greater.
// The re-keyed frontier's keys spread wider than a bucket queue's window (a ring a few steps'
// cost wide), so they wait here, least last, and each joins the queue once it fits in the
// window (takes_now): before the queue pops any key above it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "constants.hpp"
#include "heap.hpp"

namespace seaway {

class Rekeyed {
 public:
  // Empties `heap` into this store under key(pixel, label) for the pixels not yet settled
  // (label >= 0), once each, and restarts the queue.
  template <class Queue, class Labels, class Key>
  void take(Queue& heap, const Labels& labels, Key&& key) {
    while (!heap.empty()) {
      const std::uint32_t id = heap.pop().id;
      const double d = labels.get(id);
      if (!std::signbit(d)) later_.push_back({key(id, d), id});
    }
    std::sort(later_.begin(), later_.end(), [](const HeapEntry& a, const HeapEntry& b) {
      return a.key > b.key || (a.key == b.key && a.id > b.id);  // least last; the same on every run
    });
    auto same = [](const HeapEntry& a, const HeapEntry& b) { return a.id == b.id; };
    later_.erase(std::unique(later_.begin(), later_.end(), same), later_.end());
    heap.restart();
  }
  // Moves into `heap` every entry it takes now (called before each pop).
  template <class Queue>
  void feed(Queue& heap) {
    while (!later_.empty() && (heap.empty() || heap.takes_now(later_.back().key))) {
      if (heap.empty()) heap.restart();  // an empty ring starts again at the least key
      heap.push(later_.back());
      later_.pop_back();
    }
  }
  bool empty() const { return later_.empty(); }
  double least() const { return later_.empty() ? inf : later_.back().key; }
  template <class F>
  void for_each(F&& f) const {
    for (const HeapEntry& e : later_) f(e);
  }
  std::size_t capacity_bytes() const { return later_.capacity() * sizeof(HeapEntry); }

 private:
  std::vector<HeapEntry> later_;
};

}  // namespace seaway
