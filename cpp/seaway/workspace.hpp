// The plain search's labels, kept by a thread across queries (a pool of PreparedChart).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "constants.hpp"

namespace seaway {

// 8 bytes of accumulated cost and 1 of predecessor step per pixel. The next query resets only
// the pixels this one reached, listed while they are few (up to 1/8 of the chart, half a byte
// per pixel); past that, the whole cost array is reset, which then costs no more than the
// query that touched them did. An expanded pixel has its cost's sign bit set: the relaxation
// test `new < dist` then fails for it without a separate flag.
struct Workspace {
  std::vector<double> dist;
  std::vector<std::uint8_t> pred;
  std::vector<std::uint32_t> touched;
  bool overflowed = false;

  void reset(std::int64_t n) {
    if (dist.size() != std::size_t(n)) {
      dist.assign(std::size_t(n), inf);
      pred.assign(std::size_t(n), no_pred);
      touched = {};
      touched.reserve(std::size_t(n / 8 + 1));
    } else if (overflowed) {
      std::fill(dist.begin(), dist.end(), inf);
    } else {
      for (std::uint32_t v : touched) dist[v] = inf;
    }
    touched.clear();
    overflowed = false;
  }
  void reached(std::int64_t v) {  // v's cost was inf until now
    if (touched.size() < touched.capacity()) touched.push_back(std::uint32_t(v));
    else overflowed = true;
  }
  double cost(std::int64_t v) const { return std::fabs(dist[std::size_t(v)]); }
  std::size_t bytes() const {
    return dist.capacity() * sizeof(double) + pred.capacity() + touched.capacity() * sizeof(std::uint32_t);
  }
};

}  // namespace seaway
