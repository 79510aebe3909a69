"""One voyage at a time, the way a user asks, on every chart of the family (benchmarks/family.py,
tuned on and held out): every exact method and `auto`, on a fresh and on a prepared chart (8
landmarks), under the default model (edge_cost="max"), each voyage against the peers
(benchmarks/peers.py: scikit-image, python-tcod's Dijkstra and A* on the 5 x 5 stencil,
pyastar2d) on the same voyage in the same run.

Each round runs every case of a voyage once, in a new shuffled order (a busy machine slows them
alike, and no case always follows the same one), 3 rounds or, for a short voyage, as many as
fill about ROUND_SECONDS (up to 25); the medians of the rounds give wall and CPU seconds
(time.process_time: all threads of the process), pixels settled and CPU nanoseconds per settled
pixel; ratio = the wall median over scikit-image's. Every case asserts its cost equals
Dijkstra's to 1e-9. Also timed: auto's own
work on a prepared chart (its decision: seaway.engine.methods.resolve) and on a fresh chart
(preparing it: seaway.prepare). The tables are printed at the end of the run (conftest.py).
Command (benchmarks/README.md):

    pytest benchmarks/test_voyages.py -s -p no:randomly
"""

import os
import random
import statistics
import time

import numpy as np
import pytest

import seaway
from seaway.engine import methods

from .conftest import VOYAGES
from .family import BUILDERS, NAMES, PAIRS
from .peers import peer_cases

pytest.importorskip("skimage.graph")
pytest.importorskip("tcod.path")
pytest.importorskip("pyastar2d")
ROUNDS = int(os.environ.get("SEAWAY_BENCH_ROUNDS", "3"))
#: A voyage whose round (every case once) takes less than this gets more rounds, up to
#: MAX_ROUNDS, until its rounds take about this long: medians of 3 rounds of millisecond voyages
#: differ by 10-30 % between two runs of the same search, the size of auto's 10 % margin.
ROUND_SECONDS = float(os.environ.get("SEAWAY_BENCH_SECONDS", "3"))
MAX_ROUNDS = 25
# The prepared chart's landmarks: prepare_landmarks' default count for the chart (16 up to 2^21
# pixels, else 8), or the count given.
LANDMARKS = int(os.environ["SEAWAY_BENCH_LANDMARKS"]) if os.environ.get("SEAWAY_BENCH_LANDMARKS") else None
FRESH = ("auto", "dijkstra", "astar", "bidirectional")
PREPARED = ("auto", "dijkstra", "astar", "bidirectional", "landmarks")
_BUILT: dict = {}


@pytest.fixture(scope="module")
def family(tmp_path_factory):
    def get(name):
        if name not in _BUILT:
            chart = BUILDERS[name](str(tmp_path_factory.mktemp("chart")))
            if chart is None:
                _BUILT[name] = None
            else:
                prepared = seaway.prepare(chart.cost)
                t = time.process_time()
                st = prepared.prepare_landmarks(LANDMARKS)
                VOYAGES.setdefault("notes", []).append(
                    f"{name} ({chart.kind}; {'tuned on' if chart.tuned else 'held out'}): "
                    f"{chart.raster.shape[0]} x {chart.raster.shape[1]} pixels, "
                    f"{np.isfinite(chart.raster).mean():.0%} water; {st['count']} landmarks built in "
                    f"{st['seconds']:.2f} s wall, {time.process_time() - t:.2f} s CPU, "
                    f"{st['bytes_per_pixel']:.0f} B/pixel"
                )
                _BUILT[name] = (chart, prepared)
        if _BUILT[name] is None:
            pytest.skip(f"{name}: its data (../shared/data) are absent")
        return _BUILT[name]

    return get


def _cases(chart, prepared, s, e, ps, pe):
    """What one round of a voyage runs: the peers on the raster, seaway.route on a fresh chart by
    each method (and seaway.prepare alone), the prepared chart's route by each method (and auto's
    decision alone)."""
    out = {("peer", name): run for name, run in peer_cases(chart.raster, ps, pe).items()}
    cost = chart.cost
    for m in FRESH:
        out[("fresh", m)] = lambda m=m: seaway.route(cost, s, e, method=m)
    out[("fresh", "prepare")] = lambda: seaway.prepare(cost)
    for m in PREPARED:
        out[("prepared", m)] = lambda m=m: prepared.route(s, e, method=m)
    model = prepared.model
    out[("prepared", "decision")] = lambda: methods.resolve(prepared, model, "auto")
    return out


def time_voyage(label, chart, prepared, voyage):
    """Every case of one voyage, ROUNDS rounds (more for a short voyage: ROUND_SECONDS) in a
    shuffled order after a warm-up; rows into VOYAGES."""
    (s, e), (ps, pe) = chart.voyages[voyage], chart.pixels[voyage]
    cases = _cases(chart, prepared, s, e, ps, pe)
    names = list(cases)
    wall = {n: [] for n in names}
    cpu = {n: [] for n in names}
    last = {}
    rounds, rnd = ROUNDS, 0
    while rnd <= rounds:  # round 0 warms up
        t0 = time.perf_counter()
        # A new order each round (seeded): in a fixed cyclic order each case always ran after the
        # same one, and a case after a peer found the caches cold (auto after pyastar2d took 1.12-
        # 1.15 x the same A* after Dijkstra, on every CIS voyage)
        for n in random.Random(rnd).sample(names, len(names)):
            w0, c0 = time.perf_counter(), time.process_time()
            last[n] = cases[n]()
            if rnd:
                wall[n].append(time.perf_counter() - w0)
                cpu[n].append(time.process_time() - c0)
        if rnd == 0:  # short voyages: more rounds (see ROUND_SECONDS)
            took = time.perf_counter() - t0
            rounds = max(ROUNDS, min(MAX_ROUNDS, int(ROUND_SECONDS / max(took, 1e-9))))
        rnd += 1
    exact = prepared.route(s, e, method="dijkstra").cost
    assert last[("peer", "skimage")] > 0
    peer = statistics.median(wall[("peer", "skimage")])
    rows = VOYAGES.setdefault("rows", [])
    for n in names:
        w, c = statistics.median(wall[n]), statistics.median(cpu[n])
        row = dict(
            season=label,
            tuned=chart.tuned,
            voyage=voyage,
            chart=n[0],
            method=n[1],
            wall=w,
            cpu=c,
            ratio=w / peer,
            skimage=peer,
            rounds=rounds,
        )
        r = last[n]
        if isinstance(r, seaway.Route):
            assert r.cost == pytest.approx(exact, rel=1e-9), n
            used = r.method
            if used == "bidirectional" and methods.low_contrast(prepared):
                used = "bidirectional A*"  # the potential of seaway.engine.methods
            row.update(used=used, settled=r.stats.search.settled, ns=1e9 * c / max(r.stats.search.settled, 1))
        elif n == ("prepared", "decision"):
            row.update(used=r)
        rows.append(row)


@pytest.mark.parametrize("voyage", range(1 + PAIRS))
@pytest.mark.parametrize("name", NAMES)
def test_voyage(family, name, voyage):
    chart, prepared = family(name)
    time_voyage(name, chart, prepared, voyage)
