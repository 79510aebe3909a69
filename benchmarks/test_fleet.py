"""Many routes at once: routes per second with 1 and 2 threads and on a 2-worker
LocalCluster, the memory of N concurrent queries, and a 10^8-pixel memory-mapped chart.

Each benchmark also asserts its answer: every run returns the serial run's costs exactly."""

import os
import subprocess
import sys
import time

import numpy as np
import pytest

import seaway

from .conftest import NOTES, record

pytest.importorskip("pandas")
N_ROUTES = 8
_SERIAL = {}


@pytest.fixture(scope="module")
def voyages(chart):
    """N_ROUTES (start, end) pairs of water pixels joined by water, fixed seed."""
    cost, start, end = chart
    field = seaway.cost_field(cost, start)
    reach = np.argwhere(np.isfinite(field))
    pick = np.random.default_rng(6).choice(len(reach), size=(N_ROUTES - 1, 2), replace=False)
    return [(start, end)] + [(tuple(map(int, reach[a])), tuple(map(int, reach[b]))) for a, b in pick]


def serial_costs(chart, voyages):
    if "costs" not in _SERIAL:
        t = seaway.route_many(chart[0], voyages, threads=1)
        _SERIAL["costs"] = t.cost.to_numpy()
    return _SERIAL["costs"]


def _machine_busy():
    """CPU seconds spent by every process on the machine so far (user + nice + system)."""
    with open("/proc/stat") as f:
        return sum(map(int, f.readline().split()[1:4])) / os.sysconf("SC_CLK_TCK")


def _metered(fn, usage):
    """fn, also noting per call: wall time, this process's CPU time, the whole machine's."""

    def run(*args, **kwargs):
        t, c, m = time.perf_counter(), time.process_time(), _machine_busy()
        out = fn(*args, **kwargs)
        usage.append((time.perf_counter() - t, time.process_time() - c, _machine_busy() - m))
        return out

    return run


def _rate(name, benchmark, table, usage):
    med = benchmark.stats.stats.median
    wall, mine, machine = np.median(np.array(usage), axis=0)
    record(
        name,
        benchmark,
        f"{len(table) / med:.2f} routes/s; cores busy: this process "
        f"{mine / wall:.2f}, machine {machine / wall:.2f} of {os.cpu_count()}",
    )


@pytest.mark.parametrize("threads", [1, 2])
def test_routes_per_second_threads(benchmark, chart, voyages, threads):
    usage = []
    table = benchmark.pedantic(
        _metered(seaway.route_many, usage),
        args=(chart[0], voyages),
        kwargs=dict(threads=threads),
        rounds=5,
        iterations=1,
        warmup_rounds=1,
    )
    _rate(f"route_many {N_ROUTES} routes, {threads} thread(s)", benchmark, table, usage)
    assert (table.status == "ok").all()
    np.testing.assert_array_equal(table.cost.to_numpy(), serial_costs(chart, voyages))


@pytest.fixture(scope="module")
def client():
    distributed = pytest.importorskip("dask.distributed")
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=":0")
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


def test_routes_per_second_dask(benchmark, chart, voyages, client):
    usage = []
    table = benchmark.pedantic(
        _metered(seaway.route_many, usage),
        args=(chart[0], voyages),
        kwargs=dict(cluster=client, progress=False),
        rounds=5,
        iterations=1,
        warmup_rounds=1,
    )
    _rate(f"route_many {N_ROUTES} routes, 2-worker LocalCluster", benchmark, table, usage)
    assert (table.status == "ok").all()
    np.testing.assert_array_equal(table.cost.to_numpy(), serial_costs(chart, voyages))


_CONCURRENT = """
import sys, numpy as np, seaway
def status(key):
    for line in open("/proc/self/status"):
        if line.startswith(key):
            return int(line.split()[1]) * 1024
cost = np.load(sys.argv[1]); n = int(sys.argv[2])
pairs = np.array(sys.argv[3:], dtype=int).reshape(-1, 2, 2)[:n]
seaway.route_many(cost[:50, :50], [((0, 0), (0, 0))], threads=1)  # imports before the baseline
with open("/proc/self/clear_refs", "w") as f:
    f.write("5")  # reset the peak (VmHWM) to the current resident size
before = status("VmRSS:")
t = seaway.route_many(cost, [(tuple(a), tuple(b)) for a, b in pairs], threads=n)
assert (t.status == "ok").all(), t.error.tolist()
print((status("VmHWM:") - before) / cost.size)
"""


def test_memory_of_concurrent_queries(chart, voyages, tmp_path):
    """Peak resident memory route_many adds for N queries on N threads (fresh process each)."""
    cost = chart[0]
    np.save(tmp_path / "chart.npy", cost)
    flat = [str(v) for s, e in voyages for v in (*s, *e)]
    added = {}
    for n in (1, 2, 4):
        out = subprocess.run(
            [sys.executable, "-c", _CONCURRENT, str(tmp_path / "chart.npy"), str(n), *flat],
            capture_output=True,
            text=True,
            check=True,
        )
        added[n] = float(out.stdout.split()[-1])
    per_query = (added[4] - added[1]) / 3
    NOTES["memory of N concurrent queries"] = (
        ", ".join(f"N={n}: {b:.1f} B/pixel" for n, b in added.items())
        + f"; each extra query +{per_query:.1f} B/pixel"
    )
    assert added[1] <= 16 and per_query <= 16


_BIG = """
import sys, time, numpy as np, seaway
def status(key):
    for line in open("/proc/self/status"):
        if line.startswith(key):
            return int(line.split()[1]) * 1024
n = int(sys.argv[2])
cost = np.memmap(sys.argv[1], dtype=np.float32, mode="r", shape=(n, n))
s, e = [tuple(map(int, sys.argv[i:i + 2])) for i in (3, 5)]
seaway.route_many(np.ones((50, 50)), [((0, 0), (0, 0))], threads=1)  # imports before the baseline
with open("/proc/self/clear_refs", "w") as f:
    f.write("5")
before = status("VmRSS:")
t0 = time.perf_counter()
t = seaway.route_many(cost, [(s, e)], threads=1)
wall = time.perf_counter() - t0
assert t.status[0] == "ok", t.error[0]
print(wall, status("VmHWM:"), before, t.cost[0], t.settled[0], t.length[0])
"""


def test_route_on_1e8_pixels_memory_mapped(benchmark, tmp_path):
    """A 10 000 x 10 000 float32 chart (400 MB file, np.memmap) routed corner to corner."""
    from seaway.samples import synthetic_endpoints, synthetic_sea

    n, f = 10_000, 10  # synthetic_sea(1000 x 1000), each pixel repeated into a 10 x 10 block
    path = tmp_path / "chart.f32"
    coarse = synthetic_sea((n // f, n // f)).astype(np.float32)
    mm = np.memmap(path, dtype=np.float32, mode="w+", shape=(n, n))
    for i in range(n // f):
        mm[i * f : (i + 1) * f] = np.repeat(coarse[i], f)[None, :]
    mm.flush()
    del mm
    s, e = (tuple(v * f + f // 2 for v in p) for p in synthetic_endpoints(coarse.shape))
    args = [sys.executable, "-c", _BIG, str(path), str(n), *map(str, (*s, *e))]

    def run():
        return subprocess.run(args, capture_output=True, text=True, check=True).stdout.split()

    out = benchmark.pedantic(run, rounds=1, iterations=1)
    wall, hwm, before, cost, settled, length = map(float, out)
    GiB = 2**30
    record(
        "route_many 1 route on 10^8 pixels (memmap)",
        benchmark,
        f"search {wall:.1f} s, {settled:,.0f} settled",
    )
    NOTES["10^8-pixel route peak memory"] = (
        f"VmHWM {hwm / GiB:.2f} GiB ({(hwm - before) / n**2:.1f} B/pixel over the "
        f"{before / GiB:.2f} GiB before, incl. the 0.37 GiB of mapped chart pages read)"
    )
    assert np.isfinite(cost) and length > 2 * n * 0.7 and hwm < 3 * GiB
