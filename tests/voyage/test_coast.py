"""Routes off the real coast (issue: answers a navigator can check, item 3): a finer coastline
merged with an ice chart's land (open_chart(land=...), --land FILE), by default the package's
(GLOBE) where the chart's pixels are coarser; a route sampled every 0.01 deg along its legs (the
great circles between its waypoints) stays off that land, but within a pixel of an end placed on
it. On the synthetic AARI-style February
chart of the NSR (its own coastline is coarse) and the GSHHG full-resolution land mask."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.vessel import load
from support import aari_winter
from support.data import SHARED_DATA

GSHHG = ("land", "gshhg_f_landmask_1arcmin_60N.nc")
KARA_GATE, VILKITSKY, SABETTA = (70.4, 58.6), (77.7, 104.0), (71.27, 72.07)


@pytest.fixture(scope="module")
def chart(tmp_path_factory):
    path = tmp_path_factory.mktemp("aari") / "aari_winter.shp"
    aari_winter.write(path)
    return str(path)


def samples(route, step=0.01):
    """Points every `step` degrees or less along each leg, as the ship sails it: the great circle
    between its waypoints (pyproj's Geod: the orthodrome the RTZ names)."""
    import pyproj

    geod = pyproj.Geod(ellps="WGS84")
    c = np.asarray(route.coords, float)
    pts = [c[:1]]
    for a, b in zip(c[:-1], c[1:]):
        lon_span = abs((b[1] - a[1] + 180.0) % 360.0 - 180.0)
        n = max(int(np.ceil(max(abs(b[0] - a[0]), lon_span) / step)), 1)
        mid = (
            np.array(geod.npts(a[1], a[0], b[1], b[0], n - 1)).reshape(-1, 2)[:, ::-1]
            if n > 1
            else np.zeros((0, 2))
        )
        pts += [mid, b[None]]
    return np.concatenate(pts)


def off_land(route, is_land, pixel_deg):
    """Points of the route on land that are farther than a pixel from both ends."""
    p = samples(route)
    ends = np.asarray(route.coords, float)[[0, -1]]
    near = np.min(np.abs(p[:, None, :] - ends[None]).max(axis=2), axis=1) <= pixel_deg * 1.5
    lon = (p[:, 1] + 180.0) % 360.0 - 180.0
    return p[is_land(p[:, 0], lon) & ~near]


def test_the_packages_coastline_by_default(chart):
    from global_land_mask import globe

    opened = seaway.open_chart(chart, vessel="Arc7", ends=(KARA_GATE, VILKITSKY))
    said = [n for n in opened.notes if n.startswith("land: ")]
    assert said and "the package's coastline (global-land-mask: GLOBE, 30 arc-seconds)" in said[0]
    assert "straits narrower than about two pixels" in said[0]
    r = opened.route(KARA_GATE, VILKITSKY, vessel=load("arc7-lng-carrier"), snap_km=30)
    assert any(n.startswith("land: the chart's own and the package's coastline") for n in r.notes)
    bad = off_land(r, globe.is_land, 0.1)
    assert len(bad) == 0, bad[:5]


@pytest.mark.needs_data(*GSHHG)
def test_a_land_mask_file_keeps_the_route_off_its_land(chart):
    land = xr.open_dataset(SHARED_DATA.joinpath(*GSHHG))["land"].load()
    lat, lon = land.lat.values, land.lon.values
    grid = land.values != 0

    def is_land(la, lo):
        i = np.clip(np.searchsorted(lat, la), 0, lat.size - 1)
        j = np.clip(np.searchsorted(lon, lo), 0, lon.size - 1)
        return grid[i, j]

    for a, b in ((SABETTA, (66.1, -169.5)), (KARA_GATE, VILKITSKY)):
        opened = seaway.open_chart(chart, ends=(a, b), land=str(SHARED_DATA.joinpath(*GSHHG)))
        assert any("gshhg_f_landmask_1arcmin_60N.nc (a land mask of 1.9 km)" in n for n in opened.notes)
        r = opened.route(a, b, vessel=load("arc7-lng-carrier"), snap_km=30)
        bad = off_land(r, is_land, 0.1)
        assert len(bad) == 0, bad[:5]


def test_the_charts_own_land_when_asked_and_a_coarse_chart_says_so(chart, tmp_path):
    own = seaway.open_chart(chart, ends=(KARA_GATE, VILKITSKY), land="chart")
    assert not any(n.startswith("land: ") for n in own.notes)
    merged = seaway.open_chart(chart, ends=(KARA_GATE, VILKITSKY))
    assert int(merged.land.values.sum()) > int(own.land.values.sum())
    # a 25 km chart: the coastline is not merged (it would close straits under 50 km); said
    lat, lon = np.arange(68.0, 80.0, 0.25), np.arange(50.0, 110.0, 0.75)
    ct = xr.DataArray(np.zeros((lat.size, lon.size)), coords={"lat": lat, "lon": lon}, dims=("lat", "lon"))
    xr.Dataset({"cost": ct + 1.0}).to_netcdf(tmp_path / "coarse.nc")
    coarse = seaway.open_chart(str(tmp_path / "coarse.nc"))
    assert any("a route may cross land finer than that (not merged" in n for n in coarse.notes)
