"""N threads x M queries give exactly the serial answers (one PreparedChart shared by all, and
plain seaway.route), and an interrupted call (Ctrl-C) leaves a PreparedChart answering
correctly."""

from __future__ import annotations

import os
import signal
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import seaway
from seaway.models.base import as_model

THREADS = 6


def _chart(seed, shape, dtype=np.float64):
    rng = np.random.default_rng(seed)
    cost = rng.uniform(0.5, 12.0, shape).astype(dtype)
    cost[rng.random(shape) < 0.25] = np.inf
    return cost


def _queries(cost, n, seed):
    rng = np.random.default_rng(seed)
    water = np.argwhere(np.isfinite(cost))
    pick = rng.choice(len(water), (n, 2))
    methods = ["dijkstra", "astar", ("astar", 2.0)]
    return [
        (tuple(map(int, water[a])), tuple(map(int, water[b])), methods[k % 3])
        for k, (a, b) in enumerate(pick)
    ]


def _answer(route_fn, q):
    """Everything a query returns that must not depend on threads: cost, pixels and settled."""
    a, b, how = q
    method, w = (how, None) if isinstance(how, str) else how
    try:
        r = route_fn(a, b, method=method, weight=w)
    except seaway.NoRouteError as e:
        return ("no route", str(e))
    return (r.cost, r.pixels.tobytes(), r.stats.search.settled, r.step_costs.tobytes())


def _threaded(fn, items):
    barrier = threading.Barrier(THREADS)

    def start(_):
        barrier.wait()  # every thread starts querying at once
        return None

    with ThreadPoolExecutor(THREADS) as pool:
        list(pool.map(start, range(THREADS)))
        return list(pool.map(fn, items))


@pytest.mark.slow
@pytest.mark.parametrize(
    "edge_cost, k, dtype", [("max", 3, np.float64), ("integral", 7, np.float32), ("mean", 15, np.float64)]
)
def test_threads_on_one_prepared_chart_give_the_serial_answers(edge_cost, k, dtype):
    cost = _chart(11, (90, 120), dtype)
    chart = seaway.prepare(cost, neighbourhood=k, edge_cost=edge_cost)
    queries = _queries(cost, 60, seed=k) * 2  # repeats: answers must not depend on reuse
    serial = [_answer(chart.route, q) for q in queries]
    assert sum(s[0] != "no route" for s in serial) > len(queries) // 2
    for _ in range(3):
        assert _threaded(lambda q: _answer(chart.route, q), queries) == serial


def test_threads_mixing_routes_and_cost_fields_on_one_chart():
    cost = _chart(12, (70, 90))
    chart = seaway.prepare(cost, neighbourhood=5)
    queries = _queries(cost, 30, seed=3)
    starts = [q[0] for q in queries]
    fields = [chart.cost_field(s) for s in starts]
    routes = [_answer(chart.route, q) for q in queries]

    def job(i):
        return (
            ("field", i, chart.cost_field(starts[i]))
            if i % 2
            else ("route", i, _answer(chart.route, queries[i]))
        )

    for kind, i, got in _threaded(job, range(len(queries))):
        if kind == "field":
            np.testing.assert_array_equal(got, fields[i])
        else:
            assert got == routes[i]


def test_threads_on_plain_route_and_geographic_charts_give_the_serial_answers():
    cost = _chart(13, (40, 72))
    lat, lon = np.linspace(60, 80, 40), np.arange(72) * 5.0  # wraps around the globe
    queries = [
        ((float(lat[a[0]]), float(lon[a[1]])), (float(lat[b[0]]), float(lon[b[1]])), how)
        for a, b, how in _queries(cost, 24, seed=5)
    ]

    def fresh(a, b, **kw):
        return seaway.route(cost, a, b, lat=lat, lon=lon, neighbourhood=5, **kw)

    serial = [_answer(fresh, q) for q in queries]
    assert any(s[0] != "no route" for s in serial)
    assert _threaded(lambda q: _answer(fresh, q), queries) == serial


def _interrupt_main_after(seconds):
    timer = threading.Timer(seconds, signal.raise_signal, (signal.SIGINT,))
    timer.start()
    return timer


@pytest.mark.skipif(
    threading.current_thread() is not threading.main_thread(), reason="signals reach only the main thread"
)
def test_an_interrupted_query_leaves_the_prepared_chart_correct():
    """Ctrl-C while a long search runs (GIL released): KeyboardInterrupt arrives when the search
    returns; the workspace goes back to the pool, and the next queries are exact."""
    cost = np.ones((900, 900))
    cost[100:800, 450] = np.inf
    chart = seaway.prepare(cost, neighbourhood=5)
    small = seaway.prepare(cost[:60, :60].copy(), neighbourhood=5)
    expect_field = small.cost_field((0, 0))
    expect = chart.route((0, 0), (899, 899), method="dijkstra")
    timer = _interrupt_main_after(0.05)
    t0 = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        while time.perf_counter() - t0 < 30:  # until the signal lands, whichever call it hits
            chart.route((0, 0), (899, 899), method="dijkstra")
            chart.cost_field((450, 0))
    timer.join()
    again = chart.route((0, 0), (899, 899), method="dijkstra")
    assert again.cost == expect.cost and np.array_equal(again.pixels, expect.pixels)
    assert chart.route((5, 5), (5, 5)).cost == 0.0
    np.testing.assert_array_equal(small.cost_field((0, 0)), expect_field)
    # several threads at once after the interrupt: still the serial answers
    got = _threaded(lambda _: chart.route((0, 0), (899, 899), method="dijkstra").cost, range(THREADS))
    assert got == [expect.cost] * THREADS


def test_an_interrupt_in_a_worker_thread_does_not_disturb_the_others():
    """A KeyboardInterrupt raised inside one thread's query (as a cancel) does not change what
    the other threads get."""
    cost = _chart(14, (80, 80))
    chart = seaway.prepare(cost, neighbourhood=5)
    queries = _queries(cost, 24, seed=9)
    serial = [_answer(chart.route, q) for q in queries]

    def job(i):
        if i % 4 == 0:
            try:
                _answer(chart.route, queries[i])
                raise KeyboardInterrupt
            except KeyboardInterrupt:
                return "cancelled"
        return _answer(chart.route, queries[i])

    out = _threaded(job, range(len(queries)))
    for i, got in enumerate(out):
        assert got == ("cancelled" if i % 4 == 0 else serial[i])


@pytest.mark.skipif(not hasattr(os, "sched_setaffinity"), reason="needs Linux's CPU affinity")
def test_two_thread_searches_on_one_core_give_the_answers_of_two():
    """The second thread of a two-thread search starts on another core than its creator's
    (cpp/seaway/threads.hpp); kept to one core, the process gets a plain thread there and the
    same answers: the bidirectional and landmark searches past their solo start, and the
    clearance pass of a chart of 2^20 pixels (two threads)."""
    cost = _chart(5, (1024, 1024))
    cost[:, 500:520] = np.inf
    cost[700:720, 500:520] = 3.0  # one gap: the voyages go round through it
    a, b = (30, 30), (1000, 1000)
    assert np.isfinite(cost[a]) and np.isfinite(cost[b])

    def answers():
        chart = seaway.prepare(cost, landmarks=4)
        out = [_answer(chart.route, (a, b, m)) for m in ("bidirectional", "landmarks", "dijkstra")]
        return out, chart.router.cost_range, chart.router.clearance.tobytes()

    both, *clearance = answers()
    assert both[0][0] == pytest.approx(both[2][0], rel=1e-9)  # Dijkstra's cost
    assert both[1][0] == pytest.approx(both[2][0], rel=1e-9)
    assert both[0][2] > 2 * 4096  # past the solo start: two threads ran
    allowed = os.sched_getaffinity(0)
    os.sched_setaffinity(0, {min(allowed)})
    try:
        assert answers() == (both, *clearance)
    finally:
        os.sched_setaffinity(0, allowed)


def test_queries_while_the_doubled_steps_are_left_out_keep_their_costs():
    """Threads route on a chart while the main thread prepares its landmarks three more times,
    each time dropping the table of the doubled steps to leave out and publishing a new one
    (cpp/seaway/collinear.hpp): a landmark query started in between sees every step, one started
    after sees the new table, and one that spans the swap keeps the table it began with alive;
    every cost, of the landmark queries (which read the table) and of the others (which do not),
    is the one of a chart that never left a step out (to 1e-9; the path may take the two halves
    of a doubled step instead)."""
    rng = np.random.default_rng(14)
    cost = rng.uniform(1.0, 3.0, (160, 200))
    cost[40:60, 50:150] = np.inf  # a wall to go round
    plain = seaway.prepare(cost)
    chart = seaway.prepare(cost)
    chart.prepare_landmarks(4)
    queries = [q for q in _queries(cost, 24, seed=5) if q[2] != ("astar", 2.0)]
    queries += [(a, b, how) for a, b, _ in queries[:8] for how in ("bidirectional", "landmarks")]
    expect = [
        _answer(plain.route, (a, b, "dijkstra" if how == "landmarks" else how))[0] for a, b, how in queries
    ]
    done = threading.Event()
    seen: list = []

    def worker(i):
        while True:  # at least one pass, however late the thread starts
            for q, e in zip(queries[i::4], expect[i::4]):
                got = _answer(chart.route, q)[0]
                seen.append(got == pytest.approx(e, rel=1e-9))
            if done.is_set():
                return

    with ThreadPoolExecutor(4) as pool:
        futures = [pool.submit(worker, i) for i in range(4)]
        for _ in range(3):
            chart.prepare_landmarks(4)
            time.sleep(0.05)
        done.set()
        for f in futures:
            f.result()
    assert chart.router.skip_table(chart.model.engine(chart)).any()
    assert len(seen) >= len(queries) and all(seen)


def test_two_rules_prepared_at_once_keep_both_tables():
    """Two threads prepare landmarks for the max and the mean rule on one chart at the same
    time: each publishes its table of doubled steps into the chart's list (compare and swap), so
    both stay, each the table a chart prepared for that rule alone has."""
    rng = np.random.default_rng(21)
    cost = rng.uniform(1.0, 3.0, (300, 300))
    cost[100:120, 50:250] = np.inf
    for _ in range(3):
        chart = seaway.prepare(cost)
        with ThreadPoolExecutor(2) as pool:
            for f in [pool.submit(chart.prepare_landmarks, 2, model=rule) for rule in ("max", "mean")]:
                f.result()
        assert set(chart.pruned_for) == {"max", "mean"}
        for rule in ("max", "mean"):
            alone = seaway.prepare(cost, edge_cost=rule)
            alone.prepare_landmarks(1)
            engine = as_model(rule).engine
            np.testing.assert_array_equal(
                chart.router.skip_table(engine(chart)), alone.router.skip_table(engine(alone))
            )
