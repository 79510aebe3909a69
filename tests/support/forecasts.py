"""A small CF forecast Dataset (moved from weather/test_weather.py; used by the weather, fuel,
models and zone tests)."""

import numpy as np
import xarray as xr


def forecast(shape=(21, 31), frames=1, lat0=60.0, lon0=0.0, step=0.1, hours=6, **fields):
    """A Dataset on a regular lat/lon grid with CF standard names; fields are arrays of shape
    (frames, rows, cols) or (rows, cols), or scalars."""
    lat = lat0 + step * np.arange(shape[0])
    lon = lon0 + step * np.arange(shape[1])
    time = np.datetime64("2026-01-01T00") + np.arange(frames) * np.timedelta64(hours, "h")
    names = {
        "ce": "eastward_sea_water_velocity",
        "cn": "northward_sea_water_velocity",
        "hs": "sea_surface_wave_significant_height",
        "wdir": "sea_surface_wave_from_direction",
        "wind": "wind_speed",
    }
    data = {}
    for key, value in fields.items():
        # float32 like the engine reads, so hand and brute-force values match it exactly
        a = np.broadcast_to(np.asarray(value, dtype=np.float32), (frames,) + shape).astype(float)
        data[key] = xr.DataArray(a, dims=("time", "lat", "lon"), attrs={"standard_name": names[key]})
    if not data:
        data["ce"] = xr.DataArray(
            np.zeros((frames,) + shape), dims=("time", "lat", "lon"), attrs={"standard_name": names["ce"]}
        )
        data["cn"] = data["ce"].copy()
        data["cn"].attrs["standard_name"] = names["cn"]
    return xr.Dataset(data, coords={"time": time, "lat": lat, "lon": lon})
