"""Fuzzing the public API with hypothesis: every input gives the brute-force reference's answer
(tests/reference.py) or a ValueError/TypeError, never a crash, another exception or a wrong
route. Inputs: NaN/inf/negative/huge/tiny/zero costs, float32 and float64, 1x1 and 1xN charts,
start = end, border pixels, every stencil size 3..15, both direction sets, all edge costs,
planar cell sizes, ascending/descending/wrapping lat/lon, land masks, junk arguments.

The default run is short; SEAWAY_FUZZ_EXAMPLES=N runs N examples per test (the long fuzz run
recorded in the README), e.g. SEAWAY_FUZZ_EXAMPLES=20000 pytest tests/test_fuzz.py."""

from __future__ import annotations

import os

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import seaway
from seaway.compat import route_through_array
from support.reference import RefGraph

EXAMPLES = int(os.environ.get("SEAWAY_FUZZ_EXAMPLES", "40"))
FUZZ = settings(max_examples=EXAMPLES, deadline=None, database=None, suppress_health_check=list(HealthCheck))
RTOL = 1e-9
VALUES = [0.0, -0.0, 1e-9, 0.3, 1.0, 1.0, 2.5, 7.0, 1e6, 1e30, np.inf, np.nan]
KS = [3, 5, 7, 9, 11, 13, 15]


@st.composite
def charts(draw, negative=False):
    """(cost, keyword arguments of route(), start and end as given, start and end pixels)."""
    geo = draw(st.sampled_from(["planar", "geo", "wrap"]))
    rows = draw(st.integers(1, 4 if geo == "wrap" else 7))
    cols = 16 if geo == "wrap" else draw(st.integers(1, 8))
    n = rows * cols
    values = VALUES + ([-1.0, -1e-300, -np.inf] if negative else [])
    u = np.array(draw(st.lists(st.sampled_from(values), min_size=n, max_size=n))).reshape(rows, cols)
    u = u.astype(draw(st.sampled_from([np.float64, np.float32])))
    land = None
    if draw(st.booleans()):
        land = np.array(draw(st.lists(st.booleans(), min_size=n, max_size=n))).reshape(rows, cols)
    a, b = draw(st.integers(0, n - 1)), draw(st.integers(0, n - 1))
    if draw(st.integers(0, 5)) == 0:
        b = a  # start = end
    rc = [divmod(a, cols), divmod(b, cols)]
    for p in rc:  # usually a passable start and end; sometimes not (an error is expected)
        if draw(st.integers(0, 7)) > 0:
            u[p] = 1.0 if not (np.isfinite(u[p]) and u[p] >= 0) else u[p]
            if land is not None:
                land[p] = False
    kw = dict(
        land=land,
        neighbourhood=draw(st.sampled_from(KS)),
        directions=draw(st.sampled_from(["full", "unique"])),
        edge_cost=draw(st.sampled_from(["max", "mean", "integral"])),
    )
    if geo == "planar":
        kw.update(
            dx=draw(st.sampled_from([1e-3, 0.5, 1.0, 3.0, 1e4])),
            dy=draw(st.sampled_from([1e-3, 0.25, 1.0, 2.0, 1e4])),
        )
        pts = [tuple(p) for p in rc]
    else:
        dlat = draw(st.sampled_from([-5.0, -0.5, 0.01, 0.5, 5.0]))
        lat0 = draw(st.floats(-89.0 + abs(dlat) * rows, 89.0 - abs(dlat) * rows))
        dlon = (360.0 / cols) if geo == "wrap" else draw(st.sampled_from([-3.0, -0.1, 0.25, 3.0]))
        if geo == "wrap" and draw(st.booleans()):
            dlon = -dlon
        lon0 = draw(st.floats(-180.0, 180.0))
        lat, lon = lat0 + dlat * np.arange(rows), lon0 + dlon * np.arange(cols)
        kw.update(lat=lat, lon=lon)
        pts = [(float(lat[p[0]]), float(lon[p[1]])) for p in rc]
    return u, kw, pts[0], pts[1], rc


def _passable(u, land, p):
    return bool(np.isfinite(u[p]) and u[p] >= 0 and (land is None or not land[p]))


def _reference(u, kw):
    kw = dict(kw)
    if "lon" in kw and len(kw["lon"]) == 1:  # the reference reads the step from two longitudes
        kw["lon"] = np.append(kw["lon"], kw["lon"][0] + 1.0)
    return RefGraph(u, land=kw.pop("land"), k=kw.pop("neighbourhood"), **kw)


def _check_route(r, ref, rc, expect, w=1.0):
    assert r.pixels[0].tolist() == list(rc[0]) and r.pixels[-1].tolist() == list(rc[1])
    assert ref.path_cost(r.pixels) == pytest.approx(r.cost, rel=RTOL, abs=1e-300)
    assert expect * (1 - RTOL) <= r.cost <= w * expect * (1 + RTOL) + 1e-300


@FUZZ
@given(charts(negative=True), st.sampled_from(["dijkstra", "astar", 1.0, 1.5, 4.0]))
def test_every_chart_gives_the_reference_answer_or_a_clear_error(prob, how):
    u, kw, a, b, rc = prob
    method, w = (how, None) if isinstance(how, str) else ("astar", how)
    if (u < 0).any():
        with pytest.raises(ValueError, match="negative"):
            seaway.route(u, a, b, method=method, weight=w, **kw)
        return
    if not all(_passable(u, kw["land"], p) for p in rc):
        with pytest.raises(ValueError, match="impassable"):
            seaway.route(u, a, b, method=method, weight=w, **kw)
        return
    ref = _reference(u, kw)
    expect = ref.costs(rc[0])[rc[1]]
    if np.isinf(expect):
        with pytest.raises(seaway.NoRouteError, match="no route"):
            seaway.route(u, a, b, method=method, weight=w, **kw)
        return
    r = seaway.route(u, a, b, method=method, weight=w, **kw)
    _check_route(r, ref, rc, expect, w or 1.0)
    if rc[0] == rc[1]:
        assert r.cost == 0.0 and len(r.pixels) == 1


@FUZZ
@given(charts())
def test_cost_fields_equal_the_reference(prob):
    u, kw, a, _, rc = prob
    if not _passable(u, kw["land"], rc[0]):
        with pytest.raises(ValueError, match="impassable"):
            seaway.cost_field(u, a, **kw)
        return
    field = np.asarray(seaway.cost_field(u, a, **kw))
    expect = _reference(u, kw).costs(rc[0])
    np.testing.assert_array_equal(np.isinf(field), np.isinf(expect))
    fin = np.isfinite(expect)
    np.testing.assert_allclose(field[fin], expect[fin], rtol=RTOL, atol=1e-300)


@FUZZ
@given(st.integers(1, 6), st.integers(1, 6), st.sampled_from(KS), st.data())
def test_one_prepared_chart_answers_every_pair(rows, cols, k, data):
    """Many queries on one PreparedChart (workspace reuse) against the reference, 1x1 to 6x6."""
    n = rows * cols
    u = np.array(
        data.draw(st.lists(st.sampled_from([0.0, 1.0, 3.0, np.inf]), min_size=n, max_size=n))
    ).reshape(rows, cols)
    u.flat[data.draw(st.integers(0, n - 1))] = 1.0
    chart = seaway.prepare(u, neighbourhood=k, edge_cost=data.draw(st.sampled_from(["max", "integral"])))
    ref = RefGraph(u, k=k, edge_cost=chart.edge_cost)
    water = [tuple(map(int, p)) for p in np.argwhere(np.isfinite(u))]
    for s in water[:4]:
        expect = ref.costs(s)
        for e in water:
            method = data.draw(st.sampled_from(["dijkstra", "astar"]))
            if np.isinf(expect[e]):
                with pytest.raises(seaway.NoRouteError):
                    chart.route(s, e, method=method)
            else:
                _check_route(chart.route(s, e, method=method), ref, [s, e], expect[e])


JUNK = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-5, 20),
    st.floats(allow_nan=True),
    st.text(max_size=4),
    st.tuples(st.integers(-3, 9)),
    st.tuples(st.floats(allow_nan=True), st.floats(allow_nan=True)),
    st.tuples(st.integers(-3, 9), st.integers(-3, 9)),
    st.tuples(st.integers(0, 3), st.integers(0, 3), st.integers(0, 3)),
    st.lists(st.integers(0, 3), max_size=3),
    st.just(np.array([1, 2])),
)


@FUZZ
@given(
    st.fixed_dictionaries(
        {},
        optional={
            "neighbourhood": JUNK,
            "directions": JUNK,
            "edge_cost": JUNK,
            "method": JUNK,
            "weight": JUNK,
            "dx": JUNK,
            "dy": JUNK,
        },
    ),
    JUNK,
    JUNK,
    st.sampled_from(["planar", "geo", "empty", "3d", "text", "land"]),
)
def test_junk_arguments_raise_value_or_type_errors(kw, start, end, chart):
    u = np.ones((4, 5))
    if chart == "geo":
        kw.update(lat=np.arange(4.0), lon=np.arange(5.0))
    elif chart == "empty":
        u = np.ones((0, 5))
    elif chart == "3d":
        u = np.ones((2, 4, 5))
    elif chart == "text":
        u = np.array([["a"] * 5] * 4)
    elif chart == "land":
        kw["land"] = np.ones((4, 6), bool)
    try:
        r = seaway.route(u, start, end, **kw)
    except (ValueError, TypeError) as e:
        assert len(str(e)) > 20  # a message, not a bare exception
        return
    # accepted: the arguments were valid, and the answer is the reference's
    k = kw.get("neighbourhood", 5)
    ref = RefGraph(
        u,
        k=k,
        directions=kw.get("directions", "full"),
        edge_cost=kw.get("edge_cost", "max"),
        dx=kw.get("dx", 1.0),
        dy=kw.get("dy", 1.0),
        **({"lat": kw["lat"], "lon": kw["lon"]} if "lat" in kw else {}),
    )
    expect = ref.costs(r.pixels[0])[tuple(r.pixels[-1])]
    assert ref.path_cost(r.pixels) == pytest.approx(r.cost, rel=RTOL)
    w = 1.0 if kw.get("weight") is None else float(kw["weight"])
    assert expect * (1 - RTOL) <= r.cost <= w * expect * (1 + RTOL) + 1e-12


@FUZZ
@given(st.integers(1, 5), st.integers(1, 6), st.data())
def test_compat_route_through_array_follows_skimage_rules(rows, cols, data):
    """Negative and non-finite costs are impassable, not errors (scikit-image's rules; its own
    route_through_array segfaults on some of these inputs, e.g. [[nan, nan, -1]] with
    geometric=False, so the path is checked against the rules here; test_compat compares the
    two on ordinary charts)."""
    n = rows * cols
    u = np.array(
        data.draw(st.lists(st.sampled_from([-1.0, 0.0, 0.5, 2.0, np.inf, np.nan]), min_size=n, max_size=n))
    ).reshape(rows, cols)
    s = (data.draw(st.integers(0, rows - 1)), data.draw(st.integers(0, cols - 1)))
    e = (data.draw(st.integers(0, rows - 1)), data.draw(st.integers(0, cols - 1)))
    geometric, full = data.draw(st.booleans()), data.draw(st.booleans())
    try:
        path, total = route_through_array(u, s, e, geometric=geometric, fully_connected=full)
    except ValueError as err:
        assert "no minimum-cost path" in str(err)
        return
    p = np.array(path)
    assert tuple(p[0]) == s and tuple(p[-1]) == e
    steps = np.abs(np.diff(p, axis=0))
    assert (steps.max(axis=1, initial=1) == 1).all() and (full or (steps.sum(axis=1) == 1).all())
    v = u[tuple(p.T)]
    assert (np.isfinite(v[1:]) & (v[1:] >= 0)).all()  # only the start may be impassable
    # (a negative start with geometric=True is seeded, as skimage does: its first step may
    # cost less than 0)
    if geometric:
        expect = float(np.sum((v[:-1] + v[1:]) / 2 * np.hypot(*steps.T))) if len(v) > 1 else 0.0
    else:
        expect = float(v.sum())
    assert total == pytest.approx(expect, rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("value, cell", [(1e300, 1e10), (1e308, 1.0), (1e8, 1e300)])
def test_costs_that_overflow_are_refused(value, cell):
    """A route's cost must stay a finite double: costs times step lengths that could overflow
    are an error naming the fix, not a silent 'no route'."""
    with pytest.raises(ValueError, match="overflow"):
        seaway.route(np.full((5, 5), value), (0, 0), (4, 4), dx=cell, dy=cell)


def test_cell_sizes_whose_extent_overflows_are_refused():
    with pytest.raises(ValueError, match="too large a cell size"):
        seaway.route(np.ones((5, 5)), (0, 0), (4, 4), dx=1e308)


@pytest.mark.parametrize("value, cell", [(5e-324, 1.0), (1e-310, 1.0), (1.0, 5e-324), (1e-200, 1e-200)])
def test_costs_too_small_for_double_precision_are_refused(value, cell):
    with pytest.raises(ValueError, match="small"):
        seaway.route(np.full((5, 5), value), (0, 0), (4, 4), dx=cell, dy=cell)


def test_extreme_but_representable_costs_route_exactly():
    u = np.full((6, 6), 1e250)
    u[1:5, 2] = 1e-250
    for method in ("dijkstra", "astar"):
        r = seaway.route(u, (1, 2), (4, 2), method=method, neighbourhood=3)
        assert r.cost == pytest.approx(3e-250, rel=1e-12)


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_misaligned_arrays_route_like_aligned_ones(dtype):
    """An array at an odd address (as unpickled on a Dask worker) is copied, not read in place
    (reading misaligned doubles is undefined behaviour: found by UBSan in .ci/sanitize)."""
    cost = np.random.default_rng(1).uniform(1, 5, (30, 40)).astype(dtype)
    buf = np.zeros(cost.nbytes + 1, np.uint8)
    odd = buf[1:].view(dtype).reshape(cost.shape)
    odd[...] = cost
    assert not odd.flags.aligned
    a, b = seaway.route(cost, (0, 0), (29, 39)), seaway.route(odd, (0, 0), (29, 39))
    assert a.cost == b.cost and np.array_equal(a.pixels, b.pixels)
