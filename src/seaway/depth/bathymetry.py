"""Reading bathymetry rasters for seaway.depth: NetCDF (xarray) or GeoTIFF (rasterio) on a
lat/lon grid, as depth in metres, positive down, whatever the file's convention (ETOPO and
GEBCO: elevation, negative below sea level; others: depth, positive down).

The sign is taken, in this order, from what you say (`positive=`), the variable's CF `positive`
attribute ("up"/"down"), its CF `standard_name` (DEPTH_NAMES or ELEVATION_NAMES), and otherwise
guessed from its name (elevation, z, topo ... or depth, bathymetry, h ...) or, failing that, as
ETOPO/GEBCO elevation; a guess is always stated in `Bathymetry.notes`. Units: m (any
spelling), ft and fathoms are converted; a missing unit is taken as metres and said so;
anything else is refused with the fix."""

from __future__ import annotations

import os
from dataclasses import dataclass, field

import numpy as np

from ..base.files import open_netcdf, read_geotiff
from ..base.units import metres_per
from ..chart.cf import coord_role
from ..errors import ChartError, SeawayError

#: CF standard names of depth below the surface (positive down) and of elevation (positive up).
DEPTH_NAMES = (
    "sea_floor_depth_below_sea_surface",
    "sea_floor_depth_below_geoid",
    "sea_floor_depth_below_mean_sea_level",
    "sea_floor_depth_below_reference_ellipsoid",
    "sea_floor_depth",
    "depth",
)
ELEVATION_NAMES = (
    "height_above_mean_sea_level",
    "height_above_geoid",
    "altitude",
    "surface_altitude",
    "height_above_reference_ellipsoid",
    "bedrock_altitude",
    "height",
    "sea_floor_height_above_geoid",
    "sea_floor_height_above_mean_sea_level",
)
_ELEVATION_WORDS = (
    "elevation",
    "elev",
    "z",
    "topo",
    "topography",
    "altitude",
    "height",
    "rose",
    "band1",
    "relief",
)
_DEPTH_WORDS = ("depth", "bathymetry", "bathy", "h", "deptho", "sounding", "soundings")


@dataclass
class Bathymetry:
    """raw: the file's variable as (lat, lon), both ascending, still lazy (a GEBCO or ETOPO
    global grid is read only where a chart needs it); factor: metres of depth (positive down)
    per raw unit (-1 for elevation in m); convention: how sign and units were told; notes: the
    assumptions made."""

    raw: object
    factor: float
    path: str
    convention: str
    notes: list = field(default_factory=list)

    @property
    def depth(self):
        """The whole raster as depth in m, positive down (loads it)."""
        out = self.raw.astype(np.float64) * self.factor
        out.name = "depth"
        out.attrs = {"long_name": "water depth", "units": "m", "positive": "down", "source": self.path}
        return out


def _pick_variable(path, ds, variable):
    if variable is not None:
        if variable not in ds:
            raise ChartError(f"{path} has no variable {variable!r}; it has {sorted(map(str, ds.data_vars))}")
        return variable
    two_d = [str(n) for n in ds.data_vars if ds[n].ndim >= 2]
    for names in (DEPTH_NAMES + ELEVATION_NAMES,):
        known = [n for n in two_d if str(ds[n].attrs.get("standard_name", "")).lower() in names]
        if len(known) == 1:
            return known[0]
    named = [n for n in two_d if n.lower() in _ELEVATION_WORDS + _DEPTH_WORDS]
    if len(named) == 1:
        return named[0]
    if len(two_d) == 1:
        return two_d[0]
    raise ChartError(
        f"{path}: which variable is the bathymetry? name it (variable=, or "
        f"--depth-variable), one of {sorted(two_d)}"
    )


def _sign(path, name, attrs, positive):
    """(+1 for depth positive down, -1 for elevation positive up, how it was decided, guessed)."""
    if positive is not None:
        if positive not in ("up", "down"):
            raise SeawayError(
                f"positive must be 'up' (elevation, ETOPO/GEBCO) or 'down' (depth), got {positive!r}"
            )
        return (1 if positive == "down" else -1), f"positive {positive} as given", False
    pos = str(attrs.get("positive", "")).strip().lower()
    if pos in ("up", "down"):
        return (1 if pos == "down" else -1), f"CF attribute positive = {pos!r}", False
    std = str(attrs.get("standard_name", "")).strip().lower()
    if std in DEPTH_NAMES:
        return 1, f"CF standard_name {std!r}", False
    if std in ELEVATION_NAMES:
        return -1, f"CF standard_name {std!r}", False
    if name.lower() in _DEPTH_WORDS:
        return (
            1,
            f"ASSUMED depth positive down from the variable's name {name!r} (no CF positive "
            "or standard_name attribute)",
            True,
        )
    why = (
        f"from the variable's name {name!r}"
        if name.lower() in _ELEVATION_WORDS
        else f"for {name!r}, whose name says neither"
    )
    return (
        -1,
        f"ASSUMED elevation positive up (the ETOPO/GEBCO convention) {why} (no CF "
        "positive or standard_name attribute)",
        True,
    )


def _scale(path, name, attrs, notes):
    units = str(attrs.get("units", "")).strip().lower()
    if not units:
        notes.append(f"{path}: {name} states no units: ASSUMED metres")
        return 1.0
    scale = metres_per(units)
    if scale is None:
        raise ChartError(
            f"{path}: {name} is in {attrs.get('units')!r}; depths must be a length (m, ft, fathoms, ...): "
            "convert the file, or set its units attribute if it is wrong"
        )
    return scale


def _latlon_dims(path, da):
    roles = {}
    for dim in da.dims:
        if dim in da.coords:
            role = coord_role(dim, da.coords[dim].attrs)
            if role in ("lat", "lon"):
                roles[role] = dim
    if set(roles) != {"lat", "lon"}:
        raise ChartError(
            f"{path}: the bathymetry needs 1-D lat and lon coordinates (degrees); "
            f"its dimensions are {da.dims}. Regrid it to lat/lon first (e.g. gdalwarp "
            "-t_srs EPSG:4326)"
        )
    return roles["lat"], roles["lon"]


def open_bathymetry(path, *, variable=None, positive=None) -> Bathymetry:
    """Read a bathymetry raster (NetCDF or GeoTIFF on a lat/lon grid) as depth in metres,
    positive down. `positive`: 'up' or 'down' to override what the file says (or lacks)."""

    path = str(path)
    if not os.path.exists(path):
        raise ChartError(f"{path}: no such bathymetry file")
    notes: list = []
    ext = os.path.splitext(path)[1].lower()
    if ext in (".tif", ".tiff", ".gtiff"):
        da = _geotiff(path)
    else:
        ds = open_netcdf(path, "bathymetry is NetCDF or GeoTIFF (.tif) on a lat/lon grid", ChartError)
        da = ds[_pick_variable(path, ds, variable)]
    name = str(da.name)
    lat, lon = _latlon_dims(path, da)
    extra = {d: 0 for d in da.dims if d not in (lat, lon)}
    if extra:
        notes.append(f"{path}: {name}: using index 0 of {', '.join(extra)}")
        da = da.isel(extra)
    sign, how, guessed = _sign(path, name, da.attrs, positive)
    scale = _scale(path, name, da.attrs, notes)
    if guessed:
        notes.append(
            f"{path}: {name} read as {'depth' if sign > 0 else 'elevation'}: {how}; "
            f"pass positive={'up' if sign > 0 else 'down'!r} (--depth-positive) if it "
            "holds the opposite"
        )
    raw = da.transpose(lat, lon).rename({lat: "lat", lon: "lon"})
    for dim in ("lat", "lon"):
        values = raw[dim].values
        if values.size > 1 and not np.all(np.diff(values) > 0):
            raw = raw.sortby(dim)
    convention = (
        f"{name} in {da.attrs.get('units', 'm (assumed)')}, "
        f"{'depth positive down' if sign > 0 else 'elevation positive up'} ({how})"
    )
    return Bathymetry(raw, float(sign * scale), path, convention, notes)


def _geotiff(path):
    da = read_geotiff(path, error=ChartError)
    if "crs" in da.attrs:
        raise ChartError(
            f"{path}: the bathymetry is in {da.attrs['crs']}, not lat/lon; warp it "
            f"first: gdalwarp -t_srs EPSG:4326 {path} out.tif"
        )
    return da
