"""A forecast onto the lat/lon grid a route is searched on (on_grid): from a regular lat/lon grid
linearly; from a projected model grid (polar stereographic ROMS, NEMO or WAM output: 1-D
projection_x/y_coordinate axes and a CF grid mapping, or a CRS the caller gives) bilinearly in
the projected coordinates, grid-relative vectors rotated to east/north (to_latlon). Pixels
outside the forecast have no weather (calm, no current), which the notes say, as they say the
resampling and the rotation."""

from __future__ import annotations

import numpy as np
import xarray as xr

from ..chart.cf import GRID_VECTORS, coord_role
from ..errors import ForecastError
from .forecast import grid_crs, grid_xy, to_latlon

_GRID_NAMES = {n for pair in GRID_VECTORS for n in pair}


def is_projected(ds: xr.Dataset) -> bool:
    """Is the forecast on a projected grid: 1-D projection_x/y_coordinate axes and no 1-D
    latitude and longitude axes?"""
    std = {c.attrs.get("standard_name") for c in ds.coords.values() if c.ndim == 1}
    roles = {coord_role(str(n), c.attrs) for n, c in ds.coords.items() if c.ndim == 1}
    return {"projection_x_coordinate", "projection_y_coordinate"} <= std and not {"lat", "lon"} <= roles


def on_grid(ds: xr.Dataset, lat, lon, dims=("lat", "lon"), source="the forecast", crs=None):
    """(the forecast on the lat/lon grid `lat`, `lon` with dimensions `dims`, notes): resampled
    linearly in latitude and longitude (exact where the grids share points; longitudes in either
    convention), or, from a projected grid (is_projected), bilinearly in its projected
    coordinates with grid-relative vectors rotated to east/north (seaway.weather.to_latlon;
    `crs` overrides the file's grid mapping). Pixels outside the forecast's extent have no
    weather (calm), which the notes say."""
    if is_projected(ds) or crs is not None:
        return _from_projected(ds, lat, lon, dims, source, crs)
    role = {coord_role(str(n), c.attrs): str(n) for n, c in ds.coords.items() if c.ndim == 1}
    if "lat" not in role or "lon" not in role:
        raise ForecastError(
            f"{source} is neither on a lat/lon grid nor on a projected one (its coordinates: "
            f"{sorted(map(str, ds.coords))}): give its axes the CF standard names latitude/"
            "longitude or projection_x/y_coordinate with a grid mapping, or resample it onto "
            "a lat/lon grid first (e.g. cdo remapbil)"
        )
    lat, lon = np.asarray(lat, float), np.asarray(lon, float)
    src_lon = np.asarray(ds[role["lon"]].values, float)
    want_lon = lon % 360.0 if src_lon.max() > 180.0 else (lon + 180.0) % 360.0 - 180.0
    out = ds.interp(
        {role["lat"]: xr.DataArray(lat, dims=dims[0]), role["lon"]: xr.DataArray(want_lon, dims=dims[1])}
    )
    out = out.drop_vars([role["lat"], role["lon"]], errors="ignore")
    out = out.assign_coords({dims[0]: lat, dims[1]: lon})
    src_lat = np.asarray(ds[role["lat"]].values, float)
    inside_lat = (lat >= src_lat.min()) & (lat <= src_lat.max())
    inside_lon = (want_lon >= src_lon.min()) & (want_lon <= src_lon.max())
    outside = 1.0 - inside_lat.mean() * inside_lon.mean()
    notes = []
    if outside > 0:
        notes.append(
            f"{100 * outside:.0f} % of the grid lies outside {source}: no weather (calm) is assumed there"
        )
    return out, notes


def _from_projected(ds, lat, lon, dims, source, crs):
    try:
        proj, x_ax, y_ax, _ = grid_crs(ds, crs)
    except ValueError:
        raise ForecastError(
            f"{source} is on a projected grid but names no grid mapping (no variable's "
            "grid_mapping attribute names one): give its projection with --forecast-crs "
            "(crs= in the API), e.g. '+proj=stere +lat_0=90 +lat_ts=60 +lon_0=58 +R=6371000'"
        ) from None
    lat, lon = np.asarray(lat, float), np.asarray(lon, float)
    out = to_latlon(ds, lat, lon, crs=crs)
    x, y, _ = grid_xy(ds, lat, lon, crs)
    xs, ys = np.asarray(x_ax.values, float), np.asarray(y_ax.values, float)
    outside = (x < xs.min()) | (x > xs.max()) | (y < ys.min()) | (y > ys.max())
    mask = xr.DataArray(outside, dims=("lat", "lon"))
    out = out.map(lambda v: v.where(~mask, 0.0) if {"lat", "lon"} <= set(v.dims) else v)
    out = out.rename({"lat": dims[0], "lon": dims[1]}) if tuple(dims) != ("lat", "lon") else out
    op = proj.coordinate_operation
    name = op.method_name if op is not None else proj.name
    text = proj.srs if len(proj.srs) <= 160 else proj.name
    notes = [
        f"{source}: resampled from its {name} grid ({text}) onto the "
        f"lat/lon grid ({lat.size} x {lon.size} pixels), bilinear in the projected coordinates"
    ]
    rotated = [
        f"{v} ({ds[v].attrs['standard_name']})"
        for v in ds.data_vars
        if ds[v].attrs.get("standard_name") in _GRID_NAMES and v in out
    ]
    if rotated:
        notes.append(
            f"{source}: grid-relative vectors rotated to east/north by the angle between the "
            f"grid's y axis and north at each pixel: {', '.join(rotated)}"
        )
    if outside.any():
        notes.append(
            f"{100 * outside.mean():.0f} % of the grid lies outside {source}'s model grid: no "
            "weather (calm, no current) is assumed there"
        )
    return out, notes
