"""Forecast files as they come: one file per variable, CF NetCDF with or without standard names,
NetCDF that CDO converted from GRIB (variables named var229, an absolute time axis "day as
%Y%m%d.%f"), GRIB through cfgrib (the [grib] extra); merged into one Dataset whose fields the
weather models find by role.

* Roles (ROLES): found by CF standard name (STANDARD_NAMES; grid-relative x/y components,
  GRID_VECTORS, are kept for rotation: seaway.weather.roles), then by GRIB short name
  (GRIB_NAMES: swh, mwd, mwp, u10, v10, uo, vo, ...), or given as {role: variable}; an unknown
  role is refused naming the valid ones, and a file whose variables are only GRIB code numbers
  (CDO's varNNN) is refused naming the flags that map them.
* Time (decode_time): CF "UNIT since DATE" in the standard calendars, CDO's absolute "day as
  %Y%m%d.%f", and cfgrib's lead times (`step` with `valid_time`) become a datetime64 `time`
  axis; anything else is refused naming the time variable and how to fix it.
* Several files are merged on time: on the span they share, every `step` hours (the finest
  step of the files), linearly in time as the engine reads frames; on the first file's grid."""

from __future__ import annotations

import re
import warnings

import numpy as np
import xarray as xr

from ..chart.roles import CDO_CODES
from ..errors import ForecastError
from .forecast import ROLES, check_roles, grib_times, read_forecast
from .projected import on_grid  # noqa: F401 - its old home; seaway.weather.projected now
from .roles import as_roles, pick

_CDO_ABSOLUTE = re.compile(r"^\s*day\s+as\s+%Y%m%d(\.%f)?\s*$")


def unknown_fields_hint(ds) -> str:
    """A sentence naming the --forecast-variable flags for CDO's varNNN names, or ''."""
    codes = [n for n in map(str, ds.data_vars) if n in CDO_CODES]
    if not codes:
        return ""
    flags = " ".join(f"--forecast-variable {CDO_CODES[n][0]}={n}" for n in codes if CDO_CODES[n][0])
    meaning = "; ".join(f"{n} = {CDO_CODES[n][1]}" for n in codes)
    return (
        f"; its variables look like GRIB code numbers written by CDO ({meaning}; a code number alone "
        f"does not say which table it is from): if they are, map them with {flags or 'no role'} "
        f"(variables={{role: name}} in the API)"
    )


def _time_name(ds) -> str | None:
    for name, c in ds.coords.items():
        if name == "time" or c.attrs.get("axis") == "T" or c.attrs.get("standard_name") == "time":
            return str(name)
    return None


def decode_time(ds: xr.Dataset, source: str = "the forecast") -> xr.Dataset:
    """`ds` with its time axis as datetime64 values in a dimension named `time` (see the
    module docstring); a forecast without a time axis is returned unchanged."""
    if "step" in ds.dims and "valid_time" in ds.coords:  # cfgrib: one run's frames along step
        ds = grib_times(ds, source)
    name = _time_name(ds)
    if name is None:
        return ds
    t = ds[name]
    if not np.issubdtype(t.dtype, np.datetime64):
        ds = ds.assign_coords({name: (t.dims, _decode(t, source), _kept(t.attrs))})
    if name != "time":
        ds = ds.rename({name: "time"})
    if "time" not in ds.dims and ds["time"].ndim == 0:
        ds = ds.expand_dims("time")
    if ds["time"].ndim != 1:
        raise ForecastError(f"{source}: its time variable {name!r} is not one axis ({ds['time'].dims})")
    return ds


def _kept(attrs):
    return {k: v for k, v in attrs.items() if k not in ("units", "calendar")}


def _decode(t, source) -> np.ndarray:
    units = str(t.attrs.get("units", t.encoding.get("units", "")))
    calendar = str(t.attrs.get("calendar", "standard")).lower()
    fix = (
        f"give it CF units such as 'hours since 2026-09-15 00:00:00' (e.g. cdo -r setreftime or "
        f"ncatted -a units,{t.name},o,c,'hours since ...')"
    )
    if calendar not in ("standard", "gregorian", "proleptic_gregorian"):
        raise ForecastError(
            f"{source}: its time variable {t.name!r} is in the {calendar!r} calendar; "
            "seaway needs real dates (standard or proleptic_gregorian calendar)"
        )
    values = np.asarray(t.values)
    if _CDO_ABSOLUTE.match(units):  # CDO's absolute axis: YYYYMMDD plus the fraction of the day
        v = values.astype(np.float64)
        if not np.all(np.isfinite(v)):
            raise ForecastError(f"{source}: its time variable {t.name!r} has missing values")
        day = np.floor(v).astype(np.int64)
        try:
            dates = np.array(
                [np.datetime64(f"{d // 10000:04d}-{d // 100 % 100:02d}-{d % 100:02d}") for d in day.ravel()],
                "datetime64[s]",
            ).reshape(day.shape)
        except ValueError:
            raise ForecastError(
                f"{source}: its time variable {t.name!r} ({units!r}) holds "
                f"{v.ravel()[0]!r}, not a date YYYYMMDD.fraction; {fix}"
            ) from None
        seconds = np.round((v - day) * 86400.0).astype(np.int64)
        return (dates + seconds.astype("timedelta64[s]")).astype("datetime64[ns]")
    if " since " in units:
        try:
            out = xr.coding.times.decode_cf_datetime(values, units, calendar)
        except Exception as exc:  # xarray raises several types for unparsable units
            raise ForecastError(
                f"{source}: cannot decode its time variable {t.name!r} ({units!r}: {exc}); {fix}"
            ) from None
        if np.issubdtype(np.asarray(out).dtype, np.datetime64):
            return np.asarray(out, "datetime64[ns]")
    raise ForecastError(f"{source}: cannot decode its time variable {t.name!r} (units {units!r}): {fix}")


def read_forecasts(paths, variables: dict | None = None) -> tuple[xr.Dataset, list[str]]:
    """(one forecast Dataset, notes) from one or more files (NetCDF or GRIB): times decoded,
    the fields renamed to their roles, the files merged on time (module docstring). `variables`
    maps roles to variable names in any of the files. Notes say which variable plays each role
    and how the files were merged."""
    paths = [
        str(p)
        for p in ([paths] if isinstance(paths, (str, bytes)) or hasattr(paths, "__fspath__") else paths)
    ]
    if not paths:
        raise ForecastError("give at least one forecast file")
    wanted = check_roles(variables)
    parts, notes, found = [], [], {}
    for path in paths:
        ds = decode_time(_open_grib(path) if _grib(path) else read_forecast(path, decode_times=False), path)
        fields = pick(ds, wanted, found)
        if not fields:
            raise ForecastError(
                f"{path}: no forecast field seaway knows (variables "
                f"{sorted(map(str, ds.data_vars))}); mark them with CF standard names "
                "or map them to roles with --forecast-variable ROLE=NAME (roles: "
                f"{', '.join(ROLES)}){unknown_fields_hint(ds)}"
            )
        for role, (name, how) in fields.items():
            found[role] = name
            notes.append(f"forecast {role} = {path}:{name} ({how})")
        part = as_roles(ds, fields, path, notes)
        parts.append((path, part))
    missing = {r: n for r, n in wanted.items() if r not in found}
    if missing:
        role, name = next(iter(missing.items()))
        raise ForecastError(
            f"no forecast file has a variable {name!r} for {role}; the files have "
            + "; ".join(f"{p}: {sorted(map(str, d.data_vars))}" for p, d in parts)
        )
    return _merge(parts, notes), notes


def _open_grib(path: str) -> xr.Dataset:
    """A GRIB file through cfgrib, its messages of every level merged (a forecast file often
    holds waves at the surface and winds at 10 m); no index file is written beside it."""
    try:
        import cfgrib
    except ImportError:
        raise ImportError(
            f'{path}: reading GRIB needs cfgrib: pip install "seaway[grib]" (cfgrib and eccodes)'
        ) from None
    try:
        with warnings.catch_warnings():  # cfgrib's own merge warns of xarray's coming defaults
            warnings.simplefilter("ignore", FutureWarning)
            parts = cfgrib.open_datasets(path, backend_kwargs={"indexpath": ""})
    except Exception as exc:  # eccodes and cfgrib raise many types
        raise ForecastError(f"{path}: cannot read it as GRIB ({exc})") from None
    if not parts:
        raise ForecastError(f"{path}: the GRIB file holds no field")
    keep = {"time", "step", "valid_time"}
    parts = [d.drop_vars([c for c in d.coords if c not in d.dims and c not in keep]) for d in parts]
    return xr.merge(parts, compat="override", join="outer")


def _grib(path: str) -> bool:
    return path.lower().endswith((".grib", ".grib2", ".grb", ".grb2"))


def _span(ds):
    t = ds["time"].values
    return t[0], t[-1], (np.min(np.diff(t)) if t.size > 1 else None)


def _merge(parts, notes) -> xr.Dataset:
    if len(parts) == 1:
        return parts[0][1]
    first = parts[0][1]
    timed = [(p, d) for p, d in parts if "time" in d.dims and d.sizes["time"] > 1]
    axis = None
    if timed:
        spans = [_span(d) for _, d in timed]
        start, stop = max(s[0] for s in spans), min(s[1] for s in spans)
        if start > stop:
            raise ForecastError(
                "the forecast files share no time: "
                + "; ".join(f"{p}: {s[0]} to {s[1]}" for (p, _), s in zip(timed, spans))
            )
        step = min(s[2] for s in spans)
        axis = np.arange(start, stop + step // 2, step)
        if any(d.sizes["time"] != axis.size or not np.array_equal(d["time"].values, axis) for _, d in timed):
            notes.append(
                f"forecast files merged on their common span {start} to {stop}, every "
                f"{step / np.timedelta64(1, 'h'):g} h (linear in time)"
            )
    out = []
    for path, d in parts:
        if "time" in d.dims and d.sizes["time"] == 1:
            d = d.isel(time=0, drop=True)
        if axis is not None and "time" in d.dims:
            d = d.interp(time=axis)
        grid = [
            c for c in ("lat", "lon", "latitude", "longitude", "y", "x") if c in first.dims and c in d.dims
        ]
        if any(not np.array_equal(d[c].values, first[c].values) for c in grid):
            d = d.interp({c: first[c] for c in grid})
            notes.append(f"{path}: resampled onto the grid of {parts[0][0]} (linear)")
        out.append(d.drop_vars([c for c in d.coords if c not in d.dims and c != "time"], errors="ignore"))
    return xr.merge(out, compat="override", join="exact")
