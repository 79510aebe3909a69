"""Any-angle smoothing of a raster route (Grinyak et al. 2022: "the route can be smoothed afterwards").

1. Line-of-sight shortcuts (string pulling): from each anchor vertex, the route is replaced by
   one straight leg (a great circle on geographic charts) to the farthest vertex ahead such that
   the leg touches no impassable pixel and costs no more than the part of the route it replaces.
2. Refinement (optional): each turning point in turn is moved off the pixel centres by a
   compass search (steps of 1 pixel halved down to 1/32) to lower the cost of its two legs,
   then shortcuts are taken again; sweeps repeat until the cost stops falling.

Both passes run in C++ (cpp/seaway/smooth.hpp). Legs are priced by seaway.chart.legs (the
engine's model extended to arbitrary legs: exact line integral for "integral"; the max/mean
rule applied to the chain of pixels a leg crosses). Every
accepted change lowers the cost or keeps it (to a relative 1e-12 for rounding), so the smoothed
route never costs more than the route it came from, under the model that route was found with.

A route on a clock (a time model) is smoothed by seaway.smoothtime instead: its legs sailed on
the clock under its own model, never later, its waits kept."""

from __future__ import annotations

import dataclasses

import numpy as np

from .result.route import ABOVE
from .result.stats import Smoothing
from .smoothtime import smooth_on_clock

RTOL = 1e-12  # the relative rounding slack of every acceptance test (cpp/seaway/smooth.hpp)


def smooth(route, *, refine: bool = True, max_sweeps: int = 10):
    """The route with its zig-zag removed: fewer, any-angle waypoints; never a higher cost.

    Returns a Route whose vertices (`points`, fractional row/col; `coords`) are the waypoints;
    `pixels` holds the pixel of each waypoint. `stats.smoothing` (seaway.result.stats.Smoothing)
    holds cost_before (the route's cost), course_changes_before / course_changes_after, sweeps
    and shortcut_legs.

    A route on a clock (a time model: through a forecast, a season of ice charts or both) is
    smoothed under its own model by seaway.smoothtime: legs sailed on the clock, never later,
    never through land or a pixel closed when the ship is there, its waits kept; `refine` and
    `max_sweeps` do not apply to it."""
    if route.model.time_dependent:
        return smooth_on_clock(route)
    v = route.vertices
    if len(v) < 3:  # nothing to smooth; said in stats all the same
        done = Smoothing(
            cost_before=route.cost,
            course_changes_before=0,
            course_changes_after=0,
            sweeps=0,
            shortcut_legs=max(len(v) - 1, 0),
        )
        return dataclasses.replace(
            route,
            points=v.copy(),
            step_costs=route.costs(),
            stats=dataclasses.replace(route.stats, smoothing=done),
        )
    seg = route.segments()
    step_cost = route.costs()
    w, costs, sweeps = seg.pricer.smooth(v, step_cost, route.waypoint_index, bool(refine), int(max_sweeps))
    total = float(costs.sum())
    out = dataclasses.replace(
        route,
        cost=total,
        pixels=np.rint(w).astype(np.int64),
        points=w,
        step_costs=np.asarray(costs, float),
        method=f"{route.method}+smoothed",
    )
    done = Smoothing(
        cost_before=route.cost,
        course_changes_before=route.course_changes,
        course_changes_after=out.course_changes,
        sweeps=int(sweeps),
        shortcut_legs=len(w) - 1,
    )
    out = dataclasses.replace(out, stats=dataclasses.replace(route.stats, smoothing=done))
    return out


ABOVE["smoothed"] = smooth  # Route.smoothed()
