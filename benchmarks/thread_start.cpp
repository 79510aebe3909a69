// How long a new thread waits for its first instruction while its creator computes: a plain
// std::thread against seaway::thread_on_other_core (cpp/seaway/threads.hpp), 50 of each,
// alternated. Build and run from the repository's root:
//   c++ -O2 -std=c++17 -pthread -Icpp benchmarks/thread_start.cpp -o /tmp/thread_start && /tmp/thread_start
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>
#include <vector>

#include "seaway/threads.hpp"

using clk = std::chrono::steady_clock;

// Starts a thread, computes for 2 ms (as a search's first side does), returns the wait in us.
template <class Start>
double wait_us(Start&& start) {
  const clk::time_point t0 = clk::now();
  clk::time_point first{};
  std::thread t = start([&] { first = clk::now(); });
  volatile long spin = 0;
  while (clk::now() < t0 + std::chrono::milliseconds(2)) spin = spin + 1;
  t.join();
  return std::chrono::duration<double, std::micro>(first - t0).count();
}

int main() {
  std::vector<double> plain, other;
  for (int i = 0; i < 50; ++i) {
    plain.push_back(wait_us([](auto f) { return std::thread(f); }));
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    other.push_back(wait_us([](auto f) { return seaway::thread_on_other_core(f); }));
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  for (auto* v : {&plain, &other}) std::sort(v->begin(), v->end());
  std::printf("first instruction after (us): std::thread median %.0f (min %.0f, max %.0f); "
              "thread_on_other_core median %.0f (min %.0f, max %.0f)\n",
              plain[25], plain[0], plain[49], other[25], other[0], other[49]);
}
