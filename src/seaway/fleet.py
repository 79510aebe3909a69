"""Many routes in one call: voyages x vessels x charts, in threads or on a Dask cluster.

`route_many` routes every voyage for every vessel on every chart and returns a pandas DataFrame
with one row per route, in input order (charts, then vessels, then voyages). A route that fails
(no route, a point on land, a malformed point) is reported in its row and never stops the others.

Threads share each chart's memory (the C++ search releases the GIL). With `cluster=`, the work is
spread over dask.distributed workers; a dask-backed xarray time series is loaded chart by chart
on the workers. Each route is computed by the same code either way, so the results are identical."""

from __future__ import annotations

import math
import os
import sys
import threading
import time
from collections.abc import Mapping
from concurrent.futures import ThreadPoolExecutor, as_completed

import numpy as np

from .errors import NoRouteError
from ._validate import number

COLUMNS = ["chart", "vessel", "voyage", "start", "end", "cost", "length", "settled", "time_s",
           "status", "error"]


def route_many(charts, voyages, *, vessels=None, lat=None, lon=None, dx=1.0, dy=1.0, land=None,
               neighbourhood=5, directions="full", edge_cost="max", method="auto", weight=None,
               threads=None, cluster=None, progress=None, keep_routes=False, time_dim="time",
               keep_away=(), zones=(), turn_penalty=None):
    """Route every voyage for every vessel on every chart; a pandas DataFrame, one row per route.

    charts: one chart (2-D array or DataArray, or an xarray.Dataset when vessels turn it into a
        cost), a mapping id -> chart, a list of charts (ids 0, 1, ...), or an xarray object with
        a `time_dim` dimension (one chart per time step, ids = the times; may be dask-backed).
        None when every vessel is a cost raster.
    voyages: a sequence of (start, end) pairs (ids 0, 1, ...), a mapping id -> (start, end), or a
        DataFrame with start and end columns (ids = its index). Points as in seaway.route(). A
        voyage (start, end, via) passes the via points in order (a DataFrame: a `via` column).
    vessels: None (the chart is the cost), or a mapping name -> cost raster, or name -> callable
        turning a chart into a cost raster, e.g. ``lambda ds: ice_impact(ds.stage_of_development,
        "Arc7")``. A list gives ids 0, 1, ...
    lat, lon, dx, dy, land, neighbourhood, directions, edge_cost, method, weight, keep_away,
        zones, turn_penalty: as in seaway.route(), for every route (buffers and zones are
        rasterised once per chart and vessel). When land is None and a chart is a Dataset with a
        `land` variable, that variable is the land mask.
    threads: worker threads (default os.cpu_count(); 1 runs serially in the calling thread;
        not used with a cluster, whose workers have their own threads).
    cluster: None (threads in this process); True or "local" for a new
        LocalCluster(n_workers=2, threads_per_worker=1), closed afterwards; a scheduler address
        ("tcp://host:8786"); or a dask.distributed.Client.
    progress: print a progress bar on stderr (default: only with a cluster).
    keep_routes: add a `route` column with the Route objects (None where a route failed).

    Columns: chart, vessel, voyage (ids), start, end (as given), cost, length (km on geographic
    charts, grid units otherwise), settled (pixels), time_s (wall time of the search), status
    ("ok", "no route", "bad input" or "error") and error (the message; "" when ok)."""
    import pandas as pd

    threads = (os.cpu_count() or 1) if threads is None else number(threads, "threads", minimum=1,
                                                                      integer=True)
    opts = dict(chart=dict(lat=lat, lon=lon, dx=dx, dy=dy, neighbourhood=neighbourhood,
                           directions=directions, edge_cost=edge_cost, keep_away=keep_away,
                           zones=zones),
                method=method, weight=weight, land=land, keep=bool(keep_routes),
                turn_penalty=turn_penalty)
    chart_items = _chart_items(charts, time_dim)
    vessel_items = [(None, None)] if vessels is None else _items(vessels, "vessels")
    voyage_items = _voyage_items(voyages)
    if charts is not None and any(v is not None and not callable(v) for _, v in vessel_items):
        raise ValueError("a vessel given as a cost raster ignores the charts; pass charts=None, "
                         "or give the vessel as a callable turning a chart into a cost raster")
    n = len(chart_items) * len(vessel_items) * len(voyage_items)
    bar = _Progress(n, cluster is not None if progress is None else bool(progress))
    if cluster is None:
        rows = _run_threads(chart_items, vessel_items, voyage_items, opts, threads, bar)
    else:
        rows = _run_dask(chart_items, vessel_items, voyage_items, opts, cluster, bar)
    bar.close()
    ids = [(c, v, y) for c, _ in chart_items for v, _ in vessel_items for y, _ in voyage_items]
    table = pd.DataFrame([dict(chart=c, vessel=v, voyage=y, **row)
                          for (c, v, y), row in zip(ids, rows)],
                         columns=COLUMNS + (["route"] if keep_routes else []))
    table["settled"] = table["settled"].astype("Int64")
    return table


# -- inputs --------------------------------------------------------------------------------------
def _items(obj, name):
    if isinstance(obj, Mapping):
        return list(obj.items())
    if isinstance(obj, (list, tuple)):
        return list(enumerate(obj))
    raise TypeError(f"{name} must be a mapping id -> item or a list, got {type(obj).__name__}")


def _chart_items(charts, time_dim):
    if charts is None:
        return [(None, None)]
    if hasattr(charts, "dims") and hasattr(charts, "isel"):  # xarray (a Dataset is a Mapping)
        if time_dim not in charts.dims:
            return [(None, charts)]
        times = charts[time_dim].values
        return [(t, charts.isel({time_dim: i})) for i, t in enumerate(times)]
    if isinstance(charts, (Mapping, list, tuple)):
        return _items(charts, "charts")
    return [(None, charts)]


def _voyage_items(voyages):
    if hasattr(voyages, "columns") and {"start", "end"} <= set(voyages.columns):
        if "via" in voyages.columns:
            return list(zip(voyages.index, zip(voyages["start"], voyages["end"], voyages["via"])))
        return list(zip(voyages.index, zip(voyages["start"], voyages["end"])))
    return _items(voyages, "voyages")


# -- one route -----------------------------------------------------------------------------------
def _loaded(obj):
    """A dask-backed xarray object loaded into memory here (never on a distributed Client)."""
    if obj is not None and hasattr(obj, "chunks") and hasattr(obj, "compute") and obj.chunks:
        return obj.compute(scheduler="synchronous")
    return obj


def _target(chart, vessel, opts):
    """The search for one chart and vessel: a function (start, end) -> Route."""
    import seaway

    land = opts["land"]
    if land is None and hasattr(chart, "data_vars") and "land" in chart.data_vars:
        land = chart["land"]
    if vessel is None:
        if hasattr(chart, "data_vars"):
            raise TypeError("a Dataset chart needs vessels= callables turning it into a cost raster")
        cost = chart
    else:
        cost = vessel(chart) if callable(vessel) else vessel
    cost, land = _loaded(cost), _loaded(land)
    prepared = seaway.prepare(cost, land=land, **opts["chart"])  # once; a workspace per thread
    return lambda s, e, via=(): prepared.route(s, e, method=opts["method"], weight=opts["weight"],
                                               via=via, turn_penalty=opts.get("turn_penalty"))


def _status(exc):
    if isinstance(exc, NoRouteError):
        return "no route"
    if isinstance(exc, (ValueError, TypeError)):
        return "bad input"
    return "error"


def _route_one(get_target, voyage, keep):
    """One row: the route for `voyage` or the reason it failed (never raises)."""
    malformed, via = False, ()
    try:
        start, end, *rest = voyage
        if len(rest) > 1:
            raise ValueError
        via = rest[0] if rest else ()
        if via is None or (isinstance(via, float) and math.isnan(via)):  # a DataFrame's empty cell
            via = ()
    except (TypeError, ValueError):
        start, end, malformed = voyage, None, True
    row = dict(start=start, end=end, cost=math.nan, length=math.nan, settled=None, time_s=0.0)
    route = None
    t0 = time.perf_counter()
    try:
        if malformed:
            raise TypeError(f"a voyage must be a (start, end) pair or a (start, end, via) triple, got {voyage!r}")
        target = get_target()
        t0 = time.perf_counter()
        route = target(start, end, via) if len(via) else target(start, end)
        row.update(cost=float(route.cost), length=float(route.length),
                   settled=route.stats.get("settled"), status="ok", error="")
    except Exception as exc:  # noqa: BLE001 - a failing route is reported in its row
        status = _status(exc)
        row.update(status=status, error=f"{type(exc).__name__}: {exc}" if status == "error" else str(exc))
    row["time_s"] = time.perf_counter() - t0
    if keep:
        row["route"] = route
    return row


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

    work = [(ci, vi, voyage) for ci in range(len(chart_items)) for vi in range(nv)
            for _, voyage in voyage_items]
    if threads == 1:
        rows = []
        for w in work:
            rows.append(item(*w))
            bar.update(1)
        return rows
    rows = [None] * len(work)
    with ThreadPoolExecutor(max_workers=threads) as pool:
        futures = {pool.submit(item, *w): i for i, w in enumerate(work)}
        for fut in as_completed(futures):
            rows[futures[fut]] = fut.result()
            bar.update(1)
    return rows


# -- dask ----------------------------------------------------------------------------------------
def _run_batch(chart, vessel, voyages, opts):
    """On a worker: the rows of a batch of voyages for one chart and vessel, in order."""
    shared = _Shared(lambda: _target(chart, vessel, opts), len(voyages))
    return [_route_one(shared.get, v, opts["keep"]) for v in voyages]


def _run_dask(chart_items, vessel_items, voyage_items, opts, cluster, bar):
    import dask
    from dask.distributed import Client, LocalCluster
    from dask.distributed import as_completed as dask_completed

    own = []
    if cluster is True or cluster == "local":
        own.append(LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=":0"))
        client = Client(own[0])
        own.insert(0, client)
    elif isinstance(cluster, str):
        client = Client(cluster)
        own.append(client)
    else:
        client = cluster
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
        batches = [voyages[i:i + size] for i in range(0, len(voyages), size)]
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
        for fut in dask_completed(futures):
            parts[index[fut.key]] = fut.result()
            bar.update(len(parts[index[fut.key]]))
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
        sys.stderr.write(f"\rroutes {self.done:>{len(str(self.total))}}/{self.total} "
                         f"[{'#' * fill}{'.' * (self.width - fill)}] {100 * frac:3.0f} %")
        sys.stderr.flush()

    def close(self):
        if self.enabled:
            sys.stderr.write("\n")
            sys.stderr.flush()
