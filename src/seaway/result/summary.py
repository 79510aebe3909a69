"""Route.summary(): the route in figures, for the printed table and every export."""

from __future__ import annotations

import numpy as np

from ..base import sphere as geo
from .environment import CATEGORICAL, LEAST, least_depth, summarise, values_at
from .schedule import iso, schedule, voyage_summary
from .timing import step_times


def route_summary(route, speed_kn=None) -> dict:
    """name; start and end (the ends used; requested_start and requested_end when the route
    records what was asked for); cost, length, legs, course changes; speed and time; the
    environment met (max, or the governing / most frequent category); assumptions; least
    depth."""
    legs = route.legs(speed_kn)
    speed = route.speed_kn if speed_kn is None else speed_kn
    out = {
        "name": route.name,
        "start": tuple(map(float, route.coords[0])),
        "end": tuple(map(float, route.coords[-1])),
        "cost": route.cost,
        "length": route.length,
        "length_units": "km" if route.geographic else "grid units",
        "legs": len(legs),
        "course_changes": route.course_changes,
        "edge_cost": route.edge_cost,
        "cost_unit": route.unit,
        "neighbourhood": route.neighbourhood,
    }
    if route.requested is not None:
        out["requested_start"], out["requested_end"] = (tuple(map(float, p)) for p in route.requested)
    if route.geographic:
        length_nm = route.length / geo.KM_PER_NM
        out["length_nm"] = length_nm
        if route.ice_speed is not None:  # times from the speed in the ice
            out.update(
                speed_kn=route.ice_speed.v0_kn,
                time_h=float(sum(leg.time_h for leg in legs)),
                speed_model=route.ice_speed.model,
            )
            _, stopped, escorted = (float(x.sum()) for x in step_times(route))
            if stopped > 0:
                out["stopped_km"] = stopped
            if escorted > 0:
                out["escorted_km"] = escorted
                out["escorted_legs"] = [leg.number for leg in legs if leg.escorted_km > 0]
        elif speed:
            out.update(speed_kn=float(speed), time_h=length_nm / speed)
    if route.stats.voyage is not None:  # a route on a clock: its real time, not one speed's
        out.update(voyage_summary(route))
    elif route.departure is not None and np.isfinite(out.get("time_h", np.nan)):  # timed by a speed
        timed = schedule(route)
        if timed is not None:
            out.update(departure=iso(timed.eta(0)), arrival=iso(timed.eta(len(route.vertices) - 1)))
    for name, arr in route.environment.items():
        if name in CATEGORICAL:  # the governing / most frequent category of the whole route
            cat = summarise(name, values_at(arr, route.sample_pixels()))
            out[f"{cat.rule.replace(' ', '_')}_{name}"] = str(cat)
        elif name not in LEAST:
            tops = [leg.environment[name].max for leg in legs]
            tops = [v for v in tops if np.isfinite(v)]
            out[f"max_{name}"] = float(max(tops)) if tops else None
    if route.assumptions:
        out["assumptions"] = list(route.assumptions)
    if "depth" in route.environment:  # for depth the least matters (seaway.depth)
        out["least_depth_m"], out["least_depth_at"] = least_depth(route, route.environment["depth"])
    return out
