"""Hypothesis properties of route(): zero cost for start == end, symmetry, monotonicity under
added land and larger stencils, and exact A* (plus the bound of weighted A*)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import seaway
from support.reference import RefGraph

RTOL = 1e-9
VALUES = [0.0, 0.3, 1.0, 1.0, 2.5, 7.0, np.inf, np.nan]
SETTINGS = settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@st.composite
def problems(draw):
    """A small random chart, its geometry, stencil options and two passable pixels."""
    geo = draw(st.sampled_from(["planar", "geo", "wrap"]))
    rows = draw(st.integers(2, 8))
    cols = 16 if geo == "wrap" else draw(st.integers(2, 9))
    n = rows * cols
    u = np.array(draw(st.lists(st.sampled_from(VALUES), min_size=n, max_size=n))).reshape(rows, cols)
    land = np.array(draw(st.lists(st.booleans(), min_size=n, max_size=n))).reshape(rows, cols)
    land &= np.array(draw(st.lists(st.booleans(), min_size=n, max_size=n))).reshape(rows, cols)
    a, b = draw(st.integers(0, n - 1)), draw(st.integers(0, n - 1))
    rc = [divmod(a, cols), divmod(b, cols)]
    for p in rc:
        land[p] = False
        if not np.isfinite(u[p]):
            u[p] = 1.0
    kw = dict(
        land=land,
        neighbourhood=draw(st.sampled_from([3, 5, 7])),
        directions=draw(st.sampled_from(["full", "unique"])),
        edge_cost=draw(st.sampled_from(["max", "mean", "integral"])),
    )
    if geo == "planar":
        kw.update(dx=draw(st.floats(0.25, 4.0)), dy=draw(st.floats(0.25, 4.0)))
        pts = [tuple(p) for p in rc]
    else:
        dlat = draw(st.sampled_from([-3.0, -0.5, 0.5, 3.0]))
        lat0 = draw(st.floats(-80.0 + 3 * rows, 80.0 - 3 * rows))
        dlon = (360.0 / cols) if geo == "wrap" else draw(st.sampled_from([-2.0, 0.75, 2.0]))
        lon0 = draw(st.floats(-180.0, 180.0))
        lat, lon = lat0 + dlat * np.arange(rows), lon0 + dlon * np.arange(cols)
        kw.update(lat=lat, lon=lon)
        pts = [(float(lat[p[0]]), float(lon[p[1]])) for p in rc]
    return u, kw, pts[0], pts[1], rc


def cost_or_inf(u, a, b, **kw):
    try:
        return seaway.route(u, a, b, **kw).cost
    except seaway.NoRouteError:
        return np.inf


def same(x, y):
    if np.isinf(x) or np.isinf(y):
        return x == y
    return x == pytest.approx(y, rel=RTOL, abs=1e-12)


@SETTINGS
@given(problems(), st.sampled_from(["dijkstra", "astar"]))
def test_start_equals_end_costs_nothing(prob, method):
    u, kw, a, _, rc = prob
    r = seaway.route(u, a, a, method=method, **kw)
    assert r.cost == 0.0
    assert r.pixels.tolist() == [list(rc[0])]
    assert r.length == 0.0
    assert seaway.cost_field(u, a, **kw)[rc[0]] == 0.0


@SETTINGS
@given(problems())
def test_reversal_gives_same_cost(prob):
    u, kw, a, b, _ = prob
    fwd = cost_or_inf(u, a, b, method="dijkstra", **kw)
    back = cost_or_inf(u, b, a, method="dijkstra", **kw)
    assert same(fwd, back)


@SETTINGS
@given(problems(), st.data())
def test_adding_land_never_lowers_cost(prob, data):
    u, kw, a, b, rc = prob
    before = cost_or_inf(u, a, b, method="astar", **kw)
    extra = np.array(data.draw(st.lists(st.booleans(), min_size=u.size, max_size=u.size))).reshape(u.shape)
    for p in rc:
        extra[p] = False
    kw2 = dict(kw, land=kw["land"] | extra)
    after = cost_or_inf(u, a, b, method="astar", **kw2)
    assert after >= before * (1 - RTOL)
    # the same obstacles given as inf costs instead of land act the same way
    u3 = np.where(extra, np.inf, u)
    assert same(cost_or_inf(u3, a, b, method="dijkstra", **kw), after)


@SETTINGS
@given(problems(), st.sampled_from([1.0, 1.3, 2.0, 5.0]))
def test_astar_matches_dijkstra_and_weighted_bound(prob, w):
    u, kw, a, b, rc = prob
    d = cost_or_inf(u, a, b, method="dijkstra", **kw)
    assert same(cost_or_inf(u, a, b, method="astar", **kw), d)
    field = seaway.cost_field(u, a, **kw)
    assert same(field[rc[1]], d)
    wa = cost_or_inf(u, a, b, method="astar", weight=w, **kw)
    if np.isinf(d):
        assert np.isinf(wa)
    else:
        assert d * (1 - RTOL) - 1e-12 <= wa <= w * d * (1 + RTOL) + 1e-12


@SETTINGS
@given(problems())
def test_larger_stencil_and_mean_never_cost_more(prob):
    u, kw, a, b, _ = prob
    kw = dict(kw, directions="full")
    by_k = [cost_or_inf(u, a, b, **dict(kw, neighbourhood=k)) for k in (3, 5, 7)]
    assert by_k[1] <= by_k[0] * (1 + RTOL) and by_k[2] <= by_k[1] * (1 + RTOL)
    # mean(u_i, u_j) <= max(u_i, u_j) on every edge
    mean = cost_or_inf(u, a, b, **dict(kw, edge_cost="mean"))
    mx = cost_or_inf(u, a, b, **dict(kw, edge_cost="max"))
    assert mean <= mx * (1 + RTOL) or (np.isinf(mean) and np.isinf(mx))


@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(problems(), st.sampled_from(["dijkstra", "astar"]))
def test_route_matches_reference(prob, method):
    u, kw, a, b, rc = prob
    kw = dict(kw)
    ref = RefGraph(u, land=kw.pop("land"), k=kw.pop("neighbourhood"), **kw)
    expect = ref.costs(rc[0])[rc[1]]
    land = prob[1]["land"]
    got = cost_or_inf(u, a, b, method=method, **prob[1])
    assert same(got, expect)
    if np.isfinite(got):
        r = seaway.route(u, a, b, method=method, **prob[1])
        assert ref.path_cost(r.pixels) == pytest.approx(r.cost, rel=RTOL, abs=1e-12)
        assert not land[tuple(r.pixels.T)].any()
