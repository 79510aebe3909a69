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

import numpy as np

from . import _core
from ._chart import as_chart
from ._engine import PreparedChart, _check_options, _heuristic_weight
from .forecast import STANDARD_NAMES, find_fields
from .models import EdgeCost, TravelTime, WaveDanger
from .route import Route
from .vessel import Vessel

__all__ = ["ForecastGrid", "Vessel", "route_time", "route_safest", "rhumb_line_km",
           "position_at", "replan"]

KNOTS_PER_MS = 3600.0 / 1852.0


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


class ForecastGrid:
    """A forecast as the engine reads it: float32 (frames, rows, cols) fields by role (NaN set
    to 0), the time axis relative to `departure` (default the first time), and where the sea is
    (not NaN in every field). The models of seaway.models read it; prepare() gives the chart
    to route on (its static cost: 1 per km)."""

    def __init__(self, forecast, variables=None, departure=None):
        fields = find_fields(forecast, variables)
        if not fields:
            raise ValueError("the forecast has no field seaway knows; mark them with CF standard "
                             f"names ({', '.join(n[0] for n in STANDARD_NAMES.values())}) or pass "
                             "variables=")
        some = next(iter(fields.values()))
        dims = tuple(d for d in some.dims if d != "time")
        self.frames, self.first_h, self.step_h = _time_axis(forecast, departure)
        arrays = {role: _frames(f, dims, self.frames) for role, f in fields.items()}
        self.dry = np.all([np.isnan(a).all(axis=0) for a in arrays.values()], axis=0)
        if "wind_speed" not in arrays and "wind_east" in arrays:
            arrays["wind_speed"] = np.hypot(arrays.pop("wind_east"), arrays.pop("wind_north"))
        arrays.pop("wind_east", None), arrays.pop("wind_north", None)
        self.arrays = {k: np.ascontiguousarray(np.nan_to_num(a, nan=0.0)) for k, a in arrays.items()}
        self.template = some.isel(time=0, drop=True) if "time" in some.dims else some
        self.shape = self.dry.shape
        self.departure = None
        if "time" in forecast.dims:
            self.departure = (forecast["time"].values[0] if departure is None
                              else np.datetime64(departure))

    def prepare(self, land=None, neighbourhood=5) -> PreparedChart:
        """The forecast's lat/lon grid as a chart: land where every field is NaN or `land` is
        True; its static cost is 1 per km (distance), the weather models bring their own."""
        _check_options(neighbourhood, "full")
        km = self.template.copy(data=np.ones(self.shape, np.float32))
        chart = as_chart(km, land=self.dry if land is None else (np.asarray(land, bool) | self.dry))
        if not chart.geographic:
            raise ValueError("weather routing needs a forecast on a lat/lon grid (coordinates lat/lon)")
        return PreparedChart._from_chart(chart, neighbourhood, "full", EdgeCost("max"), "segment")

    def engine(self) -> _core.Forecast:
        return _core.Forecast(self.first_h, self.step_h, **self.arrays)

    def frame_at(self, hours, roles) -> ForecastGrid:
        """A one-frame copy with the fields of `roles` it has: the frame valid nearest `hours`
        after departure."""
        k = int(np.clip(round((hours - self.first_h) / self.step_h), 0, self.frames - 1))
        out = object.__new__(ForecastGrid)
        out.__dict__.update(self.__dict__, frames=1, first_h=0.0, step_h=1.0)
        out.arrays = {r: np.ascontiguousarray(self.arrays[r][k:k + 1]) for r in roles
                      if r in self.arrays}
        return out

    def best_extra_kn(self, vessel: Vessel) -> float:
        """The most the weather can add to a calm-water speed: following seas under Khokhlov's
        formula, plus the strongest current (for A*'s admissible bound)."""
        extra, a = 0.0, self.arrays
        if vessel.speed_loss == "khokhlov" and "wave_height" in a:
            gain = (0.275 * np.pi - 0.745) * 1.32 * float(a["wave_height"].max())
            extra += max(gain, 0.0) * (1 - 1.35e-6 * vessel.displacement_t * vessel.speed_kn)
        if "current_east" in a:
            extra += float(np.hypot(a["current_east"], a["current_north"]).max()) * KNOTS_PER_MS
        return extra


def route_time(forecast, start, end, *, vessel: Vessel = Vessel(), departure=None, land=None,
               neighbourhood=5, method="astar", variables=None) -> Route:
    """The quickest route from `start` to `end` (lat, lon) through a forecast.

    forecast: xarray.Dataset on a regular lat/lon grid, optionally with a `time` dimension
        (regular steps, e.g. 6-hourly); fields found by CF standard name (STANDARD_NAMES) or
        `variables`. NaN in every field at a pixel marks land, as do True pixels of `land`.
    departure: a datetime (numpy/pandas/str) within or before the forecast; default its first time.
    Returns a Route whose cost is the passage time in hours (stats hold departure and arrival).
    The same as ForecastGrid(forecast).prepare().route(start, end, model=TravelTime(...)).
    """
    vessel.check()
    _heuristic_weight(method, None)
    fc = ForecastGrid(forecast, variables, departure)
    model = TravelTime(fc, vessel)
    return fc.prepare(land, neighbourhood).route(start, end, model=model, method=method)


def route_safest(forecast, start, end, *, ship_length_m, speed_kn, at_hours=0.0, land=None,
                 neighbourhood=5, method="astar", variables=None) -> Route:
    """The route of least wave danger (paper 003): minimises sum (u_i + u_j) / 2 * r with the
    danger u in [1, 10] from MSC.1/Circ.1228's criteria for the step's heading (see
    seaway._core.wave_danger and cpp/seaway/waves.hpp), on the forecast frame valid nearest
    `at_hours` after its first time. Needs wave height, direction and period fields; cost in
    danger x km."""
    _heuristic_weight(method, None)
    fc = ForecastGrid(forecast, variables)
    model = WaveDanger(fc, ship_length_m, speed_kn, at_hours)
    return fc.prepare(land, neighbourhood).route(start, end, model=model, method=method)


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
