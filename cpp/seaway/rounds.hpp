// What the two sides of the bidirectional search (bidirectional_side.hpp) exchange at their
// barriers, and what each side keeps of a round for the meeting check.
#pragma once

#include <atomic>
#include <cstdint>
#include <thread>
#include <type_traits>
#include <vector>

#include "constants.hpp"

namespace seaway {

namespace detail {

// What the two sides exchange at the barriers (written before one, read after it).
struct Rounds {
  std::atomic<int> arrived[2] = {0, 0};
  std::atomic<bool> abort{false};  // a side failed (cancel, error): the other leaves too
  // [round parity][side]: a side writes round k + 1's while the other may still read round k's.
  double top[2][2] = {};
  double mu_part[2][2] = {};
  std::int64_t meet_part[2][2] = {};
  bool empty[2][2] = {};
  // With a potential the keys are reduced: stop once top_f + top_b >= mu + p(t) - p(s) (plus a
  // relative 1e-12 against the potentials' rounding).
  double mu_offset = 0, mu_slack = 0;

  // Wait until the other side has passed as many barriers as this one; false on abort.
  bool barrier(int self, int& passed) {
    arrived[self].store(++passed, std::memory_order_release);
    while (arrived[1 - self].load(std::memory_order_acquire) < passed)
      if (abort.load(std::memory_order_relaxed)) return false;
      else std::this_thread::yield();
    return !abort.load(std::memory_order_relaxed);
  }
};

}  // namespace detail

struct Meeting {
  std::int64_t pixel = -1;  // labelled by both sides on an optimal route; -1: no route
  double cost = inf;
};

// Whether a side's potential is a CachedBound (lazy_labels.hpp): one that reads tables.
template <class P, class = void>
constexpr bool is_cached = false;
template <class P>
constexpr bool is_cached<P, std::void_t<decltype(P::cached)>> = P::cached;

// What one side did in a round: the pixels it settled (the round's count) and those it labelled
// or relabelled. A pair of labels is checked at the barrier after the later of the two labels'
// last change, by the side that made it: a side checks the pixels it relabelled in the round,
// or, once it relabelled more of them than its queue holds, the round's settled pixels and its
// whole queue (a pixel relabelled in the round is in one of them; the list then stops growing).
// The list is kept only for potentials that read tables (`track`: is_cached, the landmarks),
// whose wide queues made the scan a few % of a query; on the others it cost more than it saved
// (benchmarks/README.md).
class RoundLog {
 public:
  explicit RoundLog(bool track) : scan_queue_(!track), track_(track) {}
  void start() {
    settled_.clear();
    relabelled_.clear();
    scan_queue_ = !track_;
  }
  void settled(std::int64_t v) { settled_.push_back(std::uint32_t(v)); }
  void pushed(std::int64_t w) {  // labelled or relabelled, and queued
    ++queued_;
    if (scan_queue_) return;
    relabelled_.push_back(std::uint32_t(w));
    if (relabelled_.size() > queued_ + settled_.size()) scan_queue_ = true, relabelled_.clear();
  }
  void popped() { --queued_; }
  std::size_t settled_count() const { return settled_.size(); }
  template <class Check, class Queue, class Later>
  void for_each_changed(Check&& check, const Queue& heap, const Later& later) {
    if (!scan_queue_) {
      for (std::uint32_t v : relabelled_) check(v);
      return;
    }
    for (std::uint32_t v : settled_) check(v);
    heap.for_each([&](const auto& e) { check(e.id); });
    later.for_each([&](const auto& e) { check(e.id); });
  }
  std::size_t capacity_bytes() const {  // the rounds' peak: clear() keeps a vector's capacity
    return (settled_.capacity() + relabelled_.capacity()) * sizeof(std::uint32_t);
  }

 private:
  std::vector<std::uint32_t> settled_, relabelled_;
  bool scan_queue_, track_;
  std::size_t queued_ = 0;  // entries in the queue (pushes less pops)
};

}  // namespace seaway
