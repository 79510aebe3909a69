"""seaway.route_many: serial, threaded and Dask runs agree with each other and with seaway.route;
bad items are reported in their rows; the rows keep the input order."""

import numpy as np
import pytest

import seaway
from seaway.samples import synthetic_endpoints, synthetic_sea

pd = pytest.importorskip("pandas")

SHAPE = (90, 120)


@pytest.fixture(scope="module")
def sea():
    cost = synthetic_sea(SHAPE)
    start, end = synthetic_endpoints(SHAPE)
    return cost, start, end


def water_pairs(cost, n, seed=1):
    """n (start, end) pairs of water pixels in the start's water body (costs are finite)."""
    start, _ = synthetic_endpoints(cost.shape)
    field = seaway.cost_field(cost, start)
    reach = np.argwhere(np.isfinite(field))
    pick = np.random.default_rng(seed).choice(len(reach), size=(n, 2), replace=False)
    return [(tuple(map(int, reach[a])), tuple(map(int, reach[b]))) for a, b in pick]


def walled_chart():
    """Open water with a walled pond: its middle (15, 45) cannot be reached from outside."""
    cost = np.ones((40, 60))
    cost[10:21, 40:51] = np.inf
    cost[13:18, 43:48] = 1.0
    return cost


def test_threads_equal_serial_and_single_routes(sea):
    cost, start, end = sea
    pairs = water_pairs(cost, 12) + [(start, end)]
    voyages = {f"v{9 - i}": p for i, p in enumerate(pairs)}  # ids deliberately out of order
    serial = seaway.route_many(cost, voyages, threads=1, neighbourhood=5, edge_cost="mean")
    threaded = seaway.route_many(cost, voyages, threads=2, neighbourhood=5, edge_cost="mean")
    assert list(serial.voyage) == list(voyages) == list(threaded.voyage)
    assert (serial.status == "ok").all() and (serial.error == "").all()
    assert serial.cost.tolist() == threaded.cost.tolist()
    assert serial.settled.tolist() == threaded.settled.tolist()
    for (vid, (s, e)), row in zip(voyages.items(), serial.itertuples()):
        r = seaway.route(cost, s, e, neighbourhood=5, edge_cost="mean")
        assert (row.voyage, row.start_row, row.start_col, row.end_row, row.end_col) == (vid, *s, *e)
        assert (row.used_start_row, row.used_start_col, row.start_moved) == (*s, 0.0)
        assert row.cost == r.cost and row.length == r.length
        assert row.settled == r.stats.search.settled and row.time_s > 0
    assert serial.cost.iloc[-1] > 100  # the corner-to-corner voyage is long


def test_bad_items_are_reported_not_fatal():
    cost = walled_chart()
    voyages = [
        ((0, 0), (39, 59)),  # ok
        ((12, 42), (0, 5)),  # start on the wall
        ((0, 0), (15, 45)),  # end inside the pond: unreachable
        (("x", 3), (1, 1)),  # malformed point
        ((0, 0),),  # not a (start, end) pair
        ((0, 0), (40, 0)),  # end outside the chart
        ((5, 5), (2, 2)),
    ]  # ok, after the failures
    table = seaway.route_many(cost, voyages, threads=2)
    assert table.status.tolist() == [
        "ok",
        "bad input",
        "no route",
        "bad input",
        "bad input",
        "bad input",
        "ok",
    ]
    assert table.cause.tolist() == [
        "",
        "closed by ice",  # an infinite cost that is not land
        "no route",
        "bad input",
        "bad input",
        "off chart",
        "",
    ]
    walled = seaway.route_many(cost, voyages[:2], land=~np.isfinite(cost), threads=1)
    assert walled.cause.tolist() == ["", "land"]
    assert "impassable" in table.error[1] and "nearest passable pixel" in table.error[1]
    assert "no route" in table.error[2]
    assert "pair of numbers" in table.error[3] and "(start, end) pair" in table.error[4]
    assert "outside the chart" in table.error[5]
    assert table.cost[0] == seaway.route(cost, (0, 0), (39, 59)).cost
    assert table.cost[6] == seaway.route(cost, (5, 5), (2, 2)).cost
    assert table.cost[1:6].isna().all() and table.settled[1:6].isna().all()
    assert table.voyage.tolist() == list(range(7))


def test_charts_times_vessels_keep_routes(sea):
    cost, start, end = sea
    charts = {"winter": cost, "summer": np.where(np.isfinite(cost), 1 + (cost - 1) / 29, np.inf)}
    vessels = {"Arc7": lambda c: c, "Arc4": lambda c: c * 2.5}
    voyages = [(start, end), (end, (start[0] - 3, start[1]))]
    table = seaway.route_many(
        charts, voyages, vessels=vessels, threads=2, keep_routes=True, method="dijkstra"
    )
    assert len(table) == 8
    expect = [(c, v, y) for c in charts for v in vessels for y in range(2)]
    assert list(zip(table.chart, table.vessel, table.voyage)) == expect
    for row in table.itertuples():
        r = seaway.route(vessels[row.vessel](charts[row.chart]), *voyages[row.voyage], method="dijkstra")
        assert row.status == "ok" and row.cost == r.cost
        np.testing.assert_array_equal(row.route.pixels, r.pixels)
    w = table[table.chart == "winter"]
    assert w.cost.iloc[2] == pytest.approx(2.5 * w.cost.iloc[0], rel=1e-12)
    assert table[table.chart == "summer"].cost.iloc[0] < w.cost.iloc[0]


def test_failing_vessel_and_bad_options(sea):
    cost, start, end = sea

    def broken(chart):
        raise RuntimeError("no ice table for this class")

    table = seaway.route_many(cost, [(start, end)] * 2, vessels={"ok": lambda c: c, "x": broken})
    assert table.status.tolist() == ["ok", "ok", "error", "error"]
    assert table.error[2] == "RuntimeError: no ice table for this class"
    with pytest.raises(ValueError, match="ignores the charts"):
        seaway.route_many(cost, [(start, end)], vessels={"raster": cost})
    raster = seaway.route_many(None, [(start, end)], vessels={"raster": cost})
    assert raster.cost[0] == table.cost[0]
    with pytest.raises(ValueError, match="threads"):
        seaway.route_many(cost, [(start, end)], threads=0)


def test_dataframe_voyages_and_progress_bar(sea, capsys):
    cost, start, end = sea
    plan = pd.DataFrame(
        {"start": [start, end, start], "end": [end, start, start]}, index=["out", "back", "stay"]
    )
    table = seaway.route_many(cost, plan, threads=2, progress=True)
    assert table.voyage.tolist() == ["out", "back", "stay"] and table.cost[2] == 0.0
    assert table.cost[0] == seaway.route(cost, start, end).cost
    err = capsys.readouterr().err
    assert "routes 3/3" in err and "100 %" in err and err.endswith("\n")


# -- Dask ----------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def client():
    distributed = pytest.importorskip("dask.distributed")
    cluster = distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=False, dashboard_address=":0"
    )
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


def season(cost, days=3):
    """A dask-backed daily series of geographic charts (a Dataset with land), chunked by time."""
    xr = pytest.importorskip("xarray")
    rows, cols = cost.shape
    lat, lon = np.linspace(76, 72, rows), np.linspace(60, 75, cols)
    ice = np.stack([np.where(np.isfinite(cost), cost * (1 + 0.2 * d), 0.0) for d in range(days)])
    time = np.arange(days).astype("timedelta64[D]") + np.datetime64("2025-01-01")
    ds = xr.Dataset(
        {"ice": (("time", "lat", "lon"), ice), "land": (("lat", "lon"), ~np.isfinite(cost))},
        coords=dict(time=time, lat=lat, lon=lon),
    )
    return ds.chunk({"time": 1}), lat, lon


@pytest.mark.dask
def test_dask_season_equals_serial(sea, client):
    cost, start, end = sea
    ds, lat, lon = season(cost)
    assert ds.ice.chunks[0] == (1, 1, 1)
    dry = np.argwhere(~np.isfinite(cost))[0]
    pts = [((lat[s[0]], lon[s[1]]), (lat[e[0]], lon[e[1]])) for s, e in water_pairs(cost, 3)]
    voyages = {
        "main": ((lat[start[0]], lon[start[1]]), (lat[end[0]], lon[end[1]])),
        **{f"p{i}": p for i, p in enumerate(pts)},
        "on land": ((lat[dry[0]], lon[dry[1]]), pts[0][1]),
    }  # ice 0 there: land var
    vessels = {"Arc7": lambda d: d.ice, "Arc5": lambda d: d.ice * 1.7 + 0.5}
    serial = seaway.route_many(ds, voyages, vessels=vessels, threads=1)
    dist = seaway.route_many(ds, voyages, vessels=vessels, cluster=client)
    threaded = seaway.route_many(ds, voyages, vessels=vessels, threads=2)
    assert len(serial) == 3 * 2 * 5
    assert list(dist.chart) == list(serial.chart) == list(np.repeat(ds.time.values, 10))
    for other in (dist, threaded):
        np.testing.assert_array_equal(other.cost, serial.cost)  # exactly; NaN where failed
        pd.testing.assert_frame_equal(other.drop(columns="time_s"), serial.drop(columns="time_s"))
    ok = serial[serial.status == "ok"]
    assert len(ok) == 24 and (serial.status[serial.voyage == "on land"] == "bad input").all()
    day = ds.isel(time=1).load()
    r = seaway.route(day.ice * 1.7 + 0.5, *voyages["main"], land=day.land)
    row = serial[(serial.chart == ds.time.values[1]) & (serial.vessel == "Arc5")].iloc[0]
    assert row.cost == r.cost and row.length == r.length and row.length > 300  # km


@pytest.mark.dask
def test_dask_by_scheduler_address(sea, client, capsys):
    cost, start, end = sea
    voyages = water_pairs(cost, 4, seed=5) + [(start, end)]
    serial = seaway.route_many({"a": cost, "b": cost + 1}, voyages, threads=1)
    dist = seaway.route_many({"a": cost, "b": cost + 1}, voyages, cluster=client.scheduler.address)
    assert dist.cost.tolist() == serial.cost.tolist() and (dist.status == "ok").all()
    assert list(dist.chart) == ["a"] * 5 + ["b"] * 5
    assert "routes 10/10" in capsys.readouterr().err  # the progress bar is on with a cluster


@pytest.mark.dask
def test_dask_default_local_cluster(sea):
    """cluster=True starts LocalCluster(n_workers=2, threads_per_worker=1) and closes it."""
    cost, start, end = sea
    voyages = [(start, end), (end, start), ((0, 0), (1, 1, 1))]
    serial = seaway.route_many(cost, voyages, threads=1)
    dist = seaway.route_many(cost, voyages, cluster=True, progress=False)
    np.testing.assert_array_equal(dist.cost, serial.cost)
    assert dist.status.tolist() == ["ok", "ok", "bad input"]
    assert dist.cost[0] == pytest.approx(dist.cost[1], rel=1e-12)  # summed in another order
