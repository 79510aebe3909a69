"""The CF tables are read once, from the ecosystem: which coordinate is latitude, longitude, y or
x by cf_xarray's criteria; the CRS of a grid mapping by one reader (pyproj) for charts and
forecasts alike; a wrong grid mapping refused naming the fix."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from seaway.chart.cf import coord_role, grid_mapping_crs

pyproj = pytest.importorskip("pyproj")


@pytest.mark.parametrize(
    ("name", "attrs", "role"),
    [
        ("nav_y", {"_CoordinateAxisType": "Lat"}, "lat"),  # THREDDS/NcML's attribute
        ("phi", {"units": "degreesN"}, "lat"),
        ("lambda", {"units": "degree_E"}, "lon"),
        ("j", {"standard_name": "projection_y_coordinate"}, "y"),
        ("i", {"axis": "X"}, "x"),
        ("latitude", {}, "lat"),  # no attributes: its name
        ("depth", {"units": "m"}, None),
    ],
)
def test_coordinate_roles_are_cf_xarrays_criteria(name, attrs, role):
    assert coord_role(name, attrs) == role


def _stereo(attrs):
    ds = xr.Dataset({"ice": (("y", "x"), np.zeros((2, 2)), {"grid_mapping": "crs"})})
    return ds.assign(crs=xr.DataArray(0, attrs=attrs))


def test_one_crs_reader_for_charts_and_forecasts():
    want = pyproj.CRS.from_epsg(3413)
    cf = want.to_cf()
    for attrs, source in (
        ({"crs_wkt": want.to_wkt()}, "crs.crs_wkt"),
        (
            {"proj4_string": "+proj=stere +lat_0=90 +lat_ts=70 +lon_0=-45 +datum=WGS84 +units=m"},
            "crs.proj4_string",
        ),
        ({k: v for k, v in cf.items() if k not in ("crs_wkt", "spatial_ref")}, "crs (CF parameters)"),
    ):
        crs, said = grid_mapping_crs(_stereo(attrs), "crs", "ice")
        assert said == source
        t = pyproj.Transformer.from_crs(crs, want, always_xy=True)
        assert np.allclose(t.transform(100_000.0, -200_000.0), (100_000.0, -200_000.0), atol=1e-3)
    with pytest.raises(ValueError, match="ice names the grid mapping 'polar', which the file does not have"):
        grid_mapping_crs(_stereo({}), "polar", "ice")
    with pytest.raises(
        ValueError, match=r"cannot read the projection of ice from its grid mapping 'crs'.*crs_wkt"
    ):
        grid_mapping_crs(_stereo({"grid_mapping_name": "no_such_projection"}), "crs", "ice")


def test_one_table_of_forecast_roles_names_every_reader_and_hint():
    from seaway.chart.roles import ALIASES, CDO_CODES, GRIB_NAMES, ROLES, STANDARD_NAMES
    from seaway.weather.forecast import check_roles

    assert set(STANDARD_NAMES) == set(GRIB_NAMES) == set(ROLES)
    assert GRIB_NAMES["wave_height"] == ("swh", "htsgw") and CDO_CODES["var229"][0] == "wave_height"
    assert {r for r, _ in CDO_CODES.values()} - {None} <= set(ROLES) and set(ALIASES.values()) <= set(ROLES)
    with pytest.raises(ValueError, match=r"unknown forecast role 'hs' \(did you mean wave_height\?\)"):
        check_roles({"hs": "VHM0"})
