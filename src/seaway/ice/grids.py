"""Target grids for rasterising ice charts: regular lat/lon, or a projected grid (e.g. polar
stereographic) given by its CRS, extent and resolution.

Pixel centres run north to south (row 0 is the top) and west to east. Projected grids carry
their x/y coordinates in km, so that seaway.route measures lengths in km on them (distances
in the projection's plane, not on the Earth: polar stereographic scale errors are a few %).
Only numpy is needed to build a Grid; pyproj is used when a chart is reprojected onto it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

GEOGRAPHIC = "EPSG:4326"


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


def _axis(lo, hi, step, name):
    if not (np.isfinite(lo) and np.isfinite(hi) and hi > lo and step > 0):
        raise ValueError(
            f"{name}: need finite low < high and a positive resolution, got {lo!r}, {hi!r}, {step!r}"
        )
    n = int(round((hi - lo) / step))
    if n < 2 or abs(n * step - (hi - lo)) > 1e-6 * step:
        raise ValueError(f"{name}: extent {hi - lo:g} is not a whole number (>= 2) of resolution {step:g}")
    return lo + (np.arange(n) + 0.5) * step


def latlon_grid(south, north, west, east, resolution) -> Grid:
    """Regular lat/lon grid whose pixel edges are the given extent (degrees); resolution in
    degrees, one number or (dlat, dlon). Longitudes as the chart has them (-180..180)."""
    dlat, dlon = (resolution, resolution) if np.isscalar(resolution) else resolution
    lat = _axis(south, north, dlat, "latitude")[::-1]
    lon = _axis(west, east, dlon, "longitude")
    return Grid(GEOGRAPHIC, lon, lat.copy())


def projected_grid(crs, xmin, xmax, ymin, ymax, resolution_km) -> Grid:
    """Projected grid: `crs` (e.g. 'EPSG:3413', NSIDC polar stereographic north, or a PROJ
    string in metres), extent of pixel edges and resolution in km."""
    x = _axis(xmin, xmax, resolution_km, "x")
    y = _axis(ymin, ymax, resolution_km, "y")[::-1]
    return Grid(str(crs), x, y.copy())
