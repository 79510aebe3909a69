"""Why no route joins two ends, from the chart itself (the engine's own searches, so the answer
holds for the same stencil and land rule):

* how far the ship gets: the pixel its cost field from the start reaches that is nearest the end
  (nearest_reachable);
* what closes the way: each pixel the ship may not enter gets a level (1, 2, ...: the higher,
  the harder to open; land stays closed), and the least-barrier way between the ends is the
  least-cost route when a pixel of level k costs BASE**k: it crosses as few pixels of the top
  level as it can, then of the next, ... (least_barrier). When even that finds nothing, only the
  land (or the stencil) keeps the ends apart.

explain_no_route puts these into a NoRouteError (seaway.errors) for any cost raster;
seaway.icenav.noroute does it for ice charts, with levels from the ice classes."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from ..base.sphere import distance_km
from ..errors import ChartError, NoRouteError
from .api import route
from .prepared import PreparedChart

if TYPE_CHECKING:
    from ..chart.raster import Chart
    from ..result.route import Route
    from .constrained import Point

#: (row, col) -> the point to report for a pixel (e.g. the lat/lon of a projected chart's pixel).
Show = Callable[[tuple[int, int]], Any]

#: A pixel of level k costs BASE**k: one step into level k outweighs any way at lower levels
#: (more than 1e9 pixel steps of the longest to the shortest step); 12 levels stay below 1e120.
BASE = 1e9


@dataclass(frozen=True)
class Reach:
    """The reachable pixel nearest the end: its (row, col), its point (lat, lon or y, x) and
    its distance to the end (km on geographic charts, chart units on planar ones)."""

    pixel: tuple[int, int]
    point: tuple[float, ...]
    distance: float


def nearest_reachable(prepared: PreparedChart, start: Point, end: Point) -> Reach | None:
    """The pixel the ship reaches from `start` (the prepared chart's cost field) that is nearest
    `end`; None when the start itself is not usable."""
    chart = prepared.chart
    try:
        field = chart_order(prepared.cost_field(start), chart)
    except ValueError:  # an impassable start
        return None
    cand = np.argwhere(np.isfinite(field))
    e = [float(v) for v in end]
    if chart.geographic:
        lat, lon = chart.axes
        d = distance_km(lat[cand[:, 0]], lon[cand[:, 1]], e[0], e[1])
    else:
        y, x = chart.axes
        there = chart.pixel_coords(np.array([[int(e[0]), int(e[1])]]))[0]
        d = np.hypot(y[cand[:, 0]] - there[0], x[cand[:, 1]] - there[1])
    i = int(np.argmin(d))
    r, c = (int(v) for v in cand[i])
    point = tuple(float(v) for v in chart.pixel_coords(np.array([[r, c]]))[0])
    if chart.geographic:
        point = (point[0], (point[1] + 180.0) % 360.0 - 180.0)
    return Reach((r, c), point, float(d[i]))


def least_barrier(
    chart: Chart, levels: npt.ArrayLike, start: Point, end: Point, neighbourhood: int = 5
) -> Route | None:
    """The route between the ends on the validated `chart`'s grid that crosses the least of the
    highest level, then of the next, ... (`levels`, in the chart's (row, col) order: 0 where the
    ship may go, k >= 1 where it may not, the higher the harder; negative: closed, like land);
    None when no way joins them even then."""
    lv = np.asarray(levels, float)
    index = np.where(lv >= 0, lv, -1).astype(np.int64)
    powers = np.append(BASE ** np.arange(max(int(index.max()), 0) + 1, dtype=float), np.inf)
    cost = powers[index]  # index -1 (closed) takes the last entry, inf
    where: dict[str, Any] = {}
    raster: Any = cost
    if chart.template is not None:
        raster = chart.template.copy(data=cost)
        raster.attrs = {}  # no CF flags: the levels are the costs
    elif chart.geographic:
        lat, lon = chart.axes
        where = {"lat": lat, "lon": lon}
    else:
        where = {"dx": chart.grid.dx, "dy": chart.grid.dy}
    try:
        return route(
            raster, start, end, land=chart.land, neighbourhood=neighbourhood, method="dijkstra", **where
        )  # faster than the others on costs this uneven
    except NoRouteError:
        return None


def explain_no_route(
    cost: Any,
    start: Point,
    end: Point,
    *,
    levels: Any = None,
    lat: npt.ArrayLike | None = None,
    lon: npt.ArrayLike | None = None,
    dx: float = 1.0,
    dy: float = 1.0,
    land: Any = None,
    neighbourhood: int = 5,
    show: Show | None = None,
    asked: tuple[Point, Point] | None = None,
) -> NoRouteError:
    """The NoRouteError for ends that `cost` does not join, with its cause ("land" or
    "impassable"), the reachable point nearest the end and its distance (seaway.errors).

    levels: as in least_barrier, on the cost's grid (default: 1 on every impassable pixel that
    is not land). show: (row, col) -> the point to report (e.g. lat/lon of a projected chart's
    pixel; default the pixel's own coordinates); asked: the ends as the user gave them, for the
    message (default start, end)."""
    prepared = PreparedChart(cost, lat=lat, lon=lon, dx=dx, dy=dy, land=land, neighbourhood=neighbourhood)
    chart = prepared.chart
    if levels is None:
        levels = np.where(np.isfinite(chart.values) & (chart.values >= 0), 0.0, 1.0)
    else:
        levels = chart_order(levels, chart)
    if chart.land is not None:
        levels = np.where(chart.land != 0, -1.0, levels)
    way = least_barrier(chart, levels, start, end, neighbourhood)
    reach = nearest_reachable(prepared, start, end)
    unit = "km" if chart.geographic or show else "chart units"
    text = "no route from {} to {}: ".format(*(_pt(p) for p in (asked or (start, end))))
    if way is None:
        text += (
            "even with every impassable pixel that is not land opened, no chain of steps joins "
            f"them with neighbourhood={neighbourhood} (separate water bodies, or a passage "
            "narrower than the land rule allows): check the land mask, try a larger "
            "neighbourhood or choose other ends"
        )
    else:
        text += "pixels of infinite or NaN cost that are not land close the way (the land alone does not)"
    err = NoRouteError(text, cause="land" if way is None else "impassable")
    return with_reach(err, reach, show, unit, (asked or (start, end))[1] if asked else None)


def chart_order(array: Any, chart: Chart) -> npt.NDArray[np.float64]:
    """A raster on the chart's grid (array or DataArray) in the chart's (row, col) order."""
    if hasattr(array, "dims") and chart.template is not None and set(array.dims) == set(chart.template.dims):
        array = array.transpose(*chart.template.dims)
    out = np.asarray(getattr(array, "values", array), float)
    if out.shape != chart.shape:
        raise ChartError(f"a raster of shape {out.shape} is not on the chart's grid {chart.shape}")
    return out


def with_reach(
    err: NoRouteError,
    reach: Reach | None,
    show: Show | None = None,
    unit: str = "km",
    end: Point | None = None,
) -> NoRouteError:
    """`err` with the reachable point nearest the end (attributes and message). show: pixel ->
    (lat, lon) of a projected chart, with `end` the end in lat/lon: the distance is then the
    great-circle distance between them."""
    if reach is None:
        return err
    point, dist = reach.point, reach.distance
    if show is not None:
        point = tuple(float(v) for v in show(reach.pixel))
        if end is not None:
            e = [float(v) for v in end]
            dist = float(distance_km(point[0], point[1], e[0], e[1]))
    return NoRouteError(
        f"{err}; the ship can get as far as {_pt(point, 4)}, {dist:.1f} {unit} from the end",
        cause=err.cause,
        closing_ice=err.closing_ice,
        weakest_class=err.weakest_class,
        reachable=point,
        reachable_km=dist,
    )


def _pt(p: Point, digits: int | None = None) -> str:
    return ",".join(f"{float(v):g}" if digits is None else f"{float(v):.{digits}f}" for v in p)


__all__ = [
    "BASE",
    "Reach",
    "nearest_reachable",
    "least_barrier",
    "explain_no_route",
    "with_reach",
    "chart_order",
]
