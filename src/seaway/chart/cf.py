"""CF conventions, written once: the names and attributes that say which coordinate of a file is
latitude, longitude, y or x, and which variable of a forecast plays which role."""

from __future__ import annotations

from collections.abc import Hashable, Mapping
from typing import Any

import numpy as np
import xarray as xr

from ..base.units import km_per

LAT_NAMES = ("lat", "latitude", "nav_lat")
LON_NAMES = ("lon", "longitude", "long", "nav_lon")
Y_NAMES = ("y", "yc", "northing")
X_NAMES = ("x", "xc", "easting")

#: CF standard names searched for each field, first match wins.
STANDARD_NAMES = {
    "current_east": (
        "eastward_sea_water_velocity",
        "surface_eastward_sea_water_velocity",
        "barotropic_eastward_sea_water_velocity",
    ),
    "current_north": (
        "northward_sea_water_velocity",
        "surface_northward_sea_water_velocity",
        "barotropic_northward_sea_water_velocity",
    ),
    "wave_height": ("sea_surface_wave_significant_height",),
    "wave_from": ("sea_surface_wave_from_direction",),
    "wave_period": (
        "sea_surface_wave_mean_period",
        "sea_surface_wave_mean_period_from_variance_spectral_density_first_frequency_moment",
        "sea_surface_wave_period_at_variance_spectral_density_maximum",
    ),
    "wind_east": ("eastward_wind",),
    "wind_north": ("northward_wind",),
    "wind_speed": ("wind_speed",),
    # the ice of a coupled ice-ocean forecast (HYCOM-CICE, TOPAZ, ROMS): priced with the currents
    "ice_concentration": ("sea_ice_area_fraction",),
    "ice_thickness": ("sea_ice_thickness",),
}
#: Roles that are the ice of a forecast, not its weather (seaway.voyage.forecastice prices them).
ICE_ROLES = ("ice_concentration", "ice_thickness")

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


def coord_role(name: Hashable, attrs: Mapping[Any, Any]) -> str | None:
    """'lat', 'lon', 'y' or 'x' for a coordinate, by its name or CF attributes."""
    lname = str(name).lower()
    std = str(attrs.get("standard_name", "")).lower()
    units = str(attrs.get("units", "")).lower()
    axis = str(attrs.get("axis", "")).upper()
    if lname in LAT_NAMES or std == "latitude" or units in ("degrees_north", "degree_north", "degrees_n"):
        return "lat"
    if lname in LON_NAMES or std == "longitude" or units in ("degrees_east", "degree_east", "degrees_e"):
        return "lon"
    if lname in Y_NAMES or std == "projection_y_coordinate" or axis == "Y":
        return "y"
    if lname in X_NAMES or std == "projection_x_coordinate" or axis == "X":
        return "x"
    return None


def planar_in_km(da: xr.DataArray, what: str = "the chart") -> tuple[xr.DataArray, tuple[str, ...]]:
    """(da with its planar y/x coordinates in km, what was assumed or converted, in words) for
    models that price steps per km. A lat/lon grid is returned as it is; coordinates in metres
    are divided by 1000; coordinates without units are taken as km (said); no coordinate
    values: each pixel is taken as 1 km (said); other units raise ValueError naming the fix."""
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
            raise ValueError(
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
