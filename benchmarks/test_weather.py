"""Weather routing on the Kara-Sea-sized chart (1900 x 2300 pixels): the quickest route through
ice and a gale forecast at once (seaway.weather.kara_autumn: three daily ice charts and a
6-hourly westerly gale), through the gale alone on the same grid, and the static route through
the departure day's ice on the same chart (the integral model over the same hours per km), in
the same run. Asserts what can be checked at this size: A* and Dijkstra give the same time,
and a calm forecast gives the ice season's route exactly."""

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.ice.seasongrid import SeasonGrid
from seaway.models import IceSeasonTime, IceWeatherTime, TravelTime
from seaway.vessel import load
from seaway.weather import ForecastGrid, kara_autumn, on_grid

from .conftest import SHAPE, record

GATE, EAST = (70.34, 58.28), (75.5, 85.0)
DEPART = "2026-10-01T06:00"


@pytest.fixture(scope="module")
def voyage():
    ice, gale = kara_autumn(days=3, shape=SHAPE)
    grid = SeasonGrid(ice)
    t = grid.template
    fc, _ = on_grid(gale, t[t.dims[0]].values, t[t.dims[1]].values, t.dims)
    ship = load("pc6-general-cargo")
    return grid, seaway.prepare(grid, neighbourhood=5), ForecastGrid(fc, departure=DEPART), ship


@pytest.mark.parametrize("method", ["astar", "dijkstra"])
def test_ice_and_weather_route(benchmark, voyage, method):
    grid, chart, fc, ship = voyage
    model = IceWeatherTime(grid, fc, ship.ice_class, ship.vessel)
    r = benchmark.pedantic(
        chart.route, (GATE, EAST), {"model": model, "method": method}, rounds=3, iterations=1, warmup_rounds=1
    )
    record(
        f"ice+weather route PC6 {method} k=5",
        benchmark,
        f"{r.cost:.2f} h, {r.stats.search.settled:,} settled",
    )
    other = chart.route(GATE, EAST, model=model, method={"astar": "dijkstra", "dijkstra": "astar"}[method])
    assert r.cost == pytest.approx(other.cost, rel=1e-9)
    zero = fc.template.copy(data=np.zeros(grid.shape))
    calm = ForecastGrid(
        xr.Dataset(
            {
                "ce": zero.assign_attrs(standard_name="eastward_sea_water_velocity"),
                "cn": zero.assign_attrs(standard_name="northward_sea_water_velocity"),
            }
        ),
        departure=DEPART,
    )
    still = chart.route(
        GATE, EAST, model=IceWeatherTime(grid, calm, ship.ice_class, ship.vessel), method=method
    )
    alone = chart.route(
        GATE,
        EAST,
        model=IceSeasonTime(grid, ship.ice_class, ship.vessel.speed_kn, departure=calm.departure),
        method=method,
    )
    assert still.cost == pytest.approx(alone.cost, rel=1e-12)


def test_weather_route_same_grid(benchmark, voyage):
    grid, _, fc, ship = voyage
    chart = fc.prepare(land=grid.dry, neighbourhood=5)
    model = TravelTime(fc, ship.vessel)
    r = benchmark.pedantic(
        chart.route,
        (GATE, EAST),
        {"model": model, "method": "astar"},
        rounds=3,
        iterations=1,
        warmup_rounds=1,
    )
    record(
        "weather route (gale, no ice) astar k=5",
        benchmark,
        f"{r.cost:.2f} h, {r.stats.search.settled:,} settled",
    )


def test_static_route_same_chart(benchmark, voyage):
    grid, _, _, ship = voyage
    hours = IceSeasonTime(grid, ship.ice_class, ship.vessel.speed_kn).hours_per_km[0]
    static = seaway.prepare(
        grid.template.copy(data=hours), land=grid.dry, neighbourhood=5, edge_cost="integral"
    )
    r = benchmark.pedantic(
        static.route, (GATE, EAST), {"method": "astar"}, rounds=3, iterations=1, warmup_rounds=1
    )
    record(
        "static route PC6 day-1 chart astar k=5",
        benchmark,
        f"{r.cost:.2f} h, {r.stats.search.settled:,} settled",
    )
