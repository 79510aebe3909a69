// Bucket queues for Dijkstra (and exact A* with a scaled bound) when every step costs at least
// `width` > 0: pixels whose keys share a bucket [k*width, (k+1)*width) cannot improve each
// other, so a bucket may be emptied in any order and the labels stay exact (Dial's algorithm on
// real keys). BucketQueue keeps each bucket in a vector; ChunkedBucketQueue in pooled chunks
// (for rings of many sparsely filled buckets). Both pop a bucket last in, first out.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "heap.hpp"

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

  // The bucket of a pushed key, counted in. Keys are never below the current bucket (a step
  // costs >= 0), and never a ring or more above it (a step costs < span); rounding is clamped
  // at both ends.
  __attribute__((always_inline)) std::uint64_t add(double key) {
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

class BucketQueue {
 public:
  // width: at most the cheapest step; span: at least the costliest step. A bucket holds only
  // the pixel ids (4 bytes, not a 16-byte entry): the order within a bucket does not matter,
  // so pop() gives the bucket's floor as the key.
  BucketQueue(double width, double span) : keys_(width, span), ring_(keys_.buckets()) {}

  bool empty() const { return keys_.empty(); }
  std::size_t peak() const { return keys_.peak(); }
  std::size_t capacity_bytes() const {
    std::size_t b = ring_.capacity() * sizeof(ring_[0]);
    for (const auto& v : ring_) b += v.capacity() * sizeof(std::uint32_t);
    return b;
  }
  double lower_bound() const { return keys_.lower_bound(); }
  template <class F>
  void for_each(F&& f) const {  // every entry, in no order
    if (keys_.empty()) return;
    for (std::uint64_t k = keys_.current(); k <= keys_.highest(); ++k)  // no entry lies outside these
      for (std::uint32_t id : ring_[keys_.slot(k)]) f(HeapEntry{keys_.floor(k), id});
  }

  __attribute__((always_inline)) void push(const HeapEntry& e) {
    ring_[keys_.slot(keys_.add(e.key))].push_back(e.id);
  }

  // The id pop() returns `ahead` pops from now (0: next) when it lies in the current bucket
  // (for a prefetch), else none.
  std::uint32_t peek(std::size_t ahead = 0) const {
    const std::vector<std::uint32_t>& b = ring_[keys_.slot(keys_.current())];
    return b.size() > ahead ? b[b.size() - 1 - ahead] : 0xffffffffu;
  }

  HeapEntry pop() {
    const std::uint64_t k = keys_.take([&](std::size_t b) { return ring_[b].empty(); });
    std::vector<std::uint32_t>& b = ring_[keys_.slot(k)];
    const std::uint32_t id = b.back();
    b.pop_back();
    return {keys_.floor(k), id};
  }

 private:
  detail::BucketRing keys_;
  std::vector<std::vector<std::uint32_t>> ring_;
};

class ChunkedBucketQueue {
 public:
  // As BucketQueue, but each bucket is a stack of 64-byte chunks of 15 ids taken from one pool
  // and given back when emptied: no allocation per bucket, and the chunks in use stay few and
  // warm in cache. For rings of many sparsely filled buckets (landmark A*, whose bucket width
  // is a small share of the cheapest step): 7 % faster there; on Dijkstra's few full buckets
  // the vectors of BucketQueue are 10 % faster.
  ChunkedBucketQueue(double width, double span)
      : keys_(width, span), head_(keys_.buckets(), none), fill_(keys_.buckets(), 0) {}

  bool empty() const { return keys_.empty(); }
  std::size_t peak() const { return keys_.peak(); }
  std::size_t capacity_bytes() const {
    return chunks_.capacity() * sizeof(Chunk) + head_.capacity() * sizeof(std::uint32_t) + fill_.capacity();
  }
  double lower_bound() const { return keys_.lower_bound(); }
  template <class F>
  void for_each(F&& f) const {  // every entry, in no order
    if (keys_.empty()) return;
    for (std::uint64_t k = keys_.current(); k <= keys_.highest(); ++k) {  // no entry lies outside these
      const std::size_t b = keys_.slot(k);
      std::size_t n = fill_[b];
      for (std::uint32_t c = head_[b]; c != none; c = chunks_[c].next, n = per_chunk)
        for (std::size_t i = 0; i < n; ++i) f(HeapEntry{keys_.floor(k), chunks_[c].ids[i]});
    }
  }

  __attribute__((always_inline)) void push(const HeapEntry& e) {
    const std::size_t b = keys_.slot(keys_.add(e.key));
    if (head_[b] == none || fill_[b] == per_chunk) {  // a new chunk on top of the bucket's stack
      const std::uint32_t c = take_chunk();
      chunks_[c].next = head_[b];
      head_[b] = c;
      fill_[b] = 0;
    }
    chunks_[head_[b]].ids[fill_[b]++] = e.id;
  }

  HeapEntry pop() {
    const std::uint64_t k = keys_.take([&](std::size_t b) { return head_[b] == none; });
    const std::size_t b = keys_.slot(k);
    const std::uint32_t c = head_[b];
    const std::uint32_t id = chunks_[c].ids[--fill_[b]];
    if (fill_[b] == 0) {  // the chunk is empty: back to the pool; the one below it is full
      head_[b] = chunks_[c].next;
      fill_[b] = head_[b] == none ? 0 : per_chunk;
      chunks_[c].next = free_;
      free_ = c;
    }
    return {keys_.floor(k), id};
  }

 private:
  static constexpr std::uint32_t none = 0xffffffffu;
  static constexpr std::uint8_t per_chunk = 15;
  struct Chunk {
    std::uint32_t next;  // the chunk below in the bucket's stack (full), or in the free list
    std::uint32_t ids[per_chunk];
  };
  std::uint32_t take_chunk() {
    if (free_ != none) {
      const std::uint32_t c = free_;
      free_ = chunks_[c].next;
      return c;
    }
    chunks_.emplace_back();
    return std::uint32_t(chunks_.size() - 1);
  }
  detail::BucketRing keys_;
  std::vector<std::uint32_t> head_;  // per bucket: its top chunk, or none
  std::vector<std::uint8_t> fill_;   // per bucket: ids in its top chunk
  std::vector<Chunk> chunks_;
  std::uint32_t free_ = none;
};

}  // namespace seaway
