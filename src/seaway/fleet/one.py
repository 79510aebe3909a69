"""One route of route_many: the search for a chart and vessel, and a row that never raises."""

from __future__ import annotations

import math
import time

from ..engine.api import prepare
from ..errors import NoRouteError, SeawayTypeError


def _loaded(obj):
    """A dask-backed xarray object loaded into memory here (never on a distributed Client)."""
    if obj is not None and hasattr(obj, "chunks") and hasattr(obj, "compute") and obj.chunks:
        return obj.compute(scheduler="synchronous")
    return obj


def _target(chart, vessel, opts):
    """The search for one chart and vessel: a function (start, end) -> Route."""
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
    prepared = prepare(cost, land=land, **opts["chart"])  # once; a workspace per thread
    return lambda s, e, via=(): prepared.route(
        s, e, method=opts["method"], weight=opts["weight"], via=via, turn_penalty=opts.get("turn_penalty")
    )


def _status(exc):
    if isinstance(exc, NoRouteError):
        return "no route"
    if isinstance(exc, (ValueError, TypeError)):
        return "bad input"
    return "error"


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
    row = dict(start=start, end=end, cost=math.nan, length=math.nan, settled=None, time_s=0.0)
    route = None
    t0 = time.perf_counter()
    try:
        if malformed:
            raise SeawayTypeError(
                f"a voyage must be a (start, end) pair or a (start, end, via) triple, got {voyage!r}"
            )
        target = get_target()
        t0 = time.perf_counter()
        route = target(start, end, via) if len(via) else target(start, end)
        row.update(
            cost=float(route.cost),
            length=float(route.length),
            settled=None if route.stats.search is None else route.stats.search.settled,
            status="ok",
            error="",
        )
    except Exception as exc:  # noqa: BLE001 - a failing route is reported in its row
        status = _status(exc)
        row.update(status=status, error=f"{type(exc).__name__}: {exc}" if status == "error" else str(exc))
    row["time_s"] = time.perf_counter() - t0
    if keep:
        row["route"] = route
    return row
