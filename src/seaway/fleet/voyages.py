"""Many voyages through time: vessels x voyages x departures on one opened chart, season or
forecast (seaway.open_chart, open_season, open_forecast), each routed by that object's own
route() — the answer a single route gives, waits for the ice included — on threads.

`route_voyages` returns a tidy pandas DataFrame, one row per (vessel, voyage, departure): the
ends asked for and used (as numbers), departure, arrival, hours, distance, waits, escorted
miles, status and cause. `to_dataset` turns it into an xarray Dataset indexed by vessel x voyage
x departure (NetCDF: ``to_dataset(table).to_netcdf(path)``); pandas writes Parquet and CSV."""

from __future__ import annotations

import inspect
import os
import sys
import weakref
from collections.abc import Callable, Iterable, Mapping
from concurrent.futures import ThreadPoolExecutor
from typing import Any

import numpy as np

from .. import native as _core
from ..base.interrupt import cancelling
from ..errors import SeawayError, SeawayTypeError
from .journal import Journal, row_key
from .rows import COLUMNS, unit_rows, units
from .run import _Progress, open_client


def daily(first: Any, last: Any, step_h: float = 24.0) -> np.ndarray:
    """Departures from `first` to `last` (both included when on the step), every step_h hours."""
    a, b = np.datetime64(first, "s"), np.datetime64(last, "s")
    if not step_h > 0 or b < a:
        raise SeawayError(f"departures from {a} to {b} every {step_h} h: give first <= last and step_h > 0")
    step = np.timedelta64(int(round(step_h * 3600)), "s")
    return np.arange(a, b + np.timedelta64(1, "s"), step)


def route_voyages(
    source: Any,
    voyages: Mapping[Any, tuple] | Iterable[tuple],
    *,
    vessels: Mapping[str, Any] | Iterable[Any] = ("Arc7",),
    departures: Iterable[Any] = (None,),
    snap_km: float | None = None,
    threads: int | None = None,
    cluster: Any = None,
    keep_routes: bool = False,
    journal: str | os.PathLike[str] | None = None,
    progress: bool | None = None,
    **options: Any,
):
    """Route every voyage for every vessel at every departure through `source`.

    source: an OpenChart, OpenSeason or OpenForecast (anything whose route(start, end, vessel=,
        depart=, ...) gives a seaway Route). Each row is what ``source.route`` answers alone; a
        source that routes from one start to many ends (OpenSeason.routes) answers the rows of
        one vessel, start and departure from one Dijkstra search, each row then what
        ``source.route(..., method="dijkstra")`` answers (exact, as the default A*: the same
        least time; where two ways tie, the search may take the other); a `method` option
        routes row by row.
    voyages: a mapping id -> (start, end) or a sequence of (start, end) pairs (ids 0, 1, ...);
        ends (lat, lon) as source.route takes them.
    vessels: a mapping name -> vessel (a seaway.vessel.Vessel, e.g. from a vessel file, or an
        ice class), or a sequence of them (named by their name or class).
    departures: dates (numpy.datetime64 or ISO strings; `daily(first, last)` gives a range);
        None: the source's own default (a season's first chart, a forecast's first time).
    snap_km: ends in unusable water move at most this far (as the single route's snap_km).
    threads: worker threads (default 2; 1 runs in this thread). Ctrl-C stops every running
        search of the batch and raises KeyboardInterrupt.
    cluster: run on dask.distributed instead (as route_many: a Client, a scheduler address, or
        True / "local" for a LocalCluster of 2 workers, closed afterwards): `source` is sent to
        each worker once (and keeps what it computed for the batch there: each class's speeds
        in every chart), and on a Client given the next batch through the same source reuses
        it; every row is computed by the same code, so the table is the same.
    keep_routes: add a `route` column with each Route (None where it failed, or read back from
        the journal).
    journal: a CSV file each row is appended to as soon as it is routed; when it exists, the
        rows it holds (same vessel name, voyage id and departure) are read back, not routed
        again: a batch that stopped (a crash, Ctrl-C, a killed job) goes on where it was.
    progress: a progress bar on stderr (default: only with a cluster).
    options: passed to every source.route call (e.g. objective="time", escort=True).

    Status and cause (route_many's words): "ok"; "no route" (cause "closed by ice": ice the
    vessel may not enter closes the way, or holds an end farther than snap_km from usable
    water; "land" or "impassable": what else closes the way; "no route"); "bad input" (cause
    "land" or "off chart" for an end farther than snap_km from usable water, "off chart" for an
    end outside the chart, else "bad input"). `error` holds the message, with the nearest
    usable point and its distance."""
    import pandas as pd

    if not callable(getattr(source, "route", None)):
        raise SeawayTypeError(
            f"route_voyages needs an opened chart, season or forecast (seaway.open_chart, "
            f"open_season, open_forecast), not {type(source).__name__}"
        )
    if snap_km is not None:
        params = inspect.signature(source.route).parameters
        if "snap_km" not in params and not any(p.kind is p.VAR_KEYWORD for p in params.values()):
            raise SeawayTypeError(f"{type(source).__name__}.route takes no snap_km: leave it out")
        options["snap_km"] = snap_km
    voyage_items = list(voyages.items() if isinstance(voyages, Mapping) else enumerate(voyages))
    vessel_items = list(vessels.items() if isinstance(vessels, Mapping) else ((_name(v), v) for v in vessels))
    departs = [None if d is None else np.datetime64(d, "s") for d in departures]
    if not voyage_items or not vessel_items or not departs:
        raise SeawayError("give at least one voyage, one vessel and one departure")
    work = [(n, v, k, ends, d) for n, v in vessel_items for k, ends in voyage_items for d in departs]

    log = None if journal is None else Journal(journal, COLUMNS, say=_say)
    done = {} if log is None else log.done
    todo = [w for w in work if row_key(w[0], w[2], w[4]) not in done]
    if log is not None and len(todo) < len(work):
        _say(f"{log.path}: {len(work) - len(todo)} of {len(work)} rows read back, {len(todo)} to route")
    write = (lambda row: row) if log is None else (lambda row: log.write(row) or row)

    bar = _Progress(len(todo), cluster is not None if progress is None else bool(progress))
    share = units(source, todo, options)

    def done_unit(rows):
        bar.update(len(rows))
        return [write(row) for row in rows]

    try:
        if cluster is not None:
            parts = _run_dask(source, share, options, keep_routes, cluster, done_unit)
        else:
            parts = _run(
                lambda unit: done_unit(unit_rows(source, unit, options, keep_routes)),
                share,
                2 if threads is None else int(threads),
            )
    finally:
        bar.close()
    new = {row_key(w[0], w[2], w[4]): row for unit, rows in zip(share, parts) for w, row in zip(unit, rows)}
    routed = new
    rows = []
    for name, _, key, _, depart in work:  # input order; ids and dates as given
        row = routed.get(row_key(name, key, depart)) or dict(done[row_key(name, key, depart)], route=None)
        rows.append(
            dict(row, vessel=name, voyage=key, departure=row["departure"] if depart is None else depart)
        )
    cols = COLUMNS + (["route"] if keep_routes else [])
    return pd.DataFrame(rows, columns=cols)


def _say(message: str) -> None:
    print(f"seaway route_voyages: {message}", file=sys.stderr)


def to_dataset(table):
    """The table of route_voyages as an xarray Dataset indexed by vessel x voyage x departure."""
    return (
        table.drop(columns=[c for c in ("route",) if c in table])
        .set_index(["vessel", "voyage", "departure"])
        .to_xarray()
    )


def _name(vessel: Any) -> str:
    if isinstance(vessel, str):
        return vessel
    return str(getattr(vessel, "name", None) or getattr(vessel, "ice_class", None) or vessel)


def _run(one: Callable, work: list, threads: int) -> list:
    if threads < 1:
        raise SeawayError(f"threads={threads}: give 1 or more")
    if threads == 1:
        return [one(w) for w in work]
    token = _core.CancelToken()  # every search of the batch polls it (seaway.base.interrupt)

    def cancellable(w):
        with cancelling(token):
            return one(w)

    pool = ThreadPoolExecutor(max_workers=threads)
    try:
        futures = [pool.submit(cancellable, w) for w in work]
        return [f.result() for f in futures]
    except KeyboardInterrupt:
        token.set()
        for f in futures:
            f.cancel()
        raise
    finally:
        pool.shutdown(wait=True, cancel_futures=True)


#: Each source sent to a client's workers, by client: the next batch on the same warm client
#: reuses it (and what the workers computed for it: each class's speeds in every chart). An
#: entry goes when its source is garbage-collected, which releases the workers' copies.
_SENT: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def _scattered(client, source, keep: bool):
    """The future of `source` on every worker of `client`: sent once (per client, when `keep`)."""
    try:
        sent = _SENT.setdefault(source, {}) if keep else None
    except TypeError:  # a source that cannot be weakly referenced: sent for this batch only
        sent = None
    future = None if sent is None else sent.get(client.id)
    if future is None or future.status != "finished":
        future = client.scatter(source, broadcast=True, hash=False)
        if sent is not None:
            sent[client.id] = future
    return future


def _unit_rows(source, units_, options, keep) -> list[list[dict]]:
    """The rows of a share of the batch's units, on a worker."""
    return [unit_rows(source, unit, options, keep) for unit in units_]


def _run_dask(source, work, options, keep, cluster, done) -> list:
    """The rows of each unit of `work` on a Dask cluster; done(rows) as each share comes back."""
    from dask.distributed import as_completed

    client, own = open_client(cluster)
    try:
        shared = _scattered(client, source, keep=not own)
        workers = max(len(client.scheduler_info().get("workers", {})), 1)
        size = max(len(work) // (4 * workers), 1)
        shares = [work[i : i + size] for i in range(0, len(work), size)]
        futures = [client.submit(_unit_rows, shared, share, options, keep, pure=False) for share in shares]
        where = {f.key: k for k, f in enumerate(futures)}
        parts: list = [None] * len(futures)
        try:
            for fut in as_completed(futures):
                parts[where[fut.key]] = [done(rows) for rows in fut.result()]
        except KeyboardInterrupt:
            client.cancel(futures)
            raise
        return [rows for part in parts for rows in part]
    finally:
        for obj in own:
            obj.close()
