"""PreparedChart.routes: one Dijkstra search from a start to many ends (cpp/seaway/many_targets.hpp).
Each route's cost equals the brute-force reference's, and the route is step for step the one a
Dijkstra search to that end alone finds; an end no route reaches gives its NoRouteError in place.
Through a season (time-dependent, waits allowed) each arrival equals the earliest arrival over
every path of the stencil (brute force)."""

from __future__ import annotations

import numpy as np
import pytest

import seaway
from seaway.ice.seasongrid import SeasonGrid
from seaway.models import IceSeasonTime
from support.grids import CASES, RTOL, make_chart, point
from support.reference import RefGraph, season_best_arrival
from support.seasons import planar_season

#: Speeds by WMO stage (knots; 0 closes the stage) and what the engine reads of them (h per km).
TABLE = {55: 12.0, 87: 6.0, 91: 3.0, 93: 0.0}


def table_hours(stage):
    speed = np.vectorize(lambda s: TABLE[int(s)])(stage)
    with np.errstate(divide="ignore"):
        return np.where(speed > 0, 1.0 / (speed * 1.852), np.inf).astype(np.float32).astype(float)


def planar_length(dx):
    return lambda p, q: float(np.hypot((q[0] - p[0]) * dx, (q[1] - p[1]) * dx))


@pytest.mark.parametrize("case", range(0, len(CASES), 7))
def test_routes_to_many_ends_equal_the_reference_and_single_searches(case):
    edge_cost, k, directions, grid = CASES[case]
    u, land, geo = make_chart(2000 + case, grid, zeros=case % 3 == 0)
    opts = dict(land=land, neighbourhood=k, directions=directions, edge_cost=edge_cost, **geo)
    ref = RefGraph(u, land=land, k=k, directions=directions, edge_cost=edge_cost, **geo)
    rng = np.random.default_rng(case)
    water = np.argwhere(ref.ok)
    start = tuple(int(v) for v in water[rng.integers(len(water))])
    expect = ref.costs(start)
    ends = [
        tuple(int(v) for v in water[i])
        for i in rng.choice(len(water), size=min(8, len(water)), replace=False)
    ]
    ends += [start, ends[0]]  # the start itself, and an end asked for twice
    chart = seaway.prepare(u, **opts)
    got = chart.routes(point(geo, start), [point(geo, e) for e in ends])
    assert len(got) == len(ends)
    for e, r in zip(ends, got):
        if not np.isfinite(expect[e]):
            assert isinstance(r, seaway.NoRouteError)
            continue
        assert r.cost == pytest.approx(expect[e], rel=RTOL, abs=1e-12)
        one = chart.route(point(geo, start), point(geo, e), method="dijkstra")
        assert r.cost == one.cost and np.array_equal(r.pixels, one.pixels)
        assert tuple(r.pixels[0]) == start and tuple(r.pixels[-1]) == e


def test_a_bad_end_is_refused_naming_it():
    chart = seaway.prepare(np.ones((20, 20)))
    with pytest.raises(seaway.SeawayError, match="end"):
        chart.routes((1, 1), [(2, 2), (40, 3)])


@pytest.mark.filterwarnings("ignore:the voyage arrives")  # beyond the last chart: assumed to hold
@pytest.mark.parametrize("seed", [1, 2, 4])
def test_season_routes_to_every_pixel_arrive_as_brute_force(seed):
    rng = np.random.default_rng(seed)
    frames, shape, k = 4, (3, 4), 3
    stage = rng.choice([55, 87, 91, 93], size=(frames,) + shape, p=[0.3, 0.3, 0.2, 0.2])
    stage[:, 0, 0] = 55
    hours = np.concatenate([[0.0], np.cumsum(rng.uniform(0.5, 3.0, frames - 1))])
    hours = np.round(hours * 3600) / 3600
    grid = SeasonGrid(planar_season(stage, hours=hours))
    model = IceSeasonTime(grid, speed=TABLE, concentration_limit=False)
    chart = seaway.prepare(grid, neighbourhood=k)
    ends = [(r, c) for r in range(shape[0]) for c in range(shape[1])]
    got = chart.routes((0, 0), ends, model=model)
    waited = 0.0
    for e, r in zip(ends, got):
        best = season_best_arrival(table_hours(stage), hours, (0, 0), e, k, planar_length(10.0))
        if not np.isfinite(best):
            assert isinstance(r, seaway.NoRouteError)
            continue
        assert r.cost == pytest.approx(best, rel=1e-9)
        one = chart.route((0, 0), e, model=model, method="dijkstra")
        assert (
            np.array_equal(r.pixels, one.pixels)
            and r.stats.voyage.wait_h.tolist() == one.stats.voyage.wait_h.tolist()
        )
        waited += r.stats.voyage.hours_waiting
    assert waited > 0  # some optimum waits for the ice
