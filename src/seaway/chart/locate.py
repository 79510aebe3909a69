"""Points on a validated chart: the pixel of a start or end (locate), its readable name
(describe), the nearest passable pixel, and the checks that a route's cost stays a normal double
(no subnormal steps, no overflow to inf that would read as "no route")."""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

import numpy as np

from ..base.units import EARTH_RADIUS_KM
from ..errors import ChartError, SeawayError, SeawayTypeError
from .raster import Chart


def nearest_passable(chart: Chart, rc: Sequence[int]) -> tuple[int, int] | None:
    ok = np.isfinite(chart.values) & (chart.values >= 0)
    if chart.land is not None:
        ok &= chart.land == 0
    cand = np.argwhere(ok)
    if cand.size == 0:
        return None
    d2 = ((cand - np.asarray(rc)) ** 2).sum(axis=1)
    r, c = cand[int(np.argmin(d2))]
    return int(r), int(c)


def describe(chart: Chart, rc: tuple[int, int]) -> str:
    r, c = rc
    if chart.geographic:
        lat, lon = chart.axes
        return f"pixel ({r}, {c}) at lat {lat[r]:.4f}, lon {lon[c]:.4f}"
    return f"pixel ({r}, {c})"


def locate(chart: Chart, point: Iterable[float], name: str) -> tuple[int, int]:
    """The pixel of a start or end point: (lat, lon) on geographic charts, (row, col) otherwise;
    ValueError when it is off the chart or impassable."""
    r, c = pixel_of(chart, point, name)
    if not chart.passable((r, c)):
        near = nearest_passable(chart, (r, c))
        hint = (
            f"the nearest passable pixel is {describe(chart, near)}"
            if near
            else "no pixel of the chart is passable"
        )
        raise SeawayError(
            f"{name} is on an impassable pixel (land, NaN or infinite cost): {describe(chart, (r, c))}; {hint}"
        )
    return r, c


def pixel_of(chart: Chart, point: Iterable[float], name: str) -> tuple[int, int]:
    """The pixel holding a point, passable or not: (lat, lon) on geographic charts, (row, col)
    otherwise; ValueError when it is off the chart."""
    try:
        a, b = (float(v) for v in point)
    except (TypeError, ValueError):
        raise SeawayTypeError(f"{name} must be a pair of numbers, got {point!r}") from None
    if not (math.isfinite(a) and math.isfinite(b)):  # (Python floats: no ufunc per query)
        raise SeawayError(f"{name} must be finite, got {point!r}")
    rows, cols = chart.shape
    g = chart.grid
    if chart.geographic:
        r = (a - g.lat0) / g.dlat
        # Shift by whole turns so the column lands in [-0.5, period - 0.5): takes 0..360 and
        # -180..180 longitudes alike, on ascending or descending charts, up to half a pixel
        # outside the first column's centre.
        period = 360.0 / abs(g.dlon)
        c = ((b - g.lon0) / g.dlon + 0.5) % period - 0.5
        if g.wrap:
            c = float(int(round(c)) % cols)
        if not (-0.5 <= r <= rows - 0.5 and -0.5 <= c <= cols - 0.5):
            lat, lon = chart.axes
            lat_lo, lat_hi = sorted((lat[0], lat[-1]))
            raise SeawayError(
                f"{name} (lat {a:g}, lon {b:g}) lies outside the chart (lat {lat_lo:g} to "
                f"{lat_hi:g}, lon {lon[0]:g} to {lon[-1]:g}); give a point on the "
                "chart as (lat, lon)"
            )
        r, c = min(int(round(r)), rows - 1), min(int(round(c)), cols - 1)
    else:
        if a != int(a) or b != int(b):
            raise SeawayError(
                f"{name} must be a (row, col) pixel index on a planar chart, got {point!r}; to give "
                "(lat, lon) points, pass lat= and lon= (or a DataArray with lat/lon coordinates)"
            )
        r, c = int(a), int(b)
        if not (0 <= r < rows and 0 <= c < cols):
            raise SeawayError(
                f"{name} (row {r}, col {c}) lies outside the chart of {rows} rows x {cols} columns; "
                f"give a (row, col) pixel index with 0 <= row < {rows} and 0 <= col < {cols}"
            )
    return r, c


# Route costs are sums of (cost x step length) in double precision: every step cost must be a
# normal number (subnormal steps lose the precision that exact A* relies on), and a route whose
# cost overflows to inf would read as "no route".
MAX_TOTAL, MIN_STEP = 1e300, 1e-290


def step_range(chart: Chart, neighbourhood: int) -> tuple[float, float]:
    """Bounds on a step's length: (shortest, longest); lat/lon: 1 mm and half the Earth."""
    if chart.geographic:
        return 1e-6, np.pi * EARTH_RADIUS_KM
    g = chart.grid
    return min(g.dx, g.dy), (neighbourhood - 1) / 2 * float(np.hypot(g.dx, g.dy))


def check_tiny(chart: Chart, neighbourhood: int) -> None:
    u = chart.values
    shortest, _ = step_range(chart, neighbourhood)
    limit = MIN_STEP / shortest
    lowest = chart.lowest if chart.lowest == chart.lowest else np.fmin.reduce(u, axis=None)
    if not lowest < limit:  # the usual case: known from validation, or one fast pass
        return
    tiny = (u > 0) & (u < min(limit, float(np.finfo(u.dtype).max)))
    if tiny.any():
        raise ChartError(
            f"positive costs as small as {float(u[tiny].min()):g} with steps of {shortest:g} are "
            f"too small for double precision (step costs below {MIN_STEP:g}); rescale the costs "
            "(or dx, dy), or use 0 for free pixels"
        )


def check_overflow(chart: Chart, neighbourhood: int) -> None:
    """Called when a search left pixels at inf cost: was it overflow rather than no route?"""
    u = chart.values
    _, longest = step_range(chart, neighbourhood)
    limit = MAX_TOTAL / (longest * u.size)
    big = (u > min(limit, float(np.finfo(u.dtype).max))) & (u < np.inf)
    if big.any():
        raise ChartError(
            f"costs up to {float(u[big].max()):g} with steps up to {longest:g} long can overflow "
            f"a route's cost (double precision) on a chart of {u.size} pixels; rescale the costs "
            f"(or dx, dy) so that largest cost x step length x pixel count stays below {MAX_TOTAL:g}"
        )
