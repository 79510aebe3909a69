"""A small CF forecast Dataset (moved from weather/test_weather.py; used by the weather, fuel,
models and zone tests)."""

import numpy as np
import xarray as xr


def forecast(
    shape=(21, 31), frames=1, lat0=60.0, lon0=0.0, step=0.1, hours=6, lat=None, lon=None, start=None, **fields
):
    """A Dataset on a regular lat/lon grid with CF standard names (the grid from shape, lat0,
    lon0 and step, or the axes lat and lon); frames every `hours` from `start` (default
    2026-01-01); fields are arrays of shape (frames, rows, cols) or (rows, cols), or scalars."""
    lat = lat0 + step * np.arange(shape[0]) if lat is None else np.asarray(lat)
    lon = lon0 + step * np.arange(shape[1]) if lon is None else np.asarray(lon)
    shape = (lat.size, lon.size)
    start = np.datetime64("2026-01-01T00") if start is None else start
    time = start + np.arange(frames) * np.timedelta64(hours, "h")
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
