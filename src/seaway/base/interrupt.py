"""Ctrl-C during a search, and progress of long searches. The C++ search runs without the GIL,
so Python's KeyboardInterrupt would only arrive when it returns. In the main thread the search
therefore runs in a helper thread while the main thread waits; on Ctrl-C the main thread sets
the search's cancel token (polled every 4096 expanded pixels), waits for the search to stop and
give its workspace back (further Ctrl-Cs while it waits are absorbed: the search stops within
4096 expansions), and re-raises. Elsewhere (worker threads, Dask) the search runs directly:
signals only reach the main thread. A search its caller knows to be short (`direct`: a
static model on a small chart, seaway.engine.prepared) runs directly in the main thread too when
nothing listens for progress: a helper thread costs about 0.06 ms a query, and a Ctrl-C then
arrives when the search returns, tens of milliseconds later at most.

The same token counts the pixels settled so far (published by the search every 4096
expansions); `reporting(callback)` makes the waiting main thread hand it to callback at each
poll, and SettledProgress turns that into a line on stderr at most once a second (the CLI).
Without a listener nothing is reported."""

from __future__ import annotations

import contextlib
import threading
import time
from collections.abc import Callable, Iterator
from typing import Any, TypeVar

from .. import native as _core

T = TypeVar("T")

#: callback(settled pixels) while a `reporting` block runs.
_listener: Callable[[int], None] | None = None
#: The cancel token of the batch a worker thread runs (`cancelling`), per thread.
_batch = threading.local()
POLL_S = 0.1  # how often the waiting main thread looks at the search (and calls the listener)
PROGRESS_EVERY_S = 1.0  # SettledProgress says at most this often


@contextlib.contextmanager
def reporting(callback: Callable[[int], None]) -> Iterator[None]:
    """Within the block, a search run by interruptible() in the main thread calls
    callback(settled pixels so far) each time the waiting main thread polls it (every POLL_S);
    the callback throttles (see SettledProgress)."""
    global _listener
    previous, _listener = _listener, callback
    try:
        yield
    finally:
        _listener = previous


class SettledProgress:
    """A `reporting` callback that says "searching: N pixels settled (P % of the chart)" at
    most once every `every_s` seconds of `clock`, and only when N has grown."""

    def __init__(
        self,
        say: Callable[[str], None],
        pixels: int,
        every_s: float | None = None,
        clock: Callable[[], float] = time.monotonic,
    ) -> None:
        every_s = PROGRESS_EVERY_S if every_s is None else every_s
        self.say, self.pixels, self.every_s, self.clock = say, max(int(pixels), 1), every_s, clock
        self.due, self.last = clock() + every_s, 0

    def __call__(self, settled: int) -> None:
        now = self.clock()
        if now < self.due or settled <= self.last:
            return
        self.due, self.last = now + self.every_s, settled
        self.say(f"searching: {settled:,} pixels settled ({100 * settled / self.pixels:.0f} % of the chart)")


@contextlib.contextmanager
def cancelling(token: _core.CancelToken) -> Iterator[None]:
    """Within the block, searches run by interruptible() in this thread (not the main thread)
    are given `token`: a batch of routes on worker threads (seaway.fleet.route_many) sets it on
    Ctrl-C to stop every running search at once, within 4096 expansions."""
    previous = getattr(_batch, "token", None)
    _batch.token = token
    try:
        yield
    finally:
        _batch.token = previous


def _stop(finished: threading.Event, token: _core.CancelToken) -> None:
    """Cancel the search and wait until it has returned, even if more Ctrl-Cs arrive meanwhile:
    the search stops within 4096 expansions and gives its workspace back to the chart's pool,
    so the next query reuses it instead of allocating a second one."""
    token.set()
    while True:
        try:
            finished.wait()
            return
        except KeyboardInterrupt:
            continue


def interruptible(search: Callable[[_core.CancelToken | None], T], direct: bool = False) -> T:
    """Run `search(cancel_token)` so that Ctrl-C stops it promptly; returns its result.
    `direct`: the search is short (see the module's note): no helper thread unless a listener
    wants progress.

    The main thread waits on an Event, not Thread.join: in CPython 3.11 a KeyboardInterrupt
    that interrupts join() marks the thread as stopped while it still runs (bpo-45274's
    cleanup releases the running thread's own lock), so a later join() returned at once and
    the cancelled search kept its workspace."""
    if threading.current_thread() is not threading.main_thread():
        return search(getattr(_batch, "token", None))
    if direct and _listener is None:
        return search(None)
    token = _core.CancelToken()
    outcome: dict[str, Any] = {}  # "value": the search's T, or "error": what it raised
    finished = threading.Event()

    def work() -> None:
        try:
            outcome["value"] = search(token)
        except BaseException as exc:  # handed to the main thread below
            outcome["error"] = exc
        finally:
            finished.set()

    worker = threading.Thread(target=work, name="seaway-search", daemon=True)
    listener = _listener
    try:
        worker.start()
        while not finished.wait(POLL_S):
            if listener is not None:
                listener(token.settled)
    except KeyboardInterrupt:
        _stop(finished, token)
        raise
    if "error" in outcome:
        raise outcome["error"]
    value: T = outcome["value"]
    return value
