"""A season of ice charts on the Kara-Sea-sized chart: seven daily charts of
1900 x 2300 pixels (seaway.samples.kara_season), an Arc7 at 14 kn from the Kara Gate to the
western approach of the Vilkitsky Strait, against the static route through the departure
day's chart in the same run (the same hours per km, seaway's integral model, and scikit-image's
MCP_Geometric as the project's peer). Asserts what can be checked at this size: A* and Dijkstra
give the same time, and, as the ice only thins, it is at least the static time through the
last (most open) chart."""

import numpy as np
import pytest

import seaway
from seaway.chart.locate import locate
from seaway.ice.seasongrid import SeasonGrid
from seaway.models import IceSeasonTime
from seaway.samples import kara_season

from .conftest import SHAPE, record

GATE, VILKITSKY_WEST = (70.34, 58.28), (77.5, 100.0)


def _static(grid, hours):
    """One chart's hours per km as a static chart (the integral model, like the season's steps)."""
    return seaway.prepare(
        grid.template.copy(data=hours), land=grid.dry, neighbourhood=5, edge_cost="integral"
    )


@pytest.fixture(scope="module")
def season():
    grid = SeasonGrid(kara_season(days=7, shape=SHAPE))
    return grid, seaway.prepare(grid, neighbourhood=5)


def test_build_season_model(benchmark, season):
    grid, _ = season
    model = benchmark.pedantic(IceSeasonTime, (grid, "Arc7", 14.0), rounds=3, iterations=1)
    record(
        "season: IceSeasonTime(7 charts) build",
        benchmark,
        f"{model.hours_per_km.nbytes / 2**20:.0f} MB of float32 hours per km",
    )


@pytest.mark.parametrize("method", ["astar", "dijkstra"])
def test_season_route(benchmark, season, method):
    grid, chart = season
    model = IceSeasonTime(grid, "Arc7", 14.0)
    r = benchmark.pedantic(
        chart.route,
        (GATE, VILKITSKY_WEST),
        {"model": model, "method": method},
        rounds=5,
        iterations=1,
        warmup_rounds=1,
    )
    best = _static(grid, model.hours_per_km[-1]).route(GATE, VILKITSKY_WEST)  # the most open chart
    record(
        f"season route Arc7 7 charts {method} k=5",
        benchmark,
        f"{r.cost:.2f} h ({r.stats.voyage.hours_waiting:.2f} h waiting), "
        f"{r.stats.search.settled:,} settled, "
        f"{r.stats.search.state_bytes / np.prod(SHAPE):.1f} B/pixel",
    )
    other = chart.route(
        GATE, VILKITSKY_WEST, model=model, method={"astar": "dijkstra", "dijkstra": "astar"}[method]
    )
    assert r.cost == pytest.approx(other.cost, rel=1e-9) and r.cost >= best.cost - 1e-9


@pytest.mark.parametrize("method", ["astar", "dijkstra"])
def test_static_route_same_chart(benchmark, season, method):
    grid, chart = season
    static = _static(grid, IceSeasonTime(grid, "Arc7", 14.0).hours_per_km[0])
    r = benchmark.pedantic(
        static.route, (GATE, VILKITSKY_WEST), {"method": method}, rounds=5, iterations=1, warmup_rounds=1
    )
    record(
        f"static route Arc7 day-1 chart {method} k=5",
        benchmark,
        f"{r.cost:.2f} h, {r.stats.search.settled:,} settled",
    )


def test_peer_skimage_on_day_one(benchmark, season):
    skimage_graph = pytest.importorskip("skimage.graph")
    grid, chart = season
    hours = IceSeasonTime(grid, "Arc7", 14.0).hours_per_km[0].astype(np.float64)
    hours[grid.dry] = np.inf
    s, e = locate(chart.chart, GATE, "start"), locate(chart.chart, VILKITSKY_WEST, "end")

    def run():
        m = skimage_graph.MCP_Geometric(hours, fully_connected=True)
        m.find_costs([s], [e])
        return m

    benchmark.pedantic(run, rounds=3, iterations=1)
    record("skimage MCP_Geometric 8-conn", benchmark, "day-1 hours per km (pixel units)")
