"""route_voyages: vessels x voyages x departures through an opened season or chart; each row is
the single route's answer (hours, arrival, distance, ends used), failures say their cause."""

import numpy as np
import pytest

import seaway
from seaway.fleet import daily, route_voyages, to_dataset
from support.seasons import DAY0, retreating_edge

pytest.importorskip("pandas")

SEA, LAND, OFF = ((71.0, 70.0), (76.0, 74.0)), ((74.0, 61.0), (76.0, 74.0)), ((60.0, 61.0), (76.0, 74.0))
DAYS = daily(DAY0, DAY0 + np.timedelta64(2, "D"))


@pytest.fixture(scope="module")
def season(tmp_path_factory):
    path = tmp_path_factory.mktemp("voyages") / "week.nc"
    retreating_edge(days=4).to_netcdf(path)
    return seaway.open_season(str(path))


@pytest.fixture(scope="module")
def table(season):
    voyages = {"sea": SEA, "land": LAND, "off": OFF}
    return route_voyages(season, voyages, vessels=("Arc4", "Arc7"), departures=DAYS, threads=2)


def test_daily_departures():
    assert [str(d) for d in DAYS] == ["2026-07-01T00:00:00", "2026-07-02T00:00:00", "2026-07-03T00:00:00"]
    assert len(daily("2026-07-01", "2026-07-02", step_h=6)) == 5
    with pytest.raises(seaway.SeawayError, match="first <= last"):
        daily("2026-07-02", "2026-07-01")


def test_each_row_is_the_single_routes_answer(season, table):
    ok = table[table.status == "ok"]
    assert sorted(set(zip(ok.vessel, ok.voyage))) == [("Arc7", "sea")] and len(ok) == 3
    for row in ok.itertuples():
        r = season.route(*SEA, vessel=row.vessel, depart=row.departure)
        assert row.hours == pytest.approx(r.stats.voyage.hours, abs=1e-9)
        assert np.datetime64(row.arrival, "ms") == np.datetime64(r.stats.voyage.arrival, "ms")
        assert row.distance_nm == pytest.approx(sum(leg.distance_nm for leg in r.legs()), abs=1e-9)
        assert (row.used_start_lat, row.used_start_lon) == tuple(map(float, r.coords[0]))
        assert row.wait_h == pytest.approx(float(np.sum(r.stats.voyage.wait_h)), abs=1e-9)
    # The edge retreats north day by day: the later the departure, the quicker the voyage.
    assert list(ok.hours) == sorted(ok.hours, reverse=True) and ok.hours.iloc[0] > ok.hours.iloc[-1] + 1


def test_failures_name_their_cause(table):
    by = {(r.vessel, r.voyage): (r.status, r.cause) for r in table.itertuples()}
    assert by["Arc4", "sea"] == ("no route", "closed by ice")  # 8/10 medium first-year ice at the end
    assert by["Arc7", "land"] == ("bad input", "land")
    assert by["Arc4", "off"] == ("bad input", "off chart")
    closed = table[(table.vessel == "Arc4") & (table.voyage == "sea")].error.iloc[0]
    assert "medium first-year ice (SA 91) at 8/10" in closed and "155.7 km away" in closed
    assert table[table.status != "ok"].hours.isna().all()


def test_snap_km_moves_the_ends_as_the_single_route_does(season):
    got = route_voyages(season, [LAND], vessels=["Arc7"], snap_km=50, threads=1)
    r = season.route(*LAND, vessel="Arc7", snap_km=50)
    row = got.iloc[0]
    assert row.status == "ok" and (row.start_lat, row.start_lon) == LAND[0]
    assert (row.used_start_lat, row.used_start_lon) == pytest.approx((74.0, 62.2), abs=1e-9)
    assert row.hours == pytest.approx(r.cost, abs=1e-9)


def test_threads_give_the_serial_answer(season, table):
    serial = route_voyages(
        season, {"sea": SEA, "land": LAND, "off": OFF}, vessels=("Arc4", "Arc7"), departures=DAYS, threads=1
    )
    assert serial.drop(columns="error").equals(table.drop(columns="error"))


def test_the_table_as_a_dataset_and_a_csv(table, tmp_path):
    import pandas as pd

    ds = to_dataset(table)
    assert dict(ds.sizes) == {"vessel": 2, "voyage": 3, "departure": 3}
    ok = table[table.status == "ok"]
    np.testing.assert_allclose(ds.hours.sel(vessel="Arc7", voyage="sea").values, ok.hours.values)
    table.to_csv(tmp_path / "t.csv", index=False)
    back = pd.read_csv(tmp_path / "t.csv")
    assert back.start_lat.dtype == float and back.used_end_lon.dtype == float
    np.testing.assert_allclose(back.hours.dropna().values, ok.hours.values)


def test_bad_batches_are_refused(season):
    with pytest.raises(seaway.SeawayTypeError, match="opened chart, season or forecast"):
        route_voyages(np.ones((3, 3)), [SEA])
    with pytest.raises(seaway.SeawayError, match="at least one voyage"):
        route_voyages(season, [])
    with pytest.raises(seaway.SeawayError, match="threads=0"):
        route_voyages(season, [SEA], threads=0)


def test_a_static_chart_is_timed_by_each_vessels_ice_curve(tmp_path):
    from seaway.vessel import load

    retreating_edge(days=1).isel(time=0).to_netcdf(tmp_path / "day.nc")
    chart = seaway.open_chart(str(tmp_path / "day.nc"))
    lng = load("arc7-lng-carrier")
    got = route_voyages(
        chart, {"sea": SEA}, vessels={"lng": lng, "Arc4": "Arc4"}, departures=["2026-07-01T06"]
    )
    row, closed = got.iloc[0], got.iloc[1]
    r = chart.route(*SEA, vessel=lng, depart="2026-07-01T06")
    hours = sum(leg.time_h for leg in r.legs())
    assert row.status == "ok" and row.hours == pytest.approx(hours, abs=1e-9) and 15 < hours < 25
    assert np.datetime64(row.arrival, "s") == np.datetime64("2026-07-01T06") + np.timedelta64(
        round(hours * 3600), "s"
    )
    assert (closed.status, closed.cause) == ("no route", "closed by ice")


def test_the_od_matrix_is_one_search_per_origin_and_each_pair_is_the_routes_hours(season, monkeypatch):
    from seaway.fleet import od_matrix

    ports = {"Ob": (71.0, 70.0), "north": (76.0, 74.0), "east": (72.0, 78.0)}
    calls = []
    field = type(season).arrival_field
    monkeypatch.setattr(
        type(season), "arrival_field", lambda self, *a, **k: calls.append(a) or field(self, *a, **k)
    )
    od = od_matrix(season, ports, vessel="Arc7", depart="2026-07-02")
    assert len(calls) == 3 and od.attrs["units"] == "h" and list(od.index) == list(od.columns) == list(ports)
    for o in ports:
        for d in ports:
            want = (
                0.0
                if o == d
                else season.route(ports[o], ports[d], vessel="Arc7", depart="2026-07-02", smooth=False).cost
            )
            assert od.loc[o, d] == pytest.approx(want, abs=1e-9)
    assert od.loc["Ob", "north"] != od.loc["north", "Ob"]  # the ice moves while the ship sails
    with pytest.raises(seaway.SeawayError, match="port Oslo .* lies outside the chart"):
        od_matrix(season, {"Ob": (71.0, 70.0), "Oslo": (59.9, 10.7)})


@pytest.mark.dask
def test_a_dask_cluster_gives_the_threads_table(season, table):
    distributed = pytest.importorskip("dask.distributed")
    cluster = distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=False, dashboard_address=":0"
    )
    with distributed.Client(cluster) as client:
        dist = route_voyages(
            season,
            {"sea": SEA, "land": LAND, "off": OFF},
            vessels=("Arc4", "Arc7"),
            departures=DAYS,
            cluster=client,
        )
        assert client.status == "running"  # a client given is left open
        sent = []
        scatter = client.scatter
        client.scatter = lambda *a, **k: sent.append(a) or scatter(*a, **k)
        again = route_voyages(season, {"sea": SEA}, vessels=("Arc7",), departures=DAYS, cluster=client)
        assert sent == []  # the season on the workers is reused by the next batch
        assert list(again.hours) == list(table[(table.vessel == "Arc7") & (table.voyage == "sea")].hours)
    cluster.close()
    assert dist.drop(columns="error").equals(table.drop(columns="error"))
    assert list(dist.hours.dropna()) == list(table.hours.dropna()) and len(dist.hours.dropna()) == 3
