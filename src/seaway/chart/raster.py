"""Turn what the user gives (numpy arrays or xarray DataArrays, with coordinates or cell sizes)
into the engine's inputs: a C-contiguous float raster, a land mask and a `_core.Geometry`.

All validation happens here, so the C++ core only sees consistent input."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, cast

import numpy as np
import numpy.typing as npt

from .. import native as _core
from ..base.memory import SEARCH, check_pixels
from ..base.validate import number
from ..errors import ChartError, SeawayError, SeawayTypeError
from .cf import coord_role
from .flags import flags_out, has_flags

if TYPE_CHECKING:
    import xarray as xr

    #: A chart's cost raster as the engine reads it.
    Costs = npt.NDArray[np.float32] | npt.NDArray[np.float64]


@dataclass
class Chart:
    """A validated raster: cost values, land mask and grid geometry."""

    values: Costs  # (rows, cols) float32 or float64, C-contiguous
    land: npt.NDArray[np.uint8] | None  # (rows, cols) uint8 or None
    grid: _core.Geometry
    lat: npt.NDArray[np.floating] | None = None  # pixel-centre latitudes (geographic grids)
    lon: npt.NDArray[np.floating] | None = None
    y: npt.NDArray[np.floating] | None = None  # pixel-centre y / x (planar grids)
    x: npt.NDArray[np.floating] | None = None
    template: xr.DataArray | None = None  # the DataArray the cost came in, for DataArray results
    lowest: float = float("nan")  # the smallest cost, NaN ignored (NaN: not known or all NaN)
    #: What pricing legs on the chart builds once (seaway.chart.legs.TimedLegs), by neighbourhood.
    kept: dict[Any, Any] = field(default_factory=dict, init=False, repr=False, compare=False)

    def __getstate__(self) -> dict[str, Any]:
        return dict(self.__dict__, kept={})  # the engine's objects are rebuilt where unpickled

    @property
    def geographic(self) -> bool:
        return bool(self.grid.geographic)

    @property
    def shape(self) -> tuple[int, int]:
        return self.values.shape

    def passable(self, rc: tuple[int, int]) -> bool:
        r, c = rc
        u = float(self.values[r, c])
        return bool(math.isfinite(u) and u >= 0 and (self.land is None or not self.land[r, c]))

    @property
    def axes(self) -> tuple[npt.NDArray[np.floating], npt.NDArray[np.floating]]:
        """The pixel-centre coordinates along rows and columns: (lat, lon) on geographic charts,
        (y, x) on planar ones."""
        a, b = (self.lat, self.lon) if self.geographic else (self.y, self.x)
        if a is None or b is None:
            raise ChartError("the chart has no pixel-centre coordinates")
        return a, b

    def pixel_coords(self, pixels: npt.NDArray[np.integer]) -> npt.NDArray[np.float64]:
        """(n, 2) lat/lon (geographic) or y/x (planar) of pixel centres."""
        a, b = self.axes
        return np.column_stack([a[pixels[:, 0]], b[pixels[:, 1]]])


def from_dataarray(
    da: xr.DataArray,
) -> tuple[npt.NDArray[Any], dict[str, npt.NDArray[np.float64]], xr.DataArray]:
    """Values in (row, col) order and the 1-D coordinates found along each dimension."""
    if da.ndim != 2:
        raise ChartError(
            f"cost must be 2-D, got a DataArray with dims {da.dims}; select one time or level "
            "first, e.g. da.isel(time=0)"
        )
    roles = {}
    for dim in da.dims:
        coord = da.coords[dim] if dim in da.coords else None  # (.get makes up a range)
        if coord is None:  # a 1-D coordinate along it under another name (NSIDC's xgrid on x)
            coord = next(
                (c for c in da.coords.values() if c.dims == (dim,) and coord_role(c.name, c.attrs)), None
            )
        if coord is None:
            if coord_role(dim, {}) in ("lat", "lon"):
                raise ChartError(
                    f"the dimension {dim!r} has no coordinate values, so its pixels' "
                    f"{coord_role(dim, {})} is unknown; give them, e.g. "
                    f"da.assign_coords({dim}=values), or rename the dimension if it is not "
                    "geographic"
                )
            continue
        role = coord_role(str(coord.name), coord.attrs)
        if role:
            roles[role] = (dim, np.asarray(coord.values, dtype=float))
    if "lat" in roles and "lon" in roles:
        if da.dims.index(roles["lat"][0]) == 1:  # (lon, lat) order: make rows latitude
            da = da.transpose(roles["lat"][0], roles["lon"][0])
        return np.asarray(da.values), {"lat": roles["lat"][1], "lon": roles["lon"][1]}, da
    if "y" in roles and "x" in roles:
        if da.dims.index(roles["y"][0]) == 1:
            da = da.transpose(roles["y"][0], roles["x"][0])
        return np.asarray(da.values), {"y": roles["y"][1], "x": roles["x"][1]}, da
    return np.asarray(da.values), {}, da


def _regular_step(values: npt.NDArray[np.float64], name: str) -> float:
    if values.ndim != 1:
        raise ChartError(f"{name} must be 1-D (pixel centres along one axis), got shape {values.shape}")
    if not np.all(np.isfinite(values)):
        raise ChartError(f"{name} holds NaN or infinite values; give the pixel-centre coordinates")
    if values.size < 2:
        return 1.0  # a single row or column: no step along this axis is ever taken
    steps = np.diff(values)
    step = (values[-1] - values[0]) / (values.size - 1)
    if step == 0 or np.max(np.abs(steps - step)) > 1e-6 * abs(step) + 1e-9:
        worst = int(np.argmax(np.abs(steps - step)))
        raise ChartError(
            f"{name} is not regularly spaced (step {steps[worst]:g} at index {worst}, mean step "
            f"{step:g}); resample the chart onto a regular grid first, e.g. with "
            "DataArray.interp()"
        )
    return float(step)


def _plain(a: npt.NDArray[Any]) -> bool:
    """Is `a` laid out as the engine reads it in place (C order, plain strides, aligned)?"""
    plain = tuple(int(np.prod(a.shape[i + 1 :], dtype=np.int64)) * a.itemsize for i in range(a.ndim))
    return bool(a.flags.c_contiguous and a.flags.aligned and a.strides == plain)


def engine_layout(a: npt.NDArray[Any]) -> npt.NDArray[Any]:
    """`a` as the engine reads it in place: C order, aligned, and with the plain strides of its
    shape. numpy calls a view C-contiguous when only its size-1 axes are odd (np.ones((1, 3))[::-1]
    has a negative row stride), but the engine's arrays (Eigen) refuse any negative stride; an
    array unpickled from a buffer (a Dask worker) may sit at an odd address. Such arrays are
    copied once; ordinary ones are read in place."""
    return a if _plain(a) else np.array(a, order="C", copy=True)


def _land_mask(land: npt.NDArray[np.generic]) -> npt.NDArray[np.uint8]:
    """The land mask as uint8 0/1: bool, or integers/floats holding only 0 (sea) and 1 (land).
    Anything else (NaN, 2, 0.5, -1, strings) is refused rather than silently read as land."""
    if land.dtype == np.bool_:
        return land.view(np.uint8)
    if not (np.issubdtype(land.dtype, np.integer) or np.issubdtype(land.dtype, np.floating)):
        raise SeawayTypeError(
            f"land must be a boolean mask (True = land), got dtype {land.dtype}; "
            "give a bool array, or 0/1 integers or floats"
        )
    bad = (land != 0) & (land != 1)  # NaN compares unequal to both
    if bad.any():
        r, c = np.argwhere(bad)[0]
        raise ChartError(
            f"land must hold only 0 (sea) and 1 (land), got {int(bad.sum())} other value(s), e.g. "
            f"{land[r, c]!r} at pixel ({r}, {c}); give a bool mask, e.g. land=np.isnan(mask) | "
            "(mask > 0.5) to say how such values should be read"
        )
    mask: npt.NDArray[np.uint8] = (land == 1).astype(np.uint8)  # (ndarray.__eq__ is untyped)
    return mask


def as_chart(
    cost: npt.ArrayLike | xr.DataArray,
    *,
    lat: npt.ArrayLike | None = None,
    lon: npt.ArrayLike | None = None,
    dx: float = 1.0,
    dy: float = 1.0,
    land: npt.ArrayLike | xr.DataArray | None = None,
    allow_negative: bool = False,
) -> Chart:
    """Validate the user's raster and coordinates and build the engine's view of them. A
    chart-like object with an as_chart() method (seaway.ice.SeasonGrid) gives its own."""
    own = getattr(cost, "as_chart", None)
    if callable(own) and not hasattr(cost, "dims"):
        if lat is not None or lon is not None or land is not None:
            raise ChartError(
                f"a {type(cost).__name__} brings its own grid and land: give no lat, lon or land"
            )
        return cast(Chart, own())
    template = None
    coords: dict[str, npt.NDArray[np.float64]] = {}
    flag_land = None
    if hasattr(cost, "dims") and hasattr(cost, "coords"):  # an xarray.DataArray
        values, coords, template = from_dataarray(cast("xr.DataArray", cost))
        if has_flags(template):  # CF flags and values outside valid_range are never costs
            flagged = flags_out(template, "cost")
            values, flag_land = np.asarray(flagged.values.values), flagged.land
    else:
        values = np.asarray(cost)
    if lat is not None or lon is not None:
        if lat is None or lon is None:
            raise ChartError("give both lat and lon (1-D pixel-centre coordinates), or neither")
        coords = {"lat": np.asarray(lat, dtype=float), "lon": np.asarray(lon, dtype=float)}
    if values.ndim != 2:
        raise ChartError(
            f"cost must be a 2-D raster, got shape {values.shape}; give one (rows, cols) layer, "
            "e.g. cost[0] for the first time step"
        )
    if values.shape[0] < 1 or values.shape[1] < 1:
        raise ChartError(f"cost is empty (shape {values.shape}); give at least one pixel")
    if values.size >= 2**32 - 1:
        raise ChartError(f"the chart has {values.size} pixels; the engine handles fewer than 2**32")
    if values.dtype == np.bool_ or not np.issubdtype(values.dtype, np.number) or np.iscomplexobj(values):
        raise SeawayTypeError(f"cost must hold real numbers, got dtype {values.dtype}")
    converted = values.dtype not in (np.float32, np.float64)
    copied = converted or not _plain(values)
    check_pixels(  # the copy (a broadcast view may stand for far more memory than it holds)
        values.shape[0],
        values.shape[1],
        SEARCH + (8 if converted else values.itemsize if copied else 0),
        "the search on a chart"
        + (" converted to float64" if converted else " copied to C order" if copied else ""),
        "route on a coarser chart (e.g. cost[::2, ::2]) or on a part of it",
        SeawayError,
    )
    if converted:
        values = values.astype(np.float64)
    values = engine_layout(values)
    lowest = float(np.fmin.reduce(values, axis=None))  # one pass, no temporary array
    if not allow_negative and lowest < 0:
        negative = values < 0
        if negative.any():
            r, c = np.argwhere(negative)[0]
            raise ChartError(
                f"cost has {int(negative.sum())} negative value(s), e.g. {values[r, c]:g} at pixel "
                f"({r}, {c}); costs must be >= 0: mark impassable pixels with np.inf (or NaN) or "
                "pass them in the land mask"
            )

    rows, cols = values.shape
    mask = None
    if land is not None:
        if hasattr(land, "dims") and template is not None and set(land.dims) == set(template.dims):
            land = cast("xr.DataArray", land).transpose(*template.dims)  # the cost's (row, col) order
        land_arr = np.asarray(cast("xr.DataArray", land).values if hasattr(land, "dims") else land)
        if land_arr.shape != values.shape:
            raise ChartError(
                f"land has shape {land_arr.shape} but cost has shape {values.shape}; give a mask of the same shape"
            )
        mask = engine_layout(_land_mask(land_arr))
    if flag_land is not None:
        mask = engine_layout(
            flag_land.astype(np.uint8) if mask is None else mask | flag_land.astype(np.uint8)
        )

    grid = _core.Geometry()
    grid.rows, grid.cols = rows, cols
    chart = Chart(values=values, land=mask, grid=grid, template=template, lowest=lowest)
    if "lat" in coords:
        la, lo = coords["lat"], coords["lon"]
        if la.shape != (rows,) or lo.shape != (cols,):
            raise ChartError(
                f"lat has {la.size} values and lon {lo.size}, but the cost has {rows} rows and "
                f"{cols} columns; give one latitude per row and one longitude per column"
            )
        lo_grid = lo
        if lo.size > 1 and np.all(np.isfinite(lo)) and np.any(np.abs(np.diff(lo)) > 180):
            # labelled across the antimeridian (..., 170, -180, -170, ...): make it continuous
            lo_grid = lo[0] + np.concatenate([[0.0], np.cumsum((np.diff(lo) + 180) % 360 - 180)])
        dlat, dlon = _regular_step(la, "lat"), _regular_step(lo_grid, "lon")
        if np.any(np.abs(la) > 90):
            raise ChartError("lat must lie within [-90, 90] degrees")
        span = abs(dlon) * cols
        if span > 360 * (1 + 1e-9):
            raise ChartError(f"lon spans {span:g} degrees; a chart covers at most 360 degrees of longitude")
        grid.geographic = True
        grid.lat0, grid.dlat, grid.lon0, grid.dlon = float(la[0]), dlat, float(lo[0]), dlon
        grid.wrap = bool(abs(span - 360) < 1e-6 * 360)
        if grid.wrap and cols < 16:
            raise ChartError("a chart that wraps around the globe needs at least 16 columns")
        chart.lat, chart.lon = la, lo
    else:
        if "y" in coords:
            dy, dx = abs(_regular_step(coords["y"], "y")), abs(_regular_step(coords["x"], "x"))
            chart.y, chart.x = coords["y"], coords["x"]
        dx = number(dx, "dx", above=0, what="a positive cell size", example=1.0)
        dy = number(dy, "dy", above=0, what="a positive cell size", example=1.0)
        for name, v, n in (("dx", dx, cols), ("dy", dy, rows)):
            if not v * n < 1e306:
                raise ChartError(
                    f"{name} = {v!r} is too large a cell size: the chart would span "
                    f"{v * n:g} units; rescale the cell sizes"
                )
        grid.dx, grid.dy = float(dx), float(dy)
        if chart.y is None:
            chart.y, chart.x = np.arange(rows) * float(dy), np.arange(cols) * float(dx)
    return chart
