"""The lat/lon grid a route through a forecast is searched on (seaway.voyage.forecast).

A forecast on a regular lat/lon grid is routed on its own grid. One on a projected model grid
(polar stereographic ROMS, NEMO, WAM: projection_x/y_coordinate axes and a grid mapping, or
--forecast-crs) is resampled onto a lat/lon grid (seaway.weather.on_grid: bilinear in the
projected coordinates, grid-relative vectors rotated to east/north, calm outside the model
grid): with an ice CHART the chart's grid; without one the box around the route's ends that
`seaway route` chooses for vector charts (seaway.ice.routegrid) at about the forecast's own
resolution, or --grid. Land is then where the model has none of its fields, and the package's
coastline (global-land-mask)."""

from __future__ import annotations

import numpy as np

from ..base.memory import FORECAST_FIELD, SEARCH, check_pixels
from ..base.units import KM_PER_DEG
from ..chart.cf import coord_role
from ..errors import ForecastError
from ..ice.grids import latlon_grid
from ..ice.routegrid import route_grid
from ..weather import is_projected, on_grid
from ..weather.forecast import grid_crs


def coastline(ds) -> np.ndarray:
    """The package's coastline (global-land-mask) at the forecast's pixel centres."""
    from global_land_mask import globe

    lat, lon = latlon_axes(ds)
    la, lo = np.meshgrid(
        np.asarray(lat, float), (np.asarray(lon, float) + 180.0) % 360.0 - 180.0, indexing="ij"
    )
    return globe.is_land(la, lo)


def latlon_axes(ds, source="the forecast"):
    """(lat, lon) 1-D axes of a forecast on a regular lat/lon grid; else ValueError naming the
    file, a field and the fix."""
    role = {coord_role(str(n), c.attrs): str(n) for n, c in ds.coords.items() if c.ndim == 1}
    field = next(iter(ds.data_vars.values()), None)
    dims = tuple(d for d in field.dims if d != "time") if field is not None else ()
    if "lat" in role and "lon" in role and set(dims) == {role["lat"], role["lon"]}:
        return ds[role["lat"]].values, ds[role["lon"]].values
    raise ForecastError(
        f"{source}: {field.name if field is not None else 'its fields'} lies on the axes {dims}, "
        "neither a regular lat/lon grid nor a projected one seaway can resample (1-D "
        "projection_x/y_coordinate axes and a grid mapping): give its axes those CF standard "
        "names, its projection with --forecast-crs, or resample it onto a lat/lon grid first "
        "(e.g. cdo remapbil)"
    )


def _resolution_km(ds, crs) -> float:
    _, x_ax, y_ax, scale = grid_crs(ds, crs)
    steps = [np.median(np.abs(np.diff(np.asarray(a.values, float)))) for a in (x_ax, y_ax) if a.size > 1]
    return float(min(steps)) * scale / 1000.0 if steps else 10.0


def fields(ds) -> int:
    """The 2-D fields of a forecast: each variable's frames (times, levels) summed."""
    return sum(int(np.prod(v.shape[:-2], dtype=np.int64)) for v in ds.data_vars.values() if v.ndim >= 2)


def onto_route_grid(ds, source, target=None, *, grid=None, ends=None, crs=None):
    """(the forecast on the lat/lon grid it is routed on, notes): unchanged on a lat/lon grid
    without `target`; else resampled onto `target` ((lat, lon, dims): an ice chart's grid),
    `grid` (south, north, west, east, res in degrees), or the box around the route's `ends` at
    the forecast's resolution. crs: the forecast's projection when its file names none."""
    projected = is_projected(ds) or crs is not None
    if not projected:  # with a chart, route_ice_weather resamples it onto the chart's grid
        if target is None:
            latlon_axes(ds, source)
        return ds, []
    notes = []
    per_pixel = FORECAST_FIELD * fields(ds) + SEARCH  # bytes (seaway.base.memory)
    what = f"{source} ({fields(ds)} fields and frames) resampled onto a grid"
    if target is None:
        if grid is not None:
            box = latlon_grid(*grid, bytes_per_pixel=per_pixel, what=what)
            notes.append(f"grid: the lat/lon grid --grid {','.join(f'{v:g}' for v in grid)}")
        else:
            km = _resolution_km(ds, crs)
            box, note = route_grid(*ends, dlat=km / KM_PER_DEG, bytes_per_pixel=per_pixel, what=what)
            notes.append(f"{note}; about the forecast's {km:g} km resolution")
        target = (box.y, box.x, ("lat", "lon"))
    lat, lon, dims = target
    check_pixels(
        len(lat),
        len(lon),
        per_pixel,
        what,
        "give a coarser grid or a smaller box, or fewer forecast times",
        ForecastError,
    )
    out, said = on_grid(ds, lat, lon, dims, source=source, crs=crs)
    return out, notes + said
