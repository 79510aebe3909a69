"""Time-optimal and least-danger routes through forecasts of currents, wind and waves
(Olovyannikov 2025, Grinyak et al. 2018, Sotnikova 2009), and re-planning during the voyage.

A step's cost is its duration in hours. The weather is read at both ends of the step, at the
time the ship starts it, linearly interpolated between forecast frames (held constant before
the first frame and after the last). The search labels every pixel with its earliest arrival
time, which is exact when the weather is FIFO: leaving later never means arriving earlier
(true unless a forecast speeds the ship up faster than time passes).

Physics (Olovyannikov 2025), computed in the C++ core for every step and course:
* speed through water in wind waves, Khokhlov (eq. 8):
  V = V0 - (0.745 h - 0.275 q h)(1 - 1.35e-6 D V0), h = 1.32 x significant height (3 % waves,
  Rayleigh), q the waves' bearing from the bow in radians (0 head seas, pi following seas),
  D displacement in t, V in knots; valid for 5000-25000 t and 9-20 kn;
* speed over ground holding the track through a current Vt at angle q to the course:
  V = Vt cos q + sqrt(V0^2 - (Vt sin q)^2). The paper prints a plus under the root; holding
  the track means cancelling the cross current, which gives the minus, and
  Vt |sin q| >= V0 (the track cannot be held) is impassable;
* impassable where the wind exceeds max_wind_ms (25 m/s) or the waves max_wave_m (5 m), and,
  for Sotnikova 2009's moving danger zones, where the wind exceeds danger_wind_ms (11 m/s) at the
  time the ship would be there.
"""

from __future__ import annotations

import numpy as np

from ..base.sphere import rhumb_line_km  # noqa: F401 - part of this API
from ..engine.api import prepare
from ..engine.danger import least_danger_route
from ..engine.methods import heuristic_weight
from ..errors import ChartError, ForecastError, NoRouteError, SeawayError
from ..ice.seasongrid import SeasonGrid
from ..models import IceWeatherTime, TravelTime, WaveDanger
from ..result.route import Route
from ..smoothtime import on_clock
from ..vessel import Vessel
from .grid import ForecastGrid
from .projected import on_grid


def route_time(
    forecast,
    start,
    end,
    *,
    vessel: Vessel = Vessel(),
    departure=None,
    land=None,
    neighbourhood=5,
    method="astar",
    variables=None,
    zones=(),
    keep_away=(),
    via=(),
    if_no_safe_route="least_danger",
    persist=False,
    source=None,
    smooth=True,
) -> Route:
    """The quickest route from `start` to `end` (lat, lon) through a forecast.

    forecast: xarray.Dataset on a regular lat/lon grid, optionally with a `time` dimension
        (regular steps, e.g. 6-hourly); fields found by CF standard name (STANDARD_NAMES) or
        `variables`. NaN in every field at a pixel marks land, as do True pixels of `land`.
    departure: a datetime (numpy/pandas/str) within the forecast's times; default its first time.
        One outside them is refused unless persist=True (its nearest frame held, said in
        Route.assumptions). A time axis that is not decoded yet (CDO's "day as %Y%m%d.%f") is.
    source: the forecast's name in the outputs (its files), default its title.
    zones: seaway.constraints.Zone exclusions, each optionally closed only in a time window
        (`active=(t0, t1)`): the ship waits or detours only while a zone is closed.
    keep_away: hard seaway.constraints.KeepAway buffers (from land or a boolean ice mask).
    via: points to pass in order; each leg departs when the previous one arrives.
    if_no_safe_route: when no route avoids the vessel's danger zones (danger_wind_ms,
        danger_wave_m), "least_danger" returns the route with the least hours in danger, then
        the least hours (Sotnikova 2009), flagged stats.through_danger with stats.danger
        (seaway.result.stats.Danger: hours in danger, per step, and the stretches in danger:
        where, when and how long); "raise" raises NoRouteError. The hard limits (max_wind_ms,
        max_wave_m) are never crossed.
    smooth: the route's steps replaced by straight legs sailed through the forecast, never later
        and never beyond the vessel's limits, waits and via points kept (seaway.smoothtime;
        stats.smoothing); False: the engine's steps. The least-danger route is not smoothed
        (said in Route.notes).
    Returns a Route whose cost is the passage time in hours (stats.voyage holds departure,
    arrival and waits: seaway.models.results.Voyage).
    The same as ForecastGrid(forecast).prepare().route(start, end, model=TravelTime(...)).
    """
    if if_no_safe_route not in ("least_danger", "raise"):
        raise SeawayError(f"if_no_safe_route must be 'least_danger' or 'raise', got {if_no_safe_route!r}")
    heuristic_weight(method, None)
    fc = ForecastGrid(forecast, variables, departure, persist=persist, source=source)
    model = TravelTime(fc, vessel, zones=zones)
    prepared = fc.prepare(land, neighbourhood, keep_away)
    try:
        return on_clock(prepared.route(start, end, model=model, method=method, via=via), smooth)
    except NoRouteError:
        danger = vessel.danger_wind_ms is not None or vessel.danger_wave_m is not None
        if not danger or if_no_safe_route != "least_danger" or (via is not None and len(via)):
            raise
        r = least_danger_route(prepared, model, start, end, method)
        if r is None:
            raise
        return on_clock(r, smooth)


def route_ice_weather(
    season,
    forecast,
    start,
    end,
    *,
    ice_class="Arc7",
    vessel: Vessel = Vessel(),
    departure=None,
    persist=False,
    variables=None,
    land=None,
    neighbourhood=5,
    method="astar",
    speed="andreeva",
    source=None,
    smooth=True,
    **speed_options,
) -> Route:
    """The quickest route through ice and weather at once (seaway.models.IceWeatherTime): each
    step crosses the ice chart valid when it starts at the class's speed (Andreeva 2021's
    V = F x V0 with V0 = vessel.speed_kn, or a speed table: see seaway.icenav.season), changed by
    the forecast's currents and waves then as a calm-water speed is; the class's limits close
    the ice it may not enter; the ship may wait for a later chart.

    season: a season of ice charts (a Dataset or NetCDF path with a time axis, see
        seaway.icenav.season.as_season; or a SeasonGrid); one chart: expand_dims(time=[date]).
    forecast: a forecast Dataset on a lat/lon or projected grid; resampled onto the season's grid
        (seaway.weather.projected.on_grid) unless it is on it. departure, persist, variables: as in
        route_time; the departure must lie within the season too.
    smooth: the route's steps replaced by straight legs sailed through the charts and the
        forecast, never later, never through closed ice or beyond the vessel's limits, its waits
        kept (seaway.smoothtime; stats.smoothing); False: the engine's steps.
    Returns a Route whose cost is the passage time in hours, waits included; stats.voyage holds
    departure, arrival, waits, the charts used, the forecast and what was assumed."""
    heuristic_weight(method, None)
    grid = season if isinstance(season, SeasonGrid) else SeasonGrid(season, land)
    t = grid.template
    lat, lon = (t[d].values for d in t.dims)
    if not prepare(grid, neighbourhood=neighbourhood).chart.geographic:
        raise ChartError(
            "routing through ice and weather needs the ice charts on a lat/lon grid; "
            "move them onto one first (seaway.weather.to_latlon)"
        )
    forecast, notes = on_grid(forecast, lat, lon, t.dims)
    fc = ForecastGrid(forecast, variables, departure, persist=persist, source=source)
    fc.assumptions += notes
    model = IceWeatherTime(grid, fc, ice_class, vessel, speed=speed, **speed_options)
    r = prepare(grid, neighbourhood=neighbourhood).route(start, end, model=model, method=method)
    return on_clock(r, smooth)


def route_safest(
    forecast,
    start,
    end,
    *,
    ship_length_m,
    speed_kn,
    at_hours=0.0,
    land=None,
    neighbourhood=5,
    method="astar",
    variables=None,
) -> Route:
    """The route of least wave danger (Grinyak et al. 2018): minimises sum (u_i + u_j) / 2 * r with the
    danger u in [1, 10] from MSC.1/Circ.1228's criteria for the step's heading (see
    seaway._core.wave_danger and cpp/seaway/waves.hpp), on the forecast frame valid nearest
    `at_hours` after its first time. Needs wave height, direction and period fields; cost in
    danger x km."""
    heuristic_weight(method, None)
    fc = ForecastGrid(forecast, variables)
    model = WaveDanger(fc, ship_length_m, speed_kn, at_hours)
    return fc.prepare(land, neighbourhood).route(start, end, model=model, method=method)


def position_at(route: Route, hours: float) -> tuple[int, tuple[float, float]]:
    """(index, (lat, lon)) of the last pixel of a time route the ship has reached `hours` after
    departure."""
    elapsed = np.concatenate([[0.0], np.cumsum(route.costs())])
    i = int(np.searchsorted(elapsed, hours, side="right") - 1)
    return i, tuple(map(float, route.coords[i]))


def replan(route: Route, hours: float, forecast, end, **kwargs) -> Route:
    """Grinyak et al. 2018's re-planning: route again from where the ship is `hours` after departure,
    with a newer `forecast`, leaving at that time. kwargs go to route_time()."""
    voyage = route.stats.voyage
    if voyage is None or voyage.departure is None:
        raise ForecastError("re-planning needs a route found through a forecast with a time axis")
    i, here = position_at(route, hours)
    reached = float(np.sum(route.costs()[:i]))
    departure = voyage.departure + np.timedelta64(int(round(reached * 3.6e12)), "ns")
    return route_time(forecast, here, end, departure=departure, **kwargs)
