"""PreparedChart: a chart validated and prepared once; its route() is the one query, for every
cost model (seaway.models). Validate in Python, search in C++ (seaway._core).

What the other searches of the package need from a prepared chart (compat, weather, seasons,
constraints) is a method or property of it: `router` (the C++ prepared chart), `flat()`,
`search()`, `landmarks_for()` and `from_chart()`."""

from __future__ import annotations

from collections.abc import Collection, Hashable, Sequence
from typing import TYPE_CHECKING, TypedDict

import numpy as np
import numpy.typing as npt

from .. import native as _core
from ..base.interrupt import interruptible
from ..base.memory import SEARCH, check_pixels
from ..chart.locate import check_overflow, check_tiny, locate, nearest_passable
from ..chart.raster import Chart, as_chart
from ..constraints import constrain
from ..errors import ChartError, NoRouteError, SeawayError
from ..models.base import CostModel, EdgeCost, as_model
from ..result.route import Route
from . import methods
from .constrained import route_constrained
from .result import Search, no_route, to_route

if TYPE_CHECKING:
    import xarray as xr

    from ..constraints import KeepAway, Zone
    from .constrained import Point, TurnPenalty, Via

#: A static model's search on a chart of at most this many pixels x stencil steps runs in the
#: calling (main) thread, without the helper thread that lets Ctrl-C stop it (base.interrupt):
#: 2**23 steps, e.g. 350,000 pixels at 5 x 5, take tens of milliseconds at most.
DIRECT_STEPS = 2**23


class LandmarkStats(TypedDict):
    """What prepare_landmarks() reports (PreparedChart.landmark_stats[model name])."""

    count: int
    seconds: float
    bytes: int
    bytes_per_pixel: float
    #: The landmarks' (row, col).
    pixels: list[tuple[int, int]]


class PreparedChart:
    """A chart validated and prepared once for many routes, under any cost model.

    The land clearance and step lengths are built at construction; every query borrows a
    search workspace that is kept for the next one, so repeated queries allocate nothing
    large, and queries from several threads run at once (the GIL is released). The cost and
    land arrays are read in place: do not modify them while the PreparedChart is in use.
    `edge_cost` is the default model of route() and cost_field()."""

    chart: Chart
    model: CostModel
    neighbourhood: int
    directions: str
    router: _core.PreparedChart
    landmark_stats: dict[str, LandmarkStats]
    _landmarks: dict[str, _core.Landmarks]
    #: The engine models whose steps were pruned (methods.build_landmarks), by model name, kept
    #: alive with the chart.
    pruned_for: dict[str, _core.Model]
    _dims: tuple[Hashable, ...] | None

    def __init__(
        self,
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
    ) -> None:
        methods.check_options(neighbourhood, directions)
        model = EdgeCost(edge_cost)
        if keep_away or zones:  # rasterised once, with the chart (seaway.constraints)
            cost = constrain(
                cost, keep_away=keep_away, zones=zones, lat=lat, lon=lon, dx=dx, dy=dy, land=land
            )
        chart = as_chart(cost, lat=lat, lon=lon, dx=dx, dy=dy, land=land)
        self._setup(chart, neighbourhood, directions, model, "segment")
        self._dims = getattr(cost, "dims", None)
        if landmarks is True:  # the default count for the chart
            self.prepare_landmarks()
        elif landmarks:
            self.prepare_landmarks(landmarks)

    @classmethod
    def from_chart(
        cls, chart: Chart, neighbourhood: int, directions: str, model: CostModel, land_rule: str = "segment"
    ) -> PreparedChart:
        """A prepared chart from a validated Chart, with engine options the public API does not
        offer ("axis" directions, the "pixel" land rule: seaway.compat)."""
        self = cls.__new__(cls)
        self._setup(chart, neighbourhood, directions, model, land_rule)
        self._dims = None
        return self

    def _setup(
        self, chart: Chart, neighbourhood: int, directions: str, model: CostModel, land_rule: str
    ) -> None:
        check_tiny(chart, neighbourhood)
        check_pixels(  # the engine's clearance and one search workspace (seaway.base.memory)
            *chart.shape,
            SEARCH,
            "the search on a chart",
            "route on a coarser chart (e.g. cost[::2, ::2]) or on a part of it",
            SeawayError,
        )
        self.chart, self.model = chart, model
        self.neighbourhood, self.directions = neighbourhood, directions
        self.router = _core.make_router(
            chart.values, chart.land, chart.grid, neighbourhood, directions, land_rule
        )
        self._landmarks, self.landmark_stats = {}, {}
        self.pruned_for = {}
        #: A static model's search here is short (at most DIRECT_STEPS steps): no helper thread.
        self._short = chart.values.size * (neighbourhood**2 - 1) <= DIRECT_STEPS

    def prepare_landmarks(
        self, count: int | None = None, *, model: CostModel | str | None = None
    ) -> LandmarkStats:
        """Tabulate the least costs from `count` landmark pixels (float32, 4 bytes per pixel
        each) for `model` (default the chart's edge_cost), so that method="landmarks" (and
        "auto") answers later queries by A* with the landmark bound. count=None (default):
        16 on charts of at most 2^21 pixels, else 8 (methods.MANY_LANDMARKS_PIXELS). Returns
        the stats: count, seconds, bytes, bytes_per_pixel, pixels."""
        model = self.model if model is None else as_model(model)
        if count is None:
            count = methods.default_landmark_count(self.chart.values.size)
        if isinstance(count, (int, np.integer)) and 1 <= count <= 64:  # (else build_landmarks says)
            check_pixels(
                *self.chart.shape,
                4 * int(count),
                f"{count} landmark tables",
                "prepare fewer landmarks",
                SeawayError,
            )
        seed = nearest_passable(self.chart, tuple(n // 2 for n in self.chart.shape))
        if seed is None:
            raise ChartError("no pixel of the chart is passable: landmarks need water")
        lm, seconds = interruptible(lambda cancel: methods.build_landmarks(self, count, model, seed, cancel))
        self._landmarks[model.name] = lm
        px = [divmod(int(p), self.chart.shape[1]) for p in lm.pixels]
        self.landmark_stats[model.name] = stats = LandmarkStats(
            count=len(px),
            seconds=seconds,
            bytes=lm.bytes,
            bytes_per_pixel=lm.bytes / self.chart.values.size,
            pixels=px,
        )
        return stats

    def landmarks_for(self, model: CostModel) -> _core.Landmarks | None:
        """The landmark tables prepared for `model`, or None."""
        return self._landmarks.get(model.name)

    @property
    def edge_cost(self) -> str:
        """The name of the default model."""
        return self.model.name

    def flat(self, rc: tuple[int, int]) -> int:
        """The flat index of pixel (row, col)."""
        return rc[0] * self.chart.shape[1] + rc[1]

    def search(
        self, s: tuple[int, int], e: tuple[int, int], weight: float, model: CostModel, method: str = "astar"
    ) -> Search:
        """The search between two located pixels (cost inf if unreachable)."""
        engine = model.engine(self)
        return interruptible(
            lambda cancel: methods.search(
                self, engine, self.flat(s), self.flat(e), method, weight, model, cancel
            ),
            direct=model.static and self._short,
        )

    def route(
        self,
        start: Point,
        end: Point,
        *,
        model: CostModel | str | None = None,
        method: str = "auto",
        weight: float | None = None,
        via: Via | None = (),
        turn_penalty: TurnPenalty | None = None,
    ) -> Route:
        """The least-cost route from `start` to `end` under `model` (a seaway.models.CostModel
        or an edge-cost name; default the chart's edge_cost), through the `via` points in order
        and with an optional turn penalty (seaway.engine.constrained). See seaway.route."""
        methods.heuristic_weight(method, weight)
        model = self.model if model is None else as_model(model)
        requested, method = method, methods.resolve(self, model, method, weight)
        w = methods.heuristic_weight(method, weight)  # the resolved method's: auto -> astar is A*
        if (via is not None and len(via)) or turn_penalty is not None:
            return route_constrained(self, start, end, model, method, w, via, turn_penalty)
        s, e = locate(self.chart, start, "start"), locate(self.chart, end, "end")
        model.check_ends(self, s, e)
        if (voyage := methods.for_voyage(self, model, requested, weight, method, s, e)) != method:
            method, w = voyage, methods.heuristic_weight(voyage, weight)
        found = self.search(s, e, w, model, method)
        if not found.found:
            raise no_route(self, model, (("start", s), ("end", e)))
        return model.finish(to_route(self, found, model, method), found.per_step)

    def routes(
        self, start: Point, ends: Sequence[Point], *, model: CostModel | str | None = None
    ) -> list[Route | NoRouteError]:
        """The routes from `start` to each of `ends` under `model` from one Dijkstra search, run
        until every end is reached: each is the route route(start, end, method="dijkstra")
        gives, step for step; an end no route reaches gives its NoRouteError in its place.
        Ends are located and checked as route() does (a bad end raises)."""
        model = self.model if model is None else as_model(model)
        s = locate(self.chart, start, "start")
        targets = [locate(self.chart, e, "end") for e in ends]
        for e in targets:
            model.check_ends(self, s, e)
        engine = model.engine(self)
        flat = [self.flat(e) for e in targets]
        found = interruptible(lambda cancel: self.router.routes(engine, self.flat(s), flat, cancel))
        out: list[Route | NoRouteError] = []
        for e, q in zip(targets, found):
            f = Search.from_core(q)
            if f.found:
                out.append(model.finish(to_route(self, f, model, "dijkstra"), f.per_step))
            else:
                out.append(no_route(self, model, (("start", s), ("end", e))))
        return out

    def cost_field(
        self, start: Point, *, model: CostModel | str | None = None
    ) -> npt.NDArray[np.float64] | xr.DataArray:
        """The accumulated least cost from `start` to every pixel (inf where unreachable) under
        `model` (default the chart's edge_cost); a DataArray chart gives a DataArray, in the
        dimension order it came in."""
        model = self.model if model is None else as_model(model)
        engine = model.engine(self)
        chart = self.chart
        s = locate(chart, start, "start")
        model.check_ends(self, s, None)
        field, _ = interruptible(lambda cancel: self.router.field(engine, self.flat(s), cancel))
        if model.static and not np.isfinite(field).all():
            check_overflow(chart, self.neighbourhood)
        if chart.template is None:
            return field
        out = chart.template.copy(data=field)
        if self._dims is not None and out.dims != tuple(self._dims):
            out = out.transpose(*self._dims)  # the chart was turned to (lat, lon): give it back
        out.name = "accumulated_cost"
        out.attrs = {
            "long_name": "least accumulated cost from the start",
            "start": str(tuple(start)),
            "units": model.unit(chart.geographic),
        }
        return out
