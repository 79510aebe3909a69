"""Forecast files written the way real ones are (no real wave forecast is in ../shared/data):
NetCDF as CDO writes it converting ECMWF GRIB (var229/var230/var232, an absolute time axis
"day as %Y%m%d.%f", no standard names), CF NetCDF with standard names one variable per file,
and GRIB2 written with ecCodes (the [grib] extra) for cfgrib. All share one synthetic autumn
gale over the Barents Sea: a westerly sea rising in the south-west over three days."""

from __future__ import annotations

import numpy as np
import xarray as xr

LAT = np.arange(74.0, 69.99, -0.25)  # north first, as GRIB and CDO write it
LON = np.arange(20.0, 30.01, 0.25)
T0 = np.datetime64("2026-10-01T00:00", "ns")
STEP_H = 6
FRAMES = 13  # three days, 6-hourly


def gale():
    """The fields (frames, lat, lon) of the synthetic gale: significant height (m), the
    direction the waves come from (deg), mean period (s), wind east/north (m/s), currents
    east/north (m/s), and the valid times."""
    t = np.arange(FRAMES)[:, None, None] / (FRAMES - 1)
    la, lo = np.meshgrid(LAT, LON, indexing="ij")
    south_west = np.clip(((74.0 - la) / 4.0 + (30.0 - lo) / 10.0) / 2.0, 0, 1)[None]
    hs = (0.5 + 4.0 * t * south_west).astype(np.float32)  # up to 4.5 m
    wdir = np.full(hs.shape, 270.0, np.float32) + (20.0 * t).astype(np.float32)
    per = (4.0 + 1.5 * hs).astype(np.float32)
    wind_e = (6.0 + 12.0 * t * south_west).astype(np.float32) + np.zeros(hs.shape, np.float32)
    wind_n = np.full(hs.shape, 1.0, np.float32)
    cur_e = np.full(hs.shape, 0.3, np.float32) * np.cos(np.radians(la))[None].astype(np.float32)
    cur_n = np.full(hs.shape, 0.1, np.float32)
    times = T0 + np.arange(FRAMES) * np.timedelta64(STEP_H, "h")
    return dict(
        hs=hs, wdir=wdir, per=per, wind_e=wind_e, wind_n=wind_n, cur_e=cur_e, cur_n=cur_n, times=times
    )


def in_memory(keys=("hs", "wdir", "per", "wind_e", "wind_n", "cur_e", "cur_n")):
    """The gale as a CF Dataset with standard names (the twin the files are checked against)."""
    g = gale()
    names = {
        "hs": "sea_surface_wave_significant_height",
        "wdir": "sea_surface_wave_from_direction",
        "per": "sea_surface_wave_mean_period",
        "wind_e": "eastward_wind",
        "wind_n": "northward_wind",
        "cur_e": "eastward_sea_water_velocity",
        "cur_n": "northward_sea_water_velocity",
    }
    return xr.Dataset(
        {k: (("time", "lat", "lon"), g[k], {"standard_name": names[k]}) for k in keys},
        coords={"time": g["times"], "lat": LAT, "lon": LON},
    )


def write_cdo_waves(path):
    """ECMWF wave fields as `cdo -f nc copy` writes them: var229 (Hs), var230 (mean direction),
    var232 (mean period) with code/table attributes and no standard names, on lon/lat, and the
    absolute time axis 'day as %Y%m%d.%f' (cdo -a)."""
    g = gale()
    day = g["times"].astype("datetime64[D]")
    frac = (g["times"] - day) / np.timedelta64(1, "D")
    ymd = np.array([int(str(d).replace("-", "")) for d in day], float) + frac
    data = {
        f"var{code}": (("time", "lat", "lon"), g[key], {"table": np.int32(140), "code": np.int32(code)})
        for code, key in ((229, "hs"), (230, "wdir"), (232, "per"))
    }
    ds = xr.Dataset(
        data,
        coords={
            "time": (
                "time",
                ymd,
                {
                    "standard_name": "time",
                    "units": "day as %Y%m%d.%f",
                    "calendar": "proleptic_gregorian",
                    "axis": "T",
                },
            ),
            "lat": (
                "lat",
                LAT,
                {"standard_name": "latitude", "long_name": "latitude", "units": "degrees_north", "axis": "Y"},
            ),
            "lon": (
                "lon",
                LON,
                {
                    "standard_name": "longitude",
                    "long_name": "longitude",
                    "units": "degrees_east",
                    "axis": "X",
                },
            ),
        },
        attrs={
            "CDI": "Climate Data Interface version 2.0.5",
            "Conventions": "CF-1.6",
            "history": "cdo -a -f nc copy waves.grib waves.nc",
            "CDO": "Climate Data Operators version 2.0.5",
        },
    )
    ds.to_netcdf(path, encoding={"time": {"dtype": "float64"}})
    return path


def write_cf_per_variable(folder, step_h=STEP_H):
    """One CF NetCDF file per variable pair (waves, winds, currents), with standard names and
    'hours since' time units; the currents file every `step_h` hours."""
    full = in_memory()
    paths = []
    for name, keys in (
        ("waves", ["hs", "wdir", "per"]),
        ("winds", ["wind_e", "wind_n"]),
        ("currents", ["cur_e", "cur_n"]),
    ):
        ds = full[keys]
        if name == "currents" and step_h != STEP_H:
            ds = ds.isel(time=slice(None, None, step_h // STEP_H))
        path = folder / f"{name}.nc"
        ds.to_netcdf(path, encoding={"time": {"units": "hours since 2026-10-01 00:00:00"}})
        paths.append(path)
    return paths


def write_grib(path, eccodes):
    """The gale's waves (swh, mwd, mwp at the surface) and 10 m winds (10u, 10v) as one GRIB2
    file of one ECMWF run: a message per field and lead time."""
    g = gale()
    with open(path, "wb") as f:
        for k in range(FRAMES):
            for short, key in (
                ("swh", "hs"),
                ("mwd", "wdir"),
                ("mwp", "per"),
                ("10u", "wind_e"),
                ("10v", "wind_n"),
            ):
                h = eccodes.codes_grib_new_from_samples("regular_ll_sfc_grib2")
                for name, value in dict(
                    Ni=LON.size,
                    Nj=LAT.size,
                    latitudeOfFirstGridPointInDegrees=float(LAT[0]),
                    longitudeOfFirstGridPointInDegrees=float(LON[0]),
                    latitudeOfLastGridPointInDegrees=float(LAT[-1]),
                    longitudeOfLastGridPointInDegrees=float(LON[-1]),
                    iDirectionIncrementInDegrees=0.25,
                    jDirectionIncrementInDegrees=0.25,
                    dataDate=20261001,
                    dataTime=0,
                    stepRange=str(k * STEP_H),
                    shortName=short,
                ).items():
                    eccodes.codes_set(h, name, value)
                eccodes.codes_set_values(h, g[key][k].astype(np.float64).ravel())
                eccodes.codes_write(h, f)
                eccodes.codes_release(h)
    return path
