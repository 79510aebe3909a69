"""GRIB forecasts through cfgrib (the [grib] extra): a GRIB2 file written with ecCodes is read
with its valid times as the time axis, and routes through it exactly as through the same
forecast in memory."""

from __future__ import annotations

import functools

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.weather import Vessel, grib_times, read_forecast, route_time

#: The engine's steps: these tests hold them to brute force and to values by hand.
route_time = functools.partial(route_time, smooth=False)

eccodes = pytest.importorskip("eccodes")
pytest.importorskip("cfgrib")

LAT = np.arange(75.0, 69.9, -0.5)  # GRIB's usual north-to-south rows
LON = np.arange(20.0, 30.1, 0.5)
WIND = {0: 5.0, 6: 5.0, 12: 30.0}  # m/s east by lead time (h): above the 25 m/s limit at +12 h
VALID = np.array(["2016-02-01T12", "2016-02-01T18", "2016-02-02T00"], "datetime64[ns]")


def _write_grib(path):
    with open(path, "wb") as f:
        for step, east in WIND.items():
            for short, value in (("10u", east), ("10v", 0.0)):
                h = eccodes.codes_grib_new_from_samples("regular_ll_sfc_grib2")
                keys = dict(
                    Ni=LON.size,
                    Nj=LAT.size,
                    latitudeOfFirstGridPointInDegrees=75.0,
                    longitudeOfFirstGridPointInDegrees=20.0,
                    latitudeOfLastGridPointInDegrees=70.0,
                    longitudeOfLastGridPointInDegrees=30.0,
                    iDirectionIncrementInDegrees=0.5,
                    jDirectionIncrementInDegrees=0.5,
                    dataDate=20160201,
                    dataTime=1200,
                    stepRange=str(step),
                    shortName=short,
                )
                for k, v in keys.items():
                    eccodes.codes_set(h, k, v)
                eccodes.codes_set_values(h, np.full(LAT.size * LON.size, value))
                eccodes.codes_write(h, f)
                eccodes.codes_release(h)


def _in_memory():
    shape = (len(WIND), LAT.size, LON.size)
    east = np.broadcast_to(np.array(list(WIND.values()))[:, None, None], shape)
    return xr.Dataset(
        {
            "u10": (("time", "lat", "lon"), east, {"standard_name": "eastward_wind"}),
            "v10": (("time", "lat", "lon"), np.zeros(shape), {"standard_name": "northward_wind"}),
        },
        coords={"time": VALID, "lat": LAT, "lon": LON},
    )


def test_grib_forecast_reads_valid_times_and_routes_as_the_same_forecast_in_memory(tmp_path):
    path = tmp_path / "wind.grib2"
    _write_grib(path)
    fc = read_forecast(path)
    assert fc["time"].values.tolist() == VALID.tolist()  # valid times, not lead times
    assert float(fc["u10"].isel(time=2).max()) == 30.0 and float(fc["u10"].isel(time=1).max()) == 5.0
    vessel = Vessel(speed_kn=12, displacement_t=15000)
    # 71 N 21 E -> 72 N 24 E takes about 6 h: arrives before the wind passes 25 m/s (22:48).
    short = route_time(fc, (71.0, 21.0), (72.0, 24.0), vessel=vessel)
    twin = route_time(_in_memory(), (71.0, 21.0), (72.0, 24.0), vessel=vessel)
    assert short.cost == pytest.approx(twin.cost, rel=1e-12) and short.cost < 10.8
    assert short.pixels.tolist() == twin.pixels.tolist()
    assert short.stats.voyage.arrival == twin.stats.voyage.arrival == np.datetime64("2016-02-01T19:28:19")
    # 71 N 21 E -> 74.5 N 29.5 E takes about 20 h: the wind closes the whole chart before then.
    for forecast in (fc, _in_memory()):
        with pytest.raises(seaway.NoRouteError):
            route_time(forecast, (71.0, 21.0), (74.5, 29.5), vessel=vessel)


def test_grib_with_several_analyses_is_refused():
    two = xr.Dataset(
        {"u10": (("time", "step", "lat"), np.zeros((2, 3, 4)))},
        coords={
            "time": VALID[:2],
            "step": np.arange(3) * np.timedelta64(6, "h"),
            "valid_time": (("time", "step"), np.zeros((2, 3), "datetime64[ns]")),
        },
    )
    with pytest.raises(ValueError, match=r"holds 2 analyses of 3 steps; route on one: .*isel\(time=0\)"):
        grib_times(two, "gfs.grib2")
