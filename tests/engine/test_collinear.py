"""The doubled steps a prepared chart leaves out (cpp/seaway/collinear.hpp): (±2, 0), (0, ±2)
and (±2, ±2) run straight through the middle pixel of a unit step; where the two unit steps
cost no more, the doubled step never makes a route cheaper. Which steps go, under each rule,
and that every search still gives the brute-force reference's least cost."""

from __future__ import annotations

import numpy as np
import pytest

import seaway
from seaway.models.base import as_model
from support.grids import (
    RTOL,
    blob_geo,
    blob_sea,
    check_path,
    largest_water,
    make_chart,
    point,
    reference_voyages,
)
from support.reference import RefGraph

#: Bit b of a skip word: the doubled step 2 x HALVES[b] (collinear.hpp, DoubledSteps).
HALVES = [(-1, -1), (-1, 0), (-1, 1), (0, -1), (0, 1), (1, -1), (1, 0), (1, 1)]


def table_of(chart, model=None):
    """The skip table of `model` (default the chart's) on `chart`, or None."""
    model = chart.model if model is None else as_model(model)
    return chart.router.skip_table(model.engine(chart))


def prune(chart):
    assert chart.router.prune_collinear(chart.model.engine(chart)) is True
    table = table_of(chart)
    assert table.shape == chart.chart.shape and table.dtype == np.uint16
    return table


def expected(shape, keep=lambda r, c, b: False, bits=range(8)):
    """The skip words when every doubled step on the chart is left out but those `keep` names
    (by its start pixel and bit) and those not in `bits`."""
    out = np.zeros(shape, np.uint16)
    rows, cols = shape
    for r in range(rows):
        for c in range(cols):
            for b in bits:
                di, dj = HALVES[b]
                rw, cw = r + 2 * di, c + 2 * dj
                if 0 <= rw < rows and 0 <= cw < cols and not keep(r, c, b):
                    out[r, c] |= 1 << b
                    out[rw, cw] |= 1 << (8 + b)
    return out


def test_a_uniform_planar_chart_leaves_out_every_doubled_step():
    """Cost 1 everywhere, cells 1.5 x 0.8: each doubled step costs exactly its two halves, so
    every one that lies on the chart goes, from its start and at its end."""
    chart = seaway.prepare(np.ones((9, 11)), dx=1.5, dy=0.8)
    np.testing.assert_array_equal(prune(chart), expected((9, 11)))


@pytest.mark.parametrize("edge_cost", ["max", "mean"])
def test_a_dearer_middle_keeps_the_steps_through_it(edge_cost):
    """Cost 5 at (4, 4), 1 elsewhere. Under the max rule (Grinyak et al. 2022) the doubled step
    from (3, 3) to (5, 5) costs 5 x 2 sqrt 2 against 10 sqrt 2 for its halves through (4, 4), under
    the mean rule 1 x 2 sqrt 2 against 6 sqrt 2: the 8 doubled steps through (4, 4) stay. A
    doubled step that starts or ends there costs at least its halves (max: 5 x 2 against 5 + 1,
    mean: 3 x 2 against 3 + 1) and goes."""
    u = np.ones((9, 9))
    u[4, 4] = 5.0
    chart = seaway.prepare(u, edge_cost=edge_cost)

    def through_the_middle(r, c, b):
        di, dj = HALVES[b]
        return (r + di, c + dj) == (4, 4)

    np.testing.assert_array_equal(prune(chart), expected(u.shape, keep=through_the_middle))


def test_the_line_integral_prices_a_doubled_step_as_its_two_halves():
    """Under the exact line integral the doubled step over a pixel of cost 5 costs
    2 x (0.25 + 0.5 x 5 + 0.25) = 6, as its two halves (1 x 3 + 1 x 3): every step goes."""
    u = np.ones((9, 9))
    u[4, 4] = 5.0
    chart = seaway.prepare(u, edge_cost="integral")
    np.testing.assert_array_equal(prune(chart), expected(u.shape))


def test_on_lat_lon_pixels_only_the_steps_along_a_meridian_go():
    """On 0.5 x 1 degree pixels at 70 N the great circle between two pixels of one row is
    shorter than the two steps through the pixel between them, and so is a doubled diagonal:
    at equal costs only (±2, 0), along a meridian, costs exactly its halves."""
    lat, lon = 70.0 + 0.5 * np.arange(8), 20.0 + np.arange(10)
    chart = seaway.prepare(np.ones((8, 10)), lat=lat, lon=lon)
    np.testing.assert_array_equal(prune(chart), expected((8, 10), bits=(1, 6)))


def test_land_keeps_the_steps_it_cuts():
    """A land pixel at (4, 4): no step crosses it, so no doubled step through it is left out
    (there is none), and every other doubled step on the chart goes."""
    land = np.zeros((9, 9), bool)
    land[4, 4] = True
    chart = seaway.prepare(np.ones((9, 9)), land=land)
    table = prune(chart)
    assert table[4, 4] == 0
    for r, c, b in [(2, 4, 6), (4, 2, 4), (2, 2, 7), (6, 6, 0)]:  # each ends on the land pixel
        assert not table[r, c] >> b & 1
    for r, c, b in [(3, 3, 6), (4, 5, 4), (0, 0, 7)]:  # clear of it
        assert table[r, c] >> b & 1


@pytest.mark.parametrize("seed", range(8))
@pytest.mark.parametrize("edge_cost", ["max", "mean", "integral", "length"])
@pytest.mark.parametrize("grid", ["planar", "geo_asc", "geo_wrap"])
def test_pruned_searches_give_the_reference_cost(seed, edge_cost, grid):
    """Random charts with land, inf and NaN pixels: after prepare_landmarks (which prunes) every
    exact method gives the brute-force reference's least cost and a path it prices the same."""
    u, land, geo = make_chart(seed, grid, zeros=False)
    chart = seaway.prepare(u, land=land, edge_cost=edge_cost, **geo)
    chart.prepare_landmarks(4)
    assert set(chart.pruned_for) == {edge_cost} and table_of(chart).any()
    ref = RefGraph(u, land=land, k=5, edge_cost=edge_cost, **geo)
    water = np.argwhere(ref.ok)
    rng = np.random.default_rng(seed)
    s = tuple(map(int, water[rng.integers(len(water))]))
    costs = ref.costs(s)
    for e in water[rng.choice(len(water), size=min(6, len(water)), replace=False)]:
        e = tuple(map(int, e))
        if not np.isfinite(costs[e]) or e == s:
            continue
        for method in ("dijkstra", "astar", "bidirectional", "landmarks"):
            r = chart.route(point(geo, s), point(geo, e), method=method)
            assert r.cost == pytest.approx(costs[e], rel=RTOL, abs=1e-12), (method, s, e)
            check_path(ref, r, s, e, geo)


@pytest.mark.parametrize("seed", range(3))
@pytest.mark.parametrize("edge_cost", ["max", "mean"])
def test_pruned_searches_on_a_sea_with_land_give_the_reference_cost(seed, edge_cost):
    """Charts of 15,400 pixels with land blobs, where most pixels lie far enough from land and
    border for the fast path that leaves the steps out (planar, lat/lon ascending and
    descending): every exact method gives the reference's cost and a path it prices the same,
    to random pixels and to the farthest one."""
    u = blob_sea(seed, shape=(110, 140))
    geo = blob_geo(seed, u.shape)
    chart = seaway.prepare(u, edge_cost=edge_cost, **geo)
    chart.prepare_landmarks(8)
    words = table_of(chart)
    assert np.count_nonzero(words & 0xFF) > u.size // 2  # most pixels leave a step out
    ref = RefGraph(u, k=5, edge_cost=edge_cost, **geo)
    for s, e, least in reference_voyages(ref, largest_water(u), np.random.default_rng(seed), starts=3):
        for method in ("dijkstra", "astar", "bidirectional", "landmarks"):
            r = chart.route(point(geo, s), point(geo, e), method=method)
            assert r.cost == pytest.approx(least, rel=RTOL), (method, s, e)
            check_path(ref, r, s, e, geo)


def test_each_model_keeps_its_own_table():
    """Landmarks for the max rule and then the mean rule on one chart: each model keeps the table
    a chart pruned for it alone would have (they differ), a rebuild for one leaves the other's,
    and every exact method under each gives the reference's least cost."""
    u = blob_sea(1, shape=(60, 70))
    chart = seaway.prepare(u, edge_cost="max")
    chart.prepare_landmarks(4)
    chart.prepare_landmarks(4, model="mean")
    alone = {rule: prune(seaway.prepare(u, edge_cost=rule)) for rule in ("max", "mean")}
    assert (alone["max"] != alone["mean"]).any()
    kept_mean = chart.pruned_for["mean"]
    chart.prepare_landmarks(4)  # max again: replaces its own table only
    assert set(chart.pruned_for) == {"max", "mean"} and chart.pruned_for["mean"] is kept_mean
    for rule in ("max", "mean"):
        np.testing.assert_array_equal(table_of(chart, rule), alone[rule])
        ref = RefGraph(u, k=5, edge_cost=rule)
        for s, e, least in reference_voyages(ref, largest_water(u), np.random.default_rng(1), starts=2):
            for method in ("dijkstra", "bidirectional", "landmarks"):
                r = chart.route(s, e, model=rule, method=method)
                assert r.cost == pytest.approx(least, rel=RTOL), (rule, method, s, e)
