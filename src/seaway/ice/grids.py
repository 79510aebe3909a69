"""Target grids for rasterising ice charts: regular lat/lon, or a projected grid (e.g. polar
stereographic) given by its CRS, extent and resolution.

Pixel centres run north to south (row 0 is the top) and west to east. Projected grids carry
their x/y coordinates in km, so that seaway.route measures lengths in km on them (distances
in the projection's plane, not on the Earth: polar stereographic scale errors are a few %).
Only numpy is needed to build a Grid; pyproj is used when a chart is reprojected onto it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..base.memory import ROUTE, SIGRID, check_pixels, coarser
from ..errors import ChartError

GEOGRAPHIC = "EPSG:4326"
#: Bytes per pixel of a SIGRID-3 chart rasterised onto a grid and routed (seaway.base.memory).
CHART = SIGRID + ROUTE


@dataclass(frozen=True, eq=False)
class Grid:
    """crs: 'EPSG:4326' (lat/lon) or any CRS pyproj accepts (metres); x, y: 1-D pixel centres,
    x ascending, y descending (degrees lon/lat, or km for projected grids)."""

    crs: str
    x: np.ndarray
    y: np.ndarray

    @property
    def geographic(self) -> bool:
        """True for a lat/lon grid, False for a projected one (y/x in km)."""
        return self.crs == GEOGRAPHIC

    @property
    def shape(self) -> tuple:
        """(rows, cols)."""
        return (len(self.y), len(self.x))

    @property
    def scale(self) -> float:
        """CRS units per coordinate unit: 1 for degrees, 1000 (m per km) for projected grids."""
        return 1.0 if self.geographic else 1000.0

    def transform(self):
        """(a, b, c, d, e, f) affine of the pixel edges in CRS units (rasterio/GDAL order)."""
        dx = (self.x[1] - self.x[0]) * self.scale
        dy = (self.y[1] - self.y[0]) * self.scale
        x0 = self.x[0] * self.scale - dx / 2
        y0 = self.y[0] * self.scale - dy / 2
        return (dx, 0.0, x0, 0.0, dy, y0)

    def dims(self) -> tuple:
        """The dimension names: ("lat", "lon") or ("y", "x")."""
        return ("lat", "lon") if self.geographic else ("y", "x")

    def coords(self) -> dict:
        """xarray coordinates with CF attributes."""
        if self.geographic:
            return {
                "lat": ("lat", self.y, {"standard_name": "latitude", "units": "degrees_north"}),
                "lon": ("lon", self.x, {"standard_name": "longitude", "units": "degrees_east"}),
            }
        return {
            "y": ("y", self.y, {"standard_name": "projection_y_coordinate", "units": "km", "axis": "Y"}),
            "x": ("x", self.x, {"standard_name": "projection_x_coordinate", "units": "km", "axis": "X"}),
        }

    def centres(self) -> tuple:
        """2-D arrays (X, Y) of pixel centres in CRS units."""
        xx, yy = np.meshgrid(self.x * self.scale, self.y * self.scale)
        return xx, yy


def _count(lo, hi, step, name) -> int:
    """The number of pixels along an axis from lo to hi (pixel edges) at `step`."""
    if not (np.isfinite(lo) and np.isfinite(hi) and hi > lo and np.isfinite(step) and step > 0):
        raise ChartError(
            f"{name}: need finite low < high and a positive resolution, got {lo!r}, {hi!r}, {step!r}"
        )
    n = (hi - lo) / step
    if not np.isfinite(n):
        raise ChartError(f"{name}: resolution {step:g} is too fine for an extent of {hi - lo:g}")
    n = round(n)
    if n < 2 or abs(n * step - (hi - lo)) > 1e-6 * step:
        raise ChartError(f"{name}: extent {hi - lo:g} is not a whole number (>= 2) of resolution {step:g}")
    return int(n)


def _check(rows, cols, steps, unit, bytes_per_pixel, what):
    """Refuse a grid whose chart would not fit in memory (seaway.base.memory), before any of
    it is allocated. The fix names the finest resolution that fits and still divides the box
    (a whole multiple m of the one asked for, m dividing both pixel counts), if there is one."""
    f = coarser(rows * cols, bytes_per_pixel)
    if f <= 1:
        return
    m = next(
        (m for m in range(math.ceil(f), min(math.gcd(rows, cols), 10**6) + 1) if rows % m == 0 == cols % m),
        None,
    )
    if m is None:
        finer = " x ".join(f"{s * f:.3g}" for s in dict.fromkeys(steps))
        fix = f"give a coarser grid (a resolution of {finer} {unit} or more) or a smaller box"
    else:
        res = " x ".join(f"{s * m:.6g}" for s in dict.fromkeys(steps))
        fix = f"give a coarser grid (e.g. a resolution of {res} {unit}: {rows // m:,} x {cols // m:,} pixels) or a smaller box"
    check_pixels(rows, cols, bytes_per_pixel, what, fix, ChartError)


def latlon_grid(
    south, north, west, east, resolution, *, bytes_per_pixel=CHART, what="a chart on a grid"
) -> Grid:
    """Regular lat/lon grid whose pixel edges are the given extent (degrees); resolution in
    degrees, one number or (dlat, dlon). Longitudes as the chart has them (-180..180).
    bytes_per_pixel: what a chart on it will take (default: a SIGRID-3 chart read and routed);
    a grid whose chart would not fit in memory is refused (ChartError naming `what`, the
    figure and the fix)."""
    dlat, dlon = (resolution, resolution) if np.isscalar(resolution) else resolution
    rows, cols = _count(south, north, dlat, "latitude"), _count(west, east, dlon, "longitude")
    _check(rows, cols, (dlat, dlon), "deg", bytes_per_pixel, what)
    lat = south + (np.arange(rows) + 0.5) * dlat
    lon = west + (np.arange(cols) + 0.5) * dlon
    return Grid(GEOGRAPHIC, lon, lat[::-1].copy())


def projected_grid(
    crs, xmin, xmax, ymin, ymax, resolution_km, *, bytes_per_pixel=CHART, what="a chart on a grid"
) -> Grid:
    """Projected grid: `crs` (e.g. 'EPSG:3413', NSIDC polar stereographic north, or a PROJ
    string in metres), extent of pixel edges and resolution in km; refused as latlon_grid."""
    cols, rows = _count(xmin, xmax, resolution_km, "x"), _count(ymin, ymax, resolution_km, "y")
    _check(rows, cols, (resolution_km,), "km", bytes_per_pixel, what)
    x = xmin + (np.arange(cols) + 0.5) * resolution_km
    y = ymin + (np.arange(rows) + 0.5) * resolution_km
    return Grid(str(crs), x, y[::-1].copy())
