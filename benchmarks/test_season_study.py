"""A season study as one call (seaway.fleet.route_voyages): vessels x voyages x departures
through a season of daily ice charts, waits allowed, on 1 and 2 threads and on a local 2-worker
Dask cluster; routes per second, and the extrapolation to the study of 120 days x 3 classes x
50 voyages (18,000 routes). Every run's table equals the serial run's (asserted).

The season: 30 daily charts on 0.05 deg pixels of the Kara Sea (70-78 N, 55-105 E: 160 x 1000)
with an ice edge retreating north 0.15 deg a day, thin first-year ice (4-7/10) behind it and
medium first-year (8/10) beyond, land along the south and a Novaya-Zemlya-like bar."""

import time

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.fleet import daily, route_voyages

from .conftest import NOTES, record

pytest.importorskip("pandas")
DAY0 = np.datetime64("2026-07-01T00")
CLASSES = ("Arc4", "Arc5", "Arc7")
VOYAGES = {f"v{i}": ((70.6 + 0.3 * i, 56.5 + 0.5 * i), (77.0 - 0.2 * i, 100.0 - 1.5 * i)) for i in range(5)}
DEPARTURES = daily(DAY0, DAY0 + np.timedelta64(3, "D"))
_SERIAL = {}


@pytest.fixture(scope="module")
def season(tmp_path_factory):
    lat = np.round(np.arange(77.975, 69.99, -0.05), 6)
    lon = np.round(np.arange(55.025, 105.0, 0.05), 6)
    la, lo = np.meshgrid(lat, lon, indexing="ij")
    days = 30
    beyond = la[None] - (71.5 + 0.15 * np.arange(days)[:, None, None])
    ct = np.where(beyond < 0, 0.0, np.where(beyond < 1, 4.0, np.where(beyond < 3, 7.0, 8.0)))
    sa = np.where(beyond < 0, np.nan, np.where(beyond < 3, 87.0, 91.0))
    land = (la < 70.3) | ((lo <= 57.0) & (la >= 71.0) & (la <= 76.5))
    ds = xr.Dataset(
        {
            "CT": (("time", "lat", "lon"), ct),
            "SA": (("time", "lat", "lon"), sa),
            "land": (("time", "lat", "lon"), np.broadcast_to(land, ct.shape)),
        },
        coords={"time": DAY0 + np.arange(days) * np.timedelta64(1, "D"), "lat": lat, "lon": lon},
    )
    path = tmp_path_factory.mktemp("study") / "season.nc"
    ds.to_netcdf(path)
    return seaway.open_season(str(path))


def _study(season, **kw):
    return route_voyages(season, VOYAGES, vessels=CLASSES, departures=DEPARTURES, snap_km=30, **kw)


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
        f"the 18,000-route study would take {18000 / (n / med) / 60:.0f} min at this rate"
    )
    record(name, benchmark, NOTES[name])


@pytest.mark.parametrize("threads", [1, 2])
def test_season_study_on_threads(benchmark, season, threads):
    want = _serial(season)
    table = benchmark.pedantic(
        lambda: _study(season, threads=threads), rounds=3, iterations=1, warmup_rounds=0
    )
    assert table.drop(columns="error").equals(want.drop(columns="error"))
    _rate(f"season study, {threads} thread(s)", benchmark, table)


def test_season_study_on_a_local_cluster(benchmark, season):
    distributed = pytest.importorskip("dask.distributed")
    want = _serial(season)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=":0") as cluster:
        with distributed.Client(cluster) as client:
            t = time.perf_counter()
            client.run(lambda: None)
            table = benchmark.pedantic(
                lambda: _study(season, cluster=client), rounds=3, iterations=1, warmup_rounds=0
            )
            rss = client.run(lambda: __import__("psutil").Process().memory_info().rss)
    assert table.drop(columns="error").equals(want.drop(columns="error"))
    _rate("season study, local cluster (2 workers)", benchmark, table)
    NOTES["season study, local cluster (2 workers)"] += (
        f"; worker memory {max(rss.values()) / 2**20:.0f} MiB at most; cluster ready in {time.perf_counter() - t:.1f} s"
    )
