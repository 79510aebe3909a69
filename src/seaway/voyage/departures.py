"""The best departure in a window (OpenSeason.best_departure, OpenForecast.best_departure): the
departure, and its route, that arrives first through a season of ice charts or a forecast, or,
with `arrive_by`, the one that arrives in time with the least fuel.

Departures are tried every `step_h` hours through the window (each an exact earliest-arrival
search). Arriving first: the earliest arrival, and of the departures that reach it the latest
(the ship waits in port rather than at sea). On a season the search from the window's start
already gives the earliest arrival of the whole window (waiting is allowed, so leaving later never
arrives earlier); the scan adds the latest departure that still makes it and the table of all.
With `arrive_by`: of the departures that arrive by then, the one burning the least fuel: through
a forecast the least-fuel route to the deadline (Sotnikova 2009: the engine setting chosen step
by step), through ice the hours under way at the service speed's fuel rate (waiting in ice is
counted as no fuel, an assumption)."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from typing import Any

import numpy as np

from ..errors import NoRouteError, SeawayError


@dataclasses.dataclass(frozen=True)
class Departure:
    """One departure tried: when, the arrival and hours (None when no route), hours under way and
    waiting, fuel (t, when known), and why there is no route."""

    departure: np.datetime64
    arrival: np.datetime64 | None
    hours: float | None
    under_way_h: float | None = None
    waiting_h: float | None = None
    fuel_t: float | None = None
    why: str = ""


@dataclasses.dataclass(frozen=True)
class DepartureChoice:
    """The best departure's route (`route`), its Departure (`best`), every departure tried
    (`tried`, in time order) and the rule that chose it (`rule`, in words)."""

    route: Any
    best: Departure
    tried: tuple[Departure, ...]
    rule: str

    def table(self) -> str:
        """The departures tried, one a line, the chosen one marked."""
        rows = []
        for d in self.tried:
            mark = "*" if d.departure == self.best.departure else " "
            if d.arrival is None:
                rows.append(f"{mark} {str(d.departure)[:16]}  no route: {d.why}")
                continue
            fuel = f"  {d.fuel_t:8.1f} t" if d.fuel_t is not None else ""
            rows.append(
                f"{mark} {str(d.departure)[:16]}  arrives {str(d.arrival)[:16]}  {d.hours:7.1f} h"
                f"  ({d.under_way_h or 0.0:.1f} h under way){fuel}"
            )
        return "\n".join(rows)


def window_times(window, step_h: float) -> list[np.datetime64]:
    """The departures tried: from the window's start every step_h hours to its end (included)."""
    try:
        first, last = (np.datetime64(t, "s") for t in window)
    except (TypeError, ValueError):
        raise SeawayError(
            f"the departure window is two times (first, last), e.g. ('2026-07-01', '2026-07-10'); got {window!r}"
        ) from None
    if last < first:
        raise SeawayError(f"the departure window ends ({last}) before it begins ({first})")
    if not (np.isfinite(step_h) and step_h > 0):
        raise SeawayError(f"the step between departures must be a positive number of hours, got {step_h!r}")
    n = int(np.floor((last - first) / np.timedelta64(1, "s") / (step_h * 3600.0) + 1e-9)) + 1
    if n > 2000:
        raise SeawayError(f"{n} departures in the window at {step_h:g} h: give a larger step (at most 2000)")
    return [first + np.timedelta64(int(round(k * step_h * 3600)), "s") for k in range(n)]


def best_departure(
    route: Callable[..., Any],
    window,
    *,
    step_h: float = 24.0,
    arrive_by=None,
    fuel_rate_t_per_h=None,
    **options,
) -> DepartureChoice:
    """Try route(depart=t, **options) for every departure t of the window (window_times) and
    choose by the module's rules. fuel_rate_t_per_h: the fuel at the service speed, for voyages
    through ice (their fuel: hours under way x rate)."""
    deadline = None if arrive_by is None else np.datetime64(arrive_by, "s")
    tried, routes = [], {}
    for t in window_times(window, step_h):
        try:
            r = route(depart=t, **options)
        except NoRouteError as exc:
            tried.append(Departure(t, None, None, why=str(exc).split(": ", 1)[-1][:160]))
            continue
        v = r.stats.voyage
        under = float(v.hours_under_way if v is not None and v.hours_under_way is not None else r.cost)
        waiting = float(v.hours_waiting or 0.0) if v is not None else 0.0
        fuel = (
            r.stats.fuel.fuel_t
            if r.stats.fuel is not None
            else (under * fuel_rate_t_per_h if fuel_rate_t_per_h else None)
        )
        arrival = np.datetime64(v.arrival, "s") if v is not None and v.arrival is not None else None
        tried.append(Departure(t, arrival, float(v.hours if v is not None else r.cost), under, waiting, fuel))
        routes[t] = r
    ok = [d for d in tried if d.arrival is not None]
    if not ok:
        raise NoRouteError(
            f"no departure from {tried[0].departure} to {tried[-1].departure} finds a route: {tried[0].why}"
        )
    if deadline is None:
        first = min(d.arrival for d in ok)
        best = max((d for d in ok if d.arrival == first), key=lambda d: d.departure)
        rule = "the earliest arrival; of the departures that make it, the latest"
    else:
        in_time = [d for d in ok if d.arrival <= deadline]
        if not in_time:
            soonest = min(d.arrival for d in ok)
            raise NoRouteError(
                f"no departure of the window arrives by {deadline}: the earliest arrives at {soonest}"
            )
        if all(d.fuel_t is not None for d in in_time):
            best = min(in_time, key=lambda d: (d.fuel_t, d.arrival))
            rule = f"of the departures arriving by {deadline}, the least fuel"
        else:
            best = min(in_time, key=lambda d: (d.under_way_h, d.arrival))
            rule = f"of the departures arriving by {deadline}, the fewest hours under way (no fuel curve)"
    r = routes[best.departure]
    when = str(best.departure)[:16].replace("T", " ")
    note = f"best departure in the window: {when} ({rule}; {len(tried)} departures every {step_h:g} h)"
    return DepartureChoice(dataclasses.replace(r, notes=tuple(r.notes) + (note,)), best, tuple(tried), rule)
