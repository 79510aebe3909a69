"""Running route_many's rows: on threads sharing each chart, or in batches on Dask workers,
with a progress line."""

from __future__ import annotations

import contextlib
import math
import sys
import threading
from concurrent.futures import ThreadPoolExecutor, as_completed, wait

from .. import native as _core
from ..base.interrupt import cancelling
from .one import _loaded, _route_one, _target


class _Shared:
    """A value built once on first use (under a lock) and dropped after its last use."""

    def __init__(self, make, uses):
        self.make, self.uses, self.lock = make, uses, threading.Lock()
        self.value = self.error = None
        self.built = False

    def get(self):
        with self.lock:
            if not self.built:
                try:
                    self.value = self.make()
                except Exception as exc:  # noqa: BLE001 - re-raised to every user
                    self.error = exc
                self.built, self.make = True, None
            if self.error is not None:
                raise self.error
            return self.value

    def release(self):
        with self.lock:
            self.uses -= 1
            if self.uses <= 0:
                self.value = None


# -- threads -------------------------------------------------------------------------------------
def _run_threads(chart_items, vessel_items, voyage_items, opts, threads, bar):
    nv, ny = len(vessel_items), len(voyage_items)
    loaded = [_Shared(lambda c=c: _loaded(c), nv) for _, c in chart_items]
    targets = {}
    for ci in range(len(chart_items)):
        for vi, (_, vessel) in enumerate(vessel_items):

            def make(ci=ci, vessel=vessel):
                try:
                    return _target(loaded[ci].get(), vessel, opts)
                finally:
                    loaded[ci].release()

            targets[ci, vi] = _Shared(make, ny)

    def item(ci, vi, voyage):
        try:
            return _route_one(targets[ci, vi].get, voyage, opts["keep"])
        finally:
            targets[ci, vi].release()

    work = [
        (ci, vi, voyage) for ci in range(len(chart_items)) for vi in range(nv) for _, voyage in voyage_items
    ]
    if threads == 1:
        rows = []
        for w in work:
            rows.append(item(*w))
            bar.update(1)
        return rows
    rows = [None] * len(work)
    token = _core.CancelToken()  # every search of the batch polls it (seaway.base.interrupt)

    def cancellable(*w):
        with cancelling(token):
            return item(*w)

    pool = ThreadPoolExecutor(max_workers=threads)
    futures = {}
    try:
        for i, w in enumerate(work):
            futures[pool.submit(cancellable, *w)] = i
        for fut in as_completed(futures):
            rows[futures[fut]] = fut.result()
            bar.update(1)
    except BaseException:  # Ctrl-C (or a failure): stop the running searches, start no more
        token.set()
        pool.shutdown(wait=False, cancel_futures=True)
        _await(futures)
        raise
    finally:
        pool.shutdown(wait=True)
    return rows


def _await(futures):
    """Wait until every started item has stopped (each within 4096 expansions of the cancel),
    absorbing further Ctrl-Cs meanwhile, so that no search outlives route_many. (Items the
    shutdown cancelled never count as done for wait(): they were never started.)"""
    started = [f for f in futures if not f.cancelled()]
    while True:
        try:
            wait(started)
            return
        except KeyboardInterrupt:
            continue


# -- dask ----------------------------------------------------------------------------------------
def _run_batch(chart, vessel, voyages, opts):
    """On a worker: the rows of a batch of voyages for one chart and vessel, in order."""
    shared = _Shared(lambda: _target(chart, vessel, opts), len(voyages))
    return [_route_one(shared.get, v, opts["keep"]) for v in voyages]


class _OwnCluster:
    """A dask.distributed Client on a LocalCluster of its own (worker processes; no dashboard),
    closed so that distributed's shutdown races print no traceback: the workers' logger is
    quietened first (a worker whose heartbeat is in flight while it closes logs "Failed to
    communicate with scheduler during heartbeat" with a traceback), then the client closes and
    the cluster closes its workers (each nanny awaited) before the scheduler. (Retiring the
    workers through the client first left the nannies to close themselves while the cluster
    closed them too: a CancelledError traceback, twice in 7 runs under load.)"""

    def __init__(self, n_workers: int = 2, threads_per_worker: int = 1):
        from dask.distributed import Client, LocalCluster

        self.cluster = LocalCluster(
            n_workers=n_workers, threads_per_worker=threads_per_worker, dashboard_address=":0"
        )
        self.client = Client(self.cluster)

    def close(self) -> None:
        try:
            self.client.run(_quiet_at_shutdown)
        finally:
            self.client.close()
            self.cluster.close()


def _quiet_at_shutdown() -> None:
    """On a worker of a cluster being shut down: its own logger keeps CRITICAL records only."""
    import logging

    logging.getLogger("distributed.worker").setLevel(logging.CRITICAL)


@contextlib.contextmanager
def local_cluster(n_workers: int = 2, threads_per_worker: int = 1):
    """A dask.distributed Client on a LocalCluster of its own, shut down when the block ends
    without a traceback (the workers' logger quietened, then the client, the workers and the
    scheduler closed: _OwnCluster)."""
    own = _OwnCluster(n_workers, threads_per_worker)
    try:
        yield own.client
    finally:
        own.close()


def open_client(cluster):
    """(client, what to close afterwards) for cluster=: True or "local" starts
    LocalCluster(n_workers=2, threads_per_worker=1), closed in order afterwards; a string is a
    scheduler address; anything else is a dask.distributed.Client used as it is (and left open)."""
    from dask.distributed import Client

    if cluster is True or cluster == "local":
        own = _OwnCluster()
        return own.client, [own]
    if isinstance(cluster, str):
        client = Client(cluster)
        return client, [client]
    return cluster, []


def _run_dask(chart_items, vessel_items, voyage_items, opts, cluster, bar):
    import dask
    from dask.distributed import as_completed as dask_completed

    client, own = open_client(cluster)
    try:

        def ship(obj):  # arrays go to the workers once; dask-backed charts are loaded there
            if obj is None or callable(obj) or dask.is_dask_collection(obj):
                return obj
            return client.scatter(obj, broadcast=False, hash=False)

        workers = max(len(client.scheduler_info().get("workers", {})), 1)
        groups = len(chart_items) * len(vessel_items)
        per_group = min(max(math.ceil(4 * workers / groups), 1), max(len(voyage_items), 1))
        size = max(math.ceil(len(voyage_items) / per_group), 1)
        voyages = [v for _, v in voyage_items]
        batches = [voyages[i : i + size] for i in range(0, len(voyages), size)]
        opts = dict(opts, land=ship(opts["land"]))
        run = dask.delayed(_run_batch, pure=False)
        tasks = []
        for _, chart in chart_items:
            chart = ship(chart)
            for _, vessel in vessel_items:
                tasks += [run(chart, ship(vessel), batch, opts) for batch in batches]
        futures = client.compute(tasks)
        index = {f.key: i for i, f in enumerate(futures)}
        parts = [None] * len(futures)
        try:
            for fut in dask_completed(futures):
                parts[index[fut.key]] = fut.result()
                bar.update(len(parts[index[fut.key]]))
        except KeyboardInterrupt:  # the batches not yet started are dropped
            client.cancel(futures)
            raise
        return [row for part in parts for row in part]
    finally:
        for obj in own:
            obj.close()


class _Progress:
    """A plain progress bar on stderr: `routes  37/120 [#######.............]  31 %`."""

    def __init__(self, total, enabled, width=30):
        self.total, self.enabled, self.width, self.done = total, enabled, width, 0
        self.lock = threading.Lock()
        self._draw()

    def update(self, n):
        with self.lock:
            self.done += n
            self._draw()

    def _draw(self):
        if not self.enabled:
            return
        frac = self.done / self.total if self.total else 1.0
        fill = int(round(frac * self.width))
        sys.stderr.write(
            f"\rroutes {self.done:>{len(str(self.total))}}/{self.total} "
            f"[{'#' * fill}{'.' * (self.width - fill)}] {100 * frac:3.0f} %"
        )
        sys.stderr.flush()

    def close(self):
        if self.enabled:
            sys.stderr.write("\n")
            sys.stderr.flush()
