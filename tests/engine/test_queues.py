"""The engine picks its priority queue from the chart: a bucket queue when every step costs at
least some positive width (Dijkstra, and A* with a slightly scaled bound), a radix heap when a
step may cost zero, a 4-ary heap for weighted A*. All must give the same optimal costs.

A pixel of cost 0 walled in by land changes no route but forces the radix heap, so the same
chart is routed through both queues."""

import numpy as np
import pytest

import seaway
from support.reference import RefGraph


def _chart(rows, cols, seed, land_fraction=0.15):
    rng = np.random.default_rng(seed)
    cost = rng.uniform(1.0, 30.0, (rows, cols))
    cost[rng.random((rows, cols)) < land_fraction] = np.inf
    cost[rows // 2, 1] = cost[rows // 2, cols - 2] = 5.0  # the ends are water
    return cost


def _with_zero_pixel(cost):
    """The same chart plus an unreachable pixel of cost 0 (forces the radix heap)."""
    out = cost.copy()
    out[2:5, 2:5] = np.inf
    out[3, 3] = 0.0
    return out


@pytest.mark.parametrize("k", [3, 5, 7])
@pytest.mark.parametrize("edge_cost", ["max", "mean", "integral"])
def test_long_chart_all_queues_agree(k, edge_cost):
    # Long enough that the A* bound of the start is many times the costliest step, which is
    # where a bucket queue that assumed keys start near zero went wrong.
    cost = _chart(30, 700, seed=k)
    start, end = (15, 1), (15, 698)
    kw = dict(neighbourhood=k, edge_cost=edge_cost)
    runs = {
        "bucket dijkstra": seaway.route(cost, start, end, method="dijkstra", **kw),
        "bucket astar": seaway.route(cost, start, end, method="astar", **kw),
        "radix dijkstra": seaway.route(_with_zero_pixel(cost), start, end, method="dijkstra", **kw),
        "radix astar": seaway.route(_with_zero_pixel(cost), start, end, method="astar", **kw),
    }
    best = runs["radix dijkstra"].cost
    for name, r in runs.items():
        assert r.cost == pytest.approx(best, rel=1e-9), name
    w = seaway.route(cost, start, end, method="astar", weight=2.0, **kw)
    assert best * (1 - 1e-12) <= w.cost <= 2.0 * best


@pytest.mark.parametrize("method", ["dijkstra", "astar"])
def test_bucket_queue_matches_reference(method):
    cost = _chart(12, 160, seed=11)
    ref = RefGraph(cost, k=5, directions="full", edge_cost="mean")
    expected = ref.costs((6, 1))[6, 158]
    r = seaway.route(cost, (6, 1), (6, 158), neighbourhood=5, edge_cost="mean", method=method)
    assert r.cost == pytest.approx(expected, rel=1e-9)
    assert ref.path_cost(r.pixels) == pytest.approx(expected, rel=1e-9)


def test_wide_cost_range_falls_back_and_stays_exact():
    # Costs from 1e-3 to 1e3: too many buckets, so the radix heap is used; still exact.
    rng = np.random.default_rng(5)
    cost = 10.0 ** rng.uniform(-3, 3, (40, 60))
    d = seaway.route(cost, (0, 0), (39, 59), method="dijkstra", neighbourhood=5)
    a = seaway.route(cost, (0, 0), (39, 59), method="astar", neighbourhood=5)
    ref = RefGraph(cost, k=5, directions="full", edge_cost="max")
    assert d.cost == pytest.approx(ref.costs((0, 0))[39, 59], rel=1e-9)
    assert a.cost == pytest.approx(d.cost, rel=1e-9)
