"""route_many's table written out (issue 30): the ends are numbers in CSV and Parquet, read back
as they were; on planar charts the point columns are (row, col) pixels and snapping moves an end
by chart units."""

import math

import numpy as np
import pytest

import seaway

pd = pytest.importorskip("pandas")


def geographic_sea():
    """A 60 x 80 geographic chart (lat 76-72 N, lon 60-75 E) with an island and its land mask."""
    cost = np.ones((60, 80))
    cost[20:40, 30:50] = np.inf
    lat, lon = np.linspace(76, 72, 60), np.linspace(60, 75, 80)
    xr = pytest.importorskip("xarray")
    land = xr.DataArray(~np.isfinite(cost), coords=dict(lat=lat, lon=lon), dims=("lat", "lon"))
    return xr.DataArray(np.where(np.isfinite(cost), cost, np.inf), coords=land.coords), land


@pytest.fixture(scope="module")
def table():
    cost, land = geographic_sea()
    voyages = {
        "open": ((75.5, 61.0), (72.5, 74.0)),
        "from the island": ((74.0, 67.5), (72.5, 74.0)),  # moved to the island's shore
        "off chart": ((68.97, 33.08), (72.5, 74.0)),
    }
    return seaway.route_many(cost, voyages, land=land, snap_km=100, threads=1)


def test_the_table_carries_ends_as_numbers(table):
    assert table.status.tolist() == ["ok", "ok", "bad input"]
    assert table.cause.tolist() == ["", "", "off chart"]
    for col in ("start_lat", "start_lon", "end_lat", "end_lon", "used_start_lat", "used_end_lon"):
        assert table[col].dtype == np.float64
    assert table.start_lat.tolist() == [75.5, 74.0, 68.97] and table.start_lon.tolist() == [61.0, 67.5, 33.08]
    assert table.start_moved_km[0] == 0.0 and 60 < table.start_moved_km[1] < 100
    assert (table.used_start_lat[1], table.used_start_lon[1]) != (74.0, 67.5)
    assert math.isnan(table.used_start_lat[2]) and math.isnan(table.start_moved_km[2])
    assert "moved" in table.notes[1] and table.notes[0] == ""


def test_csv_round_trip(table, tmp_path):
    path = tmp_path / "routes.csv"
    table.to_csv(path, index=False)
    back = pd.read_csv(path, keep_default_na=False, na_values=[""])
    assert back.start_lat.dtype == np.float64 and back.end_lon.dtype == np.float64
    for col in ("start_lat", "start_lon", "end_lat", "end_lon", "used_start_lat", "used_start_lon"):
        np.testing.assert_array_equal(back[col], table[col])
    np.testing.assert_array_equal(back.start_moved_km, table.start_moved_km)
    assert back.status.tolist() == table.status.tolist()
    assert "(" not in path.read_text().splitlines()[1]  # no "(75.5, 61.0)" strings


def test_parquet_round_trip(table, tmp_path):
    pytest.importorskip("pyarrow")
    path = tmp_path / "routes.parquet"
    table.to_parquet(path)
    back = pd.read_parquet(path)
    pd.testing.assert_frame_equal(back, table)


def test_planar_points_are_pixels_and_snap_in_chart_units():
    cost = np.ones((40, 60))
    cost[10:21, 40:51] = np.inf  # a wall around a pond
    cost[13:18, 43:48] = 1.0
    voyages = [((12, 42), (0, 5)), ((0, 0), (39, 59))]
    table = seaway.route_many(cost, voyages, snap_km=3, threads=1)
    assert "start_row" in table.columns and "start_lat" not in table.columns
    assert table.status.tolist() == ["ok", "ok"]
    first = table.iloc[0]
    assert (first.start_row, first.start_col) == (12, 42)
    assert (first.used_start_row, first.used_start_col) == (9, 42)  # out of the wall, to open water
    assert first.start_moved == 3.0 and table.start_moved[1] == 0.0
    refused = seaway.route_many(cost, voyages[:1], snap_km=2, threads=1)
    assert refused.cause[0] == "closed by ice" and "farther than max_km=2" in refused.error[0]
