"""auto's choice on a chart without landmarks: one-way A* where most of the water costs the
least (open water around patches of ice: the straight-line bound is the true cost over most of
it), bidirectional search elsewhere; every choice gives Dijkstra's cost."""

import numpy as np
import pytest

import seaway
from seaway.engine.methods import LEAST_COST_SHARE, LONG_VOYAGE_PIXELS, mostly_least_cost
from seaway.models import EdgeCost


def _sea(costly_share, seed=3):
    """A 300 x 300 sea of cost 1 with square floes of cost 6 over `costly_share` of it and an
    island of land."""
    rng = np.random.default_rng(seed)
    u = np.ones((300, 300))
    while np.mean(u > 1) < costly_share:
        r, c = rng.integers(0, 290, 2)
        u[r : r + 10, c : c + 10] = 6.0
    u[120:180, 140:160] = np.inf
    return u


@pytest.mark.parametrize(("costly", "method"), [(0.2, "astar"), (0.4, "astar"), (0.7, "bidirectional")])
def test_auto_takes_astar_where_most_water_costs_the_least(costly, method):
    u = _sea(costly)
    chart = seaway.prepare(u, edge_cost="max")
    share = np.mean(u[np.isfinite(u)] == 1.0)
    assert (share >= LEAST_COST_SHARE) == (method == "astar")
    s, e = (10, 10), (290, 290)
    r = chart.route(s, e)
    d = chart.route(s, e, method="dijkstra")
    assert r.method == method
    assert r.cost == pytest.approx(d.cost, rel=1e-9)
    if method == "astar":  # the bound prunes: far fewer pixels than Dijkstra
        assert r.stats.search.settled < 0.7 * d.stats.search.settled
    assert seaway.route(u, s, e).method == method  # a fresh chart decides alike


def _sample_share(values, land=None, n=4096):
    """The share of the sampled passable pixels within 1 % of the least passable cost, by numpy:
    pixel (i * 2654435761) mod size for i < n (the preparation's sample, cpp/seaway/passability.hpp)."""
    flat = np.asarray(values, float).reshape(-1)
    ok_all = np.isfinite(flat) & (flat >= 0)
    if land is not None:
        ok_all &= np.asarray(land).reshape(-1) == 0
    lo = flat[ok_all].min() if ok_all.any() else 0.0
    picked = np.arange(min(n, flat.size), dtype=np.uint64) * np.uint64(2654435761) % np.uint64(flat.size)
    ok = ok_all[picked]
    return float(np.mean(flat[picked][ok] <= lo * 1.01)) if ok.any() and lo > 0 else 0.0


def test_the_share_is_read_while_the_chart_is_prepared_from_a_fixed_sample():
    u = _sea(0.2)
    chart = seaway.prepare(u)
    assert chart.router.least_cost_share == _sample_share(u) > 0.7
    assert mostly_least_cost(chart, EdgeCost("max"))
    assert seaway.prepare(u).router.least_cost_share == chart.router.least_cost_share  # every run
    # land given apart from the costs is not water; "length" prices steps by length alone
    land = np.zeros(u.shape, bool)
    land[:, :200] = True  # the land covers most of the cost-1 sea: two thirds of the rest are floes
    v = u.copy()
    v[:, 200:] = np.where(np.arange(100) % 3 != 0, 6.0, 1.0)
    assert seaway.prepare(v, land=land).router.least_cost_share == pytest.approx(_sample_share(v, land))
    assert not mostly_least_cost(seaway.prepare(v, land=land), EdgeCost("max"))
    assert mostly_least_cost(seaway.prepare(v, land=land), EdgeCost("length"))


@pytest.mark.parametrize("seed", range(6))
def test_the_share_equals_numpys_on_random_charts(seed):
    """NaN and infinite pixels, land, costs near the least, charts smaller than the
    sample, float32: the C++ share equals numpy's on the same sample."""
    rng = np.random.default_rng(seed)
    shape = [(7, 9), (64, 64), (100, 333), (301, 17), (1, 5000), (200, 200)][seed]
    u = rng.choice(
        [0.5, 0.5 * 1.009, 0.5 * 1.02, 3.0, np.nan, np.inf], size=shape, p=[0.3, 0.1, 0.1, 0.3, 0.1, 0.1]
    )
    land = rng.random(shape) < 0.1
    dtype = np.float32 if seed % 2 else np.float64
    chart = seaway.prepare(u.astype(dtype), land=land, neighbourhood=3)
    assert chart.router.least_cost_share == pytest.approx(_sample_share(u.astype(dtype), land), abs=1e-12)


def test_auto_keeps_the_landmarks_for_every_voyage_where_most_water_costs_the_least():
    """A prepared chart with landmarks where most water costs the least: the landmark search for
    short voyages in open water too (one-way A* there lost to it once its fixed costs fell), for a
    long one and round a wall; Dijkstra's cost every time. Without the landmarks the same chart
    takes one-way A* for all of them (none lies LONG_VOYAGE_PIXELS apart)."""
    u = _sea(0.2)
    u[20:200, 60:62] = np.inf  # a wall from the top: (100, 40) -> (100, 80) goes round its foot
    voyages = [
        ((220, 100), (290, 150), "astar"),  # 86 pixels apart in open water
        ((250, 30), (280, 150), "astar"),  # 124 apart
        ((10, 100), (60, 180), "astar"),  # 94 apart, floes in the way
        ((10, 10), (290, 290), "astar"),  # 396 pixels apart: < LONG_VOYAGE_PIXELS
        ((100, 40), (100, 80), "astar"),  # 40 pixels apart across the wall
    ]
    plain = seaway.prepare(u, edge_cost="max")
    assert mostly_least_cost(plain, plain.model)
    chart = seaway.prepare(u, edge_cost="max")
    chart.prepare_landmarks(8)
    for s, e, without in voyages:
        d = chart.route(s, e, method="dijkstra")
        for prepared, method in ((chart, "landmarks"), (plain, without)):
            r = prepared.route(s, e)
            assert r.method == method, (s, e)
            assert r.cost == pytest.approx(d.cost, rel=1e-9)
    assert np.hypot(290 - 10, 290 - 10) < LONG_VOYAGE_PIXELS


def test_auto_takes_bidirectional_for_a_long_voyage_where_most_water_costs_the_least():
    """Without landmarks, on a chart where most water costs the least: one-way A* up to
    LONG_VOYAGE_PIXELS between the ends, bidirectional search beyond; not with a weight (weighted
    A*) or a method asked for; Dijkstra's cost every time."""
    u = np.ones((60, 1000))
    u[10:50, 300:303] = np.inf
    chart = seaway.prepare(u, edge_cost="max")
    assert LONG_VOYAGE_PIXELS == 900
    for e, method in [((30, 850), "astar"), ((30, 900), "astar"), ((30, 901), "bidirectional")]:
        r, d = chart.route((30, 0), e), chart.route((30, 0), e, method="dijkstra")
        assert r.method == method
        assert r.cost == pytest.approx(d.cost, rel=1e-9)
        assert seaway.route(u, (30, 0), e, edge_cost="max").method == method  # a fresh chart alike
    assert chart.route((30, 0), (30, 999), weight=1.0).method == "astar"
    assert chart.route((30, 0), (30, 999), method="astar").method == "astar"


def test_a_voyage_across_the_antimeridian_is_as_long_as_its_way_over_the_seam():
    """On a pan-Arctic chart of 360 degrees (wrap) the ends' distance in pixels is taken over
    the seam: 20 pixels apart across it is a short voyage (one-way A*), not 1,180 the other way."""
    lat, lon = np.arange(70.0, 80.0, 0.25), np.arange(-179.85, 180.0, 0.3)
    assert lon.size == 1200
    chart = seaway.prepare(np.ones((lat.size, lon.size)), lat=lat, lon=lon, edge_cost="max")
    r = chart.route((75.0, lon[10]), (75.0, lon[-10]))
    assert r.method == "astar"
    assert r.cost == pytest.approx(chart.route((75.0, lon[10]), (75.0, lon[-10]), method="dijkstra").cost)
    assert chart.route((75.0, lon[0]), (75.0, lon[599])).method == "astar"  # 599 the short way
    assert chart.route((72.0, lon[0]), (72.0, lon[-1])).length < 100  # the way over the seam
