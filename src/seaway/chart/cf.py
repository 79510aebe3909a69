"""CF conventions, written once: the names and attributes that say which coordinate of a file is
latitude, longitude, y or x, and which variable of a forecast plays which role."""

from __future__ import annotations

from collections.abc import Hashable, Mapping
from typing import Any

import numpy as np
import xarray as xr

from ..base.units import km_per
from ..errors import SeawayError
from .roles import STANDARD_NAMES

LAT_NAMES = ("lat", "latitude", "nav_lat")
LON_NAMES = ("lon", "longitude", "long", "nav_lon")
Y_NAMES = ("y", "yc", "northing")
X_NAMES = ("x", "xc", "easting")

#: Grid-relative vector pairs and the east/north names they become. In the CF standard name table
#: "x" and "y" name components along the grid's own x and y axes (positive towards increasing
#: x, y), which on a projected grid are not east and north: sea_water_x_velocity,
#: barotropic_sea_water_x_velocity, x_wind (and the table's older aliases of x_wind / y_wind,
#: grid_eastward_wind / grid_northward_wind). x_sea_water_velocity is not in the table: it is
#: what MET Norway's ROMS products write for the 3-D current.
GRID_VECTORS = {
    ("sea_water_x_velocity", "sea_water_y_velocity"): (
        "eastward_sea_water_velocity",
        "northward_sea_water_velocity",
    ),
    ("barotropic_sea_water_x_velocity", "barotropic_sea_water_y_velocity"): (
        "barotropic_eastward_sea_water_velocity",
        "barotropic_northward_sea_water_velocity",
    ),
    ("x_sea_water_velocity", "y_sea_water_velocity"): (
        "eastward_sea_water_velocity",
        "northward_sea_water_velocity",
    ),
    ("x_wind", "y_wind"): ("eastward_wind", "northward_wind"),
    ("grid_eastward_wind", "grid_northward_wind"): ("eastward_wind", "northward_wind"),
}


def grid_role(standard_name: Any) -> tuple[str, str] | None:
    """(role, the grid-relative pair's first name) of a grid-relative vector component by its
    standard name: ('current_east', 'sea_water_x_velocity') for sea_water_x_velocity, the
    north role for the y component; None for any other name."""
    for pair, earth in GRID_VECTORS.items():
        if standard_name in pair:
            k = pair.index(standard_name)
            role = next(r for r, names in STANDARD_NAMES.items() if earth[k] in names)
            return role, pair[0]
    return None


#: For each vector role, the grid-relative pair a field mapped onto it is marked with.
GRID_PAIRS = {
    "current_east": ("sea_water_x_velocity", "sea_water_y_velocity"),
    "current_north": ("sea_water_x_velocity", "sea_water_y_velocity"),
    "wind_east": ("x_wind", "y_wind"),
    "wind_north": ("x_wind", "y_wind"),
}


#: Our roles and cf_xarray's names for them; the attributes that say which is which (standard_name,
#: units, axis, _CoordinateAxisType, ...) are cf_xarray's table (cf_xarray.criteria), not ours.
_CF_ROLES = (
    ("lat", "latitude", LAT_NAMES),
    ("lon", "longitude", LON_NAMES),
    ("y", "Y", Y_NAMES),
    ("x", "X", X_NAMES),
)


def coord_role(name: Hashable, attrs: Mapping[Any, Any]) -> str | None:
    """'lat', 'lon', 'y' or 'x' for a coordinate, by its CF attributes (cf_xarray's criteria)
    or, for a file that writes none, its name."""
    from cf_xarray.criteria import coordinate_criteria

    for role, cf_name, names in _CF_ROLES:
        for attr, values in coordinate_criteria[cf_name].items():
            if str(attrs.get(attr, "")) in values:
                return role
        if str(name).lower() in names:
            return role
    return None


#: Attributes of a grid-mapping variable that hold the whole CRS as text (WKT or a PROJ string).
_CRS_TEXT = ("crs_wkt", "spatial_ref", "proj4_string", "proj4text", "proj4", "proj_params")


def grid_mapping_crs(ds: xr.Dataset, name: str, what: str) -> tuple[Any, str]:
    """(pyproj.CRS, where it was read) of the grid-mapping variable `name` of `ds`: its WKT or
    PROJ text, else its CF grid-mapping parameters (pyproj.CRS.from_cf). `what` names the file's
    variable in the errors. Needs pyproj (the [ice] extra)."""
    if name not in ds.variables:
        raise SeawayError(f"{what} names the grid mapping {name!r}, which the file does not have")
    try:
        import pyproj
    except ImportError:
        raise ImportError(
            f'{what} is on a projected grid, which needs pyproj: pip install "seaway[ice]"'
        ) from None
    attrs = dict(ds[name].attrs)
    for key in _CRS_TEXT:
        if attrs.get(key):
            try:
                return pyproj.CRS.from_user_input(attrs[key]), f"{name}.{key}"
            except pyproj.exceptions.CRSError:
                continue
    try:
        return pyproj.CRS.from_cf(attrs), f"{name} (CF parameters)"
    except pyproj.exceptions.CRSError as exc:
        raise SeawayError(
            f"cannot read the projection of {what} from its grid mapping {name!r} ({exc}); "
            "fix its attributes (crs_wkt, or the CF grid-mapping parameters)"
        ) from None


def planar_in_km(da: xr.DataArray, what: str = "the chart") -> tuple[xr.DataArray, tuple[str, ...]]:
    """(da with its planar y/x coordinates in km, what was assumed or converted, in words) for
    models that price steps per km. A lat/lon grid is returned as it is; coordinates in metres
    are divided by 1000; coordinates without units are taken as km (said); no coordinate
    values: each pixel is taken as 1 km (said); other units raise SeawayError naming the fix."""
    roles = {coord_role(d, da[d].attrs if d in da.coords else {}): d for d in da.dims}
    if "lat" in roles and "lon" in roles:
        return da, ()
    bare, none = [], []
    for d in da.dims:
        if d not in da.coords:
            none.append(str(d))
            continue
        units = str(da[d].attrs.get("units", "")).strip().lower()
        if not units:
            bare.append(str(d))
        elif km_per(units) is None:
            raise SeawayError(
                f"{what}'s {d} coordinate is in {units!r}: give planar coordinates in a length ('m' or 'km') "
                "(a lat/lon grid needs latitude/longitude coordinates)"
            )
        elif km_per(units) != 1.0:
            km = np.asarray(da[d].values, float) * km_per(units)
            da = da.assign_coords({d: (d, km, {**da[d].attrs, "units": "km"})})
    said = []
    if bare:
        have = " and ".join(bare) + (" coordinates have" if len(bare) > 1 else " coordinate has")
        said.append(f"{what}'s {have} no units: taken as km (set the units attribute to 'm' or 'km')")
    if none:
        said.append(f"{what} has no values on its {' and '.join(none)} axis: each pixel taken as 1 km")
    return da, tuple(said)
