"""The turn penalty (cpp/seaway/turns.hpp) against a brute-force Dijkstra on the expanded
(pixel, incoming step) graph (tests/reference_turns.py), every stencil size, planar and lat/lon
grids; hand-worked cases; via-points carry the incoming step across a via point."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

import seaway
from support.grids import make_chart, point
from support.reference import RefGraph
from support.reference_turns import turn_angle, turn_route_cost

KS = (3, 5, 7, 9, 11, 13, 15)
GRIDS = ("planar", "geo_asc", "geo_desc", "geo_wrap")
CASES = list(itertools.product(KS, GRIDS))
TABLE = {0: 0.0, 30: 0.2, 90: 1.5, 180: 4.0}


def path_cost_with_turns(ref, pixels, angles, costs, geo):
    """The route's cost recomputed: its edges plus the penalty of each course change."""
    dx, dy = geo.get("dx", 1.0), geo.get("dy", 1.0)
    total = ref.path_cost(pixels)
    for a, v, b in zip(pixels[:-2], pixels[1:-1], pixels[2:]):
        ang = turn_angle(ref, ref.node(v), ref.offset(a, v), ref.offset(v, b), dx, dy)
        total += float(np.interp(ang, angles, costs))
    return total


@pytest.mark.parametrize("k,grid", CASES)
def test_turn_penalty_matches_expanded_reference(k, grid):
    seed = CASES.index((k, grid))
    u, land, geo = make_chart(5000 + seed, grid, zeros=seed % 3 == 0)
    if k >= 11:  # keep the expanded reference small: pixels x offsets states
        u, land = u[:8, :], land[:8, :]
        if "lat" in geo:
            geo = dict(geo, lat=geo["lat"][:8])
    directions = ("full", "unique")[seed % 2]
    edge_cost = ("max", "mean", "integral")[seed % 3]
    per_degree = seed % 2 == 0
    penalty = 0.02 if per_degree else TABLE
    angles, costs = ([0, 180], [0, 180 * 0.02]) if per_degree else (list(TABLE), list(TABLE.values()))
    ref = RefGraph(u, land=land, k=k, directions=directions, edge_cost=edge_cost, **geo)
    chart = seaway.prepare(u, land=land, neighbourhood=k, directions=directions, edge_cost=edge_cost, **geo)
    rng = np.random.default_rng(seed)
    water = np.argwhere(ref.ok)
    checked = 0
    for _ in range(3):
        s, e = (tuple(int(v) for v in water[i]) for i in rng.choice(len(water), 2, replace=False))
        want = turn_route_cost(ref, s, e, angles, costs, geo.get("dx", 1.0), geo.get("dy", 1.0))
        for method in ("dijkstra", "astar"):
            if not np.isfinite(want):
                with pytest.raises(seaway.NoRouteError):
                    chart.route(point(geo, s), point(geo, e), method=method, turn_penalty=penalty)
                continue
            r = chart.route(point(geo, s), point(geo, e), method=method, turn_penalty=penalty)
            assert r.cost == pytest.approx(want, rel=1e-9, abs=1e-12)
            assert tuple(r.pixels[0]) == s and tuple(r.pixels[-1]) == e
            assert path_cost_with_turns(ref, r.pixels, angles, costs, geo) == pytest.approx(
                want, rel=1e-9, abs=1e-12
            )
            assert r.step_costs.sum() == pytest.approx(r.cost, rel=1e-12)
            checked += 1
    assert checked > 0


def test_zero_penalty_equals_plain_search():
    u = np.random.default_rng(3).uniform(0.5, 2.0, (20, 30))
    geo = dict(lat=60 + 0.5 * np.arange(20), lon=10 + 0.8 * np.arange(30))
    chart = seaway.prepare(u, neighbourhood=5, **geo)
    s, e = (60.0, 10.0), (69.5, 33.2)
    plain, zero = chart.route(s, e, method="dijkstra"), chart.route(s, e, method="dijkstra", turn_penalty=0)
    assert zero.cost == pytest.approx(plain.cost, rel=1e-12)
    assert zero.stats.search.settled > plain.stats.search.settled  # states, not pixels
    # the penalty is recorded as its table {degrees: cost}: 0 per degree, 0 to 180
    assert zero.stats.constraints.turn_penalty == {0.0: 0.0, 180.0: 0.0}
    assert zero.stats.constraints.via_pixels == () and plain.stats.constraints is None


def test_hand_worked_dogleg():
    """Open 5 x 5 sea, 3 x 3 stencil, from (4, 0) to (0, 4)... an L-shaped corridor forces one
    90 degree turn: the route is 8 unit steps + 90 x 0.5 = 53 with 0.5 per degree."""
    u = np.full((5, 5), np.inf)
    u[4, :] = 1.0
    u[:, 4] = 1.0
    r = seaway.route(u, (4, 0), (0, 4), neighbourhood=3, turn_penalty=0.5, method="dijkstra")
    assert r.cost == pytest.approx(8 + 45.0)
    assert r.pixels.tolist() == [[4, c] for c in range(5)] + [[rr, 4] for rr in (3, 2, 1, 0)]
    assert r.step_costs.tolist() == [1, 1, 1, 1, 1 + 45, 1, 1, 1]


def test_penalty_straightens_the_route():
    """A costly pixel on the straight line: without a penalty the route dodges it (two 45-degree
    turns, 4 + 2 sqrt 2); at 2 per degree the dodge costs 4 + 2 sqrt 2 + 180 > 104 = straight."""
    u = np.ones((3, 7))
    u[1, 3] = 50.0  # an obstacle-ish pixel on the straight line, max edge cost
    plain = seaway.route(u, (1, 0), (1, 6), neighbourhood=3, edge_cost="max")
    assert plain.cost == pytest.approx(4 + 2 * np.sqrt(2))
    dodge = seaway.route(u, (1, 0), (1, 6), neighbourhood=3, edge_cost="max", turn_penalty=0.5)
    assert dodge.cost == pytest.approx(4 + 2 * np.sqrt(2) + 90 * 0.5)
    turned = seaway.route(u, (1, 0), (1, 6), neighbourhood=3, edge_cost="max", turn_penalty=2.0)
    assert turned.pixels[:, 0].tolist() == [1] * 7  # straight through: 4 + 2 x 50 = 104
    assert turned.cost == pytest.approx(4 + 2 * 50)


def test_via_point_carries_the_incoming_step():
    """Through a via point, the course change there is charged: straight across costs nothing,
    a U-turn at the via point costs the 180-degree penalty."""
    u = np.ones((1, 9))
    r = seaway.route(u, (0, 0), (0, 8), via=[(0, 4)], neighbourhood=3, turn_penalty=0.1)
    assert r.cost == pytest.approx(8.0)
    back = seaway.route(u, (0, 0), (0, 2), via=[(0, 6)], neighbourhood=3, turn_penalty=0.1)
    assert back.cost == pytest.approx(6 + 4 + 18.0)  # 6 out, 4 back, one 180-degree turn
    assert back.pixels[:, 1].tolist() == [0, 1, 2, 3, 4, 5, 6, 5, 4, 3, 2]


@pytest.mark.parametrize(
    "bad,err",
    [
        (-1, ValueError),
        (float("nan"), ValueError),
        (True, TypeError),
        ({200: 1}, ValueError),
        ({0: -1}, ValueError),
        ("x", TypeError),
    ],
)
def test_bad_turn_penalty(bad, err):
    with pytest.raises(err, match="turn_penalty"):
        seaway.route(np.ones((4, 4)), (0, 0), (3, 3), turn_penalty=bad)


def test_turn_route_refuses_smoothing_and_names_its_model():
    """Smoothing would price legs without the penalties that the route's cost holds: refused."""
    u = np.ones((5, 9))
    r = seaway.route(u, (0, 0), (4, 8), neighbourhood=3, turn_penalty=0.1, edge_cost="mean")
    assert r.edge_cost == "mean" and r.step_costs.sum() == pytest.approx(r.cost)
    with pytest.raises(ValueError, match="turn penalties"):
        r.smoothed()


def test_astar_bound_is_the_cost_to_go_without_penalties():
    """A* searches the (pixel, step) states with the exact least cost to the end without turn
    penalties as its bound (a plain search from the end first): same cost as Dijkstra over the
    states, far fewer states settled; an end out of reach is refused without the state search."""
    rng = np.random.default_rng(3)
    u = rng.uniform(1.0, 30.0, (60, 80))
    u[rng.random(u.shape) < 0.15] = np.inf
    u[2, 2] = u[57, 77] = 1.0
    chart = seaway.prepare(u, edge_cost="mean")
    d = chart.route((2, 2), (57, 77), method="dijkstra", turn_penalty=0.05)
    a = chart.route((2, 2), (57, 77), method="astar", turn_penalty=0.05)
    assert a.cost == pytest.approx(d.cost, rel=1e-9)
    assert a.stats.search.settled < 0.5 * d.stats.search.settled
    walled = u.copy()
    walled[55:60, 74] = walled[55, 74:80] = np.inf  # the end's corner is cut off
    with pytest.raises(seaway.NoRouteError):
        seaway.prepare(walled).route((2, 2), (57, 77), method="astar", turn_penalty=0.05)


@pytest.mark.parametrize("seed", range(8))
def test_dominated_states_dropped_exactly_for_any_penalty_table(seed):
    """States are dropped by the margin of their offsets (turn_penalty.hpp), which holds for any
    table: growing or not with the angle, convex or concave, with a cost for going straight on.
    On charts large enough for many headings to reach a pixel at close costs, with turns priced
    like a few steps, each route against the expanded brute-force reference."""
    rng = np.random.default_rng(700 + seed)
    rows, cols = 22, 30
    u = rng.uniform(0.5, 3.0, (rows, cols))
    u[rng.random((rows, cols)) < 0.12] = np.inf
    geo = dict(dx=1.0, dy=float(rng.uniform(0.7, 1.4)))
    if seed % 2:
        geo = dict(lat=60 + 0.1 * np.arange(rows), lon=10 + 0.2 * np.arange(cols))
    k = (3, 5, 7)[seed % 3]
    angles = sorted({0.0, 180.0, *rng.uniform(5, 175, 3).round(1)})
    costs = rng.uniform(0, 4, len(angles)).round(2).tolist()
    if seed < 2:
        costs = [0.03 * a for a in angles]  # per degree: the margin is the turn's penalty
    ref = RefGraph(u, k=k, edge_cost="max", **geo)
    chart = seaway.prepare(u, neighbourhood=k, **geo)
    water = np.argwhere(ref.ok)
    checked = 0
    for _ in range(4):
        s, e = (tuple(int(v) for v in water[i]) for i in rng.choice(len(water), 2, replace=False))
        want = turn_route_cost(ref, s, e, angles, costs, geo.get("dx", 1.0), geo.get("dy", 1.0))
        if not np.isfinite(want):
            continue
        for method in ("dijkstra", "astar"):
            r = chart.route(
                point(geo, s), point(geo, e), method=method, turn_penalty=dict(zip(angles, costs))
            )
            assert r.cost == pytest.approx(want, rel=1e-9, abs=1e-12), (angles, costs, method)
            checked += 1
    assert checked >= 4


@pytest.mark.parametrize("seed", range(6))
def test_turn_search_exact_on_planar_charts_with_walls(seed):
    """A* keeps its buckets at 1 % of the bound (5 % when that needs too many buckets: costs up
    to 1000; a heap beyond: costs up to 1e5), a second expansion of a pixel skips the steps an
    earlier one took no dearer, and a pop checks only the pixel's expanded states (a bit mask).
    Non-square pixels, ends behind a wall that forces turning away and back, steep per-degree
    and table penalties: the same cost as the expanded brute-force reference and as Dijkstra
    over the states."""
    rng = np.random.default_rng(900 + seed)
    rows, cols = 20, 26
    top = (3.0, 3.0, 1000.0, 1e5, 3.0, 3.0)[seed]
    u = rng.uniform(1.0, top, (rows, cols))
    u[rng.random((rows, cols)) < 0.1] = np.inf
    u[4:16, 12] = np.inf  # a wall between the ends' halves, open at both ends
    geo = dict(dx=1.0, dy=(0.5, 2.0, 1.0, 0.7, 1.3, 1.0)[seed])
    k = (3, 5, 7, 5, 3, 5)[seed]
    per_degree = seed % 2 == 0
    angles, costs = (
        ([0.0, 180.0], [0.0, 180.0 * 0.3]) if per_degree else ([0, 45, 120, 180], [0.5, 3, 20, 25])
    )
    penalty = 0.3 if per_degree else dict(zip(angles, costs))
    ref = RefGraph(u, k=k, edge_cost="max", **geo)
    chart = seaway.prepare(u, neighbourhood=k, **geo)
    water = np.argwhere(ref.ok)
    left, right = water[water[:, 1] < 10], water[water[:, 1] > 14]
    checked = 0
    for _ in range(4):
        s = tuple(int(v) for v in left[rng.integers(len(left))])
        e = tuple(int(v) for v in right[rng.integers(len(right))])
        want = turn_route_cost(ref, s, e, angles, costs, geo["dx"], geo["dy"])
        if not np.isfinite(want):
            continue
        a = chart.route(s, e, method="astar", turn_penalty=penalty)
        d = chart.route(s, e, method="dijkstra", turn_penalty=penalty)
        assert a.cost == pytest.approx(want, rel=1e-9, abs=1e-12)
        assert d.cost == pytest.approx(want, rel=1e-9, abs=1e-12)
        assert path_cost_with_turns(ref, a.pixels, angles, costs, geo) == pytest.approx(want, rel=1e-9)
        assert a.stats.search.settled <= d.stats.search.settled
        checked += 1
    assert checked >= 2
