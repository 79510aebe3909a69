"""One voyage at a time, the way a user asks: every exact method and `auto`, on a fresh and on a
prepared chart (8 landmarks), winter and summer costs, the corner-to-corner voyage and 8 random
pairs of connected water pixels, under the default model (edge_cost="max"), each voyage against
scikit-image's MCP_Geometric (8-connected) on the same voyage in the same run.

Each round runs every case of a voyage once, in a rotated order (a busy machine slows them
alike); the medians of the rounds give wall and CPU seconds (time.process_time: all threads of
the process), pixels settled and CPU nanoseconds per settled pixel; ratio = seaway's wall median
over scikit-image's. Every case asserts its cost equals Dijkstra's to 1e-9. The tables are
printed at the end of the run (conftest.py). Command (benchmarks/README.md):

    pytest benchmarks/test_voyages.py -s -p no:randomly
"""

import os
import statistics
import time

import numpy as np
import pytest

import seaway
from seaway.chart.locate import locate
from seaway.engine import methods

from .conftest import VOYAGES

skgraph = pytest.importorskip("skimage.graph")
ROUNDS = int(os.environ.get("SEAWAY_BENCH_ROUNDS", "3"))
FRESH = ("auto", "dijkstra", "astar", "bidirectional")
PREPARED = ("auto", "dijkstra", "astar", "bidirectional", "landmarks")
RANDOM_PAIRS = 8


def summer(cost):
    """The winter chart's costs mapped onto 1-2 (open summer ice), same land."""
    return np.where(np.isfinite(cost), 1.0 + (cost - 1.0) / 29.0, np.inf)


@pytest.fixture(scope="module")
def seasons(chart):
    cost, start, end = chart
    maps = {"winter": cost, "summer": summer(cost)}
    prepared = {}
    for name, c in maps.items():
        p = seaway.prepare(c)
        t = time.process_time()
        st = p.prepare_landmarks(8)
        VOYAGES.setdefault("notes", []).append(
            f"{name}: 8 landmarks built in {st['seconds']:.2f} s wall, "
            f"{time.process_time() - t:.2f} s CPU, {st['bytes_per_pixel']:.0f} B/pixel"
        )
        prepared[name] = p
    return maps, prepared


@pytest.fixture(scope="module")
def voyages(chart):
    """The corner-to-corner voyage and RANDOM_PAIRS random pairs of water pixels connected to it."""
    cost, start, end = chart
    reach = np.argwhere(np.isfinite(seaway.cost_field(cost, start)))
    pick = np.random.default_rng(21).choice(len(reach), size=(RANDOM_PAIRS, 2), replace=False)
    return [(start, end)] + [(tuple(map(int, reach[a])), tuple(map(int, reach[b]))) for a, b in pick]


def _skimage(cost, s, e):
    m = skgraph.MCP_Geometric(cost, fully_connected=True)
    costs, _ = m.find_costs([s], [e])
    return float(costs[e])


def _cases(cost, route, prepared, s, e):
    """What one round of a voyage runs: the peer on the raster, seaway.route on a fresh chart by
    each method, and the prepared chart's route by each method."""
    raster = np.asarray(getattr(cost, "values", cost), float)
    ps, pe = locate(prepared.chart, s, "start"), locate(prepared.chart, e, "end")
    out = {("skimage", "peer"): lambda: _skimage(raster, ps, pe)}
    for m in FRESH:
        out[("fresh", m)] = lambda m=m: route(cost, s, e, method=m)
    for m in PREPARED:
        out[("prepared", m)] = lambda m=m: prepared.route(s, e, method=m)
    return out


def time_voyage(label, voyage, cost, prepared, s, e, route=seaway.route):
    """Every case of one voyage, ROUNDS rounds in rotated order after a warm-up; rows into VOYAGES."""
    cases = _cases(cost, route, prepared, s, e)
    names = list(cases)
    wall = {n: [] for n in names}
    cpu = {n: [] for n in names}
    last = {}
    for rnd in range(ROUNDS + 1):  # round 0 warms up
        k = rnd % len(names)
        for n in names[k:] + names[:k]:
            w0, c0 = time.perf_counter(), time.process_time()
            last[n] = cases[n]()
            if rnd:
                wall[n].append(time.perf_counter() - w0)
                cpu[n].append(time.process_time() - c0)
    exact = prepared.route(s, e, method="dijkstra").cost
    peer = statistics.median(wall[("skimage", "peer")])
    rows = VOYAGES.setdefault("rows", [])
    for n in names:
        w, c = statistics.median(wall[n]), statistics.median(cpu[n])
        row = dict(
            season=label, voyage=voyage, chart=n[0], method=n[1], wall=w, cpu=c, ratio=w / peer, skimage=peer
        )
        if n[0] != "skimage":
            r = last[n]
            assert r.cost == pytest.approx(exact, rel=1e-9), n
            used = r.method
            if used == "bidirectional" and methods.low_contrast(prepared):
                used = "bidirectional A*"  # the potential of seaway.engine.methods
            row.update(used=used, settled=r.stats.search.settled, ns=1e9 * c / max(r.stats.search.settled, 1))
        rows.append(row)


@pytest.mark.parametrize("voyage", range(1 + RANDOM_PAIRS))
@pytest.mark.parametrize("season", ["winter", "summer"])
def test_voyage(seasons, voyages, season, voyage):
    maps, prepared = seasons
    s, e = voyages[voyage]
    time_voyage(season, voyage, maps[season], prepared[season], s, e)
