"""A season of ice charts: routes through ice that changes during the voyage (issue 10).

A season is an ice chart Dataset (see seaway.ice) with a `time` dimension: CT (tenths) with SA
(WMO stage) and/or `thickness` (m), and `land`. Build one from SIGRID-3 files with their dates
(`read_season`) or open a NetCDF with a time dimension (`as_season` also takes CF
`sea_ice_area_fraction` and `sea_ice_thickness`, e.g. an ocean model's aice and hice).

How a step reads the charts: chart k is valid from its time until the next chart's time (the
last one for ever after) — piecewise constant, as ice services mean "valid at". A step started
at time t crosses the ice of the chart valid at t, at the class's speed there; its duration is
the exact time of the straight step through that chart (the line integral of 1 / speed over the
pixels it crosses), and it is closed if its segment touches a pixel closed in that chart.

Waiting is allowed, anywhere the ship has reached (including its start: a later departure).
Without it the graph is not FIFO — leaving just before a chart that clears the ice would arrive
later than leaving with that chart — and label-setting would not be exact. With it a step's
arrival is min over departures t' >= t of t' + duration(t'), which never decreases with t, so
the search's earliest-arrival labels are exact (cpp/seaway/ice_time.hpp). A ship waits wherever
it is, also in ice its class may not enter meanwhile: the charts are not drift forecasts.

Speed of a class in a chart's ice (knots), `speed=`:
* "andreeva" (default): paper 002, V = F * V0, F = f1 * f2 * f3 with f2 = 1 - h / h_pass
  (h_pass the class's Table-1 thickness unless given); h is the `thickness` layer if the season
  has one, else the governing stage's typical thickness (the upper end of its WMO range by
  default: conservative; `stage_thickness="mid"` takes the middle); f1 * f3 is `other_factor`
  (1 by default; e.g. andreeva.f1(draft, depth) for depth). Ice-free water: V0.
* a table {WMO stage: knots} or {stage: {max CT tenths: knots, ...}} read on the governing stage
  (55 ice free, 99 unknown) and total concentration; a stage the table lacks raises.
Either way, unknown ice (NaN CT, stage 99, old ice without a thickness), land and pixels off the
chart are closed, and with `concentration_limit=True` (default) so is ice above the class's
independent-navigation concentration (paper 000 Table 1: Arc4-Arc6 6/10, Arc7-Arc8 8/10).
"""

from __future__ import annotations

import warnings

import numpy as np
import xarray as xr

from .. import _core
from .._chart import as_chart
from .._engine import PreparedChart, _check_options, _describe, _heuristic_weight, locate
from .._interrupt import interruptible
from ..errors import NoRouteError
from ..route import Route
from .andreeva import KM_PER_NM, f2
from .classes import get_class
from .codes import ICE_FREE, STAGE_CODES
from .impact import governing_stage


def read_season(charts, grid, **read_kwargs) -> xr.Dataset:
    """SIGRID-3 files with their dates -> a season Dataset on `grid` (seaway.ice.grids).
    charts: {date: path} or [(date, path), ...]; each chart is valid from its date (any form
    numpy.datetime64 takes) until the next one's. read_kwargs go to read_sigrid3."""
    from .sigrid import read_sigrid3

    items = list(charts.items()) if isinstance(charts, dict) else list(charts)
    if not items:
        raise ValueError("give at least one (date, path) chart")
    dated = sorted((np.datetime64(d, "s"), p) for d, p in items)
    frames = [read_sigrid3(p, grid, **read_kwargs) for _, p in dated]
    keep = ["CT", "CA", "SA", "land", "off_chart"]
    ds = xr.concat([f[keep] for f in frames], dim="time", coords="minimal", compat="override")
    return ds.assign_coords(time=[d for d, _ in dated])


def as_season(season) -> xr.Dataset:
    """A season Dataset from a Dataset or NetCDF path: CF sea_ice_area_fraction (fraction or %)
    becomes CT in tenths, sea_ice_thickness becomes `thickness` (m); times sorted and unique."""
    if not isinstance(season, xr.Dataset):
        from ..forecast import open_forecast

        season = open_forecast(season)
    ds = season
    by_std = {v.attrs.get("standard_name"): k for k, v in ds.data_vars.items()}
    if "CT" not in ds and "sea_ice_area_fraction" in by_std:
        frac = ds[by_std["sea_ice_area_fraction"]]
        scale = 0.1 if str(frac.attrs.get("units", "")).strip() in ("%", "percent") else 10.0
        ds = ds.assign(CT=(frac * scale).clip(0.0, 10.0))  # models' round-off: -1e-6 ... 1 + 1e-6
    if "thickness" not in ds and "sea_ice_thickness" in by_std:
        ds = ds.assign(thickness=ds[by_std["sea_ice_thickness"]])
    if "time" not in ds.dims:
        raise ValueError("a season needs a `time` dimension (one chart per time); for one chart, "
                         "add it with ds.expand_dims(time=[date])")
    if "CT" not in ds or not ({"SA", "thickness"} & set(ds)):
        raise ValueError(f"a season needs CT (tenths, or CF sea_ice_area_fraction) and SA (WMO "
                         f"stage) or thickness (m, or CF sea_ice_thickness); it has {sorted(ds.data_vars)}")
    t = ds["time"].values
    if t.size > 1 and not np.all(t[1:] > t[:-1]):
        raise ValueError("chart times must be unique and increasing: ds.sortby('time'), then drop "
                         "duplicate dates")
    return ds


def _concentration(frame):
    return np.asarray(frame["CT"].values, dtype=float)


def _closed(frame, ct, ice_class, concentration_limit):
    """Where no class may go: land, off the chart, unknown concentration, over the class's limit."""
    shut = np.isnan(ct)
    for name in ("land", "off_chart"):
        if name in frame:
            shut |= np.asarray(frame[name].values, dtype=bool)
    if concentration_limit:
        shut |= ct > get_class(ice_class).max_concentration
    return shut


def andreeva_speed_kn(frame, ice_class, v0_kn, *, h_pass_m=None, stage_thickness="upper",
                      other_factor=1.0, concentration_limit=True) -> np.ndarray:
    """Paper 002's V = F * V0 (knots) on one chart of a season; 0 where closed."""
    ct = _concentration(frame)
    h_pass = get_class(ice_class).h_pass if h_pass_m is None else float(h_pass_m)
    if not h_pass > 0:
        raise ValueError(f"{get_class(ice_class).name} passes no ice (h_pass 0); give h_pass_m")
    if "thickness" in frame:
        h = np.asarray(frame["thickness"].values, dtype=float)
    else:
        if stage_thickness not in ("upper", "mid"):
            raise ValueError(f"stage_thickness must be 'upper' or 'mid', got {stage_thickness!r}")
        stage = governing_stage(frame).values
        h = np.full(ct.shape, np.nan)
        for code, (_, (lo, hi)) in STAGE_CODES.items():
            h[stage == code] = hi if stage_thickness == "upper" else 0.5 * (lo + hi)
    h = np.where(ct == 0, 0.0, h)
    speed = f2(h, h_pass) * np.asarray(other_factor, dtype=float) * v0_kn
    return np.where(_closed(frame, ct, ice_class, concentration_limit), 0.0, speed)


def table_speed_kn(frame, ice_class, table, *, concentration_limit=True) -> np.ndarray:
    """Speeds (knots) from a user table on one chart: {stage: kn} or {stage: {max CT: kn}}."""
    ct = _concentration(frame)
    stage = governing_stage(frame).values
    speed = np.zeros(ct.shape)
    known = np.isnan(stage)
    for code, entry in table.items():
        hit = stage == float(code)
        known |= hit
        if isinstance(entry, dict):
            left = hit.copy()
            for limit in sorted(entry):
                take = left & (ct <= float(limit))
                speed[take], left = float(entry[limit]), left & ~take
            speed[left] = 0.0  # concentrations above the table's last row: closed
        else:
            speed[hit] = float(entry)
    if not known.all():
        missing = sorted({float(c) for c in np.unique(stage[~known])})
        raise ValueError(f"the speed table has no entry for stages {missing[:10]} met in the "
                         f"season (e.g. {ICE_FREE} ice free, 99 unknown); add them (0 knots closes them)")
    if not np.all(np.isfinite(speed) & (speed >= 0)):
        raise ValueError("speeds in the table must be finite knots >= 0")
    return np.where(_closed(frame, ct, ice_class, concentration_limit), 0.0, speed)


class SeasonChart:
    """A season turned into engine inputs for one vessel and departure: hours per km
    (float32, frames from the chart valid at departure on), validity times in hours after
    departure, and the prepared chart (pixels closed in every frame are impassable)."""

    def __init__(self, season, *, ice_class, v0_kn, departure, speed, land, neighbourhood,
                 **speed_options):
        _check_options(neighbourhood, "full", "integral")
        if not (np.isfinite(v0_kn) and v0_kn > 0):
            raise ValueError(f"v0_kn must be a positive speed in knots, got {v0_kn!r}")
        ds = as_season(season)
        times = ds["time"].values
        self.departure = times[0] if departure is None else np.datetime64(departure)
        if self.departure < times[0]:
            raise ValueError(f"departure {self.departure} is before the first chart ({times[0]}): "
                             "the ice then is unknown; depart later or add an earlier chart")
        k0 = int(np.searchsorted(times, self.departure, side="right")) - 1
        self.times = times[k0:]
        self.valid_from_h = ((self.times - self.departure) / np.timedelta64(1, "h")).astype(float)
        speeds = []
        for k in range(k0, times.size):
            frame = ds.isel(time=k)
            if callable(getattr(speed, "get", None)):
                speeds.append(table_speed_kn(frame, ice_class, speed, **speed_options))
            elif speed == "andreeva":
                speeds.append(andreeva_speed_kn(frame, ice_class, v0_kn, **speed_options))
            else:
                raise ValueError(f"speed must be 'andreeva' or a table {{stage: knots}}, got {speed!r}")
        speed_kn = np.stack(speeds)
        fastest = float(speed_kn.max())
        if not fastest > 0:
            raise NoRouteError(f"class {get_class(ice_class).name} may go nowhere in any chart of the "
                               "season from departure on")
        with np.errstate(divide="ignore"):
            hours = np.where(speed_kn > 0, 1.0 / (speed_kn * KM_PER_NM), np.inf)
        self.hours_per_km = np.ascontiguousarray(hours, dtype=np.float32)
        self.min_hours_per_km = float(self.hours_per_km.min())
        template = ds["CT"].isel(time=0, drop=True)
        never = np.all(speed_kn <= 0, axis=0)
        sea = template.copy(data=np.where(never, np.nan, 1.0).astype(np.float32))
        self.chart = as_chart(sea.drop_vars([c for c in sea.coords if c not in sea.dims]), land=land)
        self.neighbourhood = neighbourhood
        self.prepared = PreparedChart._from_chart(self.chart, neighbourhood, "full", "integral", "segment")
        self._ice_class, self._last = get_class(ice_class).name, ds.isel(time=-1)

    def locate(self, point, name):
        """locate(), naming the ice when the point is at sea but closed in every chart."""
        try:
            return locate(self.chart, point, name)
        except ValueError as exc:
            dry = np.zeros(self.chart.shape, bool)
            for k in ("land", "off_chart"):
                if k in self._last:
                    dry |= np.asarray(self._last[k].values, bool)
            if self.chart.land is not None:
                dry |= self.chart.land.astype(bool)
            sea = self.chart.template.copy(data=np.where(dry, np.nan, 1.0).astype(np.float32))
            try:
                r, c = locate(as_chart(sea), point, name)
            except ValueError:
                raise exc from None
            f = self._last.isel({d: i for d, i in zip(self._last["CT"].dims, (r, c))})
            ice = ", ".join(f"{k} {float(f[k]):g}" for k in ("CT", "SA", "thickness") if k in f)
            near = str(exc).split("; ", 1)[-1]
            raise ValueError(f"{name} {_describe(self.chart, (r, c))} is in ice class {self._ice_class} may "
                             f"not enter in any chart from {self.departure} on (last chart: {ice}); "
                             f"{near}") from None


def route_season(season, start, end, *, ice_class="Arc7", v0_kn=12.0, departure=None,
                 speed="andreeva", land=None, neighbourhood=5, method="astar",
                 **speed_options) -> Route:
    """The earliest-arriving route from `start` to `end` through a season of ice charts.

    season: a season Dataset or NetCDF path (see the module docstring and as_season).
    ice_class: any class of seaway.ice.classes; v0_kn: its open-water speed (knots).
    departure: a date within the season (default its first chart's time).
    speed: "andreeva" (paper 002) or a speed table; speed_options go to andreeva_speed_kn
        (h_pass_m, stage_thickness, other_factor, concentration_limit) or table_speed_kn.
    Returns a Route whose cost is the passage time in hours, waiting included; stats hold
    departure, arrival, hours_under_way, hours_waiting, waits (pixel, (lat, lon) or (y, x),
    from, hours) and the dates of the charts the voyage used."""
    w = _heuristic_weight(method, None)
    sc = SeasonChart(season, ice_class=ice_class, v0_kn=v0_kn, departure=departure, speed=speed,
                     land=land, neighbourhood=neighbourhood, **speed_options)
    chart = sc.chart
    s, e = sc.locate(start, "start"), sc.locate(end, "end")
    cols = chart.shape[1]
    (hours, path, stats, cumulative), depart = interruptible(lambda cancel: _core.route_ice_season(
        sc.prepared._router, s[0] * cols + s[1], e[0] * cols + e[1], w, sc.hours_per_km,
        sc.valid_from_h, sc.min_hours_per_km, cancel))
    if not np.isfinite(hours):
        raise NoRouteError(f"no route for class {get_class(ice_class).name} from {_describe(chart, s)} "
                           f"to {_describe(chart, e)} in any chart of the season from {sc.departure} "
                           "on, even waiting for the ice to clear; try a stronger class or another end")
    pixels = np.column_stack(np.divmod(path, cols)).astype(np.int64)
    depart = np.asarray(depart, float)
    wait = depart - cumulative[:-1]
    coords = chart.pixel_coords(pixels)
    at = lambda h: sc.departure + np.timedelta64(int(round(h * 3.6e6)), "ms")  # noqa: E731
    waits = [(tuple(int(x) for x in pixels[i]), tuple(float(x) for x in coords[i]), at(cumulative[i]),
              float(wait[i])) for i in np.flatnonzero(wait > 1e-9)]
    used = np.unique(np.searchsorted(sc.valid_from_h, depart, side="right") - 1)
    stats = dict(stats, hours=float(hours), departure=sc.departure, arrival=at(hours),
                 hours_waiting=float(wait.sum()), hours_under_way=float(hours - wait.sum()),
                 waits=waits, charts_used=[sc.times[k] for k in used], ice_class=get_class(ice_class).name)
    if sc.valid_from_h.size > 1 and hours > sc.valid_from_h[-1] + np.median(np.diff(sc.valid_from_h)):
        warnings.warn(f"the voyage arrives at {stats['arrival']}, beyond the last chart ({sc.times[-1]}) "
                      "and its usual validity; the last chart was assumed to hold", stacklevel=2)
    return Route(chart=chart, cost=float(hours), pixels=pixels, method=method,
                 neighbourhood=neighbourhood, edge_cost="time", stats=stats,
                 step_costs=np.diff(cumulative), speed_kn=float(v0_kn))


def arrival_field(season, start, *, ice_class="Arc7", v0_kn=12.0, departure=None,
                  speed="andreeva", land=None, neighbourhood=5, **speed_options):
    """Earliest arrival at every pixel from `start` (hours after departure; inf where never),
    a DataArray on the season's grid: isochrones of the voyage."""
    sc = SeasonChart(season, ice_class=ice_class, v0_kn=v0_kn, departure=departure, speed=speed,
                     land=land, neighbourhood=neighbourhood, **speed_options)
    s = sc.locate(start, "start")
    field, _ = interruptible(lambda cancel: _core.ice_season_field(
        sc.prepared._router, s[0] * sc.chart.shape[1] + s[1], sc.hours_per_km, sc.valid_from_h,
        sc.min_hours_per_km, cancel))
    out = sc.chart.template.copy(data=field)
    out.name = "arrival_hours"
    out.attrs = {"long_name": "earliest arrival after departure (waiting allowed)", "units": "h",
                 "departure": str(sc.departure), "ice_class": get_class(ice_class).name}
    return out
