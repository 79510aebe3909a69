"""One route of route_many: the search for a chart and vessel, and a row that never raises.

A row carries the ends as numbers (as asked for, and as used after snapping: seaway.engine.snap,
the code seaway.route's callers snap with), the move of each snapped end, and the cause of a
failure: land, closed by ice (an impassable cost that is not land), off chart, no route."""

from __future__ import annotations

import math
import time

from ..chart.locate import pixel_of
from ..engine.api import prepare
from ..engine.snap import snap_prepared
from ..errors import NoRouteError, SeawayTypeError

#: A row's cause of failure ("" when the route was found).
CAUSES = ("land", "closed by ice", "off chart", "no route", "bad input", "error")
CLOSED = "closed by ice (impassable cost that is not land)"
_NAN2 = (math.nan, math.nan)


def _loaded(obj):
    """A dask-backed xarray object loaded into memory here (never on a distributed Client)."""
    if obj is not None and hasattr(obj, "chunks") and hasattr(obj, "compute") and obj.chunks:
        return obj.compute(scheduler="synchronous")
    return obj


class _Target:
    """The search for one chart and vessel: the chart prepared once, routes (start, end, via)."""

    def __init__(self, prepared, opts):
        self.prepared, self.opts = prepared, opts
        self.chart = prepared.chart

    def why(self, r, c):
        """What closes pixel (r, c): "land" or "closed by ice (...)" (the cause's words)."""
        land = self.chart.land
        return "land" if land is not None and land[r, c] else CLOSED

    def cause(self, start, end):
        """Why an end cannot be used as it is ("off chart", "land", "closed by ice",
        "bad input"), or None when both ends lie on pixels the ship may use."""
        for p, name in ((start, "start"), (end, "end")):
            try:
                rc = pixel_of(self.chart, p, name)
            except SeawayTypeError:
                return "bad input"
            except ValueError as exc:
                return "off chart" if "outside the chart" in str(exc) else "bad input"
            if not self.chart.passable(rc):
                return "land" if self.why(*rc) == "land" else "closed by ice"
        return None

    def route(self, start, end, via=()):
        o = self.opts
        return self.prepared.route(
            start, end, method=o["method"], weight=o["weight"], via=via, turn_penalty=o.get("turn_penalty")
        )


def _target(chart, vessel, opts):
    """The search for one chart and vessel (a _Target)."""
    land = opts["land"]
    if land is None and hasattr(chart, "data_vars") and "land" in chart.data_vars:
        land = chart["land"]
    if vessel is None:
        if hasattr(chart, "data_vars"):
            raise SeawayTypeError("a Dataset chart needs vessels= callables turning it into a cost raster")
        cost = chart
    else:
        cost = vessel(chart) if callable(vessel) else vessel
    cost, land = _loaded(cost), _loaded(land)
    return _Target(prepare(cost, land=land, **opts["chart"]), opts)  # once; a workspace per thread


def _status(exc):
    if isinstance(exc, NoRouteError):
        return "no route"
    if isinstance(exc, (ValueError, TypeError)):
        return "bad input"
    return "error"


def _numbers(point):
    """A point as two floats (NaN, NaN when it is not a pair of numbers)."""
    try:
        a, b = (float(v) for v in point)
    except (TypeError, ValueError):
        return _NAN2
    return a, b


def _route_one(get_target, voyage, keep):
    """One row: the route for `voyage` or the reason it failed (never raises)."""
    malformed, via = False, ()
    try:
        start, end, *rest = voyage
        if len(rest) > 1:
            raise ValueError
        via = rest[0] if rest else ()
        if via is None or (isinstance(via, float) and math.isnan(via)):  # a DataFrame's empty cell
            via = ()
    except (TypeError, ValueError):
        start, end, malformed = voyage, None, True
    row = dict(
        start=_NAN2 if malformed else _numbers(start),
        end=_NAN2 if malformed else _numbers(end),
        used_start=_NAN2,
        used_end=_NAN2,
        start_moved=0.0,
        end_moved=0.0,
        cost=math.nan,
        length=math.nan,
        settled=None,
        time_s=0.0,
        cause="",
        notes="",
        geographic=None,
    )
    route, cause = None, None
    t0 = time.perf_counter()
    try:
        if malformed:
            raise SeawayTypeError(
                f"a voyage must be a (start, end) pair or a (start, end, via) triple, got {voyage!r}"
            )
        target = get_target()
        row["geographic"] = target.chart.geographic
        t0 = time.perf_counter()
        cause = target.cause(start, end)
        snap_km = target.opts.get("snap_km")
        if snap_km is not None and cause in ("land", "closed by ice"):
            snapped = snap_prepared(target.prepared, start, end, max_km=snap_km, why=target.why)
            start, end, cause = *snapped.ends, None
            moved = {m.name: m.distance for m in snapped.moves}
            row.update(
                start_moved=moved.get("start", 0.0),
                end_moved=moved.get("end", 0.0),
                notes="; ".join(snapped.notes),
            )
            route = target.route(start, end, via)
            route = snapped.record(route)
        else:
            route = target.route(start, end, via)
        row.update(
            used_start=_numbers(start),
            used_end=_numbers(end),
            cost=float(route.cost),
            length=float(route.length),
            settled=None if route.stats.search is None else route.stats.search.settled,
            status="ok",
            error="",
        )
    except Exception as exc:  # noqa: BLE001 - a failing route is reported in its row
        status = _status(exc)
        row.update(
            status=status,
            cause=cause or status,
            error=f"{type(exc).__name__}: {exc}" if status == "error" else str(exc),
            start_moved=math.nan,
            end_moved=math.nan,
        )
    row["time_s"] = time.perf_counter() - t0
    if keep:
        row["route"] = route
    return row
