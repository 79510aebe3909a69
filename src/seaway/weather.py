"""Time-optimal routes through forecasts of currents, wind and waves (papers 001 and 004).

A step's cost is its duration in hours. The weather is read at both ends of the step, at the
time the ship starts it, linearly interpolated between forecast frames (held constant before
the first frame and after the last). The search labels every pixel with its earliest arrival
time, which is exact when the weather is FIFO: leaving later never means arriving earlier
(true unless a forecast speeds the ship up faster than time passes).

Physics (paper 001), computed in the C++ core for every step and course:
* speed through water in wind waves, Khokhlov (eq. 8):
  V = V0 - (0.745 h - 0.275 q h)(1 - 1.35e-6 D V0), h = 1.32 x significant height (3 % waves,
  Rayleigh), q the waves' bearing from the bow in radians (0 head seas, pi following seas),
  D displacement in t, V in knots; valid for 5000-25000 t and 9-20 kn;
* speed over ground holding the track through a current Vt at angle q to the course:
  V = Vt cos q + sqrt(V0^2 - (Vt sin q)^2). The paper prints a plus under the root; holding
  the track means cancelling the cross current, which gives the minus (DOMAIN.md), and
  Vt |sin q| >= V0 (the track cannot be held) is impassable;
* impassable where the wind exceeds max_wind_ms (25 m/s) or the waves max_wave_m (5 m), and,
  for paper 004's moving danger zones, where the wind exceeds danger_wind_ms (11 m/s) at the
  time the ship would be there.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from . import _core
from ._chart import as_chart
from ._engine import PreparedChart, _check_options, _describe, _heuristic_weight, locate
from ._interrupt import interruptible
from ._validate import number
from .errors import NoRouteError
from .forecast import STANDARD_NAMES, find_fields
from .route import Route

KNOTS_PER_MS = 3600.0 / 1852.0
@dataclass(frozen=True)
class Vessel:
    """A ship for weather routing. Speeds in knots, displacement in tonnes, limits in SI."""

    speed_kn: float = 15.0
    displacement_t: float = 15000.0
    #: "khokhlov" (paper 001; 5000-25000 t, 9-20 kn), "stawave1" (any size: STAWAVE-1's added
    #: resistance in bow waves at constant power; needs beam_m, length_m, calm_resistance_kn),
    #: or "none" (waves only limit where the ship may go).
    speed_loss: str = "khokhlov"
    max_wind_ms: float = 25.0
    max_wave_m: float = 5.0
    danger_wind_ms: float | None = None  # paper 004: 11 m/s zones avoided while forecast
    outside_validity: str = "refuse"  # a speed-loss model outside its range: or "warn"
    beam_m: float | None = None  # waterline breadth
    length_m: float | None = None  # waterline length
    calm_resistance_kn: float | None = None  # calm-water resistance at speed_kn, kN

    def _outside(self, msg):
        if self.outside_validity == "warn":
            warnings.warn(msg, stacklevel=4)
        else:
            raise ValueError(msg + "; pass outside_validity='warn' to go on, or another speed_loss")

    def check_waves(self, max_hs_m: float):
        """STAWAVE-1 holds for Hs <= 2.25 sqrt(L / 100) (ITTC 7.5-04-01-01.1)."""
        if self.speed_loss == "stawave1" and max_hs_m > 2.25 * np.sqrt(self.length_m / 100):
            self._outside(f"STAWAVE-1 holds for significant heights up to 2.25 sqrt(L/100) = "
                          f"{2.25 * np.sqrt(self.length_m / 100):.2f} m; the forecast has {max_hs_m:.2f} m")

    def check(self):
        number(self.speed_kn, "speed_kn", above=0, what="positive", example=12.0)
        for name in ("displacement_t", "max_wind_ms", "max_wave_m"):
            number(getattr(self, name), name, above=0)
        for name in ("danger_wind_ms", "beam_m", "length_m", "calm_resistance_kn"):
            if getattr(self, name) is not None:
                number(getattr(self, name), name, above=0)
        if self.speed_loss not in ("khokhlov", "stawave1", "none"):
            raise ValueError(f"speed_loss must be 'khokhlov', 'stawave1' or 'none', got {self.speed_loss!r}")
        if self.speed_loss == "stawave1":
            sizes = (self.beam_m, self.length_m, self.calm_resistance_kn)
            if not all(v is not None and np.isfinite(v) and v > 0 for v in sizes):
                raise ValueError("speed_loss='stawave1' needs positive beam_m, length_m and "
                                 "calm_resistance_kn (kN at speed_kn)")
        if self.speed_loss == "khokhlov":
            inside = 5000 <= self.displacement_t <= 25000 and 9 <= self.speed_kn <= 20
            if not inside:
                self._outside(f"Khokhlov's speed-loss formula holds for 5000-25000 t and 9-20 kn; "
                              f"this vessel is {self.displacement_t:g} t at {self.speed_kn:g} kn "
                              "(speed_loss='stawave1' covers other ships)")


def _time_axis(ds, departure):
    """(frames, first_h, step_h): frame k is valid first_h + k * step_h hours after departure."""
    if "time" not in ds.dims:
        return 1, 0.0, 1.0
    t = ds["time"].values
    if t.size == 1:
        return 1, 0.0, 1.0
    hours = (t - t[0]) / np.timedelta64(1, "h")
    step = float(hours[1] - hours[0])
    if step <= 0 or np.max(np.abs(np.diff(hours) - step)) > 1e-6:
        raise ValueError("forecast times must be regularly spaced and increasing; "
                         "resample it, e.g. ds.resample(time='6h').interpolate()")
    dep = t[0] if departure is None else np.datetime64(departure)
    return t.size, float((t[0] - dep) / np.timedelta64(1, "h")), step


def _frames(field, chart_dims, frames) -> np.ndarray:
    dims = (("time",) if "time" in field.dims else ()) + chart_dims
    if set(field.dims) != set(dims):
        raise ValueError(f"forecast field {field.name!r} has dims {field.dims}; expected {dims}")
    a = np.asarray(field.transpose(*dims).values, dtype=np.float32)
    if a.ndim == 2:
        a = np.broadcast_to(a, (frames,) + a.shape)
    return np.ascontiguousarray(a)


def route_time(forecast, start, end, *, vessel: Vessel = Vessel(), departure=None, land=None,
               neighbourhood=5, method="astar", variables=None) -> Route:
    """The quickest route from `start` to `end` (lat, lon) through a forecast.

    forecast: xarray.Dataset on a regular lat/lon grid, optionally with a `time` dimension
        (regular steps, e.g. 6-hourly); fields found by CF standard name (STANDARD_NAMES) or
        `variables`. NaN in every field at a pixel marks land, as do True pixels of `land`.
    departure: a datetime (numpy/pandas/str) within or before the forecast; default its first time.
    Returns a Route whose cost is the passage time in hours (stats hold departure and arrival).
    """
    vessel.check()
    w = _heuristic_weight(method, None)
    fc = _ForecastChart(forecast, variables, land, neighbourhood, departure)
    chart, arrays = fc.chart, fc.arrays
    if "wave_height" in arrays:
        vessel.check_waves(float(arrays["wave_height"].max()))
    best = vessel.speed_kn + best_extra_kn(fc.arrays, vessel)
    max_wind = vessel.max_wind_ms if vessel.danger_wind_ms is None else min(vessel.max_wind_ms,
                                                                             vessel.danger_wind_ms)
    s, e = locate(chart, start, "start"), locate(chart, end, "end")
    cols = chart.shape[1]
    hours, path, stats, cumulative = interruptible(lambda cancel: _core.route_time(
        fc.prepared._router, s[0] * cols + s[1], e[0] * cols + e[1], w, fc.arrays, fc.frames,
        fc.first_h, fc.step_h, _vessel_dict(vessel, max_wind), best, cancel))
    if not np.isfinite(hours):
        raise NoRouteError(f"no route from {_describe(chart, s)} to {_describe(chart, e)} within "
                           "the vessel's wind and wave limits (and danger zones) of this forecast; "
                           "try a later departure, other limits or another end point")
    stats = dict(stats, hours=hours)
    if "time" in forecast.dims:
        dep = forecast["time"].values[0] if departure is None else np.datetime64(departure)
        stats["departure"] = dep
        stats["arrival"] = dep + np.timedelta64(int(round(hours * 3600)), "s")
    return fc.route(path, hours, cumulative, stats, method, "time", speed_kn=vessel.speed_kn)


def best_extra_kn(arrays: dict, vessel: Vessel) -> float:
    """The most the weather can add to a calm-water speed: following seas under Khokhlov's
    formula, plus the strongest current (for A*'s admissible bound)."""
    extra = 0.0
    if vessel.speed_loss == "khokhlov" and "wave_height" in arrays:
        gain = (0.275 * np.pi - 0.745) * 1.32 * float(arrays["wave_height"].max())
        extra += max(gain, 0.0) * (1 - 1.35e-6 * vessel.displacement_t * vessel.speed_kn)
    if "current_east" in arrays:
        extra += float(np.hypot(arrays["current_east"], arrays["current_north"]).max()) * KNOTS_PER_MS
    return extra


def _vessel_dict(vessel: Vessel, max_wind_ms: float) -> dict:
    return {"speed_kn": vessel.speed_kn, "displacement_t": vessel.displacement_t,
            "speed_loss": vessel.speed_loss, "max_wind_ms": max_wind_ms,
            "max_wave_m": vessel.max_wave_m, "beam_m": vessel.beam_m or 0.0,
            "length_m": vessel.length_m or 0.0,
            "calm_resistance_kn": vessel.calm_resistance_kn or 0.0}


class _ForecastChart:
    """A forecast turned into engine inputs: float32 (frames, rows, cols) fields with NaN set
    to 0, the prepared lat/lon chart (land: NaN in every field, or `land`) and the time axis."""

    def __init__(self, forecast, variables, land, neighbourhood, departure):
        _check_options(neighbourhood, "full", "max")
        fields = find_fields(forecast, variables)
        if not fields:
            raise ValueError("the forecast has no field seaway knows; mark them with CF standard "
                             f"names ({', '.join(n[0] for n in STANDARD_NAMES.values())}) or pass "
                             "variables=")
        some = next(iter(fields.values()))
        dims = tuple(d for d in some.dims if d != "time")
        self.frames, self.first_h, self.step_h = _time_axis(forecast, departure)
        arrays = {role: _frames(f, dims, self.frames) for role, f in fields.items()}
        dry = np.all([np.isnan(a).all(axis=0) for a in arrays.values()], axis=0)
        if "wind_speed" not in arrays and "wind_east" in arrays:
            arrays["wind_speed"] = np.hypot(arrays.pop("wind_east"), arrays.pop("wind_north"))
        arrays.pop("wind_east", None), arrays.pop("wind_north", None)
        self.arrays = {k: np.ascontiguousarray(np.nan_to_num(a, nan=0.0)) for k, a in arrays.items()}
        template = some.isel(time=0, drop=True) if "time" in some.dims else some
        sea = template.copy(data=np.where(dry, np.nan, 1.0).astype(np.float32))
        self.chart = as_chart(sea, land=land)
        if not self.chart.geographic:
            raise ValueError("weather routing needs a forecast on a lat/lon grid (coordinates lat/lon)")
        self.neighbourhood = neighbourhood
        self.prepared = PreparedChart._from_chart(self.chart, neighbourhood, "full", "max", "segment")

    def frame(self, role, hours):
        """One (1, rows, cols) frame of a field: the one valid nearest `hours` after departure."""
        k = int(np.clip(round((hours - self.first_h) / self.step_h), 0, self.frames - 1))
        return np.ascontiguousarray(self.arrays[role][k:k + 1])

    def route(self, path, cost, cumulative, stats, method, objective, **extra):
        pixels = np.column_stack(np.divmod(path, self.chart.shape[1])).astype(np.int64)
        return Route(chart=self.chart, cost=float(cost), pixels=pixels, method=method,
                     neighbourhood=self.neighbourhood, edge_cost=objective, stats=stats,
                     step_costs=np.diff(cumulative), **extra)


def route_safest(forecast, start, end, *, ship_length_m, speed_kn, at_hours=0.0, land=None,
                 neighbourhood=5, method="astar", variables=None) -> Route:
    """The route of least wave danger (paper 003): minimises sum (u_i + u_j) / 2 * r with the
    danger u in [1, 10] from MSC.1/Circ.1228's criteria for the step's heading (see
    seaway._core.wave_danger and cpp/seaway/waves.hpp), on the forecast frame valid nearest
    `at_hours` after its first time. Needs wave height, direction and period fields; cost in
    danger x km."""
    number(ship_length_m, "ship_length_m", above=0, example=150.0)
    number(speed_kn, "speed_kn", above=0, example=12.0)
    number(at_hours, "at_hours")
    w = _heuristic_weight(method, None)
    fc = _ForecastChart(forecast, variables, land, neighbourhood, None)
    missing = {"wave_height", "wave_from", "wave_period"} - set(fc.arrays)
    if missing:
        raise ValueError(f"wave danger needs {sorted(missing)}: fields with standard names "
                         + ", ".join(STANDARD_NAMES[m][0] for m in sorted(missing)))
    s, e = locate(fc.chart, start, "start"), locate(fc.chart, end, "end")
    cols = fc.chart.shape[1]
    frame = {role: fc.frame(role, at_hours) for role in ("wave_height", "wave_from", "wave_period")}
    cost, path, stats, cumulative = interruptible(lambda cancel: _core.route_danger(
        fc.prepared._router, s[0] * cols + s[1], e[0] * cols + e[1], w, frame,
        float(ship_length_m), float(speed_kn), cancel))
    if not np.isfinite(cost):
        raise NoRouteError(f"no route at sea from {_describe(fc.chart, s)} to {_describe(fc.chart, e)}")
    return fc.route(path, cost, cumulative, dict(stats), method, "wave danger", speed_kn=speed_kn)


def rhumb_line_km(lat1, lon1, lat2, lon2, radius_km=6371.0088):
    """Loxodrome (constant course) distance on a sphere, km."""
    p1, p2 = np.radians(lat1), np.radians(lat2)
    dl = np.radians((lon2 - lon1 + 180.0) % 360.0 - 180.0)
    dpsi = np.log(np.tan(np.pi / 4 + p2 / 2) / np.tan(np.pi / 4 + p1 / 2))
    q = (p2 - p1) / dpsi if abs(dpsi) > 1e-12 else np.cos(p1)
    return float(radius_km * np.hypot(p2 - p1, q * dl))


def position_at(route: Route, hours: float) -> tuple[int, tuple[float, float]]:
    """(index, (lat, lon)) of the last pixel of a time route the ship has reached `hours` after
    departure."""
    elapsed = np.concatenate([[0.0], np.cumsum(route.costs())])
    i = int(np.searchsorted(elapsed, hours, side="right") - 1)
    return i, tuple(map(float, route.coords[i]))


def replan(route: Route, hours: float, forecast, end, **kwargs) -> Route:
    """Paper 003's re-planning: route again from where the ship is `hours` after departure,
    with a newer `forecast`, leaving at that time. kwargs go to route_time()."""
    if "departure" not in route.stats:
        raise ValueError("re-planning needs a route found through a forecast with a time axis")
    i, here = position_at(route, hours)
    reached = float(np.sum(route.costs()[:i]))
    departure = route.stats["departure"] + np.timedelta64(int(round(reached * 3.6e12)), "ns")
    return route_time(forecast, here, end, departure=departure, **kwargs)
