"""The schedule of a route on a clock (a time model's Voyage: through a forecast, a season of ice
charts, or both): when the ship reaches and leaves each vertex, each leg's real time (waits
included) and the speed it makes good under way. Every output reads it from here: the leg table,
RTZ's schedule, the times in GeoJSON, GPX and CSV, and the HTML map's popups."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..base.units import KM_PER_NM
from .timing import step_times


@dataclass(frozen=True)
class Schedule:
    """Hours after departure at every vertex of the route: `arrive_h` when the ship reaches it,
    `leave_h` when it leaves it (later by any wait there; the last vertex's is its arrival);
    `departure` (a datetime64, or None when the voyage has none) turns them into times."""

    arrive_h: np.ndarray
    leave_h: np.ndarray
    departure: np.datetime64 | None
    #: The forecast the route was found through, in words (None for ice alone).
    forecast: str | None

    def at(self, hours: float) -> np.datetime64 | None:
        """The time `hours` after departure, to the second (None without a departure)."""
        if self.departure is None or not np.isfinite(hours):
            return None
        return self.departure.astype("datetime64[s]") + np.timedelta64(int(round(hours * 3600.0)), "s")

    def eta(self, i: int) -> np.datetime64 | None:
        """When the ship reaches vertex i (the departure at the first)."""
        return self.at(float(self.arrive_h[i]))

    def etd(self, i: int) -> np.datetime64 | None:
        """When the ship leaves vertex i (after any wait; the arrival at the last)."""
        return self.at(float(self.leave_h[i]))

    def leg(self, i: int, j: int, nm: float | None) -> tuple[float, float | None]:
        """(hours, speed made good in knots) of the leg between vertices i and j: the hours from
        leaving i to reaching j, with any waits at its inner vertices; the speed is the leg's
        distance over its hours under way (None on planar charts)."""
        hours = float(self.arrive_h[j] - self.arrive_h[i])
        waiting = float(np.sum(self.leave_h[i:j] - self.arrive_h[i:j]))
        under_way = hours - waiting
        speed = nm / under_way if nm is not None and under_way > 0 else None
        return hours, speed


def schedule(route) -> Schedule | None:
    """The route's Schedule from its Voyage (seaway.models.results); for a route timed by a speed
    (in the ice, or one speed) with a departure, from its step times; None for a route that is
    not on a clock."""
    voyage = route.stats.voyage
    if voyage is None:
        return _static(route)
    steps = np.asarray(route.costs() if voyage.step_h is None else voyage.step_h, dtype=float)
    arrive = np.concatenate([[0.0], np.cumsum(steps)])
    wait = np.zeros(steps.size) if voyage.wait_h is None else np.asarray(voyage.wait_h, float)
    leave = np.concatenate([arrive[:-1] + wait, arrive[-1:]])
    return Schedule(arrive, leave, voyage.departure, voyage.forecast)


def _static(route) -> Schedule | None:
    """The Schedule of a route timed by a speed, given a departure (Route.departure)."""
    if route.departure is None or not route.geographic:
        return None
    if route.ice_speed is not None:
        steps = np.asarray(step_times(route)[0], float)
    elif route.speed_kn:
        steps = np.asarray(route.step_lengths, float) / (float(route.speed_kn) * KM_PER_NM)
    else:
        return None
    arrive = np.concatenate([[0.0], np.cumsum(steps)])
    return Schedule(arrive, arrive.copy(), np.datetime64(route.departure, "s"), None)


def dated_schedule(route) -> Schedule | None:
    """The route's Schedule when it has a departure date (times of day to print), else None."""
    timed = schedule(route)
    return timed if timed is not None and timed.departure is not None else None


def iso(t) -> str:
    """A time as ISO 8601 UTC to the second, e.g. 2026-09-15T06:00:00Z ('' for None)."""
    return "" if t is None else str(np.datetime_as_string(np.datetime64(t, "s"), unit="s")) + "Z"


def short(t) -> str:
    """A time as YYYY-MM-DD HH:MM (UTC) for tables and popups ('-' for None)."""
    return "-" if t is None else str(np.datetime_as_string(np.datetime64(t, "m"), unit="m")).replace("T", " ")


def voyage_summary(route) -> dict:
    """What Route.summary() adds for a route on a clock: the real time (hours, waits included),
    hours waiting, departure and arrival (ISO 8601) and the forecast."""
    v = route.stats.voyage
    out: dict = {"time_h": float(v.hours)}
    if v.hours_waiting is not None:
        out["hours_waiting"] = float(v.hours_waiting)
    if v.departure is not None:
        out.update(departure=iso(v.departure), arrival=iso(v.arrival))
    if v.forecast:
        out["forecast"] = v.forecast
    if route.stats.danger is not None:  # no route avoided the danger zones (Sotnikova 2009)
        out["hours_in_danger"] = float(route.stats.danger.hours)
    return out
