"""Small random voyages on a clock for the tests of legs sailed on the clock and of smoothing
time routes (tests/models/test_timed_legs.py, test_smooth_time.py): each case gives the route
as found (engine steps), its TimedLegs and the reference's rate, is_open and land
(support.reference_timed). Fields independent in every pixel (the hardest case for a straight
leg, which meets every pixel's weather where an engine step reads only its two ends), or
(smooth=True) varying smoothly as real ice and weather do."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import xarray as xr

import seaway
from seaway.ice.seasongrid import SeasonGrid
from seaway.icenav.season import route_season
from seaway.models import IceWeatherTime
from seaway.weather import ForecastGrid, Vessel, route_time
from support import reference_timed as ref
from support.forecasts import forecast
from support.reference_weather import Weather
from support.seasons import DAY0, planar_season

#: Speeds by WMO stage (knots); 0 closes the stage.
TABLE = {55: 12.0, 87: 6.0, 91: 3.0, 93: 0.0}
SHIP = Vessel(speed_kn=12.0, displacement_t=15000.0, max_wind_ms=20.0)


@dataclass
class Case:
    route: object  # the route as found
    grid: ref.Grid
    move_hours: object
    is_open: object
    land: np.ndarray

    @property
    def legs(self):
        r = self.route
        return r.model.timed_legs(r.chart, r.neighbourhood)

    def sail(self, p, q, t0, n=20000):
        return ref.sail(self.grid, p, q, t0, self.move_hours, self.is_open, self.land, n)


def _wave(rng, frames, shape, lo, hi):
    """A field that varies smoothly in space and time between lo and hi: two travelling sines
    across each other (patches, not bands)."""
    r, c = np.meshgrid(np.arange(shape[0]), np.arange(shape[1]), indexing="ij")
    t = np.arange(frames)[:, None, None]
    x = 0.5
    for sign in (1, -1):
        kr, kc, w, phase = *rng.uniform(0.2, 0.6, 2), rng.uniform(0.1, 0.4), rng.uniform(0, 2 * np.pi)
        x = x + 0.25 * np.sin(kr * r + sign * kc * c + w * t + phase)
    return lo + (hi - lo) * x


def _stages(rng, frames, shape, closed=0.15, smooth=False):
    """WMO stages: independent in every pixel, or (smooth) in patches that drift chart by chart."""
    if smooth:
        x = _wave(rng, frames, shape, 0.0, 1.0)
        stage = np.select([x < 0.6 - closed, x < 0.85 - closed, x < 1 - closed], [55, 87, 91], 93)
    else:
        stage = rng.choice([55, 87, 91, 93], size=(frames,) + shape, p=[0.6 - closed, 0.25, 0.15, closed])
    stage[:, 0, 0] = stage[:, -1, -1] = 55
    return stage


def _hours(rng, frames):
    """Chart times 0.5-3 h apart, whole seconds, then the last chart again two days on (so that
    no voyage outlasts the season's charts)."""
    hours = np.round(np.concatenate([[0.0], np.cumsum(rng.uniform(0.5, 3.0, frames - 2))]) * 3600) / 3600
    return np.concatenate([hours, [hours[-1] + 48.0]])


def _held(stage):
    """The last chart of `stage` again (see _hours)."""
    stage[-1] = stage[-2]
    return stage


def ice_planar(seed, shape=(7, 9), k=5, closed=0.15, smooth=False):
    """A planar season of 10 km pixels, charts every 0.5-3 h, the TABLE speeds."""
    rng = np.random.default_rng(seed)
    frames = 5
    stage = _held(_stages(rng, frames, shape, closed, smooth))
    ds = planar_season(stage, hours=_hours(rng, frames))
    r = route_season(
        ds,
        (0, 0),
        (shape[0] - 1, shape[1] - 1),
        speed=TABLE,
        concentration_limit=False,
        neighbourhood=k,
        smooth=False,
    )
    h, valid = r.model.hours_per_km, r.model.valid_from_h
    land = np.zeros(shape, bool)
    return Case(r, ref.Grid(dy=10.0, dx=10.0), ref.season_move(h, valid), ref.season_open(h, valid), land)


def latlon_season(stage, hours, lat, lon, land=None):
    """A season Dataset on a lat/lon grid: stage (K, R, C), charts at `hours` after DAY0."""
    time = DAY0 + (np.asarray(hours) * 3600).astype("timedelta64[s]")
    ct = np.where(stage == 55, 0.0, 9.0)
    sa = np.where(stage == 55, np.nan, stage).astype(float)
    land = np.zeros(stage.shape[1:], bool) if land is None else land
    return xr.Dataset(
        {
            "CT": (("time", "lat", "lon"), ct),
            "SA": (("time", "lat", "lon"), sa),
            "land": (("time", "lat", "lon"), np.broadcast_to(land, stage.shape)),
        },
        coords={"time": time, "lat": lat, "lon": lon},
    )


def ice_latlon(seed, shape=(8, 10), k=5, closed=0.15, smooth=False):
    """A lat/lon season (0.1 deg x 0.25 deg at 72 N, ~11 x 8.6 km), a land pixel or two."""
    rng = np.random.default_rng(seed)
    frames = 5
    stage = _held(_stages(rng, frames, shape, closed, smooth))
    lat, lon = 72.0 + 0.1 * np.arange(shape[0]), 60.0 + 0.25 * np.arange(shape[1])
    land = rng.random(shape) < 0.06
    land[0, 0] = land[-1, -1] = False
    ds = latlon_season(stage, _hours(rng, frames), lat, lon, land)
    a, b = (lat[0], lon[0]), (lat[-1], lon[-1])
    r = route_season(ds, a, b, speed=TABLE, concentration_limit=False, neighbourhood=k, smooth=False)
    h, valid = r.model.hours_per_km, r.model.valid_from_h
    return Case(r, ref.Grid(lat, lon), ref.season_move(h, valid), ref.season_open(h, valid), land)


def _fields(rng, frames, shape, closed, smooth=False):
    """Currents, waves and wind (above the vessel's 20 m/s limit in a share `closed` of the
    pixels): independent in every pixel and frame, or (smooth) travelling sines."""
    wind = np.where(rng.random(shape) < closed, 24.0, 8.0)
    wind[0, 0] = wind[-1, -1] = 8.0
    wind = np.broadcast_to(wind, (frames,) + shape) * rng.uniform(0.8, 1.0, (frames, 1, 1))
    if smooth:
        return dict(
            ce=_wave(rng, frames, shape, -0.8, 0.8),
            cn=_wave(rng, frames, shape, -0.8, 0.8),
            hs=_wave(rng, frames, shape, 0.0, 2.5),
            wdir=_wave(rng, frames, shape, 180.0, 300.0),
            wind=wind,
        )
    return dict(
        ce=rng.uniform(-0.8, 0.8, (frames,) + shape),
        cn=rng.uniform(-0.8, 0.8, (frames,) + shape),
        hs=rng.uniform(0.0, 2.5, (frames,) + shape),
        wdir=rng.uniform(0, 360, (frames,) + shape),
        wind=wind,
    )


def weather(seed, shape=(9, 11), k=5, zones=(), closed=0.12, smooth=False):
    """Currents, waves and a wind over the vessel's 20 m/s limit in some pixels, 3-hourly."""
    rng = np.random.default_rng(seed)
    frames = 6
    fields = _fields(rng, frames, shape, closed, smooth)
    fc = forecast(shape=shape, frames=frames, hours=3, step=0.1, lat0=70.0, lon0=20.0, **fields)
    lat, lon = fc.lat.values, fc.lon.values
    r = route_time(
        fc, (lat[0], lon[0]), (lat[-1], lon[-1]), vessel=SHIP, neighbourhood=k, zones=zones, smooth=False
    )
    w = Weather({key: fc[key].values for key in fields}, lat, lon, step_h=3.0, max_wind_ms=20.0)
    land = np.zeros(shape, bool)
    return Case(r, ref.Grid(lat, lon), ref.weather_move(w, 12.0), ref.weather_open(w), land)


def ice_weather(seed, shape=(8, 10), k=5, closed=0.1, smooth=False):
    """A lat/lon season and a forecast on its grid, routed at once (IceWeatherTime)."""
    rng = np.random.default_rng(seed)
    charts, frames = 4, 6
    stage = _held(_stages(rng, charts, shape, closed, smooth))
    lat, lon = 72.0 + 0.1 * np.arange(shape[0]), 60.0 + 0.25 * np.arange(shape[1])
    ice = latlon_season(stage, [0.0, 2.0, 5.0, 53.0], lat, lon)
    fields = _fields(rng, frames, shape, closed, smooth)
    fc = forecast(lat=lat, lon=lon, start=DAY0, frames=frames, hours=2, **fields)
    grid = SeasonGrid(ice)
    model = IceWeatherTime(grid, ForecastGrid(fc), "Arc7", SHIP, speed=TABLE, concentration_limit=False)
    r = seaway.prepare(grid, neighbourhood=k).route((lat[0], lon[0]), (lat[-1], lon[-1]), model=model)
    w = Weather({key: fc[key].values for key in fields}, lat, lon, step_h=2.0, max_wind_ms=20.0)
    pair = (model.hours_per_km, model.valid_from_h)
    land = np.zeros(shape, bool)
    return Case(r, ref.Grid(lat, lon), ref.weather_move(w, 12.0, pair), ref.weather_open(w, pair), land)


def schedule(route):
    """(arrive_h, leave_h) at every vertex of a route on a clock."""
    v = route.stats.voyage
    arrive = np.concatenate([[0.0], np.cumsum(route.costs())])
    leave = arrive.copy()
    leave[:-1] += v.wait_h
    return arrive, leave
