// What a running search shares with whoever started it (e.g. Python's waiting main thread):
// the progress it publishes and the flag that stops it, polled in one place for every search.
#pragma once

#include <atomic>
#include <cstdint>
#include <stdexcept>

#include "constants.hpp"
#include "compat.hpp"

namespace seaway {

// Every poll_every settled pixels a search publishes how many it has settled and stops
// (throws Cancelled) if `cancel` was set. Without a control the search polls nothing.
struct SearchControl {
  std::atomic<bool> cancel{false};
  mutable std::atomic<std::int64_t> settled{0};
};

// Thrown out of a search whose cancel flag was set (e.g. Ctrl-C in Python).
struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("search cancelled") {}
};

// Counts one settled pixel (or state) and polls the control every poll_every of them;
// `report`: publish the count (false for the second side of a two-thread search).
SEAWAY_ALWAYS_INLINE inline void count_settled(std::int64_t& settled,
                                                         const SearchControl* control,
                                                         bool report = true) {
  if ((++settled & (poll_every - 1)) != 0 || !control) return;
  if (report) control->settled.store(settled, std::memory_order_relaxed);
  if (control->cancel.load(std::memory_order_relaxed)) throw Cancelled();
}

}  // namespace seaway
