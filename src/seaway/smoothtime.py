"""Smoothing a route on a clock (a time model: TravelTime through a forecast, IceSeasonTime through
a season of ice charts, IceWeatherTime through both, with zones closed in time windows): the
route's runs of steps replaced by straight legs sailed under the route's own model, never later.

String pulling on the clock (cpp/seaway/timed_smooth.hpp): from each kept vertex, left at the
time the new route leaves it, one straight leg (a great circle on lat/lon charts) to the
farthest vertex ahead that the leg reaches no later than the route did, sailed under the model
(seaway.chart.legs.TimedLegs: an engine step as the engine sails it; any other leg piece by
piece through the pixels it crosses, each at the model's rule for that pixel at the time the
ship enters it: the ice chart valid then, the weather then on the leg's course) and forbidden
where it touches land, or a pixel the model closes while the ship is in it (closed ice in any
chart valid then, wind or waves beyond the vessel's limits, a zone closed then).

Kept: both ends, every vertex where the route waits (the ship leaves it when the route left it)
and every via point. The new route reaches each kept vertex no later than the route, so it
arrives no later; where an early arrival would make a leg late (the model is not FIFO there: ice
that clears at a chart's time), the ship waits until the route's own departure from that vertex
(stats.smoothing.waits_added). Its schedule, hours and stats.voyage are those of its own legs.
There is no refinement of the waypoints off the pixel centres (the static smoothing's second
pass): moving one would move the times of every leg after it.

Not smoothed, and said: the least-danger route (Sotnikova 2009: hours in danger first, which the
legs do not price) and a route whose waits were not reported."""

from __future__ import annotations

import dataclasses

import numpy as np

from .chart.legs import turning_points
from .errors import SeawayError
from .models.results import WAIT_EPS_H, StepValues
from .result.stats import Smoothing


def why_not(route) -> str | None:
    """Why a route on a clock cannot be smoothed under its own model, or None when it can."""
    if route.stats.danger is not None:
        return (
            "not smoothed: the least-danger route (Sotnikova 2009) ranks hours in danger before "
            "hours, which legs sailed on the clock do not price; it is the route as found"
        )
    voyage = route.stats.voyage
    if voyage is None or voyage.wait_h is None:
        return "not smoothed: the route's waits were not reported; it is the route as found"
    return None


def on_clock(route, smooth: bool = True):
    """The route smoothed on the clock (smooth=True), or as found with a note saying why not
    (why_not); smooth=False: as found. What route_time, route_ice_weather, route_season and the
    voyages built on them return."""
    if not smooth:
        return route
    why = why_not(route)
    if why is not None:
        return dataclasses.replace(route, notes=tuple(route.notes) + (why,))
    return smooth_on_clock(route)


def smooth_on_clock(route):
    """The route with its zig-zag removed under its own time model, never later (see the module);
    ValueError naming why for a route that cannot be (why_not)."""
    why = why_not(route)
    if why is not None:
        raise SeawayError(why)
    step_h = route.costs()  # hours of each step, waits included
    v = _unwrapped(route)
    if len(v) < 2:  # start == end: nothing to sail
        return _done(route, np.arange(len(v)), np.zeros(0), np.zeros(0), 0)
    arrive = np.concatenate([[0.0], np.cumsum(step_h)])
    arrive[-1] = route.cost  # the search's own arrival, not the sum's rounding
    wait = np.asarray(route.stats.voyage.wait_h, float)
    wait = np.where(wait > WAIT_EPS_H, wait, 0.0)
    leave = arrive.copy()
    leave[:-1] += wait
    fixed = np.zeros(len(v), bool)
    fixed[[0, -1]] = True
    fixed[:-1] |= wait > 0
    via = route.stats.constraints.via_pixels if route.stats.constraints is not None else ()
    for p in via:
        fixed |= np.all(route.pixels == p, axis=1)
    candidates = np.union1d(turning_points(v), np.flatnonzero(fixed)).astype(np.int64)
    legs = route.model.timed_legs(route.chart, route.neighbourhood)
    kept, depart, arrival, added = legs.pricer.smooth(v, arrive, leave, fixed.astype(np.uint8), candidates)
    return _done(route, kept, depart, arrival, added, v)


def _unwrapped(route) -> np.ndarray:
    """The route's vertices with continuous columns across the seam of a 360-degree chart."""
    v = route.vertices.copy()
    chart = route.chart
    if chart.geographic and chart.grid.wrap and len(v) > 1:
        cols = chart.shape[1]
        jump = np.diff(v[:, 1])
        v[1:, 1] = v[0, 1] + np.cumsum(jump - cols * np.round(jump / cols))
    return v


def _done(route, kept, depart, arrival, added, v=None):
    """The smoothed Route: the kept vertices, each leg's hours (its wait included) and the
    model's voyage for them (model.finish)."""
    v = route.vertices if v is None else v
    points = v[kept].copy()
    if route.chart.geographic and route.chart.grid.wrap:
        points[:, 1] %= route.chart.shape[1]
    reached = np.concatenate([[0.0], arrival])
    out = dataclasses.replace(
        route,
        cost=float(reached[-1]) if len(arrival) else route.cost,
        pixels=np.rint(points).astype(np.int64),
        points=points,
        step_costs=np.diff(reached),
        method=f"{route.method}+smoothed",
    )
    done = Smoothing(
        cost_before=route.cost,
        course_changes_before=route.course_changes,
        course_changes_after=out.course_changes,
        sweeps=0,
        shortcut_legs=len(kept) - 1,
        waits_added=int(added),
    )
    out = dataclasses.replace(out, stats=dataclasses.replace(route.stats, smoothing=done))
    return route.model.finish(out, StepValues(depart_h=np.asarray(depart), wait_h=depart - reached[:-1]))
