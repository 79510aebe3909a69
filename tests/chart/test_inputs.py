"""Input handling: xarray DataArrays and their coordinates, dtypes, longitude conventions,
wrapping charts and threads."""

import math
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import seaway

xr = pytest.importorskip("xarray")

R_EARTH = 6371.0088
LAT = np.linspace(60.0, 65.0, 6)  # 1 degree steps
LON = np.linspace(-10.0, 4.0, 8)  # 2 degree steps
V = np.random.default_rng(0).uniform(1, 5, (6, 8))
A, B = (60.0, -10.0), (65.0, 4.0)


@pytest.fixture(scope="module")
def base():
    return seaway.route(V, A, B, lat=LAT, lon=LON)


def arc_km(deg):
    return R_EARTH * math.radians(deg)


# --- coordinates found on DataArrays -----------------------------------------------------


@pytest.mark.parametrize("names", [("lat", "lon"), ("latitude", "longitude")])
def test_dataarray_lat_lon_names(base, names):
    da = xr.DataArray(V, dims=names, coords={names[0]: LAT, names[1]: LON})
    r = seaway.route(da, A, B)
    assert r.geographic
    assert r.cost == base.cost
    np.testing.assert_array_equal(r.pixels, base.pixels)
    np.testing.assert_array_equal(r.coords, base.coords)


def test_dataarray_transposed_lon_lat(base):
    da = xr.DataArray(V.T, dims=("lon", "lat"), coords={"lat": LAT, "lon": LON})
    r = seaway.route(da, A, B)
    assert r.cost == base.cost
    # pixels are (lat index, lon index) whatever the input's dim order
    np.testing.assert_array_equal(r.pixels, base.pixels)
    np.testing.assert_array_equal(r.coords[[0, -1]], [A, B])


def test_cf_attributes_only(base):
    da = xr.DataArray(
        V,
        dims=("j", "i"),
        coords={"j": ("j", LAT, {"standard_name": "latitude"}), "i": ("i", LON, {"units": "degrees_east"})},
    )
    r = seaway.route(da, A, B)
    assert r.geographic and r.cost == base.cost
    # units alone on both
    da = xr.DataArray(
        V.T,
        dims=("p", "q"),
        coords={"p": ("p", LON, {"units": "degree_east"}), "q": ("q", LAT, {"units": "degrees_north"})},
    )
    assert seaway.route(da, A, B).cost == base.cost


def test_descending_latitude(base):
    da = xr.DataArray(V[::-1], dims=("lat", "lon"), coords={"lat": LAT[::-1], "lon": LON})
    r = seaway.route(da, A, B)
    assert r.cost == pytest.approx(base.cost, rel=1e-12)
    # same geographic route; row indices count from the north now
    np.testing.assert_allclose(r.coords, base.coords)
    np.testing.assert_array_equal(r.pixels[:, 0], 5 - base.pixels[:, 0])


def test_descending_longitude_and_edges(base):
    # a chart stored east to west; points at the first column's centre and within half a pixel
    r = seaway.route(V[:, ::-1], A, B, lat=LAT, lon=LON[::-1])
    assert r.cost == pytest.approx(base.cost, rel=1e-12)
    r2 = seaway.route(V[:, ::-1], (60.0, -10.9), (65.4, 4.9), lat=LAT, lon=LON[::-1])
    assert r2.cost == r.cost
    r3 = seaway.route(V, (59.6, -10.9), (65.0, 4.9), lat=LAT, lon=LON)
    assert r3.cost == base.cost


def test_projected_y_x_spacing():
    y, x = np.arange(6) * 500.0, 1000 + np.arange(8) * 250.0
    da = xr.DataArray(V, dims=("y", "x"), coords={"y": y, "x": x})
    r = seaway.route(da, (0, 0), (5, 7))  # (row, col) on planar charts
    ref = seaway.route(V, (0, 0), (5, 7), dx=250, dy=500)
    assert not r.geographic
    assert r.cost == ref.cost
    np.testing.assert_array_equal(r.pixels, ref.pixels)
    assert r.coords[0].tolist() == [0, 1000] and r.coords[-1].tolist() == [2500, 2750]
    assert r.length == pytest.approx(ref.length)
    # the route is at least as long as the straight line (in coordinate units)
    assert r.length >= math.hypot(2500, 1750) - 1e-9
    # CF axis attributes on odd names, descending y (spacing taken as |step|)
    da2 = xr.DataArray(
        V,
        dims=("north", "east"),
        coords={
            "north": ("north", y[::-1], {"standard_name": "projection_y_coordinate"}),
            "east": ("east", x, {"axis": "X"}),
        },
    )
    assert seaway.route(da2, (0, 0), (5, 7)).cost == ref.cost


# --- cost_field on DataArrays ------------------------------------------------------------


def test_cost_field_dataarray_same_coords():
    da = xr.DataArray(V, dims=("lat", "lon"), coords={"lat": LAT, "lon": LON})
    f = seaway.cost_field(da, A)
    assert isinstance(f, xr.DataArray)
    assert f.dims == ("lat", "lon")
    np.testing.assert_array_equal(f["lat"], LAT)
    np.testing.assert_array_equal(f["lon"], LON)
    ref = seaway.cost_field(V, A, lat=LAT, lon=LON)
    assert isinstance(ref, np.ndarray)
    np.testing.assert_array_equal(f.values, ref)
    assert f.values[0, 0] == 0
    # the field at the end is the route's cost (cost_field is Dijkstra, route A*)
    assert ref[5, 7] == pytest.approx(seaway.route(V, A, B, lat=LAT, lon=LON).cost, rel=1e-12)
    # a transposed DataArray comes back in its own dim order
    ft = seaway.cost_field(da.transpose("lon", "lat"), A)
    assert ft.dims == ("lon", "lat")
    np.testing.assert_array_equal(ft.values, ref.T)


# --- dtypes ---------------------------------------------------------------------------------


def test_float32_equals_float64():
    v = np.round(V * 4) / 4  # exactly representable in float32
    r64 = seaway.route(v, (0, 0), (5, 7), edge_cost="integral")
    r32 = seaway.route(v.astype(np.float32), (0, 0), (5, 7), edge_cost="integral")
    assert r32.cost == r64.cost
    np.testing.assert_array_equal(r32.pixels, r64.pixels)
    np.testing.assert_array_equal(
        seaway.cost_field(v.astype(np.float32), (2, 3)), seaway.cost_field(v, (2, 3))
    )


@pytest.mark.parametrize("dtype", [np.int8, np.int32, np.int64, np.uint16])
def test_integer_costs(dtype):
    v = np.round(V).astype(dtype)
    r = seaway.route(v, (0, 0), (5, 7))
    assert r.cost == seaway.route(v.astype(float), (0, 0), (5, 7)).cost


def test_land_as_dataarray():
    lat, lon = np.arange(4.0), np.arange(5.0)
    cost = xr.DataArray(np.ones((4, 5)), dims=("lat", "lon"), coords={"lat": lat, "lon": lon})
    m = np.zeros((4, 5), bool)
    m[1:, 2] = True  # a wall with a gap at lat 0
    land = xr.DataArray(m, dims=("lat", "lon"), coords={"lat": lat, "lon": lon})
    with_np = seaway.route(cost, (3, 0), (3, 4), land=m)
    with_da = seaway.route(cost, (3, 0), (3, 4), land=land)
    assert with_da.cost == with_np.cost
    assert 0 in with_da.pixels[:, 0]  # goes through the gap at row 0
    assert with_da.cost > seaway.route(cost, (3, 0), (3, 4)).cost
    # land in the other dim order is aligned by name, as is a transposed cost
    assert seaway.route(cost, (3, 0), (3, 4), land=land.transpose()).cost == with_np.cost
    assert seaway.route(cost.transpose(), (3, 0), (3, 4), land=land).cost == with_np.cost
    assert seaway.route(cost.transpose(), (3, 0), (3, 4), land=land.transpose()).cost == with_np.cost


# --- longitude conventions and wrapping charts -------------------------------------------


def test_longitude_conventions_on_a_regional_chart():
    lon = np.arange(100.0, 260.0, 10.0)  # 16 columns across the antimeridian, 0..360 style
    lat = np.array([-10.0, 0.0, 10.0])
    c = np.ones((3, 16))
    r1 = seaway.route(c, (0, 190), (10, 240), lat=lat, lon=lon)
    r2 = seaway.route(c, (0, -170), (10, -120), lat=lat, lon=lon)
    assert r1.pixels[0].tolist() == [1, 9] and r1.pixels[-1].tolist() == [2, 14]
    assert r2.cost == r1.cost
    np.testing.assert_array_equal(r2.pixels, r1.pixels)
    # the same chart labelled -180..180 style (..., 170, -180, -170, ...) is still regular
    lon180 = (lon + 180) % 360 - 180
    assert lon180[7:10].tolist() == [170, -180, -170]
    for end in ((10, 240), (10, -120)):
        r3 = seaway.route(c, (0, 190), end, lat=lat, lon=lon180)
        assert r3.cost == pytest.approx(r1.cost, rel=1e-12)
        np.testing.assert_array_equal(r3.pixels, r1.pixels)
    da = xr.DataArray(c, dims=("lat", "lon"), coords={"lat": lat, "lon": lon180})
    assert seaway.route(da, (0, -170), (10, -120)).cost == pytest.approx(r1.cost, rel=1e-12)
    # 20 degrees along the equator, across the antimeridian
    assert seaway.route(c, (0, 170), (0, -170), lat=lat, lon=lon180).cost == pytest.approx(arc_km(20))


def test_wrapping_chart_crosses_the_seam():
    lat, lon = np.array([-5.0, 0.0, 5.0]), np.arange(0.0, 360.0, 10.0)
    c = np.ones((3, 36))
    # equator from 20E to 20W: 40 degrees across lon 0, not 320 degrees the other way
    r = seaway.route(c, (0, 20), (0, 340), lat=lat, lon=lon)
    assert r.cost == pytest.approx(arc_km(40), rel=1e-12)  # 4447.8 km
    assert r.length == pytest.approx(arc_km(40), rel=1e-12)
    assert set(r.pixels[:, 1]) <= {0, 1, 2, 34, 35}
    gj = np.array(r.to_geojson()["geometry"]["coordinates"])
    np.testing.assert_allclose(gj[[0, -1]], [[20, 0], [-20, 0]], atol=1e-9)  # continuous lon
    assert np.all(np.diff(gj[:, 0]) < 0)
    # -20 is 340
    assert seaway.route(c, (0, 20), (0, -20), lat=lat, lon=lon).cost == r.cost
    # the same chart labelled -180..170: the best route crosses the antimeridian
    r2 = seaway.route(c, (0, 160), (0, -160), lat=lat, lon=lon - 180)
    assert r2.cost == pytest.approx(arc_km(40), rel=1e-12)
    assert seaway.route(c, (0, 160), (0, 200), lat=lat, lon=lon - 180).cost == r2.cost
    # stored east to west (350, 340, ..., 0): the same 40 degrees across the seam
    r4 = seaway.route(c, (0, 20), (0, 340), lat=lat, lon=lon[::-1])
    assert r4.cost == pytest.approx(arc_km(40), rel=1e-12)
    assert r4.pixels[0].tolist() == [1, 33] and r4.pixels[-1].tolist() == [1, 1]
    # points near the seam snap to the nearest centre: 355.1 and 4.9 are both closest to 0
    assert seaway.route(c, (0, 355.1), (0, 4.9), lat=lat, lon=lon).pixels.tolist() == [[1, 0]]
    assert seaway.route(c, (0, -4.9), (0, 4.9), lat=lat, lon=lon[::-1]).pixels.tolist() == [[1, 35]]
    # a chart one column short of the globe does not wrap: 320 degrees the long way
    r3 = seaway.route(c[:, :35], (0, 20), (0, 340), lat=lat, lon=lon[:35])
    assert r3.cost == pytest.approx(arc_km(320), rel=1e-12)


def test_seam_route_beats_an_expensive_direct_band():
    # costs 1 near lon 0, 5 elsewhere on the equator row; the seam side is cheap
    lat, lon = np.array([-5.0, 0.0, 5.0]), np.arange(0.0, 360.0, 10.0)
    c = np.full((3, 36), 5.0)
    c[:, [34, 35, 0, 1, 2]] = 1.0
    f = seaway.cost_field(c, (0, 20), lat=lat, lon=lon, neighbourhood=3)
    assert f[1, 34] == pytest.approx(arc_km(40), rel=1e-12)
    assert f[1, 35] == pytest.approx(arc_km(30), rel=1e-12)


# --- threads --------------------------------------------------------------------------------


def test_same_route_in_four_threads():
    rng = np.random.default_rng(7)
    v = rng.uniform(1, 10, (300, 300))
    v[rng.random(v.shape) < 0.1] = np.inf
    v[0, 0] = v[-1, -1] = 1.0

    def job(_):
        r = seaway.route(v, (0, 0), (299, 299), edge_cost="integral", neighbourhood=7)
        return r.cost, r.pixels

    with ThreadPoolExecutor(4) as ex:
        results = list(ex.map(job, range(8)))
    cost0, pix0 = results[0]
    assert np.isfinite(cost0) and cost0 > 0
    for cost, pix in results[1:]:
        assert cost == cost0
        np.testing.assert_array_equal(pix, pix0)
    assert cost0 == job(None)[0]


# --- land masks ----------------------------------------------------------------------------


def test_bool_and_0_1_land_masks_give_one_route():
    wall = np.zeros((7, 7), bool)
    wall[1:, 3] = True  # a wall with a gap in row 0
    routes = [
        seaway.route(np.ones((7, 7)), (6, 0), (6, 6), land=m, neighbourhood=3)
        for m in (wall, wall.astype(np.uint8), wall.astype(float), wall.astype(np.int64))
    ]
    assert {r.cost for r in routes} == {routes[0].cost}
    assert all((r.pixels[:, 1] != 3).sum() == len(r.pixels) - 1 for r in routes)  # row 0 gap
    assert routes[0].pixels[:, 0].min() == 0
