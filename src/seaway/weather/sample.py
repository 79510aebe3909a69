"""A synthetic autumn voyage in the Kara Sea (for examples and tests, never for navigation):
daily ice charts and a gale forecast on one lat/lon region."""

from __future__ import annotations

import numpy as np
import xarray as xr

from ..samples import kara_season


def kara_autumn(days=3, start="2026-10-01", shape=(190, 230)):
    """(ice, forecast), both synthetic. ice: `days` daily charts of seaway.samples.kara_season
    (its late-winter ice thinned by 0.8 m, a season Dataset: CT, SA, thickness, land) from
    `start`. forecast: a westerly gale, CF standard names, every 6 h over the same days on a
    0.5-degree grid (68-82 N, 50-110 E): significant wave height rising from 1 m to 5.5 m in the
    south-west (the Kara Gate) by the last day, waves from the west veering north-west, mean
    period 4 s + 1.5 s per metre, wind east up to 20 m/s, and a 0.3 m/s eastward coastal current."""
    ice = kara_season(days=days, start=start, melted_m=0.8, melt_m_per_day=0.0, shape=shape)
    lat, lon = np.arange(68.0, 82.01, 0.5), np.arange(50.0, 110.01, 0.5)
    times = np.datetime64(start, "ns") + np.arange(4 * days + 1) * np.timedelta64(6, "h")
    t = (np.arange(times.size) / (times.size - 1))[:, None, None]
    la, lo = np.meshgrid(lat, lon, indexing="ij")
    west = np.clip(1.0 - ((la - 68.0) / 14.0 + (lo - 50.0) / 60.0), 0.0, 1.0)[None]
    hs = 1.0 + 4.5 * t * west
    coastal = np.exp(-(((la - 72.0) / 2.0) ** 2))[None]
    fields = {
        "hs": (hs, "sea_surface_wave_significant_height", "m"),
        "wdir": (270.0 + 45.0 * t + 0 * hs, "sea_surface_wave_from_direction", "degree"),
        "tm": (4.0 + 1.5 * hs, "sea_surface_wave_mean_period", "s"),
        "u10": (6.0 + 14.0 * t * west, "eastward_wind", "m s-1"),
        "v10": (0 * hs - 2.0, "northward_wind", "m s-1"),
        "uo": (0.3 * coastal + 0 * hs, "eastward_sea_water_velocity", "m s-1"),
        "vo": (0 * hs, "northward_sea_water_velocity", "m s-1"),
    }
    forecast = xr.Dataset(
        {
            k: (("time", "lat", "lon"), v.astype(np.float32), {"standard_name": n, "units": u})
            for k, (v, n, u) in fields.items()
        },
        coords={"time": times, "lat": lat, "lon": lon},
        attrs={"title": "synthetic Kara Sea autumn gale (seaway.weather.kara_autumn)"},
    )
    return ice, forecast
