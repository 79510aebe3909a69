"""The rows of route_voyages: a share of the batch routed and turned into table rows.

Rows that share a vessel, a start and a departure are one unit: a source with routes() (an
opened season: OpenSeason.routes) answers them from one search per start, each row what
``source.route(start, end, method="dijkstra", ...)`` gives; other sources route row by row."""

from __future__ import annotations

from typing import Any

import numpy as np

from ..base.units import KM_PER_NM
from ..errors import NoRouteError, SeawayError, SnapError
from .many import ENDS

COLUMNS = [
    "vessel",
    "voyage",
    "departure",
    *ENDS,
    "arrival",
    "hours",
    "distance_nm",
    "wait_h",
    "escorted_nm",
    "status",
    "cause",
    "error",
]

#: A row's work: (vessel name, vessel, voyage id, (start, end), departure).
Item = tuple[str, Any, Any, tuple, Any]


def units(source, work: list[Item], options: dict) -> list[list[Item]]:
    """The batch in units routed together: rows of one vessel, start and departure when the
    source routes from one start to many ends (its routes(); not with a method or progress of
    the caller's), else one row each; in the batch's order of first appearance."""
    if not grouped(source, options):
        return [[w] for w in work]
    groups: dict[tuple, list[Item]] = {}
    for w in work:
        name, _, _, ends, depart = w
        groups.setdefault((name, tuple(ends[0]), depart), []).append(w)
    return list(groups.values())


def grouped(source, options: dict) -> bool:
    """Are rows of one vessel, start and departure routed from one search?"""
    return callable(getattr(source, "routes", None)) and not {"method", "progress"} & set(options)


def unit_rows(source, unit: list[Item], options: dict, keep: bool) -> list[dict]:
    """The rows of one unit, in its order."""
    name, vessel, _, ends, depart = unit[0]
    if not grouped(source, options):
        return [
            _row(unit[0], _answer(lambda: source.route(*ends, vessel=vessel, depart=depart, **options)), keep)
        ]
    try:
        found = source.routes(ends[0], [w[3][1] for w in unit], vessel=vessel, depart=depart, **options)
    except SeawayError as exc:  # the start or the vessel: every row of the unit
        found = [exc] * len(unit)
    return [_row(w, r, keep) for w, r in zip(unit, found)]


def _answer(route):
    try:
        return route()
    except SeawayError as exc:
        return exc


def _row(item: Item, answer, keep: bool) -> dict:
    """A table row of a Route or the SeawayError that answered it (route_many's words for the
    status and cause)."""
    name, _, key, (start, end), depart = item
    row: dict[str, Any] = dict.fromkeys(COLUMNS, np.nan)
    row.update(vessel=name, voyage=key, departure=depart, status="ok", cause="", error="")
    row.update(
        start_lat=float(start[0]), start_lon=float(start[1]), end_lat=float(end[0]), end_lon=float(end[1])
    )
    if isinstance(answer, NoRouteError):
        cause = {"ice": "closed by ice", "land": "land", "impassable": "impassable"}.get(
            answer.cause or "", "no route"
        )
        row.update(status="no route", cause=cause, error=str(answer))
    elif isinstance(answer, SnapError):
        cause = _end_cause(answer)
        row.update(
            status="no route" if cause == "closed by ice" else "bad input", cause=cause, error=str(answer)
        )
    elif isinstance(answer, SeawayError):
        cause = "off chart" if "outside the chart" in str(answer) else "bad input"
        row.update(status="bad input", cause=cause, error=str(answer))
    else:
        row.update(_figures(answer))
    if keep:
        row["route"] = None if isinstance(answer, SeawayError) else answer
    return row


def _end_cause(exc: SnapError) -> str:
    """What keeps an end from usable water, from the reason its Move gives (route_many's words):
    "land", "closed by ice", "off chart" or "impassable" (another impassable pixel)."""
    why = " ".join(str(getattr(m, "why", "")) for m in exc.moves).lower()
    if "land" in why:
        return "land"
    if "off the chart" in why or "outside" in why or "no chart" in why:
        return "off chart"
    if "ice" in why:
        return "closed by ice"
    return "impassable"


def _figures(r) -> dict:
    """What a row reports of a Route: the ends used, the times, the distance, waits, escort."""
    where = r.latlon if r.latlon is not None else r.coords
    out = dict(
        used_start_lat=float(where[0][0]),
        used_start_lon=float(where[0][1]),
        used_end_lat=float(where[-1][0]),
        used_end_lon=float(where[-1][1]),
    )
    legs = r.legs()
    nm = [leg.distance_nm for leg in legs]
    out["distance_nm"] = float(sum(nm)) if all(x is not None for x in nm) else float("nan")
    out["escorted_nm"] = float(sum(leg.escorted_km for leg in legs)) / KM_PER_NM
    voyage = r.stats.voyage
    if voyage is not None:
        out.update(hours=float(voyage.hours), departure=voyage.departure, arrival=voyage.arrival)
        out["wait_h"] = float(np.sum(voyage.wait_h)) if voyage.wait_h is not None else float("nan")
        return out
    times = [leg.time_h for leg in legs]
    out["wait_h"] = 0.0
    if all(t is not None for t in times):
        out["hours"] = float(sum(times))
        if r.departure is not None:
            out["arrival"] = r.departure + np.timedelta64(int(round(out["hours"] * 3600)), "s")
    return out
