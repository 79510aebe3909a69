// The second thread of the two-thread searches and of the two-thread clearance pass, started on
// another core than the caller's.
#pragma once

#include <thread>
#include <utility>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

namespace seaway {

// Runs fn on a new thread that starts on another core than the calling thread's, where the
// process may use one. Linux queued a new thread on its creator's core, and a creator busy with
// the other half of the work kept it waiting there: on the 2-core benchmark machine 2.0 ms
// median from creation to the thread's first instruction while the creator computed, 0.14 ms
// when the thread may not use the creator's core (benchmarks/README.md). Once running, the
// thread takes back the caller's whole set of cores (if it ran before the caller restricted it,
// it keeps to the other cores: where it should be). Elsewhere, or on one core: a plain thread.
template <class Fn>
std::thread thread_on_other_core(Fn&& fn) {
#if defined(__linux__)
  cpu_set_t allowed;
  const int here = sched_getcpu();
  if (here >= 0 && pthread_getaffinity_np(pthread_self(), sizeof allowed, &allowed) == 0) {
    cpu_set_t elsewhere = allowed;
    CPU_CLR(here, &elsewhere);
    if (CPU_COUNT(&elsewhere) > 0) {
      std::thread t([fn = std::forward<Fn>(fn), allowed]() mutable {
        pthread_setaffinity_np(pthread_self(), sizeof allowed, &allowed);
        fn();
      });
      pthread_setaffinity_np(t.native_handle(), sizeof elsewhere, &elsewhere);
      return t;
    }
  }
#endif
  return std::thread(std::forward<Fn>(fn));
}

}  // namespace seaway
