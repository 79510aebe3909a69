// QuaternaryHeap: a 4-ary heap with lazy deletion (heap.hpp) for keys that are not monotone
// (weighted A*).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "heap.hpp"

namespace seaway {

class QuaternaryHeap {
 public:
  bool empty() const { return items_.empty(); }
  std::size_t peak() const { return peak_; }
  std::size_t capacity_bytes() const { return items_.capacity() * sizeof(HeapEntry); }

  void push(const HeapEntry& e) {
    std::size_t at = items_.size();
    items_.push_back(e);
    peak_ = std::max(peak_, items_.size());
    while (at > 0) {
      const std::size_t parent = (at - 1) / 4;
      if (!(e.key < items_[parent].key)) break;
      items_[at] = items_[parent];
      at = parent;
    }
    items_[at] = e;
  }

  HeapEntry pop() {
    const HeapEntry top = items_.front();
    const HeapEntry last = items_.back();
    items_.pop_back();
    const std::size_t n = items_.size();
    if (n == 0) return top;
    std::size_t at = 0;
    for (;;) {
      const std::size_t first = at * 4 + 1;
      if (first >= n) break;
      std::size_t best = first;
      for (std::size_t c = first + 1; c < std::min(first + 4, n); ++c)
        if (items_[c].key < items_[best].key) best = c;
      if (!(items_[best].key < last.key)) break;
      items_[at] = items_[best];
      at = best;
    }
    items_[at] = last;
    return top;
  }

 private:
  std::vector<HeapEntry> items_;
  std::size_t peak_ = 0;
};

}  // namespace seaway
