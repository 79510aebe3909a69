"""Regression tests for the rough edges of issue 13: a workspace freed at once after Ctrl-C,
non-number arguments named in the error, land masks that are not 0/1 refused, and a negative
start pixel in seaway.compat answered as scikit-image answers it. Progress of long searches."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import seaway
from seaway import _core
from seaway.base.interrupt import interruptible, reporting


def _sleep_until(condition):
    while not condition():  # no timing assertion: only waits for the other thread
        time.sleep(0.001)


@pytest.mark.skipif(threading.current_thread() is not threading.main_thread(),
                    reason="signals reach the main thread only")
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
    assert stats["settled"] == 200 * 150
    assert token.settled == (200 * 150) // 4096 * 4096  # the last multiple of 4096 reached


@pytest.mark.skipif(threading.current_thread() is not threading.main_thread(),
                    reason="the waiting main thread reports")
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
    for t, settled in [(100.5, 4096), (101.0, 8192), (101.5, 12288), (101.9, 16384),
                       (102.0, 20480), (103.5, 20480), (104.0, 500_000)]:
        now[0] = t
        progress(settled)
    # due at 101.0 (said), then at 102.0 (said); 103.5 has no new pixels; 104.0 said.
    assert said == ["searching: 8,192 pixels settled (1 % of the chart)",
                    "searching: 20,480 pixels settled (2 % of the chart)",
                    "searching: 500,000 pixels settled (50 % of the chart)"]


@pytest.mark.parametrize("kw, name", [({"dx": "1"}, "dx"), ({"dy": [1.0]}, "dy"),
                                      ({"dx": True}, "dx"), ({"dx": None}, "dx")])
def test_a_non_number_cell_size_is_named(kw, name):
    with pytest.raises(TypeError, match=rf"{name} must be a positive cell size, got \w+ "):
        seaway.route(np.ones((4, 4)), (0, 0), (3, 3), **kw)


def test_every_numeric_argument_is_checked_by_name():
    from seaway.samples import synthetic_sea
    from seaway.corridor import corridor
    from seaway.vessel import Vessel

    u = np.ones((6, 6))
    with pytest.raises(TypeError, match="weight must be a finite number >= 1"):
        seaway.route(u, (0, 0), (5, 5), weight="2")
    with pytest.raises(TypeError, match=r"speed_kn must be positive, got str '12'"):
        Vessel(speed_kn="12").check()
    with pytest.raises(ValueError, match="displacement_t must be a finite number > 0"):
        Vessel(displacement_t=np.nan).check()
    with pytest.raises(TypeError, match="beam_m must be a finite number > 0"):
        Vessel(speed_loss="stawave1", beam_m="20", length_m=100.0, calm_resistance_kn=300.0).check()
    with pytest.raises(TypeError, match="row_nm must be a finite number > 0"):
        corridor((60, 0), (61, 5), spacing_nm=50, row_nm="20")
    with pytest.raises(TypeError, match="m must be a finite integer >= 0"):
        corridor((60, 0), (61, 5), spacing_nm=50, m=2.5)
    with pytest.raises(TypeError, match="threads must be a finite integer >= 1, got str '2'"):
        seaway.route_many(u, [((0, 0), (5, 5))], threads="2")
    with pytest.raises(ValueError, match=r"land_fraction must be a number in \[0, 0.9\)"):
        synthetic_sea((20, 20), land_fraction=np.nan)
    from seaway.models import IceSeasonTime
    with pytest.raises(TypeError, match="v0_kn must be a finite number > 0, got str '12'"):
        IceSeasonTime(None, v0_kn="12")
    r = seaway.route(u, (0, 0), (5, 5))
    with pytest.raises(ValueError, match="speed_kn must be a finite number > 0"):
        r.legs(speed_kn=0)
    assert seaway.route(u, (0, 0), (5, 5), dx=np.float32(2), dy=np.int64(2)).cost == \
        pytest.approx(2 * r.cost)  # numpy scalars are numbers


@pytest.mark.parametrize("bad", [np.nan, 2.0, 0.5, -1.0])
def test_a_land_mask_that_is_not_0_or_1_is_refused(bad):
    land = np.zeros((5, 5))
    land[2, 3] = bad
    with pytest.raises(ValueError, match=r"land must hold only 0 \(sea\) and 1 \(land\).*"
                                         r"pixel \(2, 3\).*give a bool mask"):
        seaway.route(np.ones((5, 5)), (0, 0), (4, 4), land=land)
    with pytest.raises(TypeError, match="land must be a boolean mask"):
        seaway.route(np.ones((5, 5)), (0, 0), (4, 4), land=np.full((5, 5), "0"))


def test_bool_and_0_1_land_masks_give_one_route():
    wall = np.zeros((7, 7), bool)
    wall[1:, 3] = True  # a wall with a gap in row 0
    routes = [seaway.route(np.ones((7, 7)), (6, 0), (6, 6), land=m, neighbourhood=3)
              for m in (wall, wall.astype(np.uint8), wall.astype(float), wall.astype(np.int64))]
    assert {r.cost for r in routes} == {routes[0].cost}
    assert all((r.pixels[:, 1] != 3).sum() == len(r.pixels) - 1 for r in routes)  # row 0 gap
    assert routes[0].pixels[:, 0].min() == 0


def test_compat_negative_start_by_hand_and_as_skimage():
    """8 x 4 ones, start (4, 1) at -0.5, end (0, 3): the first step costs (-0.5 + 1) / 2 x its
    length; diagonal first, 0.25 sqrt 2, then sqrt 2 + 2 to the end: 2 + 1.25 sqrt 2 (a
    straight first step gives 0.25 + 2 sqrt 2 + 1, more). With (3, 2) blocked it is that."""
    skgraph = pytest.importorskip("skimage.graph")
    from seaway.compat import route_through_array

    a = np.ones((8, 4))
    a[4, 1] = -0.5
    path, cost = route_through_array(a, (4, 1), (0, 3))
    assert cost == pytest.approx(2 + 1.25 * np.sqrt(2), rel=1e-14)
    assert path == [(4, 1), (3, 2), (2, 2), (1, 2), (0, 3)]
    assert cost == pytest.approx(skgraph.route_through_array(a, (4, 1), (0, 3))[1], rel=1e-14)
    a[3, 2] = np.inf
    path, cost = route_through_array(a, (4, 1), (0, 3))
    assert cost == pytest.approx(0.25 + 2 * np.sqrt(2) + 1, rel=1e-14)
    assert cost == pytest.approx(skgraph.route_through_array(a, (4, 1), (0, 3))[1], rel=1e-14)
    assert path[:2] == [(4, 1), (3, 1)]


def test_compat_negative_start_matches_skimage():
    skgraph = pytest.importorskip("skimage.graph")
    from seaway.compat import route_through_array

    rng = np.random.default_rng(13)
    compared = 0
    for _ in range(60):
        a = rng.uniform(-1.0, 5.0, (8, 4))  # negative pixels are impassable, except the start
        s, e = (4, 1), (int(rng.integers(8)), int(rng.integers(4)))
        a[s] = -rng.uniform(0.1, 1.0)
        for fc in (True, False):
            try:
                sk_path, sk_cost = skgraph.route_through_array(a, s, e, fully_connected=fc)
            except ValueError:
                with pytest.raises(ValueError, match="no minimum-cost path"):
                    route_through_array(a, s, e, fully_connected=fc)
                continue
            path, cost = route_through_array(a, s, e, fully_connected=fc)
            assert cost == pytest.approx(sk_cost, rel=1e-12, abs=1e-12)
            assert path[0] == s and path[-1] == e
            steps = zip(path[:-1], path[1:])
            again = sum((a[p] + a[q]) / 2 * np.hypot(p[0] - q[0], p[1] - q[1]) for p, q in steps)
            assert again == pytest.approx(cost)  # the path given has the cost given
            compared += 1
    assert compared > 40


@pytest.mark.skipif(threading.current_thread() is not threading.main_thread(),
                    reason="the waiting main thread reports")
def test_the_cli_reports_pixels_settled_during_a_long_search(monkeypatch, capsys):
    """`seaway route`'s search block prints the token's count on stderr: a search that holds on
    until a line has been printed for its 28672 settled pixels (no clock in the test)."""
    from seaway.cli.common import Progress, searching

    monkeypatch.setattr(seaway.base.interrupt, "POLL_S", 0.001)
    monkeypatch.setattr(seaway.base.interrupt, "PROGRESS_EVERY_S", 0.0)
    chart = seaway.prepare(np.ones((200, 150)), neighbourhood=3)
    printed = threading.Event()

    class Told(Progress):
        def __call__(self, message):
            super().__call__(message)
            if "28,672 pixels" in message:  # earlier lines (while it runs) may come first
                printed.set()

    def search(token):
        chart.router.field(chart.model.engine(chart), 0, token)
        printed.wait()
        return "done"

    with searching(Told("route", quiet=False), 200 * 150):
        assert interruptible(search) == "done"
    err = capsys.readouterr().err
    assert "seaway route: [" in err and "searching: 28,672 pixels settled (96 % of the chart)" in err
    say_quiet = Progress("route", quiet=True)
    with searching(say_quiet, 200 * 150):
        chart.cost_field((0, 0))
    assert capsys.readouterr().err == ""
