"""SIGRID-3 vector charts on the command line: checked (seaway.ice.vectorfile), then rasterised
onto a lat/lon grid (seaway.ice.sigrid, the [ice] extra): the regional grid around the route's
ends (seaway.ice.routegrid) unless --grid names one, else the chart's own extent."""

from __future__ import annotations

import warnings

import numpy as np

from ..errors import ChartError
from ..ice.grids import latlon_grid
from ..ice.routegrid import route_grid
from ..ice.sigrid import read_sigrid3
from ..ice.vectorfile import check_vector_file, one_line


def sigrid_chart(path, grid, ends=None, notes=None):
    """Rasterise a SIGRID-3 chart onto a lat/lon grid; ValueError naming the cause and the fix.
    What was assumed or decided (a missing .prj, the grid chosen) joins `notes`."""
    try:
        import pyogrio
    except ImportError as exc:
        raise ChartError(
            f'{path}: reading SIGRID-3 charts needs the [ice] extra ({exc}): pip install "seaway[ice]"'
        ) from None
    # a directory, an empty file, a shapefile without .dbf/.shx or with a broken .prj: ValueError
    assumed = check_vector_file(path)
    if notes is not None:
        notes += assumed
    if grid is None:
        try:
            with warnings.catch_warnings():  # GDAL's notes on a damaged file: the read names it
                warnings.simplefilter("ignore")
                info = pyogrio.read_info(path)
        except Exception as exc:  # pyogrio's DataSourceError, ...
            raise ChartError(
                f"{path}: cannot read it as a SIGRID-3 vector file ({one_line(str(exc))})"
            ) from None
    if grid is None and ends is not None:
        box = info["total_bounds"]
        try:
            target, note = route_grid(*ends, chart_bounds=box if in_degrees(info) else None)
        except ValueError as exc:
            raise ChartError(f"{path}: {exc}") from None
        if notes is not None:
            notes.append(note)
        return _said(read_sigrid3(path, target), notes)
    if grid is None:
        west, south, east, north = info["total_bounds"]
        if not (-180 <= west <= east <= 360 and -90 <= south <= north <= 90):
            raise ChartError(
                f"{path}: the chart is not in degrees ({info['crs']}); give the lat/lon "
                "grid to rasterise onto with --grid SOUTH,NORTH,WEST,EAST,RES"
            )
        res = max(north - south, east - west) / 1000
        north = south + np.ceil((north - south) / res - 1e-9) * res  # whole pixels
        east = west + np.ceil((east - west) / res - 1e-9) * res
        grid = (south, north, west, east, res)
    south, north, west, east, res = grid
    return _said(read_sigrid3(path, latlon_grid(south, north, west, east, res)), notes)


def _said(ds, notes):
    """The chart, with what its reading found said in `notes`: features without geometry."""
    empty = int(ds.attrs.get("features_without_geometry", 0))
    if empty and notes is not None:
        notes.append(
            f"{ds.attrs['source']}: {empty} of its {ds.attrs['polygons']} features have no geometry "
            "(null records): they add no ice"
        )
    return ds


def in_degrees(info) -> bool:
    """Is a vector layer in geographic coordinates (its CRS, or degrees-sized bounds)?"""
    crs = info.get("crs")
    if crs:
        try:
            import pyproj

            return bool(pyproj.CRS.from_user_input(crs).is_geographic)
        except Exception:  # an unparsable CRS: judge by the numbers
            pass
    west, south, east, north = info["total_bounds"]
    return bool(-180 <= west <= east <= 360 and -90 <= south <= north <= 90)
