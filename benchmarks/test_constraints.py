"""What the turn penalty costs: peak resident memory and time of the expanded-state
search (pixel x incoming step) on the synthetic Kara-sized chart, each in a fresh process,
beside the plain search in the same process; and the turn route against the plain one on
charts of the family (benchmarks/family.py), tuned on and held out. Slow (tens of seconds per
case): run on its own, `pytest benchmarks/test_constraints.py -s -p no:randomly` (see
benchmarks/README.md)."""

import subprocess
import sys
import time

import numpy as np
import pytest

import seaway

from .conftest import NOTES
from .family import BUILDERS

_SCRIPT = """
import sys, time, resource, numpy as np, seaway
def status(key):
    for line in open("/proc/self/status"):
        if line.startswith(key):
            return int(line.split()[1]) * 1024
cost = np.load(sys.argv[1]); start = tuple(map(int, sys.argv[2:4])); end = tuple(map(int, sys.argv[4:6]))
k = int(sys.argv[6])
chart = seaway.prepare(cost, neighbourhood=k, edge_cost="mean")
cpu = lambda: resource.getrusage(resource.RUSAGE_SELF).ru_utime
t = cpu(); plain = chart.route(start, end, method="dijkstra"); t_plain = cpu() - t
with open("/proc/self/clear_refs", "w") as f:
    f.write("5")  # reset the peak (VmHWM) to the current resident size
before = status("VmRSS:")
t = cpu(); r = chart.route(start, end, method="dijkstra", turn_penalty=0.1); t_turn = cpu() - t
print((status("VmHWM:") - before) / cost.size, r.stats.search.state_bytes / cost.size,
      r.stats.search.settled, plain.stats.search.settled, t_turn, t_plain, r.cost, plain.cost,
      r.course_changes, plain.course_changes)
"""


@pytest.mark.parametrize("k", [3, 5])
def test_turn_penalty_memory_and_time(chart, tmp_path, k):
    cost, start, end = chart
    np.save(tmp_path / "chart.npy", cost)
    out = subprocess.run(
        [
            sys.executable,
            "-c",
            _SCRIPT,
            str(tmp_path / "chart.npy"),
            *map(str, start),
            *map(str, end),
            str(k),
        ],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split()
    rss, own, states, pixels, t_turn, t_plain, c_turn, c_plain, turns, plain_turns = map(float, out)
    offsets = k * k - 1
    NOTES[f"turn penalty k={k}: peak RSS added"] = (
        f"{rss:.0f} B/pixel (address space {own:.0f} = 9 x {offsets} offsets + queue), "
        f"{states:,.0f} states vs {pixels:,.0f} pixels settled, CPU {t_turn:.1f} s vs {t_plain:.2f} s plain, "
        f"course changes {turns:.0f} vs {plain_turns:.0f}"
    )
    print(f"\nk={k}: {NOTES[f'turn penalty k={k}: peak RSS added']}")
    # 8 B of cost + 1 of predecessor per state; per pixel 9 B of best state, 8 of expanded mask
    assert 9 * offsets + 17 <= own <= 9 * offsets + 24
    assert rss <= own + 16  # pages never touched stay unmapped (calloc)
    assert c_turn > c_plain and turns < plain_turns  # the penalty buys a straighter route


_VS_PLAIN = """
import sys, time, numpy as np, seaway
cost = np.load(sys.argv[1]); start = tuple(map(int, sys.argv[2:4])); end = tuple(map(int, sys.argv[4:6]))
chart = seaway.prepare(cost)  # the default model, max
plain, turn = [], []
for _ in range(4):  # the first of each warms up
    t = time.perf_counter(); p = chart.route(start, end); plain.append(time.perf_counter() - t)
    t = time.perf_counter(); r = chart.route(start, end, turn_penalty=0.5); turn.append(time.perf_counter() - t)
print(np.median(plain[1:]), np.median(turn[1:]), r.stats.search.settled, p.stats.search.settled, r.cost,
      p.cost, r.course_changes, p.course_changes, p.method)
"""


def test_turn_penalty_against_the_plain_route(chart, tmp_path):
    """The corner voyage with 0.5 per degree of course change, default model and method (A* over
    (pixel, incoming step) with dominated states dropped) against the plain route (auto) on the
    same prepared chart, alternated in one fresh process; wall medians of 3."""
    cost, start, end = chart
    np.save(tmp_path / "chart.npy", cost)
    out = subprocess.run(
        [sys.executable, "-c", _VS_PLAIN, str(tmp_path / "chart.npy"), *map(str, start), *map(str, end)],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split()
    plain_s, turn_s, states, pixels, c_turn, c_plain, turns, plain_turns = map(float, out[:8])
    NOTES["turn penalty 0.5/degree vs plain, corner voyage"] = (
        f"{turn_s:.2f} s = {turn_s / plain_s:.1f} x the plain route ({plain_s:.3f} s, {out[8]}); "
        f"{states:,.0f} states settled vs {pixels:,.0f} pixels; cost {c_turn:.1f} vs {c_plain:.1f}; "
        f"course changes {turns:.0f} vs {plain_turns:.0f}"
    )
    print("\n" + NOTES["turn penalty 0.5/degree vs plain, corner voyage"])
    assert c_turn > c_plain and turns < plain_turns


@pytest.mark.parametrize("name", ["A winter", "B winter", "game map", "maze"])
def test_turn_penalty_against_the_plain_route_per_chart(name, tmp_path):
    """The issue-29 goal, turn route <= 3 x the plain route: voyages 0 (corner to corner) and 1
    of a family chart (A winter tuned on; B winter, game map, maze held out), prepared once,
    `route(s, e)` (auto) and `route(s, e, turn_penalty=0.5)` alternated, wall medians of 3 after
    a warm-up each. Records the ratio; asserts the penalty's real effect (a dearer route with
    fewer course changes, its cost the sum of its steps)."""
    chart = BUILDERS[name](str(tmp_path))
    prepared = seaway.prepare(chart.cost)
    for v, (s, e) in enumerate(chart.voyages[:2]):
        plain, turn = [], []
        for _ in range(4):
            t = time.perf_counter()
            p = prepared.route(s, e)
            plain.append(time.perf_counter() - t)
            t = time.perf_counter()
            r = prepared.route(s, e, turn_penalty=0.5)
            turn.append(time.perf_counter() - t)
        a, b = np.median(plain[1:]), np.median(turn[1:])
        NOTES[f"turn penalty 0.5/degree vs plain, {name} v{v}"] = (
            f"{b:.3f} s = {b / a:.1f} x the plain route ({a:.3f} s, {p.method}); "
            f"{r.stats.search.settled:,} states settled; cost {r.cost:.1f} vs {p.cost:.1f}"
        )
        print(f"\n{name} v{v}: " + NOTES[f"turn penalty 0.5/degree vs plain, {name} v{v}"])
        assert r.cost > p.cost and r.course_changes <= p.course_changes
        assert r.step_costs.sum() == pytest.approx(r.cost, rel=1e-12)
