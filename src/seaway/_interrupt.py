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


def _stop(worker: threading.Thread, token) -> None:
    """Cancel the search and join its thread even if more Ctrl-Cs arrive meanwhile: the search
    stops within 4096 expansions and gives its workspace back to the chart's pool, so the next
    query reuses it instead of allocating a second one."""
    while True:
        try:
            token.set()
            worker.join()
            return
        except KeyboardInterrupt:
            continue


def interruptible(search):
    """Run `search(cancel_token)` so that Ctrl-C stops it promptly; returns its result."""
    if threading.current_thread() is not threading.main_thread():
        return search(None)
    token = _core.CancelToken()
    outcome = {}

    def work():
        try:
            outcome["value"] = search(token)
        except BaseException as exc:  # handed to the main thread below
            outcome["error"] = exc

    worker = threading.Thread(target=work, name="seaway-search", daemon=True)
    listener = _listener
    try:
        worker.start()
        next_report = time.monotonic() + (listener[1] if listener else 0.0)
        while worker.is_alive():
            worker.join(0.1)
            if listener and worker.is_alive() and time.monotonic() >= next_report:
                listener[0](token.settled)
                next_report += listener[1]
    except KeyboardInterrupt:
        _stop(worker, token)
        raise
    if "error" in outcome:
        raise outcome["error"]
    return outcome["value"]
