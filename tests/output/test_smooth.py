"""Any-angle smoothing (seaway.smooth) and the leg model it prices shortcuts with."""

import numpy as np
import pytest

import seaway
from seaway import smooth
from seaway.models import EdgeCost
from support.reference import refraction_optimum
from support.reference_legs import Segments as NumpySegments


@pytest.mark.parametrize("edge_cost", ["max", "mean", "integral"])
@pytest.mark.parametrize("k", [3, 5, 7])
def test_leg_model_reproduces_engine_cost(edge_cost, k):
    rng = np.random.default_rng(k)
    cost = rng.uniform(1, 5, (40, 50))
    cost[10:30, 20:23] = np.inf
    r = seaway.route(cost, (20, 2), (18, 45), neighbourhood=k, edge_cost=edge_cost)
    assert EdgeCost(edge_cost).segments(r.chart, k).cost(r.vertices) == pytest.approx(r.cost, rel=1e-12)
    assert r.costs().sum() == pytest.approx(r.cost, rel=1e-12)


def test_geographic_leg_model_reproduces_engine_cost():
    lat, lon = np.linspace(70, 60, 101), np.linspace(170, 190, 201)
    cost = np.random.default_rng(0).uniform(1, 3, (101, 201))
    r = seaway.route(cost, (69, 171), (61, 189), lat=lat, lon=lon, edge_cost="integral")
    assert r.costs().sum() == pytest.approx(r.cost, rel=1e-12)


def test_long_geographic_leg_follows_the_great_circle():
    """A leg across 18 degrees of longitude at 69 N costs the great-circle distance on a
    uniform chart, and its path bulges poleward (rows decrease) as a great circle does."""
    lat, lon = np.linspace(70, 60, 101), np.linspace(170, 190, 201)
    r = seaway.route(np.ones((101, 201)), (69, 171), (61, 189), lat=lat, lon=lon)
    seg = EdgeCost("integral").segments(r.chart, 5)
    c, km = seg.leg(np.array([10.0, 2.0]), np.array([10.0, 190.0]))
    assert c == pytest.approx(seaway._core.haversine_km(69, 170.2, 69, 189.0), rel=1e-12)
    assert km == pytest.approx(c)
    path = NumpySegments(r.chart, "integral", 5)._path(
        np.array([10.0, 2.0]), np.array([10.0, 190.0]), straight=False
    )
    assert path[:, 0].min() == pytest.approx(7.42, abs=0.02)  # 0.26 degrees north of 69 N


def test_uniform_chart_becomes_the_straight_line():
    r = seaway.route(np.ones((200, 300)), (10, 5), (190, 290), neighbourhood=5)
    s = smooth(r)
    assert r.cost > np.hypot(180, 285) * 1.001  # the raster route zig-zags
    assert s.cost == pytest.approx(np.hypot(180, 285), rel=1e-12)
    assert s.points.tolist() == [[10, 5], [190, 290]]
    assert s.stats.smoothing.course_changes_before == r.course_changes > 0
    assert s.stats.smoothing.course_changes_after == 0 and s.course_changes == 0
    assert s.stats.smoothing.cost_before == r.cost and s.stats.smoothing.shortcut_legs == 1
    assert s.stats.search == r.stats.search  # the search's figures are kept
    # A route of one step has nothing to smooth, and says so (the CLI prints these figures).
    one = seaway.route(np.ones((5, 5)), (0, 0), (1, 1)).smoothed()
    assert one.cost == pytest.approx(np.sqrt(2)) and len(one.points) == 2
    assert (
        one.stats.smoothing.cost_before,
        one.stats.smoothing.course_changes_after,
        one.stats.smoothing.shortcut_legs,
    ) == (one.cost, 0, 1)


def test_island_is_rounded_at_its_corners_without_touching_it():
    cost = np.ones((200, 300))
    cost[50:150, 140:160] = np.inf
    r = seaway.route(cost, (100, 10), (100, 290), neighbourhood=5, edge_cost="integral")
    s = r.smoothed()
    # optimum: round the corners (149.5, 139.5) and (149.5, 159.5) of the island's closed squares
    best = np.hypot(49.5, 129.5) + 20 + np.hypot(49.5, 130.5)
    assert best < s.cost <= best * 1.001 and s.cost < r.cost
    assert len(s.points) == 4 and np.all(s.points[1:3, 0] > 149.5)
    seg = s.segments()
    assert all(np.isfinite(seg.leg(a, b)[0]) for a, b in zip(s.points[:-1], s.points[1:]))
    assert seg.leg(np.array([100.0, 10.0]), np.array([100.0, 290.0]))[0] == np.inf


def test_two_media_refract_as_snell():
    cost = np.ones((200, 300))
    cost[100:] = 2.0  # interface between rows 99 and 100: y = 99.5
    r = seaway.route(cost, (10, 5), (190, 290), neighbourhood=5, edge_cost="integral")
    s = r.smoothed()
    best, x = refraction_optimum(1.0, 2.0, (10, 5), (190, 290), 99.5)
    assert best <= s.cost <= best * 1.0005 and s.cost < r.cost
    assert len(s.points) == 3 and s.points[1] == pytest.approx([99.5, x], abs=0.5)


@pytest.mark.parametrize("edge_cost", ["max", "mean"])
def test_smoothing_never_raises_cost(edge_cost):
    cost = np.random.default_rng(3).uniform(1, 4, (40, 50))
    cost[10:30, 20:23] = np.inf
    for k in (3, 5, 7):
        r = seaway.route(cost, (20, 2), (21, 48), neighbourhood=k, edge_cost=edge_cost)
        s = r.smoothed()
        assert s.cost <= r.cost * (1 + 1e-12)
        assert s.costs().sum() == pytest.approx(s.cost)
        assert s.stats.smoothing.course_changes_after == s.course_changes
        # the smoothed waypoints re-priced from scratch give the same cost
        assert EdgeCost(edge_cost).segments(r.chart, k).cost(s.points) == pytest.approx(s.cost, rel=1e-12)


def test_smoothed_geographic_route_has_coords_and_length():
    lat, lon = np.linspace(70, 60, 101), np.linspace(170, 190, 201)
    r = seaway.route(np.ones((101, 201)), (69, 171), (61, 189), lat=lat, lon=lon)
    s = r.smoothed()
    gc = seaway._core.haversine_km(69, 171, 61, 189)
    assert s.cost == pytest.approx(gc, rel=1e-9) and s.length == pytest.approx(gc, rel=1e-9)
    assert s.coords.ravel() == pytest.approx([69, 171, 61, 189])
    assert r.cost > gc * 1.001


@pytest.mark.parametrize("grid", ["planar", "geo_asc", "geo_desc", "geo_wrap"])
@pytest.mark.parametrize("edge_cost", ["max", "mean", "integral"])
def test_cpp_legs_match_the_numpy_reference(grid, edge_cost):
    """Random legs (pixel centres, fractional points, long great circles, across the seam, into
    land and off the chart) cost what the former numpy implementation says."""
    from support.grids import make_chart

    u, land, geo = make_chart(900 + len(grid) + len(edge_cost), grid, zeros=False)
    u = np.where(np.isfinite(u), u, 1.0)  # keep most legs open: land comes from the mask only
    land = land & (np.random.default_rng(1).random(u.shape) < 0.3)
    chart = seaway.prepare(u, land=land, **geo).chart
    ours, ref = EdgeCost(edge_cost).segments(chart, 5), NumpySegments(chart, edge_cost, 5)
    rng = np.random.default_rng(2)
    rows, cols = u.shape
    pts = np.column_stack([rng.uniform(-0.4, rows - 0.6, 600), rng.uniform(-0.4, cols - 0.6, 600)])
    pts[:200] = np.round(pts[:200])  # pixel centres: stencil steps and longer legs
    pts[200:260, 0] = np.round(pts[200:260, 0]) + 0.5  # on pixel borders
    if grid == "geo_wrap":
        pts[260:300, 1] = rng.uniform(cols - 3, cols + 2, 40)  # across the seam
    finite = 0
    for a, b in zip(pts[:-1], pts[1:]):
        c, km = ours.leg(a, b)
        c_ref, km_ref = ref.leg(a, b)
        assert km == pytest.approx(km_ref, rel=1e-9, abs=1e-12)
        if np.isinf(c_ref):
            assert np.isinf(c), (a, b)
        else:
            assert c == pytest.approx(c_ref, rel=1e-9, abs=1e-12), (a, b)
            finite += 1
    assert finite > 100
