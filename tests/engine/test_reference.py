"""Randomised cross-checks of seaway.route / seaway.cost_field against the brute-force reference
(tests/reference.py) for every edge cost, stencil size, stencil kind and grid kind."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

import seaway
from support.grids import CASES, DIRECTIONS, EDGE_COSTS, GRIDS, KS, RTOL, check_path, make_chart, point
from support.reference import RefGraph, haversine, stencil_offsets


@pytest.mark.parametrize("edge_cost,k,directions,grid", CASES)
def test_matches_reference(edge_cost, k, directions, grid):
    seed = CASES.index((edge_cost, k, directions, grid))
    u, land, geo = make_chart(1000 + seed, grid, zeros=seed % 3 == 0)
    opts = dict(land=land, neighbourhood=k, directions=directions, edge_cost=edge_cost, **geo)
    ref = RefGraph(u, land=land, k=k, directions=directions, edge_cost=edge_cost, **geo)
    rng = np.random.default_rng(seed)
    water = np.argwhere(ref.ok)
    start = tuple(int(v) for v in water[rng.integers(len(water))])
    expect = ref.costs(start)

    field = seaway.cost_field(u, point(geo, start), **opts)
    assert field.shape == u.shape
    np.testing.assert_array_equal(np.isinf(field), np.isinf(expect))
    fin = np.isfinite(expect)
    np.testing.assert_allclose(field[fin], expect[fin], rtol=RTOL, atol=1e-12)

    reach = np.argwhere(fin)
    ends = [
        tuple(int(v) for v in reach[i])
        for i in rng.choice(len(reach), size=min(4, len(reach)), replace=False)
    ]
    far = tuple(int(v) for v in reach[np.argmax(expect[fin])])
    for end in ends + [far]:
        best = expect[end]
        for method in ("dijkstra", "astar"):
            r = seaway.route(u, point(geo, start), point(geo, end), method=method, **opts)
            assert r.cost == pytest.approx(best, rel=RTOL, abs=1e-12), (method, start, end)
            check_path(ref, r, start, end, geo)
    for w in (1.5, 4.0):
        r = seaway.route(u, point(geo, start), point(geo, far), method="astar", weight=w, **opts)
        assert expect[far] * (1 - RTOL) <= r.cost <= w * expect[far] * (1 + RTOL) + 1e-12
        check_path(ref, r, start, far, geo)

    cut = np.argwhere(~fin & ref.ok)
    for end in cut[:2]:
        for method in ("dijkstra", "astar"):
            with pytest.raises(seaway.NoRouteError):
                seaway.route(u, point(geo, start), point(geo, tuple(end)), method=method, **opts)


def test_wrap_route_crosses_antimeridian():
    """On a 360-degree chart the cheapest way between columns 1 and cols-2 runs across the seam."""
    cols = 18
    lat, lon = np.array([0.0, 10.0, 20.0, 30.0, 40.0, 50.0]), -170.0 + 20.0 * np.arange(cols)
    u = np.ones((6, cols))
    u[:, 2 : cols - 3] = 5.0  # the long way round is expensive
    for edge_cost in EDGE_COSTS:
        ref = RefGraph(u, lat=lat, lon=lon, k=7, edge_cost=edge_cost)
        expect = ref.costs((2, 1))[2, cols - 2]
        r = seaway.route(
            u,
            (20.0, lon[1]),
            (20.0, lon[cols - 2]),
            lat=lat,
            lon=lon,
            neighbourhood=7,
            edge_cost=edge_cost,
            method="dijkstra",
        )
        assert r.cost == pytest.approx(expect, rel=RTOL)
        # one step of 3 columns across the seam: exactly the great circle
        assert r.cost == pytest.approx(haversine(20.0, lon[1], 20.0, lon[cols - 2]), rel=1e-12)
        assert [tuple(p) for p in r.pixels] == [(2, 1), (2, cols - 2)]
        check_path(ref, r, (2, 1), (2, cols - 2), dict(lat=lat, lon=lon))


@pytest.mark.parametrize("k", KS)
def test_long_step_never_jumps_land(k):
    """A one-pixel wall across a straight channel: no stencil step may hop over it."""
    u = np.ones((3, 20))
    u[:, 9] = np.inf
    u[0, 9] = 1.0  # the only gap is at the top edge
    for edge_cost in EDGE_COSTS:
        ref = RefGraph(u, k=k, edge_cost=edge_cost)
        expect = ref.costs((2, 0))
        field = seaway.cost_field(u, (2, 0), neighbourhood=k, edge_cost=edge_cost)
        np.testing.assert_allclose(field, expect, rtol=RTOL)
        r = seaway.route(u, (2, 0), (2, 19), neighbourhood=k, edge_cost=edge_cost)
        assert r.cost == pytest.approx(expect[2, 19], rel=RTOL)
        check_path(ref, r, (2, 0), (2, 19), dict(dx=1.0, dy=1.0))


@pytest.mark.parametrize("k", KS)
def test_diagonal_corner_touch_forbidden(k):
    """Land that meets a step only at a corner still forbids it."""
    u = np.ones((2, 2))
    u[0, 1] = u[1, 0] = np.inf  # the diagonal (0,0)->(1,1) passes their common corner
    with pytest.raises(seaway.NoRouteError):
        seaway.route(u, (0, 0), (1, 1), neighbourhood=k)
    # (0,0)->(1,3) passes (0.5, 1.5), a corner of (0,2): forbidden when (0,2) is land
    u, land = np.ones((2, 4)), np.zeros((2, 4), dtype=bool)
    land[0, 2] = True
    want = 2 + math.sqrt(2) if k == 3 else 1 + math.sqrt(5)  # via (1,1) or via (1,2)
    for method in ("dijkstra", "astar"):
        r = seaway.route(u, (0, 0), (1, 3), land=land, neighbourhood=k, method=method)
        assert r.cost == pytest.approx(want, rel=RTOL)
        check_path(RefGraph(u, land=land, k=k), r, (0, 0), (1, 3), dict(dx=1.0, dy=1.0))
    land[1, 1] = True  # now every way from (0,0) to the right half touches land
    with pytest.raises(seaway.NoRouteError):
        seaway.route(u, (0, 0), (1, 3), land=land, neighbourhood=k)
    if k >= 7:  # and without land the single step is the route
        r = seaway.route(u, (0, 0), (1, 3), neighbourhood=k)
        assert r.cost == pytest.approx(math.sqrt(10), rel=RTOL)
        assert r.pixels.tolist() == [[0, 0], [1, 3]]


@pytest.mark.parametrize("k", [9, 15])
@pytest.mark.parametrize("grid", ["planar", "geo_wrap"])
def test_large_stencils_match_reference(k, grid):
    for i, (edge_cost, directions) in enumerate(itertools.product(EDGE_COSTS, DIRECTIONS)):
        u, land, geo = make_chart(5000 + 10 * k + i, grid, zeros=False)
        opts = dict(land=land, directions=directions, edge_cost=edge_cost, **geo)
        ref = RefGraph(u, k=k, **opts)
        start = tuple(int(v) for v in np.argwhere(ref.ok)[-1])
        expect = ref.costs(start)
        field = seaway.cost_field(u, point(geo, start), neighbourhood=k, **opts)
        np.testing.assert_allclose(field, expect, rtol=RTOL, atol=1e-12)


def test_float32_costs_match_reference():
    """A float32 chart is routed on its own values (compared in float64)."""
    for i, grid in enumerate(GRIDS):
        u, land, geo = make_chart(7000 + i, grid, zeros=False)
        u32 = u.astype(np.float32)
        for edge_cost in EDGE_COSTS:
            ref = RefGraph(u32.astype(np.float64), land=land, k=5, edge_cost=edge_cost, **geo)
            start = tuple(int(v) for v in np.argwhere(ref.ok)[0])
            field = seaway.cost_field(u32, point(geo, start), land=land, edge_cost=edge_cost, **geo)
            np.testing.assert_allclose(field, ref.costs(start), rtol=RTOL, atol=1e-12)


@pytest.mark.parametrize("geographic", [False, True])
def test_astar_settles_no_more_than_dijkstra(geographic):
    rng = np.random.default_rng(7)
    u = rng.uniform(1.0, 1.2, size=(40, 40))
    geo = dict(lat=np.linspace(30.0, 49.5, 40), lon=np.linspace(-20.0, -0.5, 40)) if geographic else {}
    a_pt, b_pt = point(geo, (20, 2)), point(geo, (20, 37))
    for k, edge_cost in itertools.product(KS, EDGE_COSTS):
        kw = dict(neighbourhood=k, edge_cost=edge_cost, **geo)
        d = seaway.route(u, a_pt, b_pt, method="dijkstra", **kw)
        a = seaway.route(u, a_pt, b_pt, method="astar", **kw)
        assert a.cost == pytest.approx(d.cost, rel=RTOL)
        assert 0 < a.stats.search.settled <= d.stats.search.settled <= u.size
        assert a.stats.search.settled < d.stats.search.settled // 2  # the heuristic actually prunes


def test_stencil_of_reference_is_the_contract():
    """Sanity of the reference itself: stencil sizes follow from the definitions."""
    for k in range(3, 16, 2):
        h = (k - 1) // 2
        assert len(stencil_offsets(k, "full")) == k * k - 1
        n = sum(math.gcd(abs(a), abs(b)) == 1 for a in range(-h, h + 1) for b in range(-h, h + 1))
        assert len(stencil_offsets(k, "unique")) == n
    assert stencil_offsets(3, "unique") == stencil_offsets(3, "full")
