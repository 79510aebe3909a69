"""The cost and land test of an arbitrary straight leg on a chart, consistent with the engine;
computed in C++ (cpp/seaway/legs.hpp, _core.LegPricer), which also smooths (seaway.smooth); and
the arrival time of a leg sailed on the clock under a time model (TimedLegs,
cpp/seaway/timed_legs.hpp).

Points are fractional (row, col) pixel indices; pixel (i, j) is the closed square
[i - 1/2, i + 1/2] x [j - 1/2, j + 1/2]. A leg is forbidden when the closed path touches the
closed square of an impassable pixel or leaves the chart (the engine's land rule).

Path of a leg: on planar charts the straight segment; on geographic charts the great circle
between its ends, followed through lat/lon index space as a polyline with one vertex every
<= 4 pixels (the chord of a 4-pixel piece departs from the arc by ~1e-3 pixel). A leg that is
one of the engine's stencil steps (pixel centres, offset within the k x k square) is the
engine's straight segment in index space, so it costs exactly what the engine charges.

Cost of a leg: split the path at pixel boundaries into pieces of lengths l_k (great-circle km or
planar units) inside pixels of cost u_k, priced by the model's own rule (the C++ functor's):
* "integral": sum l_k u_k (the engine's exact line integral).
* "max" / "mean": the engine's edge rule applied to the chain of pixels the leg crosses: the
  move between consecutive pixels k, k+1 has length (l_k + l_(k+1))/2 (the first and last
  half-pieces go to the first and last move) and costs max(u_k, u_(k+1)) or their mean per unit
  length; a leg inside one pixel costs l_0 u_0. A stencil step of the engine costs what the
  engine charges (max(u_i, u_j) r or (u_i + u_j)/2 r: only its two ends count).
A piece lying exactly on a pixel boundary is charged the larger of the two sides.
tests/support/reference_legs.py keeps the former numpy implementation as the check of the C++ one."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from .. import native as _core
from ..base import sphere as geo

if TYPE_CHECKING:
    from .raster import Chart

    #: A point in index space: fractional (row, col).
    Vertex = npt.NDArray[np.floating] | Sequence[float]

SUBDIVIDE = 4.0  # index-space length of the pieces a great-circle leg is followed by (legs.hpp)


class Segments:
    """Legs on `chart` priced under `model`, a smoothable engine model of seaway._core built on
    the chart's cost raster (e.g. _core.MaxCost(chart.values); seaway.models.EdgeCost.segments
    builds it), with the land rule of a k x k stencil (`neighbourhood`)."""

    def __init__(self, chart: Chart, model: _core.RasterRule, neighbourhood: int = 3) -> None:
        self.chart, self.half = chart, (neighbourhood - 1) // 2
        g = chart.grid
        grid = _core.Geometry()
        for name in ("rows", "cols", "geographic", "dx", "dy", "lat0", "dlat", "lon0", "dlon"):
            setattr(grid, name, getattr(g, name))
        grid.wrap = bool(chart.geographic and g.wrap)
        # reads chart.values and chart.land in place: NaN, inf, negative and land are impassable
        self.pricer = _core.LegPricer(model, chart.land, grid, self.half)

    def coords(self, pts: npt.ArrayLike) -> npt.NDArray[np.float64]:
        return index_coords(self.chart, pts)

    def is_step(self, p: Vertex, q: Vertex) -> bool:
        d = np.abs(np.asarray(q, float) - p)
        return bool(np.all(p == np.round(p)) and np.all(q == np.round(q)) and d.max() <= self.half)

    def leg(self, p: Vertex, q: Vertex) -> tuple[float, float]:
        """(cost, length) of the leg p -> q; (inf, length) if it is forbidden."""
        return self.pricer.leg(float(p[0]), float(p[1]), float(q[0]), float(q[1]))

    def cost(self, pts: Sequence[Vertex] | npt.NDArray[np.floating]) -> float:
        return float(sum(self.leg(a, b)[0] for a, b in zip(pts[:-1], pts[1:])))


class TimedLegs:
    """Legs on `chart` sailed on the clock under `model`, a time model of seaway._core (a
    TravelTimeModel, IceSeasonModel, IceWeatherModel or ZonedTravelTimeModel on the chart's grid;
    cpp/seaway/timed_legs.hpp), with the land rule of a k x k stencil (`neighbourhood`): the
    path is the one above; an engine step is sailed as the engine sails it, any other leg piece
    by piece through the pixels it crosses, each at the model's rule for that pixel at the time
    the ship enters it; forbidden where it touches the chart's impassable pixels or a pixel the
    model closes while the ship is there."""

    def __init__(self, chart: Chart, model: _core.TimeModel, neighbourhood: int = 3) -> None:
        self.chart = chart
        key = ("timed legs", neighbourhood)
        if key not in chart.kept:  # built once per chart: a season's routes share it
            router = _core.make_router(chart.values, chart.land, chart.grid, neighbourhood, "full", "segment")
            closed = ~(np.isfinite(chart.values) & (chart.values >= 0))
            if chart.land is not None:
                closed |= chart.land.astype(bool)
            chart.kept[key] = (router, closed.astype(np.uint8))
        self.router, closed = chart.kept[key]
        self.pricer = _core.TimedLegs(self.router, model, closed)

    def arrive(self, p: Vertex, q: Vertex, depart_h: float) -> float:
        """Hours after departure at which the leg p -> q, left at depart_h, arrives (inf if it is
        forbidden)."""
        return self.pricer.arrive(float(p[0]), float(p[1]), float(q[0]), float(q[1]), float(depart_h))


def leg_path(chart: Chart, p: Vertex, q: Vertex, straight: bool) -> npt.NDArray[np.float64]:
    """Vertices in index space of the leg p -> q: the straight segment (planar charts, engine
    steps) or the great circle every <= SUBDIVIDE pixels (geographic charts)."""
    p, q = np.asarray(p, float), np.asarray(q, float)
    n_index = float(np.hypot(*(q - p)))
    if not chart.geographic or straight or n_index <= SUBDIVIDE:
        return np.array([p, q])
    g = chart.grid
    lat1, lon1 = g.lat0 + p[0] * g.dlat, g.lon0 + p[1] * g.dlon
    lat2, lon2 = g.lat0 + q[0] * g.dlat, g.lon0 + q[1] * g.dlon
    m = int(np.ceil(n_index / SUBDIVIDE))
    lat, lon = geo.intermediate(lat1, lon1, lat2, lon2, np.linspace(0.0, 1.0, m + 1))
    lon = geo.unwrap_lon(np.concatenate([[lon1], lon]))[1:]
    lon += lon1 - lon[0]
    path = np.column_stack([(lat - g.lat0) / g.dlat, (lon - g.lon0) / g.dlon])
    last = q.copy()
    if g.wrap:  # a leg across the seam of a 360-degree chart ends at q's column + a whole turn
        cols = chart.shape[1]
        last[1] += cols * np.round((path[-1, 1] - q[1]) / cols)
    path[0], path[-1] = p, last
    return path


def index_coords(chart: Chart, pts: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """(n, 2) lat/lon (longitude in the chart's convention) or y/x of fractional (row, col)."""
    p = np.asarray(pts, float).reshape(-1, 2)
    g = chart.grid
    a, b = chart.axes  # (lat, lon) or (y, x): a chart from as_chart always has them
    if chart.geographic:
        lon = g.lon0 + p[:, 1] * g.dlon
        lon = lon % 360.0 if np.nanmax(b) > 180 else geo.wrap_lon(lon)
        return np.column_stack([g.lat0 + p[:, 0] * g.dlat, lon])
    return np.column_stack([a[0] + p[:, 0] * _step(a, g.dy), b[0] + p[:, 1] * _step(b, g.dx)])


def _step(v: npt.ArrayLike, default: float) -> float:
    v = np.asarray(v, float)
    return float((v[-1] - v[0]) / (v.size - 1)) if v.size > 1 else float(default)


def turning_points(vertices: npt.ArrayLike) -> npt.NDArray[np.int64]:
    """Indices of the vertices of the polyline `vertices` ((n, 2) row, col) where its
    direction changes, with both ends."""
    v = np.asarray(vertices, float)
    if len(v) < 3:
        return np.arange(len(v))
    d = np.diff(v, axis=0)
    cross = d[:-1, 0] * d[1:, 1] - d[:-1, 1] * d[1:, 0]
    dot = (d[:-1] * d[1:]).sum(axis=1)
    scale = np.hypot(*d[:-1].T) * np.hypot(*d[1:].T)
    turn = (np.abs(cross) > 1e-9 * scale) | (dot <= 0)
    return np.concatenate([[0], np.flatnonzero(turn) + 1, [len(v) - 1]]).astype(np.int64)
