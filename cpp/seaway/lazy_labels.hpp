// Search labels (cost and predecessor step per pixel) in anonymous memory that the kernel
// fills with zero pages on first write: a search that reaches part of the chart holds only the
// pages it wrote (4 KiB: 512 costs). Costs are stored as bits(cost) ^ bits(inf), so a zero page
// reads as "not reached" (inf); a settled pixel has its cost's sign bit set, as in Workspace.
// Predecessor steps are stored + 1 (0: none). Accesses are relaxed atomics, so another thread
// may read the labels while this one writes them (bidirectional.hpp); on x86-64 they are plain
// moves. Transparent huge pages are declined: one touched pixel would map 2 MiB. Pages are
// assumed 4 KiB (x86-64, aarch64 default) for the count of written pages.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <vector>

#include "geometry.hpp"
#include "compat.hpp"
#include "pages.hpp"

namespace seaway {

namespace detail {
// Zero-filled memory from calloc (the turn search's states): pages are mapped when first written.
struct FreeDeleter {
  void operator()(void* p) const { std::free(p); }
};
template <class T>
std::unique_ptr<T[], FreeDeleter> zeroed(std::size_t n) {
  void* p = std::calloc(n, sizeof(T));
  if (!p) throw std::bad_alloc();
  return std::unique_ptr<T[], FreeDeleter>(static_cast<T*>(p));
}
// Costs are stored as bits(d) ^ bits(inf), so zero-filled memory reads as inf.
inline std::uint64_t bits_of(double d) {
  std::uint64_t b;
  std::memcpy(&b, &d, 8);
  return b;
}
inline double from_bits(std::uint64_t b) {
  double d;
  std::memcpy(&d, &b, 8);
  return d;
}
}  // namespace detail

class LazyLabels {
 public:
  explicit LazyLabels(std::int64_t n)
      : n_(std::size_t(n)), cost_(map(n_ * 8)), pred_(map(n_)), written_((n_ >> 9) + 1) {}
  ~LazyLabels() {
    pages::put(cost_, n_ * 8);
    pages::put(pred_, n_);
  }
  LazyLabels(const LazyLabels&) = delete;
  LazyLabels& operator=(const LazyLabels&) = delete;

  std::int64_t size() const { return std::int64_t(n_); }
  // get() and set() are forced inline: GCC had left them out of line in the two-sided search's
  // settle loop (a call per neighbour); inlined, that search ran 16 % faster on 10^8 pixels.
  SEAWAY_ALWAYS_INLINE double get(std::int64_t v) const {
    // An unwritten page is not read: reading it would map the kernel's zero page, and the
    // owner's first write would then replace that mapping, a fault that flushes the TLB of
    // every core running the process (an interrupt to the other side's thread).
    if (compat::load_relaxed(&written_[std::size_t(v) >> 9]) != this_search) return inf;
    const std::uint64_t b = compat::load_relaxed(static_cast<const std::uint64_t*>(cost_) + v);
    return decode(b);
  }
  SEAWAY_ALWAYS_INLINE void set(std::int64_t v, double d) {  // by one thread only: the owner of these labels
    compat::store_relaxed(static_cast<std::uint64_t*>(cost_) + v, encode(d));
    compat::store_relaxed(&written_[std::size_t(v) >> 9], this_search);  // v's 4 KiB page
  }
  SEAWAY_ALWAYS_INLINE void set(std::int64_t v, double d, int pred) {
    set(v, d);
    static_cast<std::uint8_t*>(pred_)[v] = std::uint8_t(pred + 1);  // read after the threads join
  }
  int pred(std::int64_t v) const { return int(static_cast<const std::uint8_t*>(pred_)[v]) - 1; }

  // Back to "nothing reached" for the next search on the same chart, keeping the pages (a pool
  // of PreparedChart): the cost pages this search wrote are zeroed, so the next search writes
  // them without page faults. Predecessors are not: a search reads only those it wrote.
  void clear() {
    for (std::size_t p = 0; p < written_.size(); ++p)
      if (written_[p] == this_search) {
        const std::size_t first = p << 9, count = std::min<std::size_t>(512, n_ - first);
        std::memset(static_cast<std::uint64_t*>(cost_) + first, 0, count * 8);
        written_[p] = zeroed_earlier;
      }
  }
  // Give every page back (zero pages again on the next write; pages.hpp: MADV_DONTNEED on Linux,
  // a new zeroed block in the portable build).
  void release() {
    cost_ = pages::give_back(cost_, n_ * 8);
    pred_ = pages::give_back(pred_, n_);
    std::fill(written_.begin(), written_.end(), std::uint8_t(0));
  }

  // Bytes of the pages written, by this search or earlier ones on these labels (4 KiB: 512
  // costs, 4096 predecessors). Tested against the peak resident memory of a fresh process
  // (benchmarks/test_exact.py).
  std::size_t resident_bytes() const {
    std::size_t cost_pages = 0, pred_pages = 0;
    for (std::size_t p = 0; p < written_.size(); ++p) {
      cost_pages += written_[p] != 0;
      if (p % 8 == 0) {
        bool any = false;
        for (std::size_t q = p; q < std::min(p + 8, written_.size()); ++q) any = any || written_[q] != 0;
        pred_pages += any;
      }
    }
    return (cost_pages + pred_pages) * 4096 + written_.size();
  }

 private:
  static constexpr std::uint64_t inf_bits = 0x7ff0000000000000ull;
  // A page's state in written_: never written (0), written by this search, or written by an
  // earlier one and zeroed since (resident, reads as "not reached").
  static constexpr std::uint8_t this_search = 1, zeroed_earlier = 2;
  static std::uint64_t encode(double d) {
    std::uint64_t b;
    std::memcpy(&b, &d, 8);
    return b ^ inf_bits;
  }
  static double decode(std::uint64_t b) {
    b ^= inf_bits;
    double d;
    std::memcpy(&d, &b, 8);
    return d;
  }
  static void* map(std::size_t bytes) { return pages::take(bytes); }
  std::size_t n_;
  void* cost_;
  void* pred_;
  std::vector<std::uint8_t> written_;  // per 512 pixels (one 4 KiB cost page): its state
};

// A bound (or potential) computed once per pixel: a search asks for it at every push (about
// three per pixel on the benchmark chart), and a landmark bound reads a table row each time.
// Kept in labels the chart lends (LabelLease, cache = true), as the double it is, so nothing
// changes in the search but the time: cleared here of the last query's values, their pages stay
// mapped, so a repeated query writes them without page faults (fresh pages per query cost about
// 30 us of kernel time even on a 2-pixel voyage of a 10^5-pixel chart, and a fault per 4 KiB
// page touched). An inf bound reads as "not stored" and is computed again. Without a store
// (null: a side that never asks) nothing is kept.
template <class Bound>
class CachedBound {
 public:
  static constexpr bool cached = true;  // (bidirectional_side: a table-read potential)
  CachedBound(const Bound& b, LazyLabels* store) : b_(b), store_(store) {
    if (store_) store_->clear();
  }
  std::size_t resident_bytes() const { return store_ ? store_->resident_bytes() : 0; }
  bool active() const { return b_.active(); }
  double operator()(std::int64_t v) const {
    if (!store_) return b_(v);
    double h = store_->get(v);
    if (h != inf) return h;
    h = b_(v);
    store_->set(v, h);
    return h;
  }

 private:
  const Bound& b_;
  LazyLabels* store_;
};

}  // namespace seaway
