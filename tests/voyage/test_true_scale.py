"""Routes on projected charts are measured and timed in true km (seaway.voyage.projected): the
projection's point scale factor k is corrected in the search and every figure a navigator reads
(length, leg distances, speeds, hours) is a WGS84 geodesic, whatever k is on the chart."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

import seaway
from support.data import SHARED_DATA

pyproj = pytest.importorskip("pyproj")
GEOD = pyproj.Geod(ellps="WGS84")
NSIDC = ("sea_ice_concentration", "seaice_conc_daily_nh_20211231_f17_v04r00.nc")
ROMS = ("ocean_model", "metno_ROMS_Arctic20_1to5Feb_2016.nc")


def _open_water_chart(path, rows=60, cols=80, dx_m=25_000.0):
    """Open water (concentration 0) on NSIDC's polar stereographic EPSG:3413 (WGS84, true to
    scale at 70 N) with a CF grid mapping, its axes in metres, from 78 N at 20 E (row 0) towards
    the Barents Sea: k is 0.97-1.00 on it."""
    crs = pyproj.CRS.from_epsg(3413)
    x0, y0 = pyproj.Transformer.from_crs("EPSG:4326", crs, always_xy=True).transform(20.0, 78.0)
    y = y0 + dx_m * np.arange(rows)
    x = x0 + dx_m * (np.arange(cols) - cols // 2)
    conc = xr.DataArray(
        np.zeros((rows, cols), np.float32),
        dims=("y", "x"),
        attrs={"standard_name": "sea_ice_area_fraction", "units": "1", "grid_mapping": "crs"},
    )
    ds = xr.Dataset(
        {"ice_conc": conc, "crs": xr.DataArray(0, attrs={"crs_wkt": crs.to_wkt()})},
        coords={
            "y": ("y", y, {"standard_name": "projection_y_coordinate", "units": "m"}),
            "x": ("x", x, {"standard_name": "projection_x_coordinate", "units": "m"}),
        },
    )
    ds.to_netcdf(path)
    to_ll = pyproj.Transformer.from_crs(crs, "EPSG:4326", always_xy=True)
    lon, lat = to_ll.transform([x[5], x[-6]], [y[3], y[-4]])
    return str(path), (float(lat[0]), float(lon[0])), (float(lat[1]), float(lon[1]))


def _geodesic_km(latlon) -> float:
    w = np.asarray(latlon, float)
    return float(GEOD.inv(w[:-1, 1], w[:-1, 0], w[1:, 1], w[1:, 0])[2].sum() / 1e3)


def test_open_water_hours_are_the_geodesic_length_over_the_speed(tmp_path):
    path, a, b = _open_water_chart(tmp_path / "open.nc")
    chart = seaway.open_chart(path, vessel="Arc4", ends=(a, b))
    r = chart.route(a, b, speed_kn=12, objective="time")
    legs = r.legs()
    true_km = _geodesic_km(r.latlon)
    hours = sum(leg.time_h for leg in legs)
    assert r.length == pytest.approx(true_km, rel=1e-9)
    assert sum(leg.distance for leg in legs) == pytest.approx(true_km, rel=1e-9)
    assert hours == pytest.approx(true_km / 1.852 / 12, rel=1e-6)
    assert all(leg.speed_kn == pytest.approx(12.0, rel=1e-9) for leg in legs)  # the ship's, not 12.3
    assert r.cost == pytest.approx(hours, rel=0.01)  # the search's true hours agree with the table
    direct = GEOD.inv(r.latlon[0][1], r.latlon[0][0], r.latlon[-1][1], r.latlon[-1][0])[2] / 1e3
    assert direct <= r.length <= direct * 1.01
    k = np.asarray(chart.projection.k.values)
    said = [n for n in r.notes if n.startswith("distances and times in true km")]
    assert (
        said and f"scale factor k, from {k.min():.2f} to {k.max():.2f} on this chart, is corrected" in said[0]
    )
    assert (round(k.min(), 2), round(k.max(), 2)) == (0.97, 1.0)


def test_the_search_prices_each_step_by_its_true_length(tmp_path):
    """The search's cost raster is the cost per projection km times 1/k: the scale is
    pyproj's (conformal: meridional = parallel scale) at each pixel."""
    path, a, b = _open_water_chart(tmp_path / "open.nc")
    chart = seaway.open_chart(path, vessel="Arc4", ends=(a, b))
    k = np.asarray(chart.projection.k.values)
    lat, lon = chart.projection.to_latlon([chart.grid.y.values[0]], [chart.grid.x.values[40]])[0]
    f = pyproj.Proj(chart.projection.crs).get_factors(lon, lat)
    assert k[0, 40] == pytest.approx(f.meridional_scale, rel=1e-12)
    assert f.meridional_scale == pytest.approx(f.parallel_scale, rel=1e-9)
    assert 0.96 < k.min() < k.max() < 1.005
    cost = chart.cost_for("Arc4")
    assert np.allclose(chart.projection.true_cost(cost).values, cost.values / k)


@pytest.mark.needs_data(*NSIDC)
def test_a_real_nsidc_route_is_timed_in_true_km():
    a, b = (71.27, 72.07), (66.07, -169.65)
    chart = seaway.open_chart(str(SHARED_DATA.joinpath(*NSIDC)), vessel="Arc7", ends=(a, b), assume_stage=91)
    r = chart.route(a, b, objective="time", snap_km=30, speed_kn=12)
    w = np.asarray(r.latlon, float)
    direct = GEOD.inv(w[0, 1], w[0, 0], w[-1, 1], w[-1, 0])[2] / 1e3
    assert direct <= r.length == pytest.approx(_geodesic_km(w), rel=1e-9)
    hours = sum(leg.time_h for leg in r.legs())
    assert r.cost == pytest.approx(hours, rel=0.01)
    assert hours >= r.length / 1.852 / 12  # never quicker than open water at 12 kn


@pytest.mark.needs_data(*ROMS)
def test_a_real_roms_route_in_open_water_shows_the_ships_speed(tmp_path):
    with xr.open_dataset(SHARED_DATA.joinpath(*ROMS)) as src:
        ds = src.isel(time=0)[["aice", "mask", "polar_stereographic"]].load()
    ds["aice"] = ds["aice"].fillna(0.0) * 0.0  # open water everywhere: hours are distance / speed
    path = tmp_path / "roms_open.nc"
    ds.to_netcdf(path)
    a, b = (69.0, 5.0), (74.0, 30.0)
    chart = seaway.open_chart(str(path), vessel="Arc4", ends=(a, b))
    r = chart.route(a, b, speed_kn=12, objective="time")
    w = np.asarray(r.latlon, float)
    direct = GEOD.inv(w[0, 1], w[0, 0], w[-1, 1], w[-1, 0])[2] / 1e3
    assert direct <= r.length == pytest.approx(_geodesic_km(w), rel=1e-9)
    hours = sum(leg.time_h for leg in r.legs())
    assert hours == pytest.approx(r.length / 1.852 / 12, rel=1e-6)
    assert all(leg.speed_kn == pytest.approx(12.0, rel=1e-9) for leg in r.legs())


def test_a_projected_season_is_timed_per_true_km(tmp_path):
    """A season on a polar stereographic grid (a sphere of 6371 km, true to scale at 70 N; k 0.99
    at 75 N): its hours per km are per true km, its lengths WGS84 geodesics; the leg table shows
    the ship's 12 kn to within the sphere's and the ellipsoid's difference (0.5 %), not 12.2."""
    from support.seasons import projected_season

    ds = projected_season(open_day=0)
    ds.to_netcdf(tmp_path / "polar.nc")
    season = seaway.open_season(str(tmp_path / "polar.nc"))
    k = 1.0 / season.grid.per_true_km
    assert 0.98 < k.min() < k.max() < 0.995
    assert any("distances and times in true km" in n for n in season.notes)
    to_ll = pyproj.Transformer.from_crs(season.projection.crs, "EPSG:4326", always_xy=True)
    (lon0, lon1), (lat0, lat1) = to_ll.transform([float(ds.x[5]), float(ds.x[45])], [float(ds.y[15])] * 2)
    r = season.route((lat0, lon0), (lat1, lon1), vessel="Arc4", speed_kn=12)
    assert r.length == pytest.approx(_geodesic_km(r.latlon), rel=1e-9)
    hours = sum(leg.time_h for leg in r.legs())
    assert hours == pytest.approx(r.length / 1.852 / 12, rel=0.005)
    assert all(leg.speed_kn == pytest.approx(12.0, rel=0.005) for leg in r.legs())
