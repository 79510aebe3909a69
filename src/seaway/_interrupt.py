"""Ctrl-C during a search, and progress of long searches. The C++ search runs without the GIL,
so Python's KeyboardInterrupt would only arrive when it returns. In the main thread the search
therefore runs in a helper thread while the main thread waits; on Ctrl-C the main thread sets
the search's cancel token (polled every 4096 expanded pixels), waits for the search to stop and
give its workspace back (further Ctrl-Cs while it waits are absorbed: the search stops within
4096 expansions), and re-raises. Elsewhere (worker threads, Dask) the search runs directly:
signals only reach the main thread.

The same token counts the pixels settled so far; `reporting(callback)` makes the waiting main
thread call callback(settled) about once a second (the CLI prints it). Without a listener
nothing is reported."""

from __future__ import annotations

import contextlib
import threading
import time

from . import _core

_listener = None  # callback(settled pixels) while a `reporting` block runs
PROGRESS_EVERY_S = 1.0


@contextlib.contextmanager
def reporting(callback, every_s: float | None = None):
    """Within the block, searches in the main thread call callback(settled) every `every_s`
    seconds (default PROGRESS_EVERY_S)."""
    global _listener
    every_s = PROGRESS_EVERY_S if every_s is None else every_s
    previous, _listener = _listener, (callback, float(every_s))
    try:
        yield
    finally:
        _listener = previous


def _stop(finished: threading.Event, token) -> None:
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


def interruptible(search):
    """Run `search(cancel_token)` so that Ctrl-C stops it promptly; returns its result.

    The main thread waits on an Event, not Thread.join: in CPython 3.11 a KeyboardInterrupt
    that interrupts join() marks the thread as stopped while it still runs (bpo-45274's
    cleanup releases the running thread's own lock), so a later join() returned at once and
    the cancelled search kept its workspace (issue 13)."""
    if threading.current_thread() is not threading.main_thread():
        return search(None)
    token = _core.CancelToken()
    outcome = {}
    finished = threading.Event()

    def work():
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
        every = listener[1] if listener else None
        next_report = time.monotonic() + (every or 0.0)
        while not finished.wait(0.1 if every is None else min(0.1, max(every, 0.001))):
            if listener and time.monotonic() >= next_report:
                listener[0](token.settled)
                next_report = max(next_report + every, time.monotonic())
    except KeyboardInterrupt:
        _stop(finished, token)
        raise
    if "error" in outcome:
        raise outcome["error"]
    return outcome["value"]
