"""A route's legs: the Leg between consecutive waypoints (course, distance, speed, time, cost and
the chart's variables along it) and route_legs, which Route.legs() returns."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..base import sphere as geo
from ..base.validate import number
from ..errors import SeawayError
from .environment import along
from .schedule import schedule
from .timing import step_times
from .waypoints import waypoint_list


@dataclass
class Leg:
    """One leg between consecutive waypoints. Course: initial great-circle course, degrees true
    (planar charts: grid bearing from +y towards +x). distance: km (geographic) or chart units."""

    number: int
    start: tuple
    end: tuple
    course: float
    distance: float
    distance_nm: float | None
    speed_kn: float | None
    time_h: float | None
    cost: float
    #: name -> the chart variable along the leg (seaway.result.environment): Numeric (mean, max)
    #: pairs ((mean, min) for LEAST) or, for stages and forms of ice, a Category.
    environment: dict
    #: Leaves the first waypoint, reaches the last (on a clock: seaway.result.schedule) or None.
    depart: np.datetime64 | None = None
    arrive: np.datetime64 | None = None
    #: Distance (km) of the leg under icebreaker escort (seaway.result.timing), 0 when none.
    escorted_km: float = 0.0


def route_legs(route, speed_kn: float | None = None) -> list[Leg]:
    """The legs of `route` between consecutive waypoints (Route.legs): speed_kn defaults to the
    route's; a route with a speed in the ice or on a clock takes its times from those."""
    speed = route.speed_kn if speed_kn is None else number(speed_kn, "speed_kn", above=0)
    ice = route.ice_speed if route.geographic else None
    if ice is not None:  # times from the speed in the ice (seaway.result.timing)
        if speed is not None and speed != ice.v0_kn:
            raise SeawayError(
                f"the route's speeds in ice are for {ice.v0_kn:g} kn in open water, "
                f"not {speed:g} kn; make them again with with_ice_speed"
            )
        speed, (hours_of, _, escort_of) = ice.v0_kn, step_times(route)
    timed = schedule(route)  # a route on a clock: its real times, not those at one speed
    wl = waypoint_list(route)  # the waypoints every output gives (seaway.result.waypoints)
    wi, c = wl.index, wl.coords
    steps, costs = route.step_lengths, route.costs()
    out = []
    for n, (i, j) in enumerate(zip(wi[:-1], wi[1:]), start=1):
        a, b = c[n - 1], c[n]
        dist = float(steps[i:j].sum())
        if route.geographic:
            course = float(geo.course_deg(a[0], a[1], b[0], b[1]))
            nm = dist / geo.KM_PER_NM
        else:
            course = float(np.degrees(np.arctan2(b[1] - a[1], b[0] - a[0])) % 360.0)
            nm = None
        hours = nm / speed if (speed and nm is not None) else None
        leg_speed = speed
        if ice is not None and nm is not None:  # the leg's mean speed; 0 where it stops
            hours = float(hours_of[i:j].sum())
            leg_speed = nm / hours if 0 < hours < np.inf else (0.0 if hours else speed)
        if timed is not None:  # the leg's real hours and the speed it makes good under way
            hours, leg_speed = timed.leg(i, j, nm)
        out.append(
            Leg(
                n,
                tuple(map(float, a)),
                tuple(map(float, b)),
                course,
                dist,
                nm,
                leg_speed,
                hours,
                float(costs[i:j].sum()),
                along(route, i, j),
                *((timed.etd(i), timed.eta(j)) if timed is not None else (None, None)),
                float(escort_of[i:j].sum()) if ice is not None else 0.0,
            )
        )
    return out
