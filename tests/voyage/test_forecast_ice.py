"""A coupled ice-ocean forecast prices a voyage's ice with its currents (issue: the voyage in
time, item 4): the forecast roles ice_concentration (CF sea_ice_area_fraction) and ice_thickness
(CF sea_ice_thickness), found by standard name or GRIB short name, hinted for CDO's GRIB code
numbers; by hand on a synthetic forecast, and on the real ROMS Arctic-20km file."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.vessel import load
from seaway.weather.files import unknown_fields_hint

KN = 1.852
ROMS = ("ocean_model", "metno_ROMS_Arctic20_1to5Feb_2016.nc")


def coupled(tmp_path, current=0.0, name="coupled.nc"):
    """A lat/lon forecast of two days: an eastward current of `current` m/s everywhere, ice of
    10/10 and 1.05 m between 66 and 70 E, open water elsewhere."""
    lat, lon = np.round(np.arange(70.05, 76, 0.1), 2), np.round(np.arange(60.05, 80, 0.1), 2)
    t = np.array(["2026-03-01T00", "2026-03-02T00"], dtype="datetime64[ns]")
    shape = (t.size, lat.size, lon.size)
    band = ((lon > 66) & (lon < 70))[None, None, :] & np.ones(shape, bool)
    dims = ("time", "lat", "lon")
    ds = xr.Dataset(
        {
            "uo": (
                dims,
                np.full(shape, current),
                {"standard_name": "eastward_sea_water_velocity", "units": "m s-1"},
            ),
            "vo": (
                dims,
                np.zeros(shape),
                {"standard_name": "northward_sea_water_velocity", "units": "m s-1"},
            ),
            "aice": (
                dims,
                np.where(band, 1.0, 0.0),
                {"standard_name": "sea_ice_area_fraction", "units": "1"},
            ),
            "hice": (dims, np.where(band, 1.05, 0.0), {"standard_name": "sea_ice_thickness", "units": "m"}),
        },
        coords={"time": t, "lat": lat, "lon": lon},
    )
    path = tmp_path / name
    ds.to_netcdf(path)
    return str(path)


def test_the_forecasts_own_ice_is_priced_by_the_ships_curve(tmp_path):
    """The Arc7 LNG carrier's curve in 10/10 of 1.05 m: 19.5 - 17.5 x 1.05 / 2.1 = 10.75 kn;
    open water at 19.5 kn; no current: the route along the parallel, its time by hand."""
    fc = seaway.open_forecast(coupled(tmp_path))
    assert any("ice_concentration" in n and "aice" in n for n in fc.notes)
    r = fc.route((73.05, 61.05), (73.05, 78.95), vessel=load("arc7-lng-carrier"), depart="2026-03-01T00:00")
    from seaway._core import haversine_km
    from seaway.base import sphere

    hours, c = 0.0, r.coords
    for a, b in zip(c[:-1], c[1:]):
        la, lo = sphere.intermediate(a[0], a[1], b[0], b[1], (np.arange(4000) + 0.5) / 4000)
        v = np.where((lo > 66) & (lo < 70), 10.75, 19.5)
        hours += haversine_km(*a, *b) * np.mean(1 / (v * KN))
    assert r.cost == pytest.approx(hours, rel=0.01)
    assert any(n.startswith("the forecast's own ice prices the voyage") for n in r.notes)
    assert any("the ship's ice curve (0 m 19.5 kn, 2.1 m 2 kn)" in n for n in r.notes)
    # the same forecast without its ice: open water all the way
    plain = xr.open_dataset(coupled(tmp_path, name="c2.nc")).drop_vars(["aice", "hice"])
    plain.to_netcdf(tmp_path / "plain.nc")
    calm = seaway.open_forecast(str(tmp_path / "plain.nc")).route(
        (73.05, 61.05), (73.05, 78.95), vessel=load("arc7-lng-carrier"), depart="2026-03-01T00:00"
    )
    assert calm.cost == pytest.approx(calm.length / (19.5 * KN), rel=0.01) and calm.cost < r.cost


def test_ice_and_currents_act_together(tmp_path):
    """A 1 m/s (1.944 kn) eastward current adds to the ship's speed through water, in the ice as
    in open water: the voyage east is quicker than without it."""
    still = seaway.open_forecast(coupled(tmp_path)).route(
        (73.05, 61.05), (73.05, 78.95), vessel=load("arc7-lng-carrier")
    )
    helped = seaway.open_forecast(coupled(tmp_path, current=1.0, name="fast.nc")).route(
        (73.05, 61.05), (73.05, 78.95), vessel=load("arc7-lng-carrier")
    )
    assert helped.cost < still.cost * 0.95


def test_grib_coded_ice_fields_get_a_hint():
    ds = xr.Dataset(
        {"var91": (("lat", "lon"), np.zeros((2, 2))), "var92": (("lat", "lon"), np.zeros((2, 2)))}
    )
    hint = unknown_fields_hint(ds)
    assert (
        "var91 = WMO table 2: ice cover (proportion)" in hint
        and "var92 = WMO table 2: ice thickness (m)" in hint
    )
    assert "--forecast-variable ice_concentration=var91 --forecast-variable ice_thickness=var92" in hint


@pytest.mark.needs_data(*ROMS)
def test_the_real_roms_forecast_prices_its_ice_with_its_currents(shared_data):
    """MET Norway's ROMS Arctic-20km, 1 February 2016: aice and hice with ubar/vbar. Into the ice
    east of Svalbard (78.5 N 28.4 E: nearly 10/10 of about 0.4 m) the Arc7 LNG carrier slows below its
    service speed on the last leg, and every leg has a finite time."""
    fc = seaway.open_forecast(str(shared_data.joinpath(*ROMS)))
    r = fc.route(
        (74.0, 20.0), (78.51, 28.4), vessel=load("arc7-lng-carrier"), depart="2016-02-01T12:00", smooth=False
    )
    legs = r.legs()
    assert all(np.isfinite(leg.time_h) and leg.speed_kn > 0 for leg in legs)
    assert min(leg.speed_kn for leg in legs) < 19.0
    assert any("its sea-ice concentration and thickness, frame by frame (5 frames)" in n for n in r.notes)
