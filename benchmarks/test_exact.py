"""The exact searches' memory and the route quality of smoothing (their speed, voyage by voyage:
test_voyages.py).

* Search memory of the default path: <= 16 B/pixel (engine's count and peak RSS in a fresh
  process).
* Route quality: the smoothed 5x5 route's cost under the mean model against scikit-fmm's
  continuous optimum (fast marching, order 2). Goal: within 0.3 %."""

import subprocess
import sys
import time

import numpy as np
import pytest

import seaway

from .conftest import NOTES, record

_RSS_SCRIPT = """
import sys, numpy as np, seaway
def status(key):
    for line in open("/proc/self/status"):
        if line.startswith(key):
            return int(line.split()[1]) * 1024
cost = np.load(sys.argv[1]); start = tuple(map(int, sys.argv[2:4])); end = tuple(map(int, sys.argv[4:6]))
chart = seaway.prepare(cost, edge_cost="mean")
chart.route((start[0], start[1]), (start[0], start[1]))
with open("/proc/self/clear_refs", "w") as f:
    f.write("5")  # reset the peak (VmHWM) to the current resident size
before = status("VmRSS:")
r = chart.route(start, end)
print((status("VmHWM:") - before) / cost.size, r.stats.search.state_bytes / cost.size, r.method)
"""


def test_default_search_memory(chart, tmp_path):
    """Peak resident memory the default (auto = bidirectional) search adds, fresh process."""
    cost, start, end = chart
    np.save(tmp_path / "chart.npy", cost)
    out = subprocess.run(
        [sys.executable, "-c", _RSS_SCRIPT, str(tmp_path / "chart.npy"), *map(str, start), *map(str, end)],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split()
    rss, own = float(out[0]), float(out[1])
    NOTES["peak RSS added by the default search (auto), k=5"] = (
        f"{rss:.1f} B/pixel (engine's own count {own:.1f}), {out[2]}"
    )
    assert out[2] == "bidirectional" and own <= 16 and rss <= 16


def test_route_quality_against_fast_marching(benchmark, chart):
    """Smoothed 5x5 route (mean model) against scikit-fmm's continuous optimum, same chart."""
    skfmm = pytest.importorskip("skfmm")
    cost, s, e = chart
    land = ~np.isfinite(cost)
    phi = np.ones_like(cost)
    phi[s] = -1.0  # zero level set half a pixel around the start
    t0 = time.perf_counter()
    arrival = skfmm.travel_time(
        np.ma.MaskedArray(phi, land), np.where(land, 1.0, 1.0 / np.where(land, 1.0, cost)), dx=1.0, order=2
    )
    fmm_s = time.perf_counter() - t0
    best = float(arrival[e])
    r = seaway.route(cost, s, e, edge_cost="mean")
    sm = benchmark.pedantic(r.smoothed, rounds=3, iterations=1)
    raw, smooth = 100 * (r.cost / best - 1), 100 * (sm.cost / best - 1)
    record(
        "smooth benchmark chart (mean, 5x5)",
        benchmark,
        f"raw {raw:+.3f} %, smoothed {smooth:+.3f} % vs scikit-fmm order 2 ({best:.1f}, "
        f"{fmm_s:.1f} s); course changes {r.course_changes} -> {sm.course_changes}",
    )
    assert abs(smooth) <= 0.3 and sm.cost <= r.cost
