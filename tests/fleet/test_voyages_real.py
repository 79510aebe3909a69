"""route_voyages on a real season (MET Norway's ROMS Arctic-20km daily ice, 1-5 Feb 2016, a
polar stereographic grid) by lat/lon ports, its table written to Parquet, CSV and NetCDF and read
back with the same numbers; each row equals the single route's hours."""

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.fleet import daily, route_voyages, to_dataset

pd = pytest.importorskip("pandas")
pytest.importorskip("pyarrow")
pytestmark = pytest.mark.needs_data("ocean_model", "metno_ROMS_Arctic20_1to5Feb_2016.nc")
NORWAY, SVALBARD_EAST = (68.74, 5.46), (78.87, 39.31)  # open water; 5-6/10 ice east of Svalbard


def test_a_real_season_study_written_and_read_back(shared_data, tmp_path):
    season = seaway.open_season(str(shared_data / "ocean_model" / "metno_ROMS_Arctic20_1to5Feb_2016.nc"))
    voyages = {"out": (NORWAY, SVALBARD_EAST), "back": (SVALBARD_EAST, NORWAY)}
    days = daily("2016-02-01T12", "2016-02-03T12")
    table = route_voyages(season, voyages, vessels=("Arc4", "PC6"), departures=days, snap_km=30)
    assert len(table) == 12 and set(table.status) <= {"ok", "no route", "bad input"}
    ok = table[table.status == "ok"]
    assert len(ok) >= 6
    for row in ok.itertuples():
        start, end = voyages[row.voyage]
        r = season.route(start, end, vessel=row.vessel, depart=np.datetime64(row.departure, "s"), snap_km=30)
        assert row.hours == pytest.approx(r.stats.voyage.hours, rel=1e-9)  # A* and the batch's Dijkstra
        assert 60 < row.hours < 400 and row.distance_nm > 450
    # Parquet and CSV keep every number; NetCDF indexes them by vessel x voyage x departure.
    table.to_parquet(tmp_path / "study.parquet")
    pd.testing.assert_frame_equal(pd.read_parquet(tmp_path / "study.parquet"), table, check_dtype=False)
    table.to_csv(tmp_path / "study.csv", index=False)
    back = pd.read_csv(tmp_path / "study.csv")
    np.testing.assert_allclose(back.hours, table.hours, rtol=1e-12)
    np.testing.assert_allclose(back.used_end_lat, table.used_end_lat, rtol=1e-12)
    to_dataset(table).to_netcdf(tmp_path / "study.nc")
    with xr.open_dataset(tmp_path / "study.nc") as ds:
        assert dict(ds.sizes) == {"vessel": 2, "voyage": 2, "departure": 3}
        got = float(ds.hours.sel(vessel="Arc4", voyage="out", departure=np.datetime64("2016-02-01T12:00")))
    want = table[(table.vessel == "Arc4") & (table.voyage == "out")].hours.iloc[0]
    assert got == pytest.approx(want, rel=1e-12) or (np.isnan(got) and np.isnan(want))


def test_an_opened_chart_batch_snaps_its_ends_as_its_route_does(shared_data):
    """route_voyages(chart, snap_km=) on the ROMS file opened as one chart: each row is the
    chart's own route(snap_km=) answer (OpenChart.route takes its options as keywords)."""
    chart = seaway.open_chart(str(shared_data / "ocean_model" / "metno_ROMS_Arctic20_1to5Feb_2016.nc"))
    voyages = {"ice": (NORWAY, SVALBARD_EAST), "sea": (NORWAY, (75.0, 20.0))}
    table = route_voyages(chart, voyages, vessels=["Arc7"], threads=1, objective="time", snap_km=60)
    rows = table.set_index("voyage")
    ice = rows.loc["ice"]  # 1.6 m of ice 76.4 km around the end: more than snap_km
    assert (ice.status, ice.cause) == (
        "no route",
        "closed by ice",
    ) and "farther than --snap-km 60" in ice.error
    r = chart.route(NORWAY, (75.0, 20.0), vessel="Arc7", objective="time", snap_km=60)
    assert rows.loc["sea"].status == "ok"
    assert rows.loc["sea"].hours == pytest.approx(sum(leg.time_h for leg in r.legs()), rel=1e-12)
    assert (rows.loc["sea"].used_end_lat, rows.loc["sea"].used_end_lon) == pytest.approx(tuple(r.latlon[-1]))


def test_route_many_names_route_voyages_for_a_chart_file_or_an_opened_chart(shared_data):
    path = shared_data / "ocean_model" / "metno_ROMS_Arctic20_1to5Feb_2016.nc"
    for charts in (str(path), path, seaway.open_chart(str(path))):
        with pytest.raises(
            seaway.SeawayTypeError, match=r"use seaway.fleet.route_voyages\(seaway.open_chart"
        ):
            seaway.route_many(charts, {"a": (NORWAY, SVALBARD_EAST)})
