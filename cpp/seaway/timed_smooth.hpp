// Smoothing a time route (seaway.smoothtime documents it, register_smooth.cpp binds it): string pulling on the
// clock. From each kept vertex, left at the time the new route leaves it, the route is replaced
// by one straight leg (TimedLegs, timed_legs.hpp) to the farthest vertex ahead that the leg
// reaches no later than the route did and without crossing a pixel closed then. Vertices the
// route must keep (its ends, its waits, via points) are never passed by a leg.
//
// Never later: every kept vertex is reached no later than by the route, and the ship leaves it
// at once, or, at a vertex where the route waited, when the route left it. Should no leg from
// an early arrival reach its end in time (the model is not FIFO there: ice that clears at a
// chart's time, weather that speeds the ship up), the ship waits until the route left that
// vertex and tries again; failing that it sails the route's own next step, at the route's own
// times. So by induction the new route reaches every kept vertex, and its end, no later.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "leg_path.hpp"

namespace seaway {

struct TimedSmoothed {
  std::vector<std::int64_t> kept;  // the route's vertices kept, in order, both ends included
  std::vector<double> depart_h;    // each leg leaves its first vertex (after any wait there)
  std::vector<double> arrive_h;    // and reaches its last
  int waits_added = 0;             // waits the new route adds (see above)
};

// v: the route's vertices; arrive_h[i] / leave_h[i]: when the route reached and left vertex i
// (leave_h >= arrive_h: a wait); fixed[i]: a vertex to keep (the last one is); candidates:
// ascending vertex indices tried first as leg ends (the course changes and every fixed vertex);
// the legs' ends in between are found by bisection, as the static smoothing's (smooth.hpp).
template <class Legs>
TimedSmoothed smooth_timed(const Legs& legs, const std::vector<Point>& v, const std::vector<double>& arrive_h,
                           const std::vector<double>& leave_h, const std::vector<char>& fixed,
                           const std::vector<std::int64_t>& candidates) {
  const std::int64_t n = std::int64_t(v.size());
  TimedSmoothed out;
  out.kept.push_back(0);
  if (n < 2) return out;
  // The farthest vertex k in (i, stop] that the leg from i left at `depart` reaches by
  // arrive_h[k], and its arrival; -1 if none.
  auto pull = [&](std::int64_t i, double depart, std::int64_t stop, double* arrival) {
    double a = 0;
    auto fits = [&](std::int64_t k) {
      a = legs.arrive(v[std::size_t(i)], v[std::size_t(k)], depart);
      return a <= arrive_h[std::size_t(k)];
    };
    std::int64_t best = -1, fail = -1;
    for (auto it = std::upper_bound(candidates.begin(), candidates.end(), i);
         it != candidates.end() && *it <= stop; ++it) {
      if (!fits(*it)) {
        fail = *it;
        break;
      }
      best = *it;
      *arrival = a;
    }
    if (fail >= 0) {  // the farthest vertex before the first that fails
      std::int64_t lo = best < 0 ? i : best, hi = fail;
      while (hi - lo > 1) {
        const std::int64_t mid = lo + (hi - lo) / 2;
        if (fits(mid)) {
          lo = mid;
          *arrival = a;
        } else {
          hi = mid;
        }
      }
      best = lo > i ? lo : -1;
    }
    return best;
  };
  double at = arrive_h[0];
  for (std::int64_t i = 0; i < n - 1;) {
    std::int64_t stop = i + 1;
    while (!fixed[std::size_t(stop)]) ++stop;  // the last vertex is fixed
    const bool waited = leave_h[std::size_t(i)] > arrive_h[std::size_t(i)];
    double depart = waited ? leave_h[std::size_t(i)] : at, arrival = 0;
    std::int64_t k = pull(i, depart, stop, &arrival);
    if (k < 0 && depart < leave_h[std::size_t(i)]) {  // wait for the route's own departure
      depart = leave_h[std::size_t(i)];
      k = pull(i, depart, stop, &arrival);
    }
    if (k < 0) {  // the route's own step at its own times
      depart = leave_h[std::size_t(i)];
      k = i + 1;
      arrival = arrive_h[std::size_t(k)];
    }
    if (!waited && depart > at) ++out.waits_added;
    out.kept.push_back(k);
    out.depart_h.push_back(depart);
    out.arrive_h.push_back(arrival);
    at = arrival;
    i = k;
  }
  return out;
}

}  // namespace seaway
