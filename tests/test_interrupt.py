"""Ctrl-C stops a running C++ search promptly, and the chart answers correctly afterwards."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import seaway
from seaway import _core


@pytest.fixture(scope="module")
def big():
    rng = np.random.default_rng(2)
    return rng.uniform(1.0, 30.0, (2500, 2500))  # a full Dijkstra takes about a second


def _interrupt_after(seconds):
    timer = threading.Timer(seconds, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    return timer


@pytest.mark.skipif(threading.current_thread() is not threading.main_thread(),
                    reason="signals reach the main thread only")
def test_ctrl_c_stops_a_long_search_and_the_chart_still_answers(big):
    chart = seaway.prepare(big, neighbourhood=7)
    t0 = time.perf_counter()
    full = chart.cost_field((0, 0))
    whole = time.perf_counter() - t0
    _interrupt_after(0.05)
    t0 = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        chart.cost_field((0, 0))
    stopped = time.perf_counter() - t0
    assert stopped < 0.5 * whole, (stopped, whole)
    # The interrupted query's workspace is reused: the next answers are exact.
    np.testing.assert_array_equal(chart.cost_field((0, 0)), full)
    r = chart.route((0, 0), (2499, 2499), method="dijkstra")
    assert r.cost == full[2499, 2499]


def test_a_cancel_token_stops_the_engine_from_any_thread(big):
    chart = seaway.prepare(big, neighbourhood=5)
    token = _core.CancelToken()
    token.set()
    with pytest.raises(KeyboardInterrupt, match="search cancelled"):
        chart._router.route(chart.model.engine(chart), 0, big.size - 1, 0.0, token)
    assert token.is_set
    fresh = seaway.route(big, (0, 0), (0, 5), neighbourhood=5, method="dijkstra").cost
    assert chart._router.route(chart.model.engine(chart), 0, 5, 0.0)[0] == fresh
