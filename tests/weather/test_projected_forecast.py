"""Forecasts on projected model grids (polar stereographic, as ROMS, NEMO and WAM write them):
resampled onto a lat/lon grid with their grid-relative vectors turned to east/north, checked
against the projection's rotation worked by hand; the fields of such files found by their CF
grid-relative standard names; what cannot be routed refused naming the fix."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from seaway.weather import is_projected, on_grid, read_forecasts

pyproj = pytest.importorskip("pyproj")
CRS = "+proj=stere +lat_0=90 +lat_ts=60 +lon_0=58 +R=6371000"


def _polar(u=1.0, v=0.0, std=("sea_water_x_velocity", "sea_water_y_velocity"), levels=0):
    """A uniform current (u, v) along the grid's x and y axes, 20 km pixels, two daily frames."""
    X, Y = np.arange(-1500.0, 1500.1, 20.0), np.arange(-2200.0, -500.0, 20.0)
    shape = (2,) + ((levels,) if levels else ()) + (Y.size, X.size)
    dims = ("time",) + (("depth",) if levels else ()) + ("Y", "X")
    attrs = [{"grid_mapping": "gm", "units": "m s-1"} for _ in std]
    for a, s in zip(attrs, std):
        if s:
            a["standard_name"] = s
    coords = {
        "X": ("X", X, {"standard_name": "projection_x_coordinate", "units": "km"}),
        "Y": ("Y", Y, {"standard_name": "projection_y_coordinate", "units": "km"}),
        "time": np.array(["2016-02-01T12", "2016-02-02T12"], "datetime64[ns]"),
    }
    if levels:
        coords["depth"] = ("depth", np.arange(levels) * 10.0, {"standard_name": "depth"})
    return xr.Dataset(
        {
            "uu": (dims, np.full(shape, u), attrs[0]),
            "vv": (dims, np.full(shape, v), attrs[1]),
            "gm": ((), 0, {"grid_mapping_name": "polar_stereographic", "proj4_string": CRS}),
        },
        coords=coords,
    )


def test_a_current_along_grid_x_points_east_at_lon_0_and_turns_with_longitude():
    # On a north polar stereographic grid the point at longitude lon has x = r sin t,
    # y = -r cos t (t = lon - lon_0), so east is (cos t, sin t) and north (-sin t, cos t) in
    # grid axes: 1 m/s along +x is east cos t, north -sin t. At lon_0 = 58 E it points east;
    # at 28 E (t = -30) east cos 30 = 0.866, north +0.5; at 88 E (t = +30) east 0.866, north -0.5.
    ds = _polar()
    assert is_projected(ds)
    lat, lon = np.array([72.0, 74.0]), np.array([28.0, 58.0, 88.0])
    out, notes = on_grid(ds, lat, lon, source="polar.nc")
    e = out["uu"].isel(time=0).values
    n = out["vv"].isel(time=0).values
    assert out["uu"].attrs["standard_name"] == "eastward_sea_water_velocity"
    assert out["vv"].attrs["standard_name"] == "northward_sea_water_velocity"
    want_e = np.array([np.sqrt(3) / 2, 1.0, np.sqrt(3) / 2])
    want_n = np.array([0.5, 0.0, -0.5])
    np.testing.assert_allclose(e, np.broadcast_to(want_e, e.shape), atol=1e-6)
    np.testing.assert_allclose(n, np.broadcast_to(want_n, n.shape), atol=1e-6)
    assert any("Polar Stereographic" in s and "bilinear" in s for s in notes)
    assert any("rotated to east/north" in s and "uu (sea_water_x_velocity)" in s for s in notes)
    assert not any("outside" in s for s in notes)  # every point lies on the model grid


def test_pixels_outside_the_model_grid_are_calm_and_said():
    ds = _polar(u=0.0, v=2.0)
    lat, lon = np.array([60.0, 74.0]), np.array([58.0])  # 60 N, 58 E: y = -r(60) < the grid's -2200 km
    x, y = pyproj.Transformer.from_crs("EPSG:4326", CRS, always_xy=True).transform([58.0, 58.0], lat)
    assert y[0] / 1e3 < -2200.0 < y[1] / 1e3
    out, notes = on_grid(ds, lat, lon, source="polar.nc")
    assert out["uu"].isel(time=0).values[:, 0] == pytest.approx([0.0, 0.0], abs=1e-9)
    assert out["vv"].isel(time=0).values[:, 0] == pytest.approx([0.0, 2.0], abs=1e-6)  # north at 58 E
    assert "50 % of the grid lies outside polar.nc's model grid: no weather (calm, no current)" in " ".join(
        notes
    )


def test_files_found_by_grid_relative_names_or_mapped_and_said(tmp_path):
    path = tmp_path / "polar.nc"
    _polar().to_netcdf(path)
    ds, notes = read_forecasts(path)
    assert ds["current_east"].attrs["standard_name"] == "sea_water_x_velocity"  # rotated later
    assert any("polar.nc:uu is grid-relative (sea_water_x_velocity)" in n for n in notes)
    out, _ = on_grid(ds, [74.0], [88.0])
    assert float(out["current_north"].isel(time=0).squeeze()) == pytest.approx(-0.5, abs=1e-6)
    # Without standard names, mapped by the user: taken as grid-relative, said, rotated the same.
    bare = tmp_path / "bare.nc"
    _polar(std=(None, None)).to_netcdf(bare)
    ds, notes = read_forecasts(bare, {"current_east": "uu", "current_north": "vv"})
    assert any(
        "no standard name, neither east/north nor grid x/y: taken as grid-relative" in n for n in notes
    )
    out, _ = on_grid(ds, [74.0], [88.0])
    assert float(out["current_east"].isel(time=0).squeeze()) == pytest.approx(np.sqrt(3) / 2, abs=1e-6)


def test_what_cannot_be_routed_is_refused_naming_the_fix(tmp_path):
    deep = tmp_path / "deep.nc"
    _polar(levels=3).to_netcdf(deep)
    with pytest.raises(
        ValueError,
        match=r"deep.nc: uu \(current_east\) has a vertical axis 'depth' "
        r"\(3 levels\).*ncks -d depth,0",
    ):
        read_forecasts(deep)
    mixed = tmp_path / "mixed.nc"
    ds = _polar(std=("sea_water_x_velocity", "northward_sea_water_velocity"))
    ds.to_netcdf(mixed)
    with pytest.raises(
        ValueError, match=r"uu \(current_east\) is grid-relative but vv \(current_north\) is not"
    ):
        read_forecasts(mixed)
    stag = tmp_path / "stag.nc"
    ds = _polar()
    ds["vv"] = ds["vv"].rename(Y="Yv")
    ds.to_netcdf(stag)
    with pytest.raises(
        ValueError, match=r"stag.nc: .* lies on the grid .* the fields of one file must share one grid"
    ):
        read_forecasts(stag)
    nomap = _polar().drop_vars("gm")
    with pytest.raises(
        ValueError, match=r"nomap.nc is on a projected grid but names no grid mapping .*--forecast-crs"
    ):
        on_grid(nomap, [74.0], [58.0], source="nomap.nc")
    out, _ = on_grid(nomap, [74.0], [88.0], crs=CRS)  # the projection given instead
    assert float(out["uu"].isel(time=0).squeeze()) == pytest.approx(np.sqrt(3) / 2, abs=1e-6)


def test_one_unit_table_reads_every_spelling_of_km():
    """CF / UDUNITS spellings are read by one table (seaway.base.units, pint): a forecast axis
    in "kilometers" or "kilometres" was read as metres (1000 x off) by a table of its own."""
    import numpy as np
    import xarray as xr

    from seaway.base.units import km_per, metres_per
    from seaway.weather.forecast import grid_crs

    assert [km_per(u) for u in ("m", "metres", "meter", "km", "kilometers", "kilometres", "100 m")] == [
        0.001,
        0.001,
        0.001,
        1.0,
        1.0,
        1.0,
        0.1,
    ]
    assert (
        metres_per("ft") == pytest.approx(0.3048)
        and metres_per("degrees_north") is None
        and metres_per("") is None
    )
    for units in ("kilometers", "kilometres", "km"):
        ds = xr.Dataset(
            {
                "u": (("y", "x"), np.zeros((2, 2)), {"grid_mapping": "crs"}),
                "crs": ((), 0, {"crs_wkt": "EPSG:3413"}),
            },
            coords={
                "x": ("x", [0.0, 10.0], {"standard_name": "projection_x_coordinate", "units": units}),
                "y": ("y", [0.0, 10.0], {"standard_name": "projection_y_coordinate", "units": units}),
            },
        )
        assert grid_crs(ds)[3] == 1000.0
