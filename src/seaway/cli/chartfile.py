"""Open a chart file for the command line: NetCDF (xarray), GeoTIFF (rasterio, optional),
SIGRID-3 (seaway.ice.sigrid, when installed) or the built-in chart "kara".

The cost raster is chosen as follows: `variable` names it (cost per unit length, NaN or inf
impassable); otherwise a stage-of-development chart (variable `stage_of_development`, or SIGRID
`SA`) is turned into Grinyak et al. 2022's impact for the vessel's ice class; otherwise the file's only
2-D variable is the cost. A variable `land` (or `land_variable`) is the land mask."""

from __future__ import annotations

import os
from dataclasses import dataclass, field

import numpy as np

from ..base.files import open_netcdf, read_geotiff
from ..ice import chart_impact
from ..ice.grids import latlon_grid
from ..ice.routegrid import route_grid
from ..ice.sigrid import read_sigrid3
from ..samples import ice_impact, kara_sea

NETCDF = (".nc", ".nc4", ".cdf", ".netcdf", ".h5", ".hdf5")
GEOTIFF = (".tif", ".tiff", ".gtiff")
SIGRID = (".shp", ".gpkg", ".e00", ".zip")
#: Variables reported along each leg when the chart has them.
ENVIRONMENT = ("sea_ice_concentration", "ice_thickness", "CT", "thickness", "depth",
               "wave_height", "wind_speed")


class ChartError(ValueError):
    """A chart file that cannot be read or used."""


@dataclass
class ChartData:
    cost: object  # xarray.DataArray
    land: object = None
    environment: dict = field(default_factory=dict)
    description: str = ""
    notes: list = field(default_factory=list)
    layers: object = None  # the chart's Dataset (SIGRID-3 CT, SA, ... land): describes the ends


def open_chart(path: str, *, variable=None, vessel=None, land_variable=None, grid=None,
               ends=None) -> ChartData:
    """grid: (south, north, west, east, resolution) in degrees for a SIGRID-3 chart; by default
    a regional grid around `ends` ((lat, lon) start and end; seaway.ice.routegrid), else the
    chart's own extent at 1/1000 of its longer side (geographic charts only)."""

    notes: list = []
    if path.lower() in ("kara", "builtin:kara"):
        ds = kara_sea()
        kind = "built-in synthetic Kara Sea chart"
    else:
        if not os.path.exists(path):
            raise ChartError(f"{path}: no such file")
        ext = os.path.splitext(path)[1].lower()
        if ext in GEOTIFF:
            return _geotiff(path, variable, vessel)
        if ext in SIGRID:
            ds, kind = _sigrid(path, grid, ends, notes), "SIGRID-3 chart"
        else:
            try:
                ds = open_netcdf(path, f"charts are NetCDF ({', '.join(NETCDF)}), GeoTIFF "
                                       f"({', '.join(GEOTIFF)}) or SIGRID-3 ({', '.join(SIGRID)})")
            except ValueError as exc:
                raise ChartError(str(exc)) from None
            kind = "NetCDF chart"
    out = ChartData(cost=None, description=f"{kind} {path}", layers=ds)
    out.notes += notes
    land_name = land_variable or ("land" if "land" in ds else None)
    if land_variable and land_variable not in ds:
        raise ChartError(f"{path} has no variable {land_variable!r}; it has {sorted(ds.data_vars)}")
    if variable:
        if vessel:
            raise ChartError("give either --variable (a cost raster) or --vessel (an ice class "
                             "applied to the chart's stage of development), not both")
        if variable not in ds:
            raise ChartError(f"{path} has no variable {variable!r}; it has {sorted(ds.data_vars)}")
        out.cost = _two_d(ds[variable], out.notes)
        out.description += f", cost = {variable}"
    elif "stage_of_development" in ds or "SA" in ds:
        out.cost = _impact(ds, vessel or "Arc7", out.notes)
        out.description += f", ice impact for {vessel or 'Arc7'} (Grinyak et al. 2022)"
    else:
        two_d = [n for n in ds.data_vars if n != land_name and ds[n].ndim >= 2]
        if len(two_d) != 1:
            raise ChartError(f"{path}: which variable is the cost? name it with --variable, one of "
                             f"{sorted(map(str, two_d))}")
        if vessel:
            raise ChartError(f"{path} has no stage_of_development (or SIGRID SA) variable to apply "
                             "--vessel to; give the cost with --variable instead")
        out.cost = _two_d(ds[two_d[0]], out.notes)
        out.description += f", cost = {two_d[0]}"
    if land_name:
        out.land = _two_d(ds[land_name], out.notes).astype(bool)
    for name in ENVIRONMENT:
        if name in ds and ds[name].ndim >= 2:
            out.environment[name] = _two_d(ds[name], [])
    return out


def _two_d(da, notes):
    extra = [d for d in da.dims if da.sizes[d] > 1 and d not in da.dims[-2:]]
    if da.ndim > 2:
        sel = {d: 0 for d in da.dims[:-2]}
        if extra:
            notes.append(f"{da.name}: using the first of {', '.join(f'{d}={da.sizes[d]}' for d in extra)}")
        da = da.isel(sel)
    return da


def _impact(ds, vessel, notes):
    if "SA" in ds and "stage_of_development" not in ds:
        return chart_impact(ds, vessel)
    try:
        return ice_impact(_two_d(ds.stage_of_development, notes), vessel)
    except ValueError as exc:
        raise ChartError(str(exc)) from None


def _sigrid(path, grid, ends=None, notes=None):
    """Rasterise a SIGRID-3 chart onto a lat/lon grid (seaway.ice.sigrid, the [ice] extra)."""
    try:
        import pyogrio
    except ImportError as exc:
        raise ChartError(f"{path}: reading SIGRID-3 charts needs the [ice] extra ({exc}): "
                         'pip install "seaway[ice]"') from None
    if grid is None and ends is not None:
        try:
            info = pyogrio.read_info(path)
        except Exception as exc:  # pyogrio's DataSourceError, ...
            raise ChartError(f"{path}: cannot read it as a SIGRID-3 vector file ({exc})") from None
        box = info["total_bounds"]
        geographic = _in_degrees(info)
        try:
            target, note = route_grid(*ends, chart_bounds=box if geographic else None)
        except ValueError as exc:
            raise ChartError(f"{path}: {exc}") from None
        notes.append(note)
        try:
            return read_sigrid3(path, target)
        except ValueError as exc:
            raise ChartError(str(exc)) from None
    if grid is None:
        info = pyogrio.read_info(path)
        west, south, east, north = info["total_bounds"]
        if not (-180 <= west <= east <= 360 and -90 <= south <= north <= 90):
            raise ChartError(f"{path}: the chart is not in degrees ({info['crs']}); give the lat/lon "
                             "grid to rasterise onto with --grid SOUTH,NORTH,WEST,EAST,RES")
        res = max(north - south, east - west) / 1000
        north = south + np.ceil((north - south) / res - 1e-9) * res  # whole pixels
        east = west + np.ceil((east - west) / res - 1e-9) * res
        grid = (south, north, west, east, res)
    south, north, west, east, res = grid
    try:
        return read_sigrid3(path, latlon_grid(south, north, west, east, res))
    except ValueError as exc:
        raise ChartError(str(exc)) from None


def _in_degrees(info) -> bool:
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


def _geotiff(path, variable, vessel):
    if vessel:
        raise ChartError("a GeoTIFF chart is read as a cost raster (band 1); --vessel needs a "
                         "stage-of-development chart in NetCDF or SIGRID-3")
    band = int(variable) if variable and str(variable).isdigit() else 1
    try:
        da = read_geotiff(path, band)
    except ValueError as exc:
        raise ChartError(str(exc)) from None
    da.name = "cost"
    return ChartData(cost=da, description=f"GeoTIFF {path}, band {band}")
