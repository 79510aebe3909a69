"""seaway.prepare(): one chart, many queries, several threads, reused search state."""

import os
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import seaway


def _chart(seed=3, shape=(60, 80)):
    rng = np.random.default_rng(seed)
    cost = rng.uniform(1.0, 20.0, shape)
    cost[rng.random(shape) < 0.2] = np.inf
    return cost


def _water(cost, n, seed=4):
    rng = np.random.default_rng(seed)
    water = np.argwhere(np.isfinite(cost))
    return [tuple(map(int, water[i])) for i in rng.choice(len(water), n, replace=False)]


def _cost_or_none(fn):
    try:
        return fn().cost
    except seaway.NoRouteError:
        return None


def test_prepared_queries_equal_fresh_routes():
    cost = _chart()
    chart = seaway.prepare(cost, neighbourhood=5, edge_cost="integral")
    pts = _water(cost, 12)
    for method in ("dijkstra", "astar"):
        for a, b in zip(pts[:-1], pts[1:]):
            expected = _cost_or_none(
                lambda: seaway.route(cost, a, b, neighbourhood=5, edge_cost="integral", method=method)
            )
            got = _cost_or_none(lambda: chart.route(a, b, method=method))
            assert got == expected  # the same numbers, bit for bit
    field = chart.cost_field(pts[0])
    np.testing.assert_array_equal(
        field, seaway.cost_field(cost, pts[0], neighbourhood=5, edge_cost="integral")
    )


def test_state_left_by_one_query_does_not_leak_into_the_next():
    cost = _chart(seed=8)
    chart = seaway.prepare(cost, neighbourhood=3)
    a, b, c = _water(cost, 3, seed=9)
    first = chart.cost_field(a)
    chart.route(b, c, method="astar")  # a partial search from elsewhere
    chart.route(b, c, method="astar", weight=3.0)
    np.testing.assert_array_equal(chart.cost_field(a), first)


def test_threads_give_the_serial_answers():
    cost = _chart(seed=5, shape=(120, 150))
    chart = seaway.prepare(cost, neighbourhood=7)
    pts = _water(cost, 40, seed=6)
    pairs = list(zip(pts[::2], pts[1::2])) * 3
    serial = [_cost_or_none(lambda p=p: chart.route(*p)) for p in pairs]
    with ThreadPoolExecutor(4) as pool:
        threaded = list(pool.map(lambda p: _cost_or_none(lambda: chart.route(*p)), pairs))
    assert threaded == serial
    assert sum(c is not None for c in serial) > len(pairs) // 2


def _status_bytes(key):
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith(key):
                return int(line.split()[1]) * 1024
    raise KeyError(key)


@pytest.mark.skipif(not os.access("/proc/self/clear_refs", os.W_OK), reason="needs Linux /proc")
def test_second_query_allocates_nothing_large():
    cost = np.ones((1500, 1500))  # 2.25 M pixels: a workspace of ~20 MB
    chart = seaway.prepare(cost, neighbourhood=5)
    chart.route((0, 0), (1499, 1499), method="dijkstra")
    with open("/proc/self/clear_refs", "w") as f:
        f.write("5")  # reset the peak resident size to the current one
    before = _status_bytes("VmRSS:")
    r = chart.route((0, 0), (1499, 1499), method="dijkstra")
    grown = _status_bytes("VmHWM:") - before
    assert grown < 2_000_000, f"the second query grew the process by {grown} bytes"
    assert r.cost == pytest.approx(1499 * np.sqrt(2), rel=1e-12)
