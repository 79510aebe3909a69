"""Many routes in one call: voyages x vessels x charts, in threads or on a Dask cluster.

`route_many` routes every voyage for every vessel on every chart and returns a pandas DataFrame
with one row per route, in input order (charts, then vessels, then voyages). A route that fails
(no route, a point on land, a malformed point) is reported in its row and never stops the others.

Threads share each chart's memory (the C++ search releases the GIL). With `cluster=`, the work is
spread over dask.distributed workers; a dask-backed xarray time series is loaded chart by chart
on the workers. Each route is computed by the same code either way, so the results are identical."""

from __future__ import annotations

import os
from collections.abc import Mapping

from ..base.validate import number
from ..errors import SeawayError, SeawayTypeError
from .run import _Progress, _run_dask, _run_threads

#: The ends of a row as numbers: as asked for, and as used (after snapping); route_voyages's too.
ENDS = [
    "start_lat",
    "start_lon",
    "end_lat",
    "end_lon",
    "used_start_lat",
    "used_start_lon",
    "used_end_lat",
    "used_end_lon",
]

COLUMNS = [
    "chart",
    "vessel",
    "voyage",
    *ENDS,
    "start_moved_km",
    "end_moved_km",
    "cost",
    "length",
    "settled",
    "time_s",
    "status",
    "cause",
    "error",
    "notes",
]
#: The names of the point columns on planar charts, where points are (row, col) pixels.
PLANAR = {"_lat": "_row", "_lon": "_col", "_moved_km": "_moved"}


def route_many(
    charts,
    voyages,
    *,
    vessels=None,
    lat=None,
    lon=None,
    dx=1.0,
    dy=1.0,
    land=None,
    neighbourhood=5,
    directions="full",
    edge_cost="max",
    method="auto",
    weight=None,
    threads=None,
    cluster=None,
    progress=None,
    keep_routes=False,
    time_dim="time",
    keep_away=(),
    zones=(),
    turn_penalty=None,
    snap_km=None,
):
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
    keep_routes: add a `route` column with the Route objects (None where a route failed; a
        snapped route records the ends asked for and the move, as seaway.SnappedEnds.record).
    snap_km: None (default): an end on a pixel the ship may not use fails its row; a distance:
        such an end moves to the nearest usable point in water that joins both ends when that is
        at most snap_km away (km on geographic charts, chart units on planar ones), by the code
        every snapping route uses (seaway.snap_ends); farther, the row fails with SnapError's
        message.

    Columns: chart, vessel, voyage (ids); start_lat, start_lon, end_lat, end_lon (the ends asked
    for, as numbers); used_start_lat, ..., used_end_lon (the ends routed; NaN when the row
    failed); start_moved_km, end_moved_km (how far snapping moved each end: 0 when it did not,
    NaN when the row failed); cost, length (km on geographic charts, grid units otherwise),
    settled (pixels), time_s (wall time of the search), status ("ok", "no route", "bad input"
    or "error"), cause ("" when ok; "land", "closed by ice" (an impassable cost that is not
    land), "off chart", "no route", "bad input" or "error"), error (the message; "" when ok) and
    notes (a sentence per snapped end). When every chart is planar the point columns are named
    start_row, start_col, ..., start_moved, end_moved (pixels and chart units)."""
    import pandas as pd

    threads = (
        (os.cpu_count() or 1) if threads is None else number(threads, "threads", minimum=1, integer=True)
    )
    opts = dict(
        chart=dict(
            lat=lat,
            lon=lon,
            dx=dx,
            dy=dy,
            neighbourhood=neighbourhood,
            directions=directions,
            edge_cost=edge_cost,
            keep_away=keep_away,
            zones=zones,
        ),
        method=method,
        weight=weight,
        land=land,
        keep=bool(keep_routes),
        turn_penalty=turn_penalty,
        snap_km=None if snap_km is None else number(snap_km, "snap_km", minimum=0),
    )
    if isinstance(charts, (str, os.PathLike)) or callable(getattr(charts, "route", None)):
        raise SeawayTypeError(
            "route_many takes cost rasters (numpy, xarray) or callables making them; for a chart "
            "file, an opened chart, season or forecast use seaway.fleet.route_voyages("
            "seaway.open_chart(path), voyages, vessels=...)"
        )
    chart_items = _chart_items(charts, time_dim)
    vessel_items = [(None, None)] if vessels is None else _items(vessels, "vessels")
    voyage_items = _voyage_items(voyages)
    if charts is not None and any(v is not None and not callable(v) for _, v in vessel_items):
        raise SeawayError(
            "a vessel given as a cost raster ignores the charts; pass charts=None, "
            "or give the vessel as a callable turning a chart into a cost raster"
        )
    n = len(chart_items) * len(vessel_items) * len(voyage_items)
    bar = _Progress(n, cluster is not None if progress is None else bool(progress))
    try:  # Ctrl-C stops every running search (seaway.fleet.run) and raises KeyboardInterrupt
        if cluster is None:
            rows = _run_threads(chart_items, vessel_items, voyage_items, opts, threads, bar)
        else:
            rows = _run_dask(chart_items, vessel_items, voyage_items, opts, cluster, bar)
    finally:
        bar.close()
    ids = [(c, v, y) for c, _ in chart_items for v, _ in vessel_items for y, _ in voyage_items]
    table = pd.DataFrame(
        [dict(chart=c, vessel=v, voyage=y, **_flat(row)) for (c, v, y), row in zip(ids, rows)],
        columns=COLUMNS + (["route"] if keep_routes else []),
    )
    table["settled"] = table["settled"].astype("Int64")
    kinds = {row["geographic"] for row in rows} - {None}
    if kinds == {False}:  # every chart planar: the points are (row, col) pixels
        table = table.rename(columns={c: _planar(c) for c in COLUMNS})
    return table


def _flat(row):
    """A row's points as numbers, under the table's column names."""
    out = {k: v for k, v in row.items() if k != "geographic"}
    for key in ("start", "end", "used_start", "used_end"):
        out[f"{key}_lat"], out[f"{key}_lon"] = out.pop(key)
    out["start_moved_km"], out["end_moved_km"] = out.pop("start_moved"), out.pop("end_moved")
    return out


def _planar(column):
    for geo, planar in PLANAR.items():
        if column.endswith(geo):
            return column[: -len(geo)] + planar
    return column


# -- inputs --------------------------------------------------------------------------------------
def _items(obj, name):
    if isinstance(obj, Mapping):
        return list(obj.items())
    if isinstance(obj, (list, tuple)):
        return list(enumerate(obj))
    raise SeawayTypeError(f"{name} must be a mapping id -> item or a list, got {type(obj).__name__}")


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
