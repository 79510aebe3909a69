// A 4-ary min-heap of pixel ids keyed by double, with decrease-key through a position array
// that the caller owns (one uint32 per pixel), so the search state stays flat and reusable.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

namespace seaway {

class IndexedHeap {
 public:
  static constexpr std::uint32_t absent = std::numeric_limits<std::uint32_t>::max();

  explicit IndexedHeap(std::uint32_t* pos) : pos_(pos) {}

  bool empty() const { return items_.empty(); }
  std::size_t peak() const { return peak_; }
  std::size_t capacity_bytes() const { return items_.capacity() * sizeof(Item); }

  // Insert `id`, or lower its key if it is already queued with a larger one.
  void push_or_decrease(std::uint32_t id, double key) {
    std::uint32_t at = pos_[id];
    if (at == absent) {
      at = static_cast<std::uint32_t>(items_.size());
      items_.push_back({key, id});
      if (items_.size() > peak_) peak_ = items_.size();
    } else {
      if (!(key < items_[at].key)) return;
      items_[at].key = key;
    }
    sift_up(at);
  }

  // Remove and return the id with the smallest key.
  std::uint32_t pop(double& key) {
    const Item top = items_.front();
    pos_[top.id] = absent;
    const Item last = items_.back();
    items_.pop_back();
    if (!items_.empty()) {
      items_[0] = last;
      pos_[last.id] = 0;
      sift_down(0);
    }
    key = top.key;
    return top.id;
  }

  void clear() {
    for (const Item& it : items_) pos_[it.id] = absent;
    items_.clear();
  }

 private:
  struct Item {
    double key;
    std::uint32_t id;
  };

  void sift_up(std::uint32_t at) {
    const Item it = items_[at];
    while (at > 0) {
      const std::uint32_t parent = (at - 1) / 4;
      if (!(it.key < items_[parent].key)) break;
      items_[at] = items_[parent];
      pos_[items_[at].id] = at;
      at = parent;
    }
    items_[at] = it;
    pos_[it.id] = at;
  }

  void sift_down(std::uint32_t at) {
    const Item it = items_[at];
    const std::size_t n = items_.size();
    for (;;) {
      const std::size_t first = std::size_t(at) * 4 + 1;
      if (first >= n) break;
      std::size_t best = first;
      const std::size_t last = std::min(first + 4, n);
      for (std::size_t c = first + 1; c < last; ++c)
        if (items_[c].key < items_[best].key) best = c;
      if (!(items_[best].key < it.key)) break;
      items_[at] = items_[best];
      pos_[items_[at].id] = at;
      at = static_cast<std::uint32_t>(best);
    }
    items_[at] = it;
    pos_[it.id] = at;
  }

  std::vector<Item> items_;
  std::uint32_t* pos_;
  std::size_t peak_ = 0;
};

}  // namespace seaway
