"""The Route a search returns: its pixels, coordinates, cost and length, and the readable form a
navigator uses: waypoints at the course changes, legs with course, distance, time and cost."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..chart.legs import index_coords, leg_path, turning_points
from ..chart.raster import Chart
from ..models.base import CostModel, EdgeCost
from ..native import haversine_km
from .environment import extreme_name  # noqa: F401 - part of this API
from .leg import Leg, route_legs
from .stats import RouteStats
from .summary import route_summary
from .table import route_table
from .timing import SpeedField
from .waypoints import waypoint_list

#: What the layers above add to a route, each put here by its own module, which `import seaway`
#: imports before any route exists (seaway.smoothing: "smoothed"; seaway.output.webmap:
#: "explore", "to_html"): this layer imports nothing above it (pyproject.toml's import contract).
ABOVE: dict[str, Callable[..., Any]] = {}


@dataclass(frozen=True)
class Route:
    """A route a search returned: its pixels, cost and model, and what a navigator reads from it.

    cost: the sum of the step costs, in the model's unit (``unit``: cost x km, h, t, ...).
    pixels: (n, 2) (row, col) of its pixels, both ends included (``coords``: lat/lon or y/x).
    method, stats: the search that found it and its figures (seaway.result.stats).
    model, speed_kn: the cost model (seaway.models) and the speed of the leg table's times.

    Waypoints are the ends and every course change: ``legs()``, ``summary()`` and ``str()`` give
    the leg table; ``smoothed()`` removes the zig-zag, ``with_environment(ds)`` reports a chart's
    variables along the legs, ``to_geojson()``, ``to_html()`` and seaway.export write it."""

    chart: Chart = field(repr=False)
    cost: float
    pixels: np.ndarray  # (n, 2) row, col; both ends included
    method: str = "astar"
    neighbourhood: int = 5
    #: What the route minimises (seaway.models); its unit is .unit.
    model: CostModel = field(default_factory=EdgeCost)
    #: The search's figures and what the model, constraints and smoothing add (seaway.result.stats).
    stats: RouteStats = field(default_factory=RouteStats, repr=False)
    #: (n, 2) fractional (row, col) of the vertices when they are not pixel centres (smoothed).
    points: np.ndarray | None = field(default=None, repr=False)
    #: (n, 2) lat/lon of the vertices when the chart is not a lat/lon grid (corridor routes).
    latlon: np.ndarray | None = field(default=None, repr=False)
    #: Step lengths are WGS84 geodesics between the latlon vertices (projected charts: true km).
    geodesic: bool = field(default=False, repr=False)
    #: Cost of each step between vertices (computed from the chart when None).
    step_costs: np.ndarray | None = field(default=None, repr=False)
    speed_kn: float | None = None
    #: name -> (rows, cols) array on the chart's grid: ice or weather reported along each leg.
    environment: dict = field(default_factory=dict, repr=False)
    name: str = "seaway route"
    #: (start, end) as they were asked for, when recorded (seaway.engine.snap.SnappedEnds.record;
    #: `seaway route` always records them): every output gives them beside the ends used.
    requested: tuple | None = field(default=None, repr=False)
    #: Sentences on how the route was set up (an end moved to usable water): in .assumptions.
    notes: tuple = field(default=(), repr=False)
    #: The speed in the ice its times come from (with_ice_speed; seaway.result.timing).
    ice_speed: SpeedField | None = field(default=None, repr=False)
    #: When a route timed by a speed leaves its start (its schedule: seaway.result.schedule);
    #: a route on a clock has its own (stats.voyage).
    departure: np.datetime64 | None = field(default=None, repr=False)

    @property
    def assumptions(self) -> tuple:
        """What the route rests on: what was assumed to build its chart (e.g. the stage of fast
        ice of unknown stage, seaway.ice.forms: the ``assumptions`` attribute of the cost
        DataArray, which chart_impact sets), then .notes (a moved end); empty when nothing."""
        attrs = getattr(self.chart.template, "attrs", None) or {}
        said = attrs.get("assumptions", ())
        voyage = self.stats.voyage.assumptions if self.stats.voyage is not None else ()
        return ((said,) if isinstance(said, str) else tuple(said)) + tuple(self.notes) + tuple(voyage)

    @property
    def vertices(self) -> np.ndarray:
        """(n, 2) fractional (row, col) of the route's vertices."""
        return self.pixels.astype(float) if self.points is None else np.asarray(self.points, float)

    @property
    def coords(self) -> np.ndarray:
        """(n, 2) lat/lon (geographic charts) or y/x (planar charts) of the route's vertices."""
        if self.latlon is not None:
            return np.asarray(self.latlon, float)
        if self.points is not None:
            return index_coords(self.chart, self.points)
        return self.chart.pixel_coords(self.pixels)

    @property
    def edge_cost(self) -> str:
        """The name of the route's cost model ("max", "mean", "integral", "time", ...)."""
        return self.model.name

    @property
    def unit(self) -> str:
        """The unit of .cost and of each leg's cost."""
        return self.model.unit(self.geographic)

    @property
    def geographic(self) -> bool:
        """True on lat/lon charts (lengths in km, coords lat/lon), False on planar ones."""
        return self.latlon is not None or self.chart.geographic

    @property
    def step_lengths(self) -> np.ndarray:
        """Length of each step: km on geographic charts, grid units on planar charts."""
        if len(self.pixels if self.points is None else self.points) < 2:
            return np.zeros(0)
        c = self.coords
        if self.geodesic and self.latlon is not None:
            import pyproj

            lat, lon = c[:, 0], c[:, 1]
            return np.asarray(pyproj.Geod(ellps="WGS84").inv(lon[:-1], lat[:-1], lon[1:], lat[1:])[2]) / 1e3
        if self.geographic:
            return np.array([haversine_km(a[0], a[1], b[0], b[1]) for a, b in zip(c[:-1], c[1:])])
        g = self.chart.grid  # planar charts never wrap
        d = np.diff(self.vertices, axis=0)
        return np.hypot(d[:, 0] * g.dy, d[:, 1] * g.dx)

    @property
    def length(self) -> float:
        """Total length: km on geographic charts, grid units on planar charts."""
        return float(self.step_lengths.sum())

    # -- readable form -----------------------------------------------------------------------
    def segments(self):
        """The cost and land test of arbitrary legs under the route's model (ValueError for a
        model that prices only the engine's steps)."""
        seg = self.__dict__.get("_segments")
        if seg is None:
            seg = self.__dict__["_segments"] = self.model.segments(self.chart, self.neighbourhood)
        return seg

    def costs(self) -> np.ndarray:
        """Cost of each step between consecutive vertices (they sum to .cost)."""
        if self.step_costs is not None:
            return np.asarray(self.step_costs, float)
        cached = self.__dict__.get("_costs")
        if cached is None:
            seg, v = self.segments(), self.vertices
            cached = self.__dict__["_costs"] = np.array([seg.leg(a, b)[0] for a, b in zip(v[:-1], v[1:])])
        return np.asarray(cached, float)

    def with_speed(self, speed_kn: float | None) -> Route:
        """A copy whose legs are timed at `speed_kn` in open water (None: no times)."""
        return dataclasses.replace(self, speed_kn=speed_kn)

    @property
    def waypoint_index(self) -> np.ndarray:
        """Indices of the vertices that are waypoints: both ends and every course change (on a
        corridor route, every node: each leg is a great circle between nodes)."""
        v = self.vertices
        return np.arange(len(v)) if self.latlon is not None else turning_points(v)

    @property
    def waypoints(self) -> np.ndarray:
        """(m, 2) lat/lon or y/x of the waypoints (ends and course changes)."""
        return self.coords[self.waypoint_index]

    @property
    def course_changes(self) -> int:
        """The number of waypoints between the ends (each is a change of course)."""
        return max(len(self.waypoint_index) - 2, 0)

    def legs(self, speed_kn: float | None = None) -> list[Leg]:
        """The legs between consecutive waypoints, with course, distance, time, cost and the mean
        and maximum of each environment variable along the leg. speed_kn defaults to .speed_kn."""
        return route_legs(self, speed_kn)

    def sample_pixels(self, i: int = 0, j: int | None = None) -> np.ndarray:
        """(n, 2) (row, col) of the pixels crossed between vertices i and j (default the whole
        route), sampled every half pixel along each step; columns may pass the chart's last
        on charts that wrap (take them modulo the width)."""
        v = self.vertices[i : (len(self.vertices) if j is None else j + 1)]
        half = (self.neighbourhood - 1) // 2
        pts = [v[:1]]
        for p, q in zip(v[:-1], v[1:]):  # the leg's own path: a great circle on lat/lon charts
            step = bool(np.all(p == np.round(p)) and np.all(q == np.round(q)) and np.abs(q - p).max() <= half)
            path = leg_path(self.chart, p, q, step)
            for a, b in zip(path[:-1], path[1:]):
                m = max(int(np.ceil(2 * np.abs(b - a).max())), 1)
                pts.append(a + np.linspace(0, 1, m + 1)[1:, None] * (b - a))
        return np.rint(np.concatenate(pts)).astype(np.int64)

    def with_ice_speed(self, knots, model=None, escorted=None) -> Route:
        """A copy whose times come from `knots`, the speed on the chart's grid (a DataArray from
        seaway.ice.speed.ice_speed, whose attributes give the model and the open-water speed,
        or an array with `model`): each leg's time is its length over the speed along it, its
        speed the mean; speed_kn becomes the open-water speed. escorted: where the speed is an
        icebreaker escort's (each leg reports its km under escort)."""
        field = SpeedField.on(self.chart, knots, model, escorted)
        return dataclasses.replace(self, ice_speed=field, speed_kn=field.v0_kn)

    def with_environment(self, data, names=None) -> Route:
        """A copy that reports `data` along each leg: an xarray.Dataset or a dict of DataArrays or
        arrays on the chart's grid (variables of another shape are skipped)."""
        env = dict(self.environment)
        for name in names or list(data.keys()):
            arr = data[name]
            template = self.chart.template
            if hasattr(arr, "dims") and template is not None:
                if set(arr.dims) != set(template.dims):
                    continue
                arr = arr.transpose(*template.dims)
            arr = np.asarray(getattr(arr, "values", arr))
            if arr.shape == self.chart.shape and np.issubdtype(arr.dtype, np.number):
                env[str(name)] = arr
        return dataclasses.replace(self, environment=env)

    def summary(self, speed_kn: float | None = None) -> dict:
        """The route in figures (seaway.result.summary.route_summary): name, ends (and the ends
        requested), cost, length, legs, time, the ice met, assumptions, least depth."""
        return route_summary(self, speed_kn)

    def __str__(self) -> str:
        return route_table(self)

    def smoothed(self, **options) -> Route:
        """Any-angle smoothing (see seaway.smooth)."""
        return ABOVE["smoothed"](self, **options)

    def explore(self, **options):
        """An interactive folium.Map of the route over its chart, working offline (see
        seaway.output.webmap.explore for the options)."""
        return ABOVE["explore"](self, **options)

    def to_html(self, path, **options) -> None:
        """Write the interactive map (explore()) to one self-contained HTML file, atomically."""
        ABOVE["to_html"](self, path, **options)

    def to_geojson(self) -> dict:
        """A GeoJSON Feature (LineString) through the route's waypoints (the ends and course
        changes, as every export gives them: seaway.result.waypoints) with the route's cost and
        length as properties.

        Geographic charts give [lon, lat] positions with longitudes made continuous along the
        route (a route across the antimeridian runs past 180 rather than jumping back)."""
        props = {
            "cost": self.cost,
            "length": self.length,
            "length_units": "km" if self.geographic else "grid units",
            "method": self.method,
            "neighbourhood": self.neighbourhood,
            "edge_cost": self.edge_cost,
            "cost_unit": self.unit,
        }
        coords = waypoint_list(self).positions()
        if len(coords) == 1:
            coords = coords * 2  # a LineString needs two positions; start == end
        return {
            "type": "Feature",
            "geometry": {"type": "LineString", "coordinates": coords},
            "properties": props,
        }
