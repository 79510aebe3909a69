"""Engine speed against scikit-image's MCP on the synthetic Kara-sized chart, same run.

Each benchmark also asserts its result, so a fast wrong answer fails."""

import numpy as np
import pytest

import seaway
from seaway.compat import route_through_array

from .conftest import SHAPE, record

skgraph = pytest.importorskip("skimage.graph")


def test_skimage_mcp_geometric(benchmark, chart):
    cost, start, end = chart

    def run():
        m = skgraph.MCP_Geometric(cost, fully_connected=True)
        costs, _ = m.find_costs([start], [end])
        return costs[end], m.traceback(end)

    total, path = benchmark.pedantic(run, rounds=5, iterations=1, warmup_rounds=1)
    record("skimage MCP_Geometric 8-conn", benchmark, "the peer")
    assert np.isfinite(total) and path[0] == start and path[-1] == end


def test_compat_matches_skimage(benchmark, chart):
    cost, start, end = chart
    path, total = benchmark.pedantic(route_through_array, args=(cost, start, end),
                                     rounds=5, iterations=1, warmup_rounds=1)
    record("seaway.compat.route_through_array", benchmark, "same graph as the peer")
    m = skgraph.MCP_Geometric(cost, fully_connected=True)
    costs, _ = m.find_costs([start], [end])
    assert total == pytest.approx(costs[end], rel=1e-9)


@pytest.mark.parametrize("k", [3, 5, 7])
@pytest.mark.parametrize("method", ["dijkstra", "astar"])
def test_seaway_route(benchmark, chart, k, method):
    cost, start, end = chart
    r = benchmark.pedantic(seaway.route, args=(cost, start, end),
                           kwargs=dict(neighbourhood=k, method=method, edge_cost="mean"),
                           rounds=5, iterations=1, warmup_rounds=1)
    per_pixel = r.stats["state_bytes"] / cost.size
    record(f"seaway {method} k={k}", benchmark,
           f"{per_pixel:.1f} B/pixel, {r.stats['settled']:,} settled")
    exact = seaway.route(cost, start, end, neighbourhood=k, method="dijkstra", edge_cost="mean")
    assert r.cost == pytest.approx(exact.cost, rel=1e-9)
    assert per_pixel <= 16
    assert tuple(r.pixels[0]) == start and tuple(r.pixels[-1]) == end


def test_weighted_astar(benchmark, chart):
    cost, start, end = chart
    r = benchmark.pedantic(seaway.route, args=(cost, start, end),
                           kwargs=dict(neighbourhood=5, method="astar", weight=1.5, edge_cost="mean"),
                           rounds=5, iterations=1, warmup_rounds=1)
    exact = seaway.route(cost, start, end, neighbourhood=5, method="dijkstra", edge_cost="mean")
    record("seaway weighted A* w=1.5 k=5", benchmark,
           f"cost +{100 * (r.cost / exact.cost - 1):.2f} % over optimum")
    assert exact.cost <= r.cost <= 1.5 * exact.cost
    assert SHAPE == cost.shape
