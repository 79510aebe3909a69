"""Shared fixtures for the benchmarks and the ratio table printed at the end of the run.

Run: pytest benchmarks/ --benchmark-columns=median,iqr,rounds (see benchmarks/README.md)."""

import platform

import numpy as np
import pytest

from seaway.samples import synthetic_endpoints, synthetic_sea

SHAPE = (1900, 2300)  # the Kara Sea chart of Grinyak et al. 2022: about 2300 x 1900 pixels

MEDIANS: dict[str, float] = {}
NOTES: dict[str, str] = {}
CPU: dict[str, float] = {}  # median CPU seconds of the process (all threads), where recorded
PEERS: dict[str, str] = {}  # the case a ratio is taken against (default: skimage 8-conn)
VOYAGES: dict[str, list] = {}  # rows and notes of test_voyages.py (voyage_table.py prints them)


@pytest.fixture(scope="session")
def chart():
    cost = synthetic_sea(SHAPE)
    start, end = synthetic_endpoints(SHAPE)
    return cost, start, end


def record(name, benchmark, note="", cpu=None, peer=None):
    if benchmark.stats is None:  # --benchmark-disable: the code ran once, untimed
        return
    MEDIANS[name] = benchmark.stats.stats.median
    if note:
        NOTES[name] = note
    if cpu:
        CPU[name] = float(np.median(cpu[-len(benchmark.stats.stats.data) :]))
    if peer:
        PEERS[name] = peer


def pytest_terminal_summary(terminalreporter):
    from .voyage_table import lines

    for line in lines(VOYAGES):
        terminalreporter.write_line(line)
    if not MEDIANS:
        return
    tr = terminalreporter
    peer = MEDIANS.get("skimage MCP_Geometric 8-conn")
    tr.write_sep("=", "seaway benchmark: medians and ratios")
    tr.write_line(
        f"machine: {platform.processor() or platform.machine()}, python {platform.python_version()}, numpy {np.__version__}"
    )
    tr.write_line(f"{'case':44s} {'median s':>9s} {'speed-up vs skimage':>20s}  note")
    for name, med in MEDIANS.items():
        ratio = f"{peer / med:.2f}x" if peer else "-"
        tr.write_line(f"{name:44s} {med:9.3f} {ratio:>20s}  {NOTES.get(name, '')}")
    if CPU:
        tr.write_line("")
        tr.write_line("CPU time (all threads of the process; steadier than wall time on a shared machine):")
        tr.write_line(f"{'case':44s} {'wall s':>8s} {'CPU s':>8s} {'wall/peer':>10s} {'CPU/peer':>9s}  peer")
        for name, c in CPU.items():
            p = PEERS.get(name)
            wr = f"{MEDIANS[name] / MEDIANS[p]:.3f}" if p in MEDIANS else "-"
            cr = f"{c / CPU[p]:.3f}" if p in CPU else "-"
            tr.write_line(f"{name:44s} {MEDIANS[name]:8.3f} {c:8.3f} {wr:>10s} {cr:>9s}  {p or ''}")
    for name, note in NOTES.items():
        if name not in MEDIANS:
            tr.write_line(f"{name}: {note}")
    for k in (3, 5, 7):
        d, a = MEDIANS.get(f"seaway dijkstra k={k}"), MEDIANS.get(f"seaway astar k={k}")
        if d and a:
            tr.write_line(f"A* speed-up over Dijkstra, k={k}: {d / a:.2f}x")
    d, a = (MEDIANS.get(f"summer chart (costs 1-2) {m} k=5") for m in ("dijkstra", "astar"))
    if d and a:
        tr.write_line(f"A* speed-up over Dijkstra on the summer chart, k=5: {d / a:.2f}x")
