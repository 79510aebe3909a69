// What a cost model can do, declared once per model functor (static constexpr Capabilities
// caps) and read by the bindings, which offer each search for exactly the models that have what
// it needs, and by Python (each bound model class's `capabilities`), where a test holds the
// seaway.models classes' flags to them.
#pragma once

namespace seaway {

struct Capabilities {
  // A cost read from the chart's own raster that does not depend on the time of arrival: the
  // backward half of the bidirectional search can price a step, and an overflowed cost is told
  // from no route.
  bool is_static = false;
  // A step costs the same both ways: the landmark bound holds.
  bool symmetric = false;
  // A cost per unit length that a turn penalty (in the same units) may be added to.
  bool turn_penalty = false;
  // The label is a clock: a step's cost depends on when it is started (FIFO).
  bool time_dependent = false;
  // Arbitrary straight legs are priced by the model's own rule: a static rule's cost
  // (legs.hpp), a time model's arrival on the clock (timed_legs.hpp); smoothing and the leg
  // tables of smoothed routes.
  bool smoothable = false;
};

// The static rules over the chart's cost raster (max, mean, integral).
inline constexpr Capabilities raster_rule{true, true, true, false, true};
// Hours on the clock: a step's cost depends on when it starts; legs are priced on the clock by
// the model's own rule (sail, move_hours, open: timed_legs.hpp).
inline constexpr Capabilities on_the_clock{false, false, false, true, true};
// A cost on one forecast frame: fixed in time, but not the chart's raster and not symmetric.
inline constexpr Capabilities on_one_frame{false, false, false, false, false};

}  // namespace seaway
