"""A 50 x 50 origin-destination matrix on the 4.4 M-pixel benchmark chart (issue 30's speed goal:
the matrix in at most the time of 50 single-origin fields). seaway.fleet.od_matrix on a
prepared chart runs one cost field per origin and reads it at the 49 other ports; the peer is
the 50 fields alone (PreparedChart.cost_field from each port), with nothing read. The matrix
equals the fields read at the ports (asserted) and each pair the engine's route (two pairs).

Run: pytest benchmarks/test_od_matrix.py -p no:randomly -s --benchmark-columns=median,rounds"""

import time

import numpy as np
import pytest

import seaway
from seaway.fleet import od_matrix

from .conftest import record

pytest.importorskip("pandas")
N_PORTS = 50
FIELDS = "50 single-origin fields (4.4 M pixels)"
MATRIX = "od_matrix 50 x 50 (4.4 M pixels)"
_READ: dict[str, np.ndarray] = {}


@pytest.fixture(scope="module")
def prepared(chart):
    return seaway.prepare(chart[0])


@pytest.fixture(scope="module")
def ports(prepared, chart):
    """50 water pixels joined to the benchmark voyage's start, drawn with seed 30."""
    reached = np.argwhere(np.isfinite(prepared.cost_field(chart[1])))
    pick = np.random.default_rng(30).choice(len(reached), N_PORTS, replace=False)
    return {f"p{i}": tuple(int(v) for v in reached[k]) for i, k in enumerate(pick)}


def _timed(fn, cpu):
    def run(*args, **kwargs):
        c = time.process_time()
        out = fn(*args, **kwargs)
        cpu.append(time.process_time() - c)
        return out

    return run


def test_fifty_single_origin_fields(benchmark, prepared, ports):
    cpu = []
    cells = list(ports.values())

    def fields():
        return np.array([[f[p] for p in cells] for f in (prepared.cost_field(o) for o in cells)])

    read = benchmark.pedantic(_timed(fields, cpu), rounds=3, iterations=1, warmup_rounds=0)
    _READ["fields"] = read
    assert read.shape == (N_PORTS, N_PORTS) and np.isfinite(read).all() and (np.diag(read) == 0).all()
    record(FIELDS, benchmark, "one PreparedChart.cost_field per port", cpu=cpu)


def test_od_matrix_in_the_time_of_the_fields(benchmark, prepared, ports):
    cpu = []
    od = benchmark.pedantic(
        _timed(od_matrix, cpu), args=(prepared, ports), rounds=3, iterations=1, warmup_rounds=0
    )
    assert od.shape == (N_PORTS, N_PORTS) and np.isfinite(od.values).all()
    if "fields" in _READ:
        assert np.array_equal(od.values, _READ["fields"])
    for o, d in (("p0", "p1"), ("p17", "p42")):
        assert od.loc[o, d] == pytest.approx(prepared.route(ports[o], ports[d]).cost, rel=1e-12)
    record(MATRIX, benchmark, "seaway.fleet.od_matrix on the prepared chart", cpu=cpu, peer=FIELDS)
