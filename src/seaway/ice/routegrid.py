"""The grid a chart is rasterised onto when the user names none: a regional lat/lon box around
the route's ends, not the chart's extent.

A pan-Arctic chart spans every longitude from 60 N to the pole; its extent at any affordable
resolution gives pixels tens of km wide (the Kara Gate would be one pixel) and wastes most of
them on seas the voyage never sees. So the default grid is the box around the great circle
between the ends, widened on every side by a margin (a quarter of the great-circle distance,
at least 300 km) for detours around land and heavy ice, at 0.05 degrees of latitude (5.6 km)
and the same km east-west at the box's middle latitude. A lat/lon grid rather than a polar
stereographic one: on lat/lon grids the engine measures steps as great circles (no projection
scale error) and the route exports as GPX/RTZ; the box may cross the antimeridian (longitudes
past 180 are read through the chart's polygons shifted by 360) and reaches the pole when the
margin does (the grid then spans all longitudes and wraps). Charts in degrees clip the box to
their own extent (nothing beyond it is known) and keep 1/1000 of their extent if that is
finer. Large boxes are coarsened so the grid stays under MAX_PIXELS, and under what the
machine's memory holds at the chart's bytes per pixel (seaway.base.memory; then said).
"""

from __future__ import annotations

import numpy as np

from ..base.memory import fits
from ..base.units import EARTH_RADIUS_KM, KM_PER_DEG  # noqa: F401 - EARTH_RADIUS_KM: part of this API
from ..errors import SeawayError
from .grids import CHART, Grid, latlon_grid

DLAT = 0.05  # degrees: 5.6 km, the Kara Sea grid
MIN_MARGIN_KM = 300.0
MAX_PIXELS = 4_000_000


def _great_circle(a, b, n=64):
    """(lat, lon) of n points along the great circle from a to b, longitudes continuous."""
    la1, lo1, la2, lo2 = np.radians([a[0], a[1], b[0], b[1]])
    p = np.array([np.cos(la1) * np.cos(lo1), np.cos(la1) * np.sin(lo1), np.sin(la1)])
    q = np.array([np.cos(la2) * np.cos(lo2), np.cos(la2) * np.sin(lo2), np.sin(la2)])
    omega = np.arccos(np.clip(p @ q, -1.0, 1.0))
    t = np.linspace(0.0, 1.0, n)[:, None]
    if omega < 1e-12:
        pts = np.repeat(p[None], n, axis=0)
    else:
        pts = (np.sin((1 - t) * omega) * p + np.sin(t * omega) * q) / np.sin(omega)
    lat = np.degrees(np.arcsin(np.clip(pts[:, 2], -1, 1)))
    lon = np.degrees(np.unwrap(np.arctan2(pts[:, 1], pts[:, 0])))
    lon += 360.0 * np.round((a[1] - lon[0]) / 360.0)  # start at the longitude as given
    return lat, lon, omega * EARTH_RADIUS_KM


def route_grid(
    start,
    end,
    *,
    chart_bounds=None,
    dlat=DLAT,
    margin_km=None,
    max_pixels=MAX_PIXELS,
    bytes_per_pixel=CHART,
    what="a chart on a grid",
) -> tuple[Grid, str]:
    """(Grid, a sentence saying what was chosen) for a route from `start` to `end` ((lat, lon)
    in degrees). chart_bounds: (west, south, east, north) of a chart in degrees, or None.
    bytes_per_pixel: what a chart on the grid takes (seaway.base.memory), to fit in memory."""
    memory = int(0.9 * fits(bytes_per_pixel))  # (room for the edges' rounding outwards below)
    max_pixels, squeezed = min(max_pixels, memory), memory < max_pixels
    lat, lon, km = _great_circle(start, end)
    margin = max(MIN_MARGIN_KM, 0.25 * km) if margin_km is None else float(margin_km)
    south = max(lat.min() - margin / KM_PER_DEG, -90.0)
    north = min(lat.max() + margin / KM_PER_DEG, 90.0)
    if chart_bounds is not None:
        west_c, south_c, east_c, north_c = (float(v) for v in chart_bounds)
        if east_c - west_c >= 359.0:  # a ring around a pole has no vertex at the pole itself
            north_c, south_c = (90.0, south_c) if north_c > 0 else (north_c, -90.0)
        south, north = max(south, south_c), min(north, north_c)
        dlat = min(dlat, max(north_c - south_c, east_c - west_c) / 1000)
    mid = np.radians(np.clip((south + north) / 2, -85.0, 85.0))
    dlon = dlat / np.cos(mid)
    widest = np.radians(min(np.abs(lat).max(), 85.0))  # the route's highest latitude
    lon_margin = margin / (KM_PER_DEG * np.cos(widest))
    west, east = lon.min() - lon_margin, lon.max() + lon_margin
    shift = 360.0 * np.floor((west + 180.0) / 360.0)  # west in [-180, 180)
    west, east = west - shift, east - shift
    global_lon = east - west >= 360.0 or north >= 89.0 or south <= -89.0
    if chart_bounds is not None and east_c - west_c < 359.0:
        if global_lon:
            west, east = west_c, east_c
        else:  # the box and the chart, compared on the same turn of longitude
            k = np.round(((west_c + east_c) - (west + east)) / 720.0)
            west, east = max(west, west_c - 360 * k), min(east, east_c - 360 * k)
            west, east = west + 360 * k, east + 360 * k
        global_lon = False
    if global_lon:
        west, east = -180.0, 180.0
        dlon = 360.0 / max(int(round(360.0 / dlon)), 16)
    if not (north > south and east > west):
        raise SeawayError(
            f"the route's ends {tuple(start)} and {tuple(end)} lie outside the chart "
            f"(lon {chart_bounds[0]:g}..{chart_bounds[2]:g}, lat {chart_bounds[1]:g}.."
            f"{chart_bounds[3]:g}); give ends on the chart, or the grid with --grid"
        )
    rows, cols = (north - south) / dlat, (east - west) / dlon
    if rows * cols > max_pixels:
        f = float(np.sqrt(rows * cols / max_pixels))
        dlat, dlon = dlat * f, dlon * f
    if not global_lon:  # whole pixels, edges on multiples of the resolution
        west, east = np.floor(west / dlon) * dlon, np.ceil(east / dlon) * dlon
    south = max(np.floor(south / dlat) * dlat, -90.0)
    north = min(south + np.ceil((north - south) / dlat - 1e-9) * dlat, 90.0)
    south = north - np.ceil((north - south) / dlat - 1e-9) * dlat
    nlat = int(round((north - south) / dlat))
    nlon = int(round((east - west) / dlon))
    grid = latlon_grid(
        south,
        north,
        west,
        east,
        ((north - south) / nlat, (east - west) / nlon),
        bytes_per_pixel=bytes_per_pixel,
        what=what,
    )
    note = (
        f"grid: lat {south:.2f}..{north:.2f}, lon {west:.2f}..{east:.2f} at {dlat:.4g} x "
        f"{dlon:.4g} deg ({dlat * KM_PER_DEG:.1f} km north-south), {nlat} x {nlon} pixels: the "
        f"great circle between the ends widened by {margin:.0f} km (set it with --grid)"
    )
    if squeezed and rows * cols > max_pixels:
        note += f"; coarsened to fit in memory ({max_pixels:,} pixels at most)"
    return grid, note
