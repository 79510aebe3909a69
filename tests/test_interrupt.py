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
def test_ctrl_c_stops_a_long_search_and_the_chart_still_answers(big, monkeypatch):
    chart = seaway.prepare(big, neighbourhood=7)
    full = chart.cost_field((0, 0))
    assert chart.router.workspaces == 1
    tokens, make_token = [], _core.CancelToken
    monkeypatch.setattr(_core, "CancelToken", lambda: tokens.append(make_token()) or tokens[-1])

    def ctrl_c_once_searching():  # no clock: Ctrl-C once the search has settled 4096 pixels
        while not (tokens and tokens[0].settled > 0):
            time.sleep(0.001)
        os.kill(os.getpid(), signal.SIGINT)

    presser = threading.Thread(target=ctrl_c_once_searching, daemon=True)
    presser.start()
    with pytest.raises(KeyboardInterrupt):
        chart.cost_field((0, 0))
    presser.join()
    monkeypatch.undo()
    (token,) = tokens
    # Stopped part-way (the counter is published every 4096 expansions, where the cancel flag
    # is polled), and the search had given its workspace back: the chart still has one.
    assert token.is_set and 0 < token.settled < big.size and token.settled % 4096 == 0
    assert chart.router.workspaces == 1
    # The interrupted query's workspace is reused: the next answers are exact.
    np.testing.assert_array_equal(chart.cost_field((0, 0)), full)
    r = chart.route((0, 0), (2499, 2499), method="dijkstra")
    assert r.cost == full[2499, 2499]
    assert chart.router.workspaces == 1


def test_a_cancel_token_stops_the_engine_from_any_thread(big):
    chart = seaway.prepare(big, neighbourhood=5)
    token = _core.CancelToken()
    token.set()
    with pytest.raises(KeyboardInterrupt, match="search cancelled"):
        chart.router.route(chart.model.engine(chart), 0, big.size - 1, 0.0, token)
    assert token.is_set
    fresh = seaway.route(big, (0, 0), (0, 5), neighbourhood=5, method="dijkstra").cost
    assert chart.router.route(chart.model.engine(chart), 0, 5, 0.0)[0] == fresh
