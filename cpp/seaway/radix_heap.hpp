// RadixHeap: a priority queue for monotone keys (Dijkstra, and A* with a consistent bound),
// with lazy deletion (heap.hpp): amortised O(1) push, cheap pops; non-negative doubles order
// like their bit patterns.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "heap.hpp"
#include "compat.hpp"

namespace seaway {

class RadixHeap {
 public:
  bool empty() const { return size_ == 0; }
  std::size_t peak() const { return peak_; }
  std::size_t capacity_bytes() const {
    std::size_t b = 0;
    for (const auto& v : buckets_) b += v.capacity() * sizeof(HeapEntry);
    return b;
  }
  // No key left in the heap is below this (bidirectional search's stopping rule).
  double lower_bound() const { return last_key_; }
  bool takes_now(double) const { return true; }
  void restart() { last_ = 0, last_key_ = 0; }  // empty: keys start again from 0
  template <class F>
  void for_each(F&& f) const {  // every entry, in no order
    for (const auto& b : buckets_)
      for (const HeapEntry& e : b) f(e);
  }

  void push(HeapEntry e) {
    // A consistent A* bound keeps keys monotone up to rounding; never go below the last pop.
    if (e.key < last_key_) e.key = last_key_;
    buckets_[bucket(bits(e.key))].push_back(e);
    if (++size_ > peak_) peak_ = size_;
  }

  HeapEntry pop() {
    if (buckets_[0].empty()) {
      std::size_t i = 1;
      while (buckets_[i].empty()) ++i;
      std::vector<HeapEntry>& from = buckets_[i];
      auto least = std::min_element(from.begin(), from.end(),
                                    [](const HeapEntry& a, const HeapEntry& b) { return a.key < b.key; });
      last_key_ = least->key;
      last_ = bits(last_key_);
      for (const HeapEntry& e : from) buckets_[bucket(bits(e.key))].push_back(e);
      from.clear();
    }
    const HeapEntry top = buckets_[0].back();
    buckets_[0].pop_back();
    --size_;
    return top;
  }

 private:
  static std::uint64_t bits(double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  }
  std::size_t bucket(std::uint64_t k) const {
    return k == last_ ? 0 : std::size_t(64 - compat::clz64(k ^ last_));
  }

  std::array<std::vector<HeapEntry>, 65> buckets_;
  std::uint64_t last_ = 0;
  double last_key_ = 0;
  std::size_t size_ = 0, peak_ = 0;
};

}  // namespace seaway
