"""The one-call API: prepare(), route() and cost_field() build a PreparedChart and ask it."""

from __future__ import annotations

from collections.abc import Collection
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from ..result.route import Route
from . import methods
from .prepared import PreparedChart

if TYPE_CHECKING:
    import xarray as xr

    from ..constraints import KeepAway, Zone
    from .constrained import Point, TurnPenalty, Via


def prepare(
    cost: npt.ArrayLike | xr.DataArray,
    *,
    lat: npt.ArrayLike | None = None,
    lon: npt.ArrayLike | None = None,
    dx: float = 1.0,
    dy: float = 1.0,
    land: npt.ArrayLike | xr.DataArray | None = None,
    neighbourhood: int = 5,
    directions: str = "full",
    edge_cost: str = "max",
    landmarks: int | bool = 0,
    keep_away: KeepAway | Collection[KeepAway] = (),
    zones: Zone | Collection[Zone] = (),
) -> PreparedChart:
    """Validate and prepare a chart once for many routes; arguments as in route().
    landmarks=N (optional) also tabulates N landmarks for edge_cost (4 N bytes per pixel), so
    that later exact queries run A* with the landmark bound (PreparedChart.prepare_landmarks);
    landmarks=True: the default count (16 on charts of up to 2^21 pixels, else 8)."""
    return PreparedChart(
        cost,
        lat=lat,
        lon=lon,
        dx=dx,
        dy=dy,
        land=land,
        neighbourhood=neighbourhood,
        directions=directions,
        edge_cost=edge_cost,
        landmarks=landmarks,
        keep_away=keep_away,
        zones=zones,
    )


def route(
    cost: npt.ArrayLike | xr.DataArray,
    start: Point,
    end: Point,
    *,
    lat: npt.ArrayLike | None = None,
    lon: npt.ArrayLike | None = None,
    dx: float = 1.0,
    dy: float = 1.0,
    land: npt.ArrayLike | xr.DataArray | None = None,
    neighbourhood: int = 5,
    directions: str = "full",
    edge_cost: str = "max",
    method: str = "auto",
    weight: float | None = None,
    via: Via | None = (),
    turn_penalty: TurnPenalty | None = None,
    keep_away: KeepAway | Collection[KeepAway] = (),
    zones: Zone | Collection[Zone] = (),
) -> Route:
    """The least-cost route from `start` to `end` over the raster `cost`.

    cost: 2-D numpy array or xarray.DataArray of cost per unit length (>= 0; inf or NaN is
        impassable). DataArray coordinates named lat/lon, latitude/longitude or y/x, or marked
        by CF attributes, are used.
    start, end: (lat, lon) in degrees on geographic charts, (row, col) on planar charts.
    lat, lon: 1-D regularly spaced pixel-centre coordinates (makes the chart geographic:
        steps are great-circle distances in km).
    dx, dy: cell sizes of a planar chart (default 1).
    land: boolean mask of impassable pixels, same shape as cost.
    neighbourhood: k of the k x k stencil (odd, 3..15).
    directions: "full" (every offset of the square) or "unique" (only offsets with
        gcd(|di|, |dj|) = 1).
    edge_cost: one of seaway.models.EDGE_COSTS: "max" (Grinyak et al. 2022), "mean" (Grinyak et al. 2018),
        "integral" (exact line integral) or "length" (the shortest route through passable pixels:
        the costs only decide where the ship may go).
    method: "auto" (default: the fastest exact method for the query), "dijkstra", "astar",
        "bidirectional" or "landmarks" (exact; see seaway.engine.methods); "astar" with weight=w > 1
        is weighted A* (cost <= w x optimum).
    via: points the route must pass, in order; each leg between consecutive points is optimal.
    turn_penalty: cost (in the route's units) per degree of course change, or a table
        {angle_deg: cost} linear between its points; searched exactly over (pixel, last step)
        by Dijkstra (method "dijkstra") or A* (any other exact method).
    keep_away: seaway.constraints.KeepAway buffers from land or severe ice (hard and soft).
    zones: seaway.constraints.Zone exclusion or penalty areas (polygons).

    For many routes on one chart, prepare it once with seaway.prepare().
    """
    methods.heuristic_weight(method, weight)  # reject a bad method before the chart is prepared
    return prepare(
        cost,
        lat=lat,
        lon=lon,
        dx=dx,
        dy=dy,
        land=land,
        neighbourhood=neighbourhood,
        directions=directions,
        edge_cost=edge_cost,
        keep_away=keep_away,
        zones=zones,
    ).route(start, end, method=method, weight=weight, via=via, turn_penalty=turn_penalty)


def cost_field(
    cost: npt.ArrayLike | xr.DataArray,
    start: Point,
    *,
    lat: npt.ArrayLike | None = None,
    lon: npt.ArrayLike | None = None,
    dx: float = 1.0,
    dy: float = 1.0,
    land: npt.ArrayLike | xr.DataArray | None = None,
    neighbourhood: int = 5,
    directions: str = "full",
    edge_cost: str = "max",
    keep_away: KeepAway | Collection[KeepAway] = (),
    zones: Zone | Collection[Zone] = (),
) -> npt.NDArray[np.float64] | xr.DataArray:
    """The accumulated least cost from `start` to every pixel (inf where unreachable).

    Takes the same arguments as route() (no via points or turn penalty: a field has no single
    path). A DataArray in gives a DataArray out, on the same coordinates."""
    return prepare(
        cost,
        lat=lat,
        lon=lon,
        dx=dx,
        dy=dy,
        land=land,
        neighbourhood=neighbourhood,
        directions=directions,
        edge_cost=edge_cost,
        keep_away=keep_away,
        zones=zones,
    ).cost_field(start)
