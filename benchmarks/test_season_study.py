"""A season study as one call (seaway.fleet.route_voyages): 3 classes x 50 voyages between 10
ports x daily departures through a season of daily ice charts, waits allowed, on 1 and 2
threads and on a local 2-worker Dask cluster; routes per second, and the whole study of the
issue (120 days x 3 classes x 50 voyages = 18,000 routes) on 2 threads.

Rows of one vessel, port and departure come from one search (OpenSeason.routes): each equals
the single route(method="dijkstra") answer (asserted on a sample), and every run's table equals
the serial run's (asserted).

The season: 150 daily charts on 0.05 deg pixels of the Kara Sea (70-78 N, 55-105 E: 160 x 1000)
with an ice edge retreating north 0.06 deg a day, thin first-year ice (4-7/10) behind it and
medium first-year (8/10) beyond, land along the south and a Novaya-Zemlya-like bar. Ports: five
in the south-west, five in the north-east; the voyages are the 25 pairs both ways."""

import time

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.fleet import daily, route_voyages

from .conftest import NOTES, record

pytest.importorskip("pandas")
DAY0 = np.datetime64("2026-06-15T00")
CLASSES = ("Arc4", "Arc5", "Arc7")
WEST = [(70.45, 58.0), (71.2, 66.5), (72.5, 69.0), (73.5, 58.5), (70.6, 73.0)]
EAST = [(72.0, 80.0), (73.5, 80.5), (75.5, 88.0), (76.5, 97.0), (77.3, 104.0)]
VOYAGES = {f"w{i}-e{j}": (a, b) for i, a in enumerate(WEST) for j, b in enumerate(EAST)}
VOYAGES |= {f"e{j}-w{i}": (b, a) for i, a in enumerate(WEST) for j, b in enumerate(EAST)}
SLICE = daily(DAY0, DAY0 + np.timedelta64(4, "D"))  # 5 departures: 750 routes
STUDY = daily(DAY0, DAY0 + np.timedelta64(119, "D"))  # 120 departures: 18,000 routes
_SERIAL = {}


@pytest.fixture(scope="module")
def season(tmp_path_factory):
    lat = np.round(np.arange(77.975, 69.99, -0.05), 6)
    lon = np.round(np.arange(55.025, 105.0, 0.05), 6)
    la, lo = np.meshgrid(lat, lon, indexing="ij")
    days = 150
    ct = np.empty((days,) + la.shape, np.float32)
    sa = np.empty_like(ct)
    for d in range(days):
        beyond = la - (71.5 + 0.06 * d)
        ct[d] = np.where(beyond < 0, 0.0, np.where(beyond < 1, 4.0, np.where(beyond < 3, 7.0, 8.0)))
        sa[d] = np.where(beyond < 0, np.nan, np.where(beyond < 3, 87.0, 91.0))
    land = (la < 70.3) | ((lo <= 57.0) & (la >= 71.0) & (la <= 76.5))
    ds = xr.Dataset(
        {
            "CT": (("time", "lat", "lon"), ct),
            "SA": (("time", "lat", "lon"), sa),
            "land": (("lat", "lon"), land),
        },
        coords={"time": DAY0 + np.arange(days) * np.timedelta64(1, "D"), "lat": lat, "lon": lon},
    )
    path = tmp_path_factory.mktemp("study") / "season.nc"
    ds.to_netcdf(path)
    return seaway.open_season(str(path))


def _study(season, departures=SLICE, **kw):
    return route_voyages(season, VOYAGES, vessels=CLASSES, departures=departures, snap_km=30, **kw)


def _serial(season):
    if "table" not in _SERIAL:
        _SERIAL["table"] = _study(season, threads=1)
    return _SERIAL["table"]


def _rate(name, benchmark, table):
    n = len(table)
    med = benchmark.stats.stats.median if benchmark.stats else float("nan")
    ok = int((table.status == "ok").sum())
    NOTES[name] = (
        f"{n} routes ({ok} ok, waits {table.wait_h.fillna(0).sum():.0f} h in all): {n / med:.1f} routes/s; "
        f"the 18,000-route study would take {18000 / (n / med) / 60:.1f} min at this rate"
    )
    record(name, benchmark, NOTES[name])


def _check_rows(season, table, every=97):
    """A sample of rows equals the single route(method="dijkstra") answer."""
    for row in table.iloc[::every].itertuples():
        start, end = VOYAGES[row.voyage]
        depart = np.datetime64(row.departure, "s")
        r = season.route(start, end, vessel=row.vessel, depart=depart, snap_km=30, method="dijkstra")
        assert row.status == "ok" and row.hours == r.stats.voyage.hours


@pytest.mark.parametrize("threads", [1, 2])
def test_season_study_on_threads(benchmark, season, threads):
    want = _serial(season)
    table = benchmark.pedantic(
        lambda: _study(season, threads=threads), rounds=3, iterations=1, warmup_rounds=0
    )
    assert table.drop(columns="error").equals(want.drop(columns="error"))
    _check_rows(season, table)
    _rate(f"season study, {threads} thread(s)", benchmark, table)


def test_season_study_on_a_local_cluster(benchmark, season):
    distributed = pytest.importorskip("dask.distributed")
    want = _serial(season)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=":0") as cluster:
        with distributed.Client(cluster) as client:
            t = time.perf_counter()
            client.run(lambda: None)
            ready = time.perf_counter() - t
            table = benchmark.pedantic(
                lambda: _study(season, cluster=client, progress=False),
                rounds=3,
                iterations=1,
                warmup_rounds=0,
            )
            rss = client.run(lambda: __import__("psutil").Process().memory_info().rss)
    assert table.drop(columns="error").equals(want.drop(columns="error"))
    _rate("season study, local cluster (2 workers)", benchmark, table)
    NOTES["season study, local cluster (2 workers)"] += (
        f"; worker memory {max(rss.values()) / 2**20:.0f} MiB at most; cluster ready in {ready:.1f} s"
    )


def test_the_whole_study_on_two_threads(benchmark, season):
    """The issue's study as it is asked: 120 days x 3 classes x 50 voyages, once."""
    table = benchmark.pedantic(
        lambda: _study(season, departures=STUDY, threads=2), rounds=1, iterations=1, warmup_rounds=0
    )
    assert len(table) == 18000
    _check_rows(season, table, every=1499)
    _rate("season study, all 18,000 routes, 2 threads", benchmark, table)
