"""The time objective against the impact objective (issue: the voyage in time): the quickest
route (objective "time": the line integral of hours per km) and the least-impact route (Grinyak
et al. 2022) through the same opened chart, one voyage at a time, for the Arc7 LNG carrier from
its vessel file; and what the voyage layer (the ship's speed in the ice, the times of the legs,
the quickest route shown beside the impact one) adds to a bare impact search.

    pytest benchmarks/test_objectives.py -s -p no:randomly

Charts: the built-in winter Kara Sea (1900 x 2300 lat/lon pixels, synthetic ice on the real
coastline) from the Kara Gate to the Vilkitsky Strait; and the benchmark's synthetic sea made an
ice chart (winter recipe: its costs 1-30 read as stages thin to thick first-year ice)."""

import numpy as np
import pytest

import seaway
from seaway.vessel import load

from .conftest import MEDIANS, NOTES, record

SHIP = load("arc7-lng-carrier")
KARA = ((70.30, 58.49), (77.70, 103.99))
CASES = ("bare impact search", "impact, no comparison", "time", "impact beside the quickest")


@pytest.fixture(scope="module")
def kara():
    return seaway.open_chart("kara", vessel="Arc7")


def run(chart, case):
    a, b = KARA
    if case == "bare impact search":
        return seaway.route(chart.cost, a, b, land=chart.land)
    if case == "impact, no comparison":
        return chart.route(a, b, vessel=SHIP, compare=False, smooth=False)
    if case == "time":
        return chart.route(a, b, vessel=SHIP, objective="time", smooth=False)
    return chart.route(a, b, vessel=SHIP, smooth=False)


@pytest.mark.parametrize("case", CASES)
def test_objectives_on_the_kara_chart(kara, case, benchmark):
    r = benchmark.pedantic(run, args=(kara, case), rounds=3, iterations=1, warmup_rounds=1)
    record(f"objectives/kara/{case}", benchmark, note=f"{r.length:.0f} km")
    if case == "time":  # the quickest route is never slower than the least-impact one
        impact = run(kara, "impact, no comparison")
        assert r.cost <= impact.summary()["time_h"] * (1 + 1e-9)


def test_objectives_table():
    rows = [(c, MEDIANS.get(f"objectives/kara/{c}")) for c in CASES]
    if any(m is None for _, m in rows):
        pytest.skip("run with the cases above (benchmark enabled)")
    base = rows[0][1]
    print("\nobjectives on the Kara chart (Arc7 LNG carrier, Kara Gate -> Vilkitsky Strait):")
    for case, m in rows:
        print(
            f"  {case:30s} {m:7.3f} s  {m / base:5.2f} x the bare impact search  {NOTES.get('objectives/kara/' + case, '')}"
        )
    assert np.isfinite(base)
