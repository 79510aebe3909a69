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
    path, total = benchmark.pedantic(
        route_through_array, args=(cost, start, end), rounds=5, iterations=1, warmup_rounds=1
    )
    record("seaway.compat.route_through_array", benchmark, "same graph as the peer")
    m = skgraph.MCP_Geometric(cost, fully_connected=True)
    costs, _ = m.find_costs([start], [end])
    assert total == pytest.approx(costs[end], rel=1e-9)


@pytest.mark.parametrize("k", [3, 5, 7])
@pytest.mark.parametrize("method", ["dijkstra", "astar"])
def test_seaway_route(benchmark, chart, k, method):
    cost, start, end = chart
    r = benchmark.pedantic(
        seaway.route,
        args=(cost, start, end),
        kwargs=dict(neighbourhood=k, method=method, edge_cost="mean"),
        rounds=5,
        iterations=1,
        warmup_rounds=1,
    )
    per_pixel = r.stats.search.state_bytes / cost.size
    record(
        f"seaway {method} k={k}", benchmark, f"{per_pixel:.1f} B/pixel, {r.stats.search.settled:,} settled"
    )
    exact = seaway.route(cost, start, end, neighbourhood=k, method="dijkstra", edge_cost="mean")
    assert r.cost == pytest.approx(exact.cost, rel=1e-9)
    assert per_pixel <= 16
    assert tuple(r.pixels[0]) == start and tuple(r.pixels[-1]) == end


def test_weighted_astar(benchmark, chart):
    cost, start, end = chart
    r = benchmark.pedantic(
        seaway.route,
        args=(cost, start, end),
        kwargs=dict(neighbourhood=5, method="astar", weight=1.5, edge_cost="mean"),
        rounds=5,
        iterations=1,
        warmup_rounds=1,
    )
    exact = seaway.route(cost, start, end, neighbourhood=5, method="dijkstra", edge_cost="mean")
    record(
        "seaway weighted A* w=1.5 k=5",
        benchmark,
        f"cost +{100 * (r.cost / exact.cost - 1):.2f} % over optimum",
    )
    assert exact.cost <= r.cost <= 1.5 * exact.cost
    assert SHAPE == cost.shape


@pytest.mark.parametrize("method", ["dijkstra", "astar"])
def test_summer_chart(benchmark, chart, method):
    """The same land with summer ice (costs 1-2): the A* bound is tight and A* prunes."""
    cost, start, end = chart
    summer = np.where(np.isfinite(cost), 1.0 + (cost - 1.0) / 29.0, np.inf)
    r = benchmark.pedantic(
        seaway.route,
        args=(summer, start, end),
        kwargs=dict(neighbourhood=5, method=method, edge_cost="mean"),
        rounds=5,
        iterations=1,
        warmup_rounds=1,
    )
    record(f"summer chart (costs 1-2) {method} k=5", benchmark, f"{r.stats.search.settled:,} settled")
    exact = seaway.route(summer, start, end, neighbourhood=5, method="dijkstra", edge_cost="mean")
    assert r.cost == pytest.approx(exact.cost, rel=1e-9)


_RSS_SCRIPT = """
import sys, numpy as np, seaway
def status(key):
    for line in open("/proc/self/status"):
        if line.startswith(key):
            return int(line.split()[1]) * 1024
cost = np.load(sys.argv[1]); start = tuple(map(int, sys.argv[2:4])); end = tuple(map(int, sys.argv[4:6]))
seaway.route(cost[:50, :50], (0, 0), (0, 0))  # load the module before the baseline
with open("/proc/self/clear_refs", "w") as f:
    f.write("5")  # reset the peak (VmHWM) to the current resident size
before = status("VmRSS:")
r = seaway.route(cost, start, end, neighbourhood=int(sys.argv[6]), method="dijkstra")
print((status("VmHWM:") - before) / cost.size, r.stats.search.state_bytes / cost.size)
"""


@pytest.mark.parametrize("k", [3, 5, 7])
def test_peak_memory_per_pixel(chart, tmp_path, k):
    """Peak resident memory the search adds, per pixel, measured in a fresh process."""
    import subprocess
    import sys

    cost, start, end = chart
    np.save(tmp_path / "chart.npy", cost)
    out = subprocess.run(
        [
            sys.executable,
            "-c",
            _RSS_SCRIPT,
            str(tmp_path / "chart.npy"),
            *map(str, start),
            *map(str, end),
            str(k),
        ],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split()
    rss, own = float(out[0]), float(out[1])
    from .conftest import NOTES

    NOTES[f"peak RSS added by the search, k={k}"] = f"{rss:.1f} B/pixel (engine's own count {own:.1f})"
    assert own <= 16 and rss <= 16
