"""Closed-form checks on uniform and simple charts: exact optima of an obstacle-free planar grid,
the angular-error bound of a stencil, exact line integrals, and great-circle distances."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

import seaway
from support.reference import haversine

RTOL = 1e-9


def primitive_offsets(k):
    h = (k - 1) // 2
    return [
        (a, b)
        for a in range(-h, h + 1)
        for b in range(-h, h + 1)
        if (a, b) != (0, 0) and math.gcd(abs(a), abs(b)) == 1
    ]


def lattice_optimum(targets, k, dx, dy):
    """min sum_v n_v |v| over stencil vectors v with sum_v n_v v = target, n_v >= 0, for each
    (di, dj) row of `targets`.

    This is the linear-programming optimum (reached by two stencil vectors bracketing the target
    direction); it is also the integer optimum because angularly adjacent primitive vectors of a
    square stencil form a unimodular basis (consecutive Farey fractions)."""
    t = np.asarray(targets, dtype=float)
    vs = np.array(primitive_offsets(k), dtype=float)
    lengths = np.hypot(vs[:, 0] * dy, vs[:, 1] * dx)
    best = np.where((t == 0).all(axis=1), 0.0, np.inf)
    for p, q in itertools.combinations(range(len(vs)), 2):
        det = vs[p, 0] * vs[q, 1] - vs[p, 1] * vs[q, 0]
        if det == 0:
            continue
        alpha = (t[:, 0] * vs[q, 1] - t[:, 1] * vs[q, 0]) / det
        beta = (vs[p, 0] * t[:, 1] - vs[p, 1] * t[:, 0]) / det
        cost = np.where((alpha >= -1e-12) & (beta >= -1e-12), alpha * lengths[p] + beta * lengths[q], np.inf)
        best = np.minimum(best, cost)
    return best


def worst_angle_factor(k):
    """1 / cos(delta / 2), delta the widest angle between adjacent stencil directions."""
    ang = sorted(math.atan2(a, b) for a, b in primitive_offsets(k))
    gaps = np.diff(ang + [ang[0] + 2 * math.pi])
    return 1 / math.cos(gaps.max() / 2)


@pytest.mark.parametrize("k,expected", [(3, 1.0824), (5, 1.0275), (7, 1.0131)])
def test_worst_angle_factor_values(k, expected):
    assert worst_angle_factor(k) == pytest.approx(expected, abs=5e-5)


@pytest.mark.parametrize("k", [3, 5, 7])
@pytest.mark.parametrize("directions", ["full", "unique"])
@pytest.mark.parametrize("edge_cost", ["max", "mean", "integral"])
def test_uniform_planar_exact_optimum(k, directions, edge_cost):
    rng = np.random.default_rng(k * 10 + len(directions))
    dx, dy = (float(v) for v in rng.uniform(0.4, 2.5, size=2))
    n, c = 17, 8
    u = np.ones((n, n))
    field = seaway.cost_field(
        u, (c, c), dx=dx, dy=dy, neighbourhood=k, directions=directions, edge_cost=edge_cost
    )
    i, j = np.indices((n, n))
    expect = lattice_optimum(np.column_stack([i.ravel() - c, j.ravel() - c]), k, dx, dy).reshape(n, n)
    np.testing.assert_allclose(field, expect, rtol=RTOL, atol=1e-12)
    # route() from a corner agrees with the field, and scaling the cost scales the route
    r = seaway.route(
        3.5 * u, (c, c), (0, n - 3), dx=dx, dy=dy, neighbourhood=k, directions=directions, edge_cost=edge_cost
    )
    assert r.cost == pytest.approx(3.5 * expect[0, n - 3], rel=RTOL)
    assert r.length == pytest.approx(expect[0, n - 3], rel=RTOL)


@pytest.mark.parametrize("k", [3, 5, 7])
def test_uniform_planar_angle_bound(k):
    n, c = 41, 20
    field = seaway.cost_field(np.ones((n, n)), (c, c), neighbourhood=k)
    i, j = np.indices((n, n))
    straight = np.hypot(i - c, j - c)
    ratio = field[straight > 0] / straight[straight > 0]
    bound = worst_angle_factor(k)
    assert ratio.min() == pytest.approx(1.0, rel=RTOL)  # stencil directions are exact
    assert ratio.max() <= bound * (1 + RTOL)
    assert ratio.max() >= 1 + 0.8 * (bound - 1)  # and the bound is nearly reached


@pytest.mark.parametrize("k", [3, 5, 7, 9])
def test_single_row_integral_is_trapezoid_sum(k):
    """On a one-row chart every route is a straight line, so the line integral is exact:
    dx * (u0/2 + u1 + ... + u_{c-1} + uc/2)."""
    rng = np.random.default_rng(k)
    u = rng.uniform(0.0, 5.0, size=(1, 23))
    dx = 0.7
    field = seaway.cost_field(u, (0, 0), dx=dx, neighbourhood=k, edge_cost="integral")
    v = u[0]
    expect = dx * (np.concatenate([[0.0], np.cumsum((v[:-1] + v[1:]) / 2)]))
    np.testing.assert_allclose(field[0], expect, rtol=RTOL, atol=1e-12)


def test_diagonal_integral_and_mean_and_max():
    """A single diagonal step (k=3): the segment spends half its length in each end pixel and
    only meets the two other pixels at a corner."""
    u = np.array([[2.0, 7.0], [9.0, 4.0]])
    d = math.hypot(1.5, 0.5)
    for edge_cost, unit in (("integral", 3.0), ("mean", 3.0), ("max", 4.0)):
        r = seaway.route(u, (0, 0), (1, 1), dx=0.5, dy=1.5, neighbourhood=3, edge_cost=edge_cost)
        assert r.cost == pytest.approx(unit * d, rel=RTOL)
        assert r.pixels.tolist() == [[0, 0], [1, 1]]


def test_knight_step_integral_fractions():
    """Step (1, 2): a quarter of the segment in each of (0,0), (0,1), (1,1), (1,2)."""
    u = np.array([[1.0, 2.0, 50.0], [50.0, 3.0, 4.0]])
    r = seaway.route(u, (0, 0), (1, 2), neighbourhood=5, edge_cost="integral")
    assert r.cost == pytest.approx(math.sqrt(5) * (1 + 2 + 3 + 4) / 4, rel=RTOL)
    assert r.pixels.tolist() == [[0, 0], [1, 2]]


GEO_STEPS = [(0, 1), (1, 0), (1, 1), (1, -1), (2, 1), (-1, 3), (3, -2), (-3, -3), (0, 3), (2, -3)]


@pytest.mark.parametrize("lat_sign", [1, -1])
@pytest.mark.parametrize("edge_cost", ["max", "mean", "integral"])
def test_single_geographic_step_is_haversine(lat_sign, edge_cost):
    lat = lat_sign * np.linspace(-35.0, 61.0, 9)  # 12-degree spacing, ascending or descending
    lon = 150.0 + 7.5 * np.arange(8)  # crosses 180 without wrapping
    u = np.ones((9, 8))
    for (di, dj), (i, j) in itertools.product(GEO_STEPS, [(3, 3), (5, 4), (4, 3)]):
        a, b = (lat[i], lon[j]), (lat[i + di], lon[j + dj])
        r = seaway.route(u, a, b, lat=lat, lon=lon, neighbourhood=7, edge_cost=edge_cost)
        assert r.cost == pytest.approx(haversine(*a, *b), rel=1e-12), (di, dj)
        assert r.length == pytest.approx(r.cost, rel=1e-12)


def test_single_step_across_antimeridian_on_wrapping_chart():
    lat, lon = np.array([-10.0, 0.0, 10.0]), -175.0 + 22.5 * np.arange(16)
    u = np.ones((3, 16))
    r = seaway.route(
        u, (10.0, lon[15]), (-10.0, lon[1]), lat=lat, lon=lon, neighbourhood=7, method="dijkstra"
    )
    assert r.cost == pytest.approx(haversine(10.0, lon[15], -10.0, lon[1]), rel=1e-12)
    assert r.pixels.tolist() == [[2, 15], [0, 1]]


@pytest.mark.parametrize(
    "start,end", [((45, 5), (55, 35)), ((41, 1), (59, 2)), ((59, 0.5), (41, 39.5)), ((50, 0.5), (50, 39.5))]
)
def test_uniform_geographic_close_to_great_circle(start, end):
    lat, lon = np.arange(40, 60.001, 0.25), np.arange(0, 40.001, 0.25)
    u = np.ones((lat.size, lon.size))
    gc = haversine(*start, *end)
    costs = {}
    for k in (3, 5, 7):
        r = seaway.route(u, start, end, lat=lat, lon=lon, neighbourhood=k, method="dijkstra")
        a = seaway.route(u, start, end, lat=lat, lon=lon, neighbourhood=k, method="astar")
        assert a.cost == pytest.approx(r.cost, rel=RTOL)
        assert r.cost >= gc * (1 - 1e-12)
        costs[k] = r.cost
    assert costs[7] <= gc * 1.015
    assert costs[7] <= costs[5] * (1 + 1e-12) and costs[5] <= costs[3] * (1 + 1e-12)


def test_geographic_descending_axes_same_as_ascending():
    """Flipping both axes of a chart (and its coordinates) does not change any route cost."""
    rng = np.random.default_rng(3)
    lat, lon = np.linspace(-20.0, 10.0, 11), np.linspace(100.0, 125.0, 11)
    u = rng.uniform(0.5, 2.0, size=(11, 11))
    for edge_cost in ("max", "mean", "integral"):
        kw = dict(neighbourhood=5, edge_cost=edge_cost)
        f1 = seaway.cost_field(u, (-17.0, 102.5), lat=lat, lon=lon, **kw)
        f2 = seaway.cost_field(u[::-1, ::-1], (-17.0, 102.5), lat=lat[::-1], lon=lon[::-1], **kw)
        np.testing.assert_allclose(f2[::-1, ::-1], f1, rtol=RTOL)


@pytest.mark.parametrize("k", [3, 5, 7])
def test_route_over_the_pole_is_the_meridian(k):
    """Pixels on the pole row are one point (zero-length steps); the way from (60, -180) to
    (60, 0) over the pole is exactly the great circle."""
    lat, lon = np.array([60.0, 70.0, 80.0, 90.0]), -180.0 + 22.5 * np.arange(16)
    u = np.ones((4, 16))
    for method in ("dijkstra", "astar"):
        r = seaway.route(u, (60.0, -180.0), (60.0, 0.0), lat=lat, lon=lon, neighbourhood=k, method=method)
        assert r.cost == pytest.approx(haversine(60.0, -180.0, 60.0, 0.0), rel=1e-12)
        assert r.cost == pytest.approx(60 * math.pi / 180 * 6371.0088, rel=1e-12)
