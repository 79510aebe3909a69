"""Ctrl-C during a search. The C++ search runs without the GIL, so Python's KeyboardInterrupt
would only arrive when it returns. In the main thread the search therefore runs in a helper
thread while the main thread waits; on Ctrl-C the main thread sets the search's cancel token
(polled every 4096 expanded pixels), waits for it to stop, and re-raises. Elsewhere (worker
threads, Dask) the search runs directly: signals only reach the main thread."""

from __future__ import annotations

import threading

from . import _core


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
    worker.start()
    try:
        while worker.is_alive():
            worker.join(0.1)
    except KeyboardInterrupt:
        token.set()
        worker.join()
        raise
    if "error" in outcome:
        raise outcome["error"]
    return outcome["value"]
