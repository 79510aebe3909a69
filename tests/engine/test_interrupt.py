"""Ctrl-C stops a running C++ search promptly, and the chart answers correctly afterwards."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import seaway
from seaway import native as _core  # the module the searches read the core through
from seaway.base.interrupt import interruptible, reporting


@pytest.fixture(scope="module")
def big():
    rng = np.random.default_rng(2)
    return rng.uniform(1.0, 30.0, (2500, 2500))  # a full Dijkstra takes about a second


def _interrupt_after(seconds):
    timer = threading.Timer(seconds, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    return timer


@pytest.mark.slow
@pytest.mark.skipif(
    threading.current_thread() is not threading.main_thread(), reason="signals reach the main thread only"
)
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
    assert chart.router.route(chart.model.engine(chart), 0, 5, 0.0).cost == fresh


# -- workspace reuse after Ctrl-C and progress of long searches (issue 13) --------------------


def _sleep_until(condition):
    while not condition():  # no timing assertion: only waits for the other thread
        time.sleep(0.001)


@pytest.mark.skipif(
    threading.current_thread() is not threading.main_thread(), reason="signals reach the main thread only"
)
def test_after_ctrl_c_the_next_query_reuses_the_workspace():
    cost = np.random.default_rng(3).uniform(1.0, 9.0, (300, 300))
    chart = seaway.prepare(cost, neighbourhood=5)
    expected = chart.route((0, 0), (299, 299), method="dijkstra").cost
    assert chart.router.workspaces == 1

    ended = []

    def search(token):
        os.kill(os.getpid(), signal.SIGINT)  # Ctrl-C ...
        _sleep_until(lambda: token.is_set)
        os.kill(os.getpid(), signal.SIGINT)  # ... and again, while the main thread waits
        try:
            return chart.router.field(chart.model.engine(chart), 0, token)
        finally:
            ended.append(token.settled)

    with pytest.raises(KeyboardInterrupt):
        interruptible(search)
    # The cancelled search had ended (and given its workspace back) before the interrupt
    # reached the caller, 4096 expansions in; the next query reuses that workspace.
    assert ended == [4096]
    assert chart.route((0, 0), (299, 299), method="dijkstra").cost == expected
    assert chart.router.workspaces == 1


def test_settled_counter_is_published_every_4096_expansions():
    cost = np.ones((200, 150))
    chart = seaway.prepare(cost, neighbourhood=3)
    token = _core.CancelToken()
    assert token.settled == 0
    _, stats = chart.router.field(chart.model.engine(chart), 0, token)
    assert stats.settled == 200 * 150
    assert token.settled == (200 * 150) // 4096 * 4096  # the last multiple of 4096 reached


@pytest.mark.skipif(
    threading.current_thread() is not threading.main_thread(), reason="the waiting main thread reports"
)
def test_the_waiting_thread_hands_the_settled_count_to_a_listener(monkeypatch):
    """No clock: the search settles 200 x 150 pixels (counter at 28672, the last multiple of
    4096), then waits until the listener has heard that count (it may hear smaller ones
    first, while the search runs)."""
    monkeypatch.setattr(seaway.base.interrupt, "POLL_S", 0.001)
    chart = seaway.prepare(np.ones((200, 150)), neighbourhood=3)
    heard, release = [], threading.Event()

    def search(token):
        chart.router.field(chart.model.engine(chart), 0, token)
        release.wait()
        return "done"

    def listener(settled):
        heard.append(settled)
        if settled == 28672:
            release.set()

    with reporting(listener):
        assert interruptible(search) == "done"
    # (while it runs the count grows by 4096s; the last one heard is the whole search's)
    assert heard[-1] == 28672 and heard == sorted(heard) and all(n % 4096 == 0 for n in heard)
    release.clear()
    threading.Timer(0.05, release.set).start()
    n = len(heard)
    assert interruptible(search) == "done" and len(heard) == n  # no listener: no reports


def test_settled_progress_is_throttled_to_once_a_second_of_its_clock():
    now, said = [100.0], []
    progress = seaway.base.interrupt.SettledProgress(said.append, 1_000_000, clock=lambda: now[0])
    for t, settled in [
        (100.5, 4096),
        (101.0, 8192),
        (101.5, 12288),
        (101.9, 16384),
        (102.0, 20480),
        (103.5, 20480),
        (104.0, 500_000),
    ]:
        now[0] = t
        progress(settled)
    # due at 101.0 (said), then at 102.0 (said); 103.5 has no new pixels; 104.0 said.
    assert said == [
        "searching: 8,192 pixels settled (1 % of the chart)",
        "searching: 20,480 pixels settled (2 % of the chart)",
        "searching: 500,000 pixels settled (50 % of the chart)",
    ]


@pytest.mark.skipif(
    threading.current_thread() is not threading.main_thread(), reason="the main thread's own rule"
)
def test_a_short_search_runs_in_the_main_thread_and_a_long_one_in_a_helper(monkeypatch):
    """A static model's search on a chart of at most DIRECT_STEPS pixel-steps runs where it is
    called (no helper thread to start: a query's fixed cost); a larger chart's, or any search
    while a listener wants progress, runs in the helper thread that lets Ctrl-C stop it."""
    from seaway.engine import methods, prepared

    ran_in = []
    search = methods.search

    def spy(*args):
        ran_in.append(threading.current_thread().name)
        return search(*args)

    monkeypatch.setattr(methods, "search", spy)
    small = seaway.prepare(np.ones((300, 300)))  # 90,000 x 24 steps <= 2**23
    assert small.route((0, 0), (299, 299)).cost == pytest.approx(299 * np.sqrt(2))
    large = seaway.prepare(np.ones((600, 600)))  # 360,000 x 24 > 2**23
    assert large.route((0, 0), (0, 599)).cost == pytest.approx(599.0)
    with reporting(lambda settled: None):
        small.route((0, 0), (5, 5))
    assert ran_in == ["MainThread", "seaway-search", "seaway-search"]
    assert 300 * 300 * 24 <= prepared.DIRECT_STEPS < 600 * 600 * 24
    # a Ctrl-C that arrives during a direct search is not lost
    with pytest.raises(KeyboardInterrupt):
        interruptible(lambda token: os.kill(os.getpid(), signal.SIGINT) or time.sleep(1.0), direct=True)
