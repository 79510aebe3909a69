"""Small NetCDF inputs for the bad-file tests: a 41 x 51 lat/lon cost chart with a wall, and a
copy of it cut short (moved from test_bad_files.py)."""

import numpy as np
import xarray as xr


def small_dataset():
    lat, lon = np.linspace(70.0, 74.0, 41), np.linspace(60.0, 70.0, 51)
    cost = np.full((41, 51), 2.0)
    cost[10:30, 20:25] = np.inf
    return xr.Dataset(
        {
            "cost": (("lat", "lon"), cost),
            "wave_height": (
                ("lat", "lon"),
                np.ones((41, 51)),
                {"standard_name": "sea_surface_wave_significant_height"},
            ),
        },
        coords={"lat": lat, "lon": lon},
    )


def truncated_netcdf(tmp_path, fmt, keep):
    good = tmp_path / f"good-{fmt}.nc"
    small_dataset().to_netcdf(good, format=fmt)
    data = good.read_bytes()
    bad = tmp_path / f"cut-{fmt}.nc"
    bad.write_bytes(data[: int(len(data) * keep)])
    return bad, len(data)
