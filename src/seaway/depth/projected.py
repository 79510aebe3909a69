"""Depth on a projected chart grid (y/x, e.g. polar stereographic EPSG:3413 in km): every
bathymetry node near the chart is projected into the chart's CRS and each pixel takes the
shallowest node inside it (an exact binned minimum, numpy.minimum.at); pixels no node falls in
(the chart finer than the bathymetry) take the depth linearly interpolated at their centre."""

from __future__ import annotations

import numpy as np

from ..base.units import metres_per
from ..errors import ChartError


def projected_depth(raw, factor, y, x, crs, units="km"):
    """(rows, cols) depth (m, positive down, NaN unknown) and the rule used; y, x: 1-D pixel
    centres in `units` of the CRS plane; raw: lat/lon DataArray (ascending), times `factor`."""
    import pyproj
    import xarray as xr

    scale = metres_per(units)
    if scale is None:
        raise ChartError(f"the chart's y/x are in {units!r}; give them in km or m")
    crs = pyproj.CRS.from_user_input(crs)
    to_ll = pyproj.Transformer.from_crs(crs, "EPSG:4326", always_xy=True)
    to_xy = pyproj.Transformer.from_crs("EPSG:4326", crs, always_xy=True)
    y, x = np.asarray(y, float), np.asarray(x, float)
    dy, dx = (y[1] - y[0]) if y.size > 1 else 1.0, (x[1] - x[0]) if x.size > 1 else 1.0
    xx, yy = np.meshgrid(x * scale, y * scale)
    lon_c, lat_c = to_ll.transform(xx, yy)
    cell = float(np.median(np.diff(raw.lat.values)))
    pole_x, pole_y = to_xy.transform(0.0, 90.0)
    pole = (
        min(x[0], x[-1]) - abs(dx) / 2 <= pole_x / scale <= max(x[0], x[-1]) + abs(dx) / 2
        and min(y[0], y[-1]) - abs(dy) / 2 <= pole_y / scale <= max(y[0], y[-1]) + abs(dy) / 2
    )
    pixel_deg = max(abs(dx), abs(dy)) * scale / 111_195.0
    south = np.nanmin(lat_c) - pixel_deg - 2 * cell
    north = 90.0 if pole else np.nanmax(lat_c) + pixel_deg + 2 * cell
    window = raw.sel(lat=slice(south, north))
    if window.sizes["lat"] < 2:
        raise ChartError(
            f"the bathymetry (lat {float(raw.lat[0]):g}..{float(raw.lat[-1]):g}) does "
            f"not cover the chart (lat {np.nanmin(lat_c):.3g}..{np.nanmax(lat_c):.3g})"
        )
    values = np.asarray(window.values, dtype=np.float64) * factor
    lon2, lat2 = np.meshgrid(window.lon.values, window.lat.values)
    nx, ny = to_xy.transform(lon2, lat2)
    col = np.floor((nx / scale - (x[0] - dx / 2)) / dx).astype(np.int64)
    row = np.floor((ny / scale - (y[0] - dy / 2)) / dy).astype(np.int64)
    inside = (row >= 0) & (row < y.size) & (col >= 0) & (col < x.size) & np.isfinite(nx)
    out = np.full((y.size, x.size), np.inf)
    np.minimum.at(out, (row[inside], col[inside]), values[inside])  # NaN stays NaN: unknown
    count = np.zeros(out.shape, np.int64)
    np.add.at(count, (row[inside], col[inside]), 1)
    empty = count == 0
    rule = "shallowest of the nodes in each pixel"
    if empty.any():
        lon = window.lon.values
        span = lon[-1] - lon[0] + float(np.median(np.diff(lon)))
        w = window
        if span >= 360.0 - 1e-6:  # periodic: pad one column each side
            w = xr.concat(
                [
                    window.isel(lon=[-1]).assign_coords(lon=[lon[-1] - 360.0]),
                    window,
                    window.isel(lon=[0]).assign_coords(lon=[lon[0] + 360.0]),
                ],
                dim="lon",
            )
        qlon = (lon_c[empty] - lon[0]) % 360.0 + lon[0]
        pts = w.interp(lat=xr.DataArray(lat_c[empty], dims="p"), lon=xr.DataArray(qlon, dims="p"))
        out[empty] = np.asarray(pts.values, dtype=np.float64) * factor
        rule += f"; linear interpolation at the centres of the {int(empty.sum())} pixels no node falls in"
    return out, rule
