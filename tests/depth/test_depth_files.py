"""Issue 10 part 2: bathymetry files (sign and units from CF attributes, stated guesses, bad
files and units named with the fix; NetCDF and GeoTIFF), the draft and UKC checks, and the
least depth along a route across the seam of a 360-degree chart."""

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.depth import apply_draft, depth_on_grid, least_depth, open_bathymetry


def _write(path, name, values, attrs, lat, lon):
    ds = xr.Dataset(
        {name: (("lat", "lon"), values, attrs)},
        coords={
            "lat": ("lat", lat, {"units": "degrees_north"}),
            "lon": ("lon", lon, {"units": "degrees_east"}),
        },
    )
    ds.to_netcdf(path)
    return path


def test_conventions_from_cf_attributes_guesses_said_and_bad_units(tmp_path):
    lat, lon = np.array([70.0, 71.0, 72.0]), np.array([10.0, 11.0, 12.0, 13.0])
    depth = np.array([[5.0, 10, 20, 40], [-3, 8, 16, 30], [1, 2, 4, 8]])
    cases = {
        "depth_down.nc": (
            "deptho",
            depth,
            {"standard_name": "sea_floor_depth_below_sea_surface", "units": "m"},
            1.0,
            "standard_name",
        ),
        "elev_up.nc": ("elevation", -depth, {"positive": "up", "units": "metres"}, 1.0, "positive"),
        "feet.nc": ("depth", depth / 0.3048, {"positive": "down", "units": "ft"}, 1.0, "positive"),
        "guess_z.nc": ("z", -depth, {}, 1.0, "ASSUMED elevation positive up"),
        "guess_depth.nc": ("depth", depth, {"units": "m"}, 1.0, "ASSUMED depth positive down"),
    }
    for fname, (name, values, attrs, _, how) in cases.items():
        b = open_bathymetry(_write(tmp_path / fname, name, values, attrs, lat, lon))
        np.testing.assert_allclose(b.depth.values, depth, atol=1e-9)
        assert how in b.convention, (fname, b.convention)
        assert bool(b.notes) == ("ASSUMED" in how) or fname == "guess_z.nc"
    z = open_bathymetry(tmp_path / "guess_z.nc")
    assert any(
        "ASSUMED elevation positive up (the ETOPO/GEBCO convention)" in n and "positive='down'" in n
        for n in z.notes
    )
    assert any("states no units: ASSUMED metres" in n for n in z.notes)
    flipped = open_bathymetry(tmp_path / "guess_z.nc", positive="down")
    np.testing.assert_allclose(flipped.depth.values, -depth)
    km = open_bathymetry(
        _write(tmp_path / "km.nc", "depth", depth / 1000, {"units": "km", "positive": "down"}, lat, lon)
    )
    np.testing.assert_allclose(km.depth.values, depth, atol=1e-9)
    bad = _write(tmp_path / "kg.nc", "depth", depth, {"units": "kg", "positive": "down"}, lat, lon)
    with pytest.raises(ValueError, match=r"kg.nc: depth is in 'kg'; depths must be a length"):
        open_bathymetry(bad)
    (tmp_path / "junk.nc").write_bytes(b"not a netcdf file at all")
    with pytest.raises(ValueError, match="junk.nc"):
        open_bathymetry(tmp_path / "junk.nc")
    far = open_bathymetry(_write(tmp_path / "far.nc", "depth", depth, {"positive": "down"}, lat, lon))
    with pytest.raises(ValueError, match="does not cover the chart"):
        depth_on_grid(far, lat=[50.0, 50.5], lon=[10.0, 11.0])
    with pytest.raises(ValueError, match="none.nc: no such bathymetry file"):
        open_bathymetry(tmp_path / "none.nc")
    proj = xr.Dataset({"h": (("y", "x"), depth)}, coords={"y": lat, "x": lon})
    proj.to_netcdf(tmp_path / "projected.nc")
    with pytest.raises(ValueError, match="needs 1-D lat and lon coordinates"):
        open_bathymetry(tmp_path / "projected.nc")


def test_geotiff_bathymetry_guess_and_override(tmp_path):
    rasterio = pytest.importorskip("rasterio")
    from affine import Affine

    depth = np.array([[5.0, 10, 20, 40], [-3, 8, 16, 30], [1, 2, 4, 8]], dtype="float32")
    path = tmp_path / "gebco_like.tif"
    with rasterio.open(
        path,
        "w",
        driver="GTiff",
        height=3,
        width=4,
        count=1,
        dtype="float32",
        crs="EPSG:4326",
        transform=Affine(1.0, 0.0, 9.5, 0.0, -1.0, 72.5),
    ) as dst:
        dst.write(-depth, 1)  # GEBCO GeoTIFF: elevation, no CF attributes
    b = open_bathymetry(path)
    assert "ASSUMED elevation positive up" in b.convention
    np.testing.assert_allclose(b.depth.sel(lat=[72.0, 71.0, 70.0]).values, depth)
    assert list(b.depth.lon.values) == [10.0, 11.0, 12.0, 13.0]
    assert np.allclose(open_bathymetry(path, positive="down").depth.sel(lat=[72.0, 71.0, 70.0]), -depth)


def test_draft_and_ukc_are_checked():
    cost, z = np.ones((2, 2)), np.full((2, 2), 20.0)
    with pytest.raises(ValueError, match="draft must be in metres"):
        apply_draft(cost, z, -1)
    with pytest.raises(ValueError, match="under-keel clearance"):
        apply_draft(cost, z, 10, ukc=float("nan"))
    with pytest.raises(ValueError, match="resample it onto the chart"):
        apply_draft(cost, np.ones((3, 3)), 10)
    out = apply_draft(cost, np.array([[20.0, 10.9], [11.0, np.nan]]), 10)  # need 11 m
    assert out.tolist() == [[1.0, np.inf], [1.0, np.inf]]


def test_least_depth_of_a_route_across_the_seam_of_a_360_degree_chart():
    """A route from 175 E to 175 W on a chart wrapping at +-180 crosses the seam in one step;
    the pixels sampled along it stay by the seam (they once swept the whole row)."""
    lat, lon = np.arange(79.5, 59.0, -1.0), np.arange(-179.5, 180.0, 1.0)
    cost = xr.DataArray(np.ones((lat.size, lon.size)), dims=("lat", "lon"), coords={"lat": lat, "lon": lon})
    z = cost.copy(data=np.where(np.abs(lon) > 170, 100.0, 1.0)[None, :].repeat(lat.size, 0))
    for r in (seaway.route(cost, (70.5, 175.5), (70.5, -175.5)),):
        for route in (r, r.smoothed()):
            assert route.length < 400  # across the seam, not round the world
            least, where = least_depth(route, z)
            assert least == 100.0 and abs(where[1]) > 170
            cols = route.sample_pixels()[:, 1] % lon.size
            assert np.all(np.abs(lon[cols]) > 170)
