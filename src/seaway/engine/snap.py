"""Ends the ship may not use, moved to water that joins them: snap_ends.

An end on an impassable pixel (land, cost inf or NaN: e.g. ice the class may not enter) moves
to the nearest pixel centre, by great-circle distance (chart units on planar charts), that the
ship can use AND reach from the other end: both ends end up in one body of water the vessel can
cross (one component of the engine's own graph: its cost_field from a pixel of it, with the
same stencil and land rule), never each on its own into a pocket cut off from the other. When
only one end is impassable it moves into the other end's water. When both are, the water chosen
is the one that moves them least in total (components are explored nearest first, and the
search stops when no unexplored one can do better). A move longer than `max_km` is refused
(SnapError, naming the distance), so an end is never carried far from where it was asked for.

The requested and the used ends are kept (SnappedEnds.requested / .ends); SnappedEnds.record
puts them and a sentence per moved end on the Route found between them, for every output."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from ..base.sphere import distance_km
from ..chart.locate import pixel_of
from ..errors import SnapError
from .prepared import PreparedChart

if TYPE_CHECKING:
    from ..chart.raster import Chart
    from .constrained import Point

End = tuple[float, ...]
Mask = npt.NDArray[np.bool_]
Distances = npt.NDArray[np.float64]

#: The default largest move of an end (km on geographic charts, chart units on planar ones).
DEFAULT_SNAP_KM = 20.0
MAX_COMPONENTS = 12  # bodies of water explored when both ends must move


@dataclass(frozen=True)
class Move:
    """How one end would move: `name` ("start"/"end"), the point `requested`, its `pixel`, what
    makes that pixel impassable (`why`), the point `to` move to (None: no usable pixel joins the
    other end) and the `distance` (km on geographic charts; inf when there is none)."""

    name: str
    requested: End
    pixel: tuple[int, int]
    why: str
    to: End | None
    distance: float

    def sentence(self, unit: str = "km") -> str:
        here = f"{self.name} {_fmt(self.requested)} is on an impassable pixel ({self.why})"
        if self.to is None:
            return f"{here}; no usable pixel of the chart is joined to the other end"
        return (
            f"{here}; the nearest point the ship may use is {_fmt(self.to, 4)}, "
            f"{self.distance:.1f} {unit} away"
        )


@dataclass(frozen=True)
class SnappedEnds:
    """The ends a route uses. requested: (start, end) as given; ends: (start, end) used (a moved
    end is the centre of its new pixel, longitude in [-180, 180)); moves: the Move of each end
    that moved; unit: of the distances ("km" or "chart units")."""

    requested: tuple[End, End]
    ends: tuple[End, End]
    moves: tuple[Move, ...] = ()
    unit: str = "km"

    @property
    def start(self) -> End:
        return self.ends[0]

    @property
    def end(self) -> End:
        return self.ends[1]

    @property
    def notes(self) -> tuple[str, ...]:
        """A sentence per moved end, as the outputs record it."""
        return tuple(
            f"{m.name} {_fmt(m.requested)} is on an impassable pixel ({m.why}): moved "
            f"{m.distance:.1f} {self.unit} to {_fmt(m.to or (), 4)}"
            for m in self.moves
        )

    def record(self, route: Any) -> Any:
        """`route` (found between .ends) carrying the requested ends (Route.requested, in every
        output) and the moves (Route.assumptions)."""
        return dataclasses.replace(
            route, requested=tuple(self.requested), notes=tuple(route.notes) + self.notes
        )


def _fmt(p: Iterable[float], digits: int | None = None) -> str:
    return ",".join(f"{v:g}" if digits is None else f"{v:.{digits}f}" for v in p)


def snap_ends(
    cost: Any,
    start: Point,
    end: Point,
    *,
    lat: npt.ArrayLike | None = None,
    lon: npt.ArrayLike | None = None,
    dx: float = 1.0,
    dy: float = 1.0,
    land: Any = None,
    neighbourhood: int = 5,
    max_km: float = DEFAULT_SNAP_KM,
    why: Callable[[int, int], str] | None = None,
) -> SnappedEnds:
    """The ends of a route on `cost` (arguments as seaway.route's), an impassable one moved to
    the nearest point the ship may use in water that joins both ends (see the module).

    max_km: the largest move allowed (km on geographic charts, chart units on planar ones); a
        farther one raises SnapError naming the point and its distance (max_km=0: report, never
        move). why(row, col) -> str says what makes a pixel impassable (default: land, or
        its cost). An end off the chart raises ValueError."""
    prepared = PreparedChart(cost, lat=lat, lon=lon, dx=dx, dy=dy, land=land, neighbourhood=neighbourhood)
    return snap_prepared(prepared, start, end, max_km=max_km, why=why)


def snap_prepared(
    prepared: PreparedChart,
    start: Point,
    end: Point,
    *,
    max_km: float = DEFAULT_SNAP_KM,
    why: Callable[[int, int], str] | None = None,
) -> SnappedEnds:
    """snap_ends on a chart prepared once (seaway.prepare): its cost, land, stencil and
    constraints decide which pixels are usable and which water joins the ends (for many
    routes on one chart, e.g. seaway.route_many)."""
    chart = prepared.chart
    requested: tuple[End, End] = (tuple(map(float, start)), tuple(map(float, end)))
    pixels = [pixel_of(chart, p, name) for p, name in zip(requested, ("start", "end"))]
    ok = [chart.passable(px) for px in pixels]
    unit = "km" if chart.geographic else "chart units"
    if all(ok):
        return SnappedEnds(requested, requested, (), unit)
    usable = np.isfinite(chart.values) & (chart.values >= 0)
    if chart.land is not None:
        usable &= chart.land == 0
    cand = np.argwhere(usable)
    dist = [_distances(chart, cand, p) for p in requested]
    water: Mask | None
    if ok[0] or ok[1]:  # the usable end's own water
        water = _component(prepared, pixels[0] if ok[0] else pixels[1], usable)[cand[:, 0], cand[:, 1]]
    else:
        water = _joint_water(prepared, usable, cand, dist)
    moves: list[Move] = []
    ends: list[End | None] = list(requested)
    for k, name in enumerate(("start", "end")):
        if ok[k]:
            continue
        to: End | None
        if water is None or not water.any():
            to, d = None, np.inf
        else:
            i = np.flatnonzero(water)[int(np.argmin(dist[k][water]))]
            to, d = _point(chart, cand[i]), float(dist[k][i])
        reason = why(*pixels[k]) if why else _why(chart, pixels[k])
        moves.append(Move(name, requested[k], pixels[k], reason, to, d))
        ends[k] = to
    far = [m for m in moves if not m.distance <= max_km]
    if far:
        raise SnapError(far, max_km, unit)
    used = (ends[0] or requested[0], ends[1] or requested[1])  # None only with a SnapError above
    return SnappedEnds(requested, used, tuple(moves), unit)


def _why(chart: Chart, rc: tuple[int, int]) -> str:
    if chart.land is not None and chart.land[rc]:
        return "land"
    return "an impassable pixel (cost NaN or infinite)"


def _distances(chart: Chart, cand: npt.NDArray[np.intp], p: End) -> Distances:
    """Distance from p to each candidate pixel centre: km (geographic), chart units (planar)."""
    if chart.geographic:
        lat, lon = chart.axes
        return distance_km(lat[cand[:, 0]], lon[cand[:, 1]], p[0], p[1])
    y, x = chart.axes
    here = chart.pixel_coords(np.array([[int(p[0]), int(p[1])]]))[0]
    return np.asarray(np.hypot(y[cand[:, 0]] - here[0], x[cand[:, 1]] - here[1]), np.float64)


def _point(chart: Chart, rc: Iterable[Any]) -> End:
    """A pixel as an end: its centre (lat, lon in [-180, 180)) or (row, col) on planar charts."""
    r, c = (int(v) for v in rc)
    if not chart.geographic:
        return (r, c)
    lat, lon = chart.axes
    return (float(lat[r]), float((lon[c] + 180.0) % 360.0 - 180.0))


def _component(prepared: PreparedChart, rc: Iterable[Any], usable: Mask) -> Mask:
    """The pixels the ship reaches from pixel rc (the engine's cost field), as a mask."""
    reach: Mask = np.isfinite(np.asarray(prepared.cost_field(_point(prepared.chart, rc)), float))
    return reach & usable


def _joint_water(
    prepared: PreparedChart, usable: Mask, cand: npt.NDArray[np.intp], dist: list[Distances]
) -> Mask | None:
    """Mask (over `cand`) of the body of water with the least total move of both ends: bodies
    explored from the unexplored usable pixel nearest to either end, until no unexplored one
    can beat the best (its total is at least the two nearest unexplored distances)."""
    seen = np.zeros(len(cand), bool)
    best: Mask | None = None
    best_total = np.inf
    for _ in range(MAX_COMPONENTS):
        if seen.all():
            break
        near = [np.where(seen, np.inf, d) for d in dist]
        lower = [float(n.min()) for n in near]
        if sum(lower) >= best_total:
            break
        k = 0 if lower[0] <= lower[1] else 1
        seed = cand[int(np.argmin(near[k]))]
        water = _component(prepared, seed, usable)[cand[:, 0], cand[:, 1]]
        seen |= water
        total = float(dist[0][water].min() + dist[1][water].min())
        if total < best_total:
            best, best_total = water, total
    return best


__all__ = ["DEFAULT_SNAP_KM", "Move", "SnapError", "SnappedEnds", "snap_ends", "snap_prepared"]
