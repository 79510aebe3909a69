"""The steps of a route through a season (OpenSeason.route), shared with the routes from one
start to many ends (OpenSeason.routes, which seaway.fleet.route_voyages uses): what every route
of one vessel and departure shares (`plan`), the ends one route uses (`ends_used`), a found route
as the user gets it (`finish`) and the error for an end no route reaches (`explain`)."""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING, Any

import numpy as np

from ..chart.locate import locate
from ..engine.snap import DEFAULT_SNAP_KM
from ..errors import NoRouteError, SeawayError
from ..icenav.seasonwhy import closed_reason, explain_season_no_route, usable
from ..result.schedule import schedule
from ..smoothtime import on_clock
from .ends import check_ends
from .ship import vessel_notes
from .timing import CHART_AGE_DAYS

if TYPE_CHECKING:
    from ..result.route import Route


@dataclasses.dataclass(frozen=True)
class Plan:
    """What every route of one vessel and departure through a season shares."""

    ship: Any
    model: Any
    speed: Any
    limit: dict
    said: tuple[str, ...]  # the vessel's notes
    assumed: tuple[str, ...]  # the charts' assumptions
    usable: Any  # a DataArray: 1 where some chart from the departure on opens, inf elsewhere
    why: Any  # why(row, col): what closes a pixel


def plan(season, vessel, speed_kn, depart, speed_table, fast_ice, concentration_limit) -> Plan:
    """The vessel, its time model through `season` (an OpenSeason) and what its ends need."""
    ship, model, speed, limit = season._model(
        vessel, speed_kn, depart, speed_table, fast_ice, concentration_limit
    )
    return Plan(
        ship,
        model,
        speed,
        limit,
        tuple(vessel_notes(ship)),
        tuple(f"assumed: {said}" for said in model.assumptions),
        season.grid.template.copy(data=np.where(usable(model), 1.0, np.inf)),
        closed_reason(model),
    )


def ends_used(season, p: Plan, start, end, snap_km, neighbourhood):
    """((start pixel, end pixel), the sentences saying how they moved, the ends as asked).
    Only an end no chart opens moves (an end closed at departure may open later: the ship
    waits); SnapError when one must move farther than snap_km (None: not at all)."""
    snap = snap_km is not None
    asked = (tuple(start), tuple(end))
    pair = (season.pixel(start, "start"), season.pixel(end, "end"))
    chart = season.prepared(neighbourhood).chart
    if all(_open(p, chart, e, name) for e, name in zip(pair, ("start", "end"))):
        return tuple(tuple(map(float, e)) for e in pair), [], asked  # as check_ends: nothing moves
    used, moved = check_ends(
        p.usable,
        season.grid.dry,
        None,
        pair,
        snap=snap,
        snap_km=snap_km if snap else DEFAULT_SNAP_KM,
        say=lambda note: None,
        neighbourhood=neighbourhood,
        why=p.why,
        to_user=None if season.plane is None else season.plane.to_user,
        asked=asked,
    )
    return tuple(tuple(e) for e in used), moved, asked


def _open(p: Plan, chart, point, name) -> bool:
    """Does some chart from the departure on open the pixel of `point` (on the grid)?"""
    try:
        rc = locate(chart, point, name)
    except SeawayError:
        return False  # check_ends says why
    return bool(np.isfinite(p.usable.values[rc]) and not (chart.land is not None and chart.land[rc]))


def finish(season, p: Plan, found: Route, asked, moved, smooth: bool, name: str) -> Route:
    """A found route as OpenSeason.route gives it: smoothed on the clock (or not), the charts'
    ages, in lat/lon on a projected season, with every note."""
    r = on_clock(found, smooth)
    ages = chart_ages(season.grid.times, r)
    if season.plane is not None:  # vertices and waits in lat/lon for the legs and the outputs
        r = season.plane.in_degrees(r)
    return dataclasses.replace(
        r,
        name=name,
        notes=r.notes + tuple(season.notes) + p.said + tuple(moved) + tuple(ages),
        requested=asked,
    )


def explain(season, p: Plan, a, b, neighbourhood, asked, moved) -> NoRouteError:
    """The NoRouteError naming what closes the way from pixel a to pixel b."""
    err = explain_season_no_route(
        season.grid, p.model, a, b, neighbourhood=neighbourhood, speed=p.speed, asked=asked, **p.limit
    )
    err.notes = p.assumed + tuple(moved)
    return err


def chart_ages(times, r) -> list[str]:
    """The charts used against the legs that use them: a warning when a leg runs more than
    CHART_AGE_DAYS after the date of the chart it crosses (the charts are too sparse)."""
    timed = schedule(r)
    if timed is None or timed.departure is None or times.size == 0:
        return []
    at = np.array([timed.eta(i) for i in range(len(r.coords))], dtype="datetime64[s]")
    k = np.clip(np.searchsorted(times.astype("datetime64[s]"), at, side="right") - 1, 0, times.size - 1)
    age = (at - times.astype("datetime64[s]")[k]) / np.timedelta64(1, "D")
    worst = int(np.argmax(age))
    if age[worst] <= CHART_AGE_DAYS:
        return []
    date = str(times[k[worst]])[:16]
    return [
        f"warning: the ice chart of {date} is {age[worst]:.1f} days older than the part of the voyage that "
        f"crosses it (at {str(at[worst])[:16]}; more than {CHART_AGE_DAYS:g}): add newer charts"
    ]
