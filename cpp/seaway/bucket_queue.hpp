// Bucket queues for Dijkstra (and exact A* with a scaled bound) when every step costs at least
// `width` > 0: pixels whose keys share a bucket [k*width, (k+1)*width) cannot improve each
// other, so a bucket may be emptied in any order and the labels stay exact (Dial's algorithm on
// real keys). BucketQueue keeps each bucket in a vector; ChunkedBucketQueue in pooled chunks
// (for rings of many sparsely filled buckets). Both pop a bucket last in, first out.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "heap.hpp"
#include "compat.hpp"

namespace seaway {

// How many buckets a queue for these step costs needs (width: at most the cheapest step;
// span: at least the costliest step).
inline double buckets_needed(double width, double span) { return span / width + 2; }

namespace detail {

// The key arithmetic both bucket queues share: a ring of a power of two of buckets (a mask,
// not a division, finds a key's bucket), the current and highest bucket in use, and the counts.
class BucketRing {
 public:
  BucketRing(double width, double span) : inv_width_(1.0 / width), mask_(ring_size(buckets_needed(width, span)) - 1) {}

  std::size_t buckets() const { return std::size_t(mask_ + 1); }
  bool empty() const { return size_ == 0; }
  std::size_t peak() const { return peak_; }
  // No key left in the queue is below this: the current bucket's floor, less one bucket for
  // the rounding of key * (1 / width) (bidirectional search's stopping rule).
  double lower_bound() const { return current_ > 0 ? double(current_ - 1) / inv_width_ : 0.0; }
  double floor(std::uint64_t k) const { return double(k) / inv_width_; }
  std::uint64_t current() const { return current_; }
  std::uint64_t highest() const { return highest_; }
  std::size_t slot(std::uint64_t k) const { return std::size_t(k & mask_); }
  // An empty ring starts again at the bucket of the next key added.
  void restart() { started_ = false; }
  bool started() const { return started_; }
  // A key from outside the search (rekeyed.hpp: re-keyed entries, least first) may join now:
  // it fits in the ring above the current bucket. One that does not lies above every entry a
  // step can push (the ring is sized for a step's largest rise), so none passes it while it waits.
  bool takes_now(double key) const { return !started_ || std::uint64_t(key * inv_width_) <= current_ + mask_; }

  // The bucket of a pushed key, counted in. Keys are never below the current bucket (a step
  // costs >= 0), and never a ring or more above it (a step costs < span); rounding is clamped
  // at both ends.
  SEAWAY_ALWAYS_INLINE std::uint64_t add(double key) {
    std::uint64_t k = std::uint64_t(key * inv_width_);
    if (!started_) {  // the first key (an A* bound) may lie far from zero: start the ring there
      current_ = highest_ = k;
      started_ = true;
    }
    if (k < current_) k = current_;
    if (k > current_ + mask_) k = current_ + mask_;
    if (k > highest_) highest_ = k;
    if (++size_ > peak_) peak_ = size_;
    return k;
  }
  // The first bucket from the current one on that `bucket_empty(slot)` says holds entries, made
  // current; one entry is counted out of it.
  template <class IsEmpty>
  std::uint64_t take(IsEmpty&& bucket_empty) {
    while (bucket_empty(slot(current_))) ++current_;
    --size_;
    return current_;
  }

 private:
  static std::uint64_t ring_size(double needed) {
    std::uint64_t n = 2;
    while (double(n) < needed) n *= 2;
    return n;
  }
  double inv_width_;
  std::uint64_t mask_;
  std::uint64_t current_ = 0, highest_ = 0;  // the lowest and highest bucket that may hold entries
  bool started_ = false;
  std::size_t size_ = 0, peak_ = 0;
};

}  // namespace detail

// Overflow = false: every step costs less than `span` (the ring takes every key). Overflow =
// true, for steps of no finite upper cost (a ship that waits for the ice to open): keys more
// than the ring's window above the current bucket wait in an overflow heap, and join the ring
// once the scan reaches their bucket, so keys still leave in the ring's order whatever the
// span; the span only decides how many keys take the slower overflow path.
template <bool Overflow>
class BasicBucketQueue {
 public:
  // width: at most the cheapest step; span: at least the costliest step (Overflow: the
  // costliest the ring takes directly). A bucket holds only the pixel ids (4 bytes, not a
  // 16-byte entry): the order within a bucket does not matter, so pop() gives the bucket's
  // floor as the key.
  BasicBucketQueue(double width, double span)
      : keys_(width, span), ring_(keys_.buckets()), inv_width_(1.0 / width) {}

  bool empty() const {  // without Overflow exactly the ring's test (the search's loop asks it)
    if constexpr (Overflow) return keys_.empty() && over_.empty();
    return keys_.empty();
  }
  std::size_t peak() const { return keys_.peak() + over_.capacity(); }
  std::size_t capacity_bytes() const {
    std::size_t b = ring_.capacity() * sizeof(ring_[0]) + over_.capacity() * sizeof(HeapEntry);
    for (const auto& v : ring_) b += v.capacity() * sizeof(std::uint32_t);
    return b;
  }
  bool takes_now(double key) const { return keys_.takes_now(key); }
  void restart() { keys_.restart(); }  // empty: the ring starts again at the next key
  double lower_bound() const {
    if constexpr (Overflow)
      if (keys_.empty() && !over_.empty()) return over_.front().key;
    return keys_.lower_bound();
  }
  template <class F>
  void for_each(F&& f) const {  // every entry, in no order
    for (const HeapEntry& e : over_) f(e);
    if (keys_.empty()) return;
    for (std::uint64_t k = keys_.current(); k <= keys_.highest(); ++k)  // no entry lies outside these
      for (std::uint32_t id : ring_[keys_.slot(k)]) f(HeapEntry{keys_.floor(k), id});
  }

  SEAWAY_ALWAYS_INLINE void push(const HeapEntry& e) {
    if constexpr (Overflow) {
      // Beyond the window of the current bucket (the last one popped, even when the ring is
      // empty now): the ring would fold the key onto a lower bucket.
      if (keys_.started() && bucket(e.key) > keys_.current() + keys_.buckets() - 1) {
        over_.push_back(e);
        std::push_heap(over_.begin(), over_.end(), later);
        over_min_ = bucket(over_.front().key);
        return;
      }
    }
    ring_[keys_.slot(keys_.add(e.key))].push_back(e.id);
  }

  // The id pop() returns `ahead` pops from now (0: next) when it lies in the current bucket
  // (for a prefetch), else none.
  std::uint32_t peek(std::size_t ahead = 0) const {
    const std::vector<std::uint32_t>& b = ring_[keys_.slot(keys_.current())];
    return b.size() > ahead ? b[b.size() - 1 - ahead] : 0xffffffffu;
  }

  HeapEntry pop() {
    if constexpr (Overflow) {
      if (keys_.empty()) {  // only overflow keys are left: the ring starts again at the least
        keys_.restart();
        drain(over_min_);
      }
    }
    const std::uint64_t k = keys_.take([&](std::size_t b) {
      if constexpr (Overflow) drain(keys_.current());  // before the scan passes their bucket
      return ring_[b].empty();
    });
    std::vector<std::uint32_t>& b = ring_[keys_.slot(k)];
    const std::uint32_t id = b.back();
    b.pop_back();
    return {keys_.floor(k), id};
  }

 private:
  static bool later(const HeapEntry& a, const HeapEntry& b) { return a.key > b.key; }
  std::uint64_t bucket(double key) const { return std::uint64_t(key * inv_width_); }
  // The overflow keys of bucket `upto` or below into the ring (their buckets lie in its window).
  void drain(std::uint64_t upto) {
    while (over_min_ <= upto) {
      std::pop_heap(over_.begin(), over_.end(), later);
      const HeapEntry e = over_.back();
      over_.pop_back();
      over_min_ = over_.empty() ? none : bucket(over_.front().key);
      ring_[keys_.slot(keys_.add(e.key))].push_back(e.id);
    }
  }
  static constexpr std::uint64_t none = ~std::uint64_t(0);

  detail::BucketRing keys_;
  std::vector<std::vector<std::uint32_t>> ring_;
  double inv_width_;
  std::vector<HeapEntry> over_;  // Overflow: a min-heap on key (std heap ordered by `later`)
  std::uint64_t over_min_ = none;  // the bucket of its least key; none when empty
};

using BucketQueue = BasicBucketQueue<false>;
using OverflowBucketQueue = BasicBucketQueue<true>;

}  // namespace seaway
