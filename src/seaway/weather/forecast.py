"""Forecasts in: finding fields by CF standard name, opening files, and moving a forecast from
a projected model grid (e.g. polar stereographic ROMS) onto the regular lat/lon grid that
time routing works on, with vector components turned to east/north."""

from __future__ import annotations

import difflib

import numpy as np
import xarray as xr

from ..base.files import open_netcdf
from ..base.units import metres_per
from ..chart.cf import GRID_VECTORS, grid_mapping_crs  # noqa: F401 - part of this API
from ..chart.roles import ALIASES, GRIB_NAMES, ROLES, STANDARD_NAMES  # noqa: F401 - part of this API
from ..errors import ForecastError


def check_roles(variables: dict | None) -> dict:
    """`variables` ({role: variable name}) with every role checked; an unknown role raises
    ValueError naming the roles (and the closest one)."""
    out = dict(variables or {})
    for role in out:
        if role not in ROLES:
            near = ALIASES.get(str(role).lower()) or next(
                iter(difflib.get_close_matches(str(role), ROLES, n=1)), None
            )
            hint = f" (did you mean {near}?)" if near else ""
            raise ForecastError(f"unknown forecast role {role!r}{hint}; the roles are {', '.join(ROLES)}")
    return out


def role_of(var) -> tuple[str, str] | None:
    """(role, how it was found) of a forecast variable by its standard name or GRIB short name."""
    std = var.attrs.get("standard_name")
    for role, names in STANDARD_NAMES.items():
        if std in names:
            return role, f"standard name {std}"
    short = str(var.attrs.get("GRIB_shortName") or var.name).lower()
    for role, names in GRIB_NAMES.items():
        if short in names:
            return role, f"GRIB short name {short}"
    return None


def find_fields(ds, variables: dict | None = None) -> dict:
    """The forecast's fields by role ('current_east', 'wave_height', ...): named explicitly in
    `variables` (role -> variable name; an unknown role or variable raises ValueError naming the
    valid ones), else found by CF standard name, else by GRIB short name (GRIB_NAMES)."""
    variables = check_roles(variables)
    out = {}
    for role, name in variables.items():
        if name not in ds:
            raise ForecastError(
                f"the forecast has no variable {name!r} for {role}; it has {sorted(map(str, ds.data_vars))}"
            )
        out[role] = ds[name]
    for var in ds.data_vars.values():
        hit = role_of(var)
        if hit and hit[0] not in out and hit[0] not in variables:
            out[hit[0]] = var
    if ("current_east" in out) != ("current_north" in out):
        raise ForecastError(
            "the forecast has only one current component; give both "
            "eastward_sea_water_velocity and northward_sea_water_velocity"
        )
    return out


def read_forecast(path, **kwargs) -> xr.Dataset:
    """Open a NetCDF forecast, or a GRIB one through cfgrib (pip install "seaway[grib]")."""
    path = str(path)
    if path.endswith((".grib", ".grib2", ".grb", ".grb2")):
        try:
            import cfgrib  # noqa: F401
        except ImportError:
            raise ImportError(
                f'{path}: reading GRIB needs cfgrib: pip install "seaway[grib]" (cfgrib and eccodes)'
            ) from None
        return grib_times(xr.open_dataset(path, engine="cfgrib", **kwargs), path)
    return open_netcdf(path, "a forecast is CF NetCDF (or GRIB through cfgrib)", ForecastError, **kwargs)


def grib_times(ds: xr.Dataset, path="the GRIB forecast") -> xr.Dataset:
    """cfgrib gives one forecast's frames along `step` (lead time), with their `valid_time`, and
    `time` the analysis time; time routing reads a `time` axis of valid times, so `valid_time`
    becomes it. A file holding several analyses (`time` and `step` both dimensions) is refused."""
    if "step" not in ds.dims:
        return ds
    if "time" in ds.dims:
        raise ForecastError(
            f"{path} holds {ds.sizes['time']} analyses of {ds.sizes['step']} steps; "
            f"route on one: seaway.weather.grib_times(xr.open_dataset("
            f"path, engine='cfgrib').isel(time=0))"
        )
    ds = ds.drop_vars("time", errors="ignore").swap_dims(step="valid_time")
    return ds.drop_vars("step", errors="ignore").rename(valid_time="time")


def _axis(ds, name):
    for c in ds.coords.values():
        if c.ndim == 1 and c.attrs.get("standard_name") == name:
            return c
    raise ForecastError(f"the forecast has no 1-D coordinate with standard_name {name!r}")


def grid_crs(ds: xr.Dataset, crs=None):
    """(pyproj.CRS, x axis, y axis, metres per unit of the axes) of a forecast on a projected
    grid: its 1-D projection_x/y_coordinate axes (km or m) and `crs` or the CRS its grid-mapping
    variable gives (crs_wkt, proj4_string, or the CF grid-mapping attributes)."""
    try:
        import pyproj
    except ImportError:
        raise ImportError('a projected forecast needs pyproj: pip install "seaway[ice]"') from None
    x_ax, y_ax = _axis(ds, "projection_x_coordinate"), _axis(ds, "projection_y_coordinate")
    if crs is None:
        name = next(
            (v.attrs["grid_mapping"] for v in ds.data_vars.values() if v.attrs.get("grid_mapping") in ds),
            None,
        )
        if name is None:
            raise ForecastError("the forecast names no grid mapping; pass crs=")
        crs = grid_mapping_crs(ds, name, "the forecast")[0]
    scale = metres_per(x_ax.attrs.get("units") or "m")
    if scale is None:
        raise ForecastError(
            f"the forecast's projection_x_coordinate is in {x_ax.attrs.get('units')!r}: give a length (m or km)"
        )
    return pyproj.CRS.from_user_input(crs), x_ax, y_ax, scale


def grid_xy(ds: xr.Dataset, lat, lon, crs=None):
    """(x, y, north): the projected coordinates (in the axes' units) of the lat/lon grid's
    points and the angle of north from the grid's +y axis there (radians, clockwise)."""
    import pyproj

    proj, _, _, scale = grid_crs(ds, crs)
    to_grid = pyproj.Transformer.from_crs("EPSG:4326", proj, always_xy=True)
    la, lo = np.meshgrid(np.asarray(lat, float), np.asarray(lon, float), indexing="ij")
    x, y = to_grid.transform(lo, la)
    xn, yn = to_grid.transform(lo, la + 1e-4)  # a step north, to find north on the grid
    return x / scale, y / scale, np.arctan2(xn - x, yn - y)


def to_latlon(ds: xr.Dataset, lat, lon, *, crs=None) -> xr.Dataset:
    """Resample a forecast on a projected grid onto the regular lat/lon grid `lat`, `lon`
    (bilinear in the projected coordinates; NaN outside the model grid), turning grid-relative
    vectors (GRID_VECTORS) into eastward/northward ones. The projection comes from `crs` or the
    grid-mapping variable's crs_wkt / proj4_string / CF attributes. Needs pyproj (the [ice]
    extra)."""
    _, x_ax, y_ax, _ = grid_crs(ds, crs)
    x, y, north = grid_xy(ds, lat, lon, crs)
    pts = {x_ax.name: xr.DataArray(x, dims=("lat", "lon")), y_ax.name: xr.DataArray(y, dims=("lat", "lon"))}
    keep = [v for v in ds.data_vars if set(ds[v].dims) >= {x_ax.name, y_ax.name}]
    out = ds[keep].interp(pts, method="linear")
    out = out.drop_vars(
        [c for c in out.coords if c not in ("time", "lat", "lon") and c not in out.dims], errors="ignore"
    )
    out = out.assign_coords(
        lat=("lat", np.asarray(lat, float), {"standard_name": "latitude", "units": "degrees_north"}),
        lon=("lon", np.asarray(lon, float), {"standard_name": "longitude", "units": "degrees_east"}),
    )
    by_name = {out[v].attrs.get("standard_name"): v for v in out.data_vars}
    for (gx, gy), (east, north_name) in GRID_VECTORS.items():
        if gx in by_name and gy in by_name:
            u, v = out[by_name[gx]], out[by_name[gy]]
            c, s = np.cos(north), np.sin(north)
            out[by_name[gx]] = (u * c - v * s).assign_attrs(u.attrs, standard_name=east)
            out[by_name[gy]] = (u * s + v * c).assign_attrs(v.attrs, standard_name=north_name)
    return out
