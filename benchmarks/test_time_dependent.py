"""Time-dependent routes against the static route on the same chart and voyage (issue 21): a
season of ice charts (IceSeasonTime) and a weather forecast (TravelTime), each on the Kara-Sea
grid of 1900 x 2300 lat/lon pixels, from the Kara Gate to the western approach of the Vilkitsky
Strait. Each case alternates the time-dependent and the static query in one process (medians
of 3 after a warm-up, wall) and asserts exactness where it can be checked: A* = Dijkstra.

* Season: 7 daily charts (seaway.samples.kara_season), an Arc7 at 14 kn; static: the departure
  day's hours per km as a static chart (integral edge cost, the season's step rule).
* Forecast: 8 six-hourly frames of currents, waves and wind (smooth synthetic fields, land from
  kara_sea); static: the same model through the first frame alone (a forecast without a time
  axis, whose steps do not depend on the clock).

    pytest benchmarks/test_time_dependent.py -s -p no:randomly
"""

import statistics
import time

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.base.fields import smooth_noise
from seaway.ice.seasongrid import SeasonGrid
from seaway.models import IceSeasonTime, TravelTime
from seaway.samples import kara_sea, kara_season
from seaway.weather import ForecastGrid

from .conftest import NOTES, SHAPE

GATE, VILKITSKY_WEST = (70.34, 58.28), (77.5, 100.0)
ROUNDS = 3


def _alternate(cases):
    """{name: query} run ROUNDS + 1 times each, alternated; wall medians after the first."""
    times = {n: [] for n in cases}
    last = {}
    for rnd in range(ROUNDS + 1):
        for n, q in cases.items():
            t = time.perf_counter()
            last[n] = q()
            if rnd:
                times[n].append(time.perf_counter() - t)
    return {n: statistics.median(v) for n, v in times.items()}, last


def _note(key, med, last, td, static):
    NOTES[key] = (
        f"{med[td]:.3f} s = {med[td] / med[static]:.2f} x {static} ({med[static]:.3f} s); "
        + "; ".join(f"{n}: {med[n]:.3f} s, {r.stats.search.settled:,} settled" for n, r in last.items())
    )
    print("\n" + key + ": " + NOTES[key])


def test_season_against_static():
    grid = SeasonGrid(kara_season(days=7, shape=SHAPE))
    chart = seaway.prepare(grid, neighbourhood=5)
    model = IceSeasonTime(grid, "Arc7", 14.0)
    static = seaway.prepare(
        grid.template.copy(data=model.hours_per_km[0]), land=grid.dry, edge_cost="integral"
    )
    med, last = _alternate(
        {
            "season A*": lambda: chart.route(GATE, VILKITSKY_WEST, model=model, method="astar"),
            "static A*": lambda: static.route(GATE, VILKITSKY_WEST, method="astar"),
            "static auto": lambda: static.route(GATE, VILKITSKY_WEST),
        }
    )
    _note("season (IceSeasonTime, 7 charts) vs static", med, last, "season A*", "static A*")
    d = chart.route(GATE, VILKITSKY_WEST, model=model, method="dijkstra")
    assert last["season A*"].cost == pytest.approx(d.cost, rel=1e-9)


def _forecast(frames):
    ice = kara_sea(SHAPE)
    rng = np.random.default_rng(8)
    shape = (frames,) + SHAPE

    def field(scale, offset=0.0):
        base = smooth_noise(rng, SHAPE, 60.0)
        drift = smooth_noise(rng, SHAPE, 60.0)
        return np.stack(
            [offset + scale * ((1 - f / frames) * base + f / frames * drift) for f in range(frames)]
        ).astype(np.float32)

    wet = ~ice.land.values
    data = {
        "ce": (field(1.0, -0.5), "eastward_sea_water_velocity"),
        "cn": (field(1.0, -0.5), "northward_sea_water_velocity"),
        "hs": (field(3.5), "sea_surface_wave_significant_height"),
        "wdir": (field(360.0), "sea_surface_wave_from_direction"),
        "wind": (field(15.0), "wind_speed"),
    }
    t = np.datetime64("2026-07-01T00") + np.arange(frames) * np.timedelta64(6, "h")
    ds = xr.Dataset(
        {
            k: (("time", "lat", "lon"), np.where(wet, v, np.nan).reshape(shape), {"standard_name": name})
            for k, (v, name) in data.items()
        },
        coords={"time": t, "lat": ice.lat.values, "lon": ice.lon.values},
    )
    return ds


def test_forecast_against_static():
    ds = _forecast(8)
    moving, still = ForecastGrid(ds), ForecastGrid(ds.isel(time=0, drop=True))
    chart = moving.prepare()
    td, st = TravelTime(moving), TravelTime(still)
    med, last = _alternate(
        {
            "forecast A*": lambda: chart.route(GATE, VILKITSKY_WEST, model=td, method="astar"),
            "first frame A*": lambda: chart.route(GATE, VILKITSKY_WEST, model=st, method="astar"),
        }
    )
    _note("forecast (TravelTime, 8 frames) vs its first frame", med, last, "forecast A*", "first frame A*")
    d = chart.route(GATE, VILKITSKY_WEST, model=td, method="dijkstra")
    assert last["forecast A*"].cost == pytest.approx(d.cost, rel=1e-9)
