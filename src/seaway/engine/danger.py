"""Sotnikova 2009's fallback when every route crosses danger: the route that spends the least time in
the forecast's danger zones (wind above Vessel.danger_wind_ms, waves above
Vessel.danger_wave_m), then the least total time, flagged and with the stretches in danger
listed. Called by seaway.weather.route_time (cpp/seaway/danger_time.hpp searches)."""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from .. import native as _core
from ..base.interrupt import interruptible
from ..chart.locate import locate
from ..constraints import timed_zone_engine
from ..models.results import StepValues
from ..result.stats import Danger, DangerLeg
from .methods import heuristic_weight
from .result import Search, to_route

if TYPE_CHECKING:
    from ..models.forecast import TravelTime
    from ..result.route import Route
    from .constrained import Point
    from .prepared import PreparedChart


def danger_stretches(
    route: Route, danger_h: npt.NDArray[np.float64], start_h: float
) -> tuple[DangerLeg, ...]:
    """Consecutive steps in danger merged: where (start, end as lat/lon), when (hours after
    departure) and for how long (hours)."""
    coords = route.coords
    assert route.step_costs is not None  # a route as found (to_route)
    elapsed = np.concatenate([[0.0], np.cumsum(route.step_costs)]) + start_h
    out, i, n = [], 0, len(danger_h)
    while i < n:
        if danger_h[i] <= 0:
            i += 1
            continue
        j = i
        while j + 1 < n and danger_h[j + 1] > 0:
            j += 1
        out.append(
            DangerLeg(
                start=(float(coords[i][0]), float(coords[i][1])),
                end=(float(coords[j + 1][0]), float(coords[j + 1][1])),
                start_h=float(elapsed[i]),
                hours=float(np.sum(danger_h[i : j + 1])),
                steps=(i, j + 1),
            )
        )
        i = j + 1
    return tuple(out)


def least_danger_route(
    prepared: PreparedChart, model: TravelTime, start: Point, end: Point, method: str
) -> Route | None:
    """The lexicographic (hours in danger, hours) route under a TravelTime model (its zones
    included), or None when even the hard limits leave no route."""
    fc, vessel = model.forecast, model.vessel
    chart = prepared.chart
    s, e = locate(chart, start, "start"), locate(chart, end, "end")
    hard: _core.TravelTimeModel | _core.ZonedTravelTimeModel
    hard = _core.TravelTimeModel(fc.engine(), vessel.to_core(danger=False), model.best_speed_kn)
    if model.zones:
        hard = timed_zone_engine(fc, hard, model.zones)
    wind = np.inf if vessel.danger_wind_ms is None else float(vessel.danger_wind_ms)
    wave = np.inf if vessel.danger_wave_m is None else float(vessel.danger_wave_m)
    w = heuristic_weight(method, None)
    result, danger_h = interruptible(
        lambda cancel: _core.route_least_danger(
            prepared.router, hard, wind, wave, prepared.flat(s), prepared.flat(e), w, cancel
        )
    )
    found = Search.from_core(result)
    if not found.found:
        return None
    r = to_route(prepared, found, model, method)
    r = model.finish(r, StepValues())
    danger_h = np.asarray(danger_h, dtype=float)
    danger = Danger(hours=float(danger_h.sum()), step_h=danger_h, legs=danger_stretches(r, danger_h, 0.0))
    return dataclasses.replace(
        r,
        stats=dataclasses.replace(r.stats, danger=danger),
        name="seaway route (through danger: no route avoids the danger zones)",
    )
