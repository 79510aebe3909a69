"""PreparedChart.route(): the one query, for every cost model (seaway.models); route() and
cost_field() on top. Validate in Python, search in C++ (seaway._core)."""

from __future__ import annotations

import numpy as np

from . import _core, _exact
from ._chart import Chart, as_chart
from ._interrupt import interruptible
from .errors import NoRouteError
from .models import CostModel, EdgeCost, as_model
from .route import Route

DIRECTIONS = ("full", "unique")
METHODS = _exact.METHODS


def _check_options(neighbourhood, directions):
    if isinstance(neighbourhood, bool) or not isinstance(neighbourhood, (int, np.integer)):
        raise TypeError(f"neighbourhood must be an odd integer from 3 to 15, got {neighbourhood!r}")
    if neighbourhood < 3 or neighbourhood > 15 or neighbourhood % 2 == 0:
        raise ValueError(
            f"neighbourhood must be odd and between 3 and 15 (the k of the k x k stencil), got "
            f"{neighbourhood}; e.g. neighbourhood=5"
        )
    if directions not in DIRECTIONS:
        raise ValueError(f"directions must be one of {DIRECTIONS}, got {directions!r}")


_heuristic_weight = _exact.heuristic_weight


def _nearest_passable(chart: Chart, rc) -> tuple[int, int] | None:
    ok = np.isfinite(chart.values) & (chart.values >= 0)
    if chart.land is not None:
        ok &= chart.land == 0
    cand = np.argwhere(ok)
    if cand.size == 0:
        return None
    d2 = ((cand - np.asarray(rc)) ** 2).sum(axis=1)
    r, c = cand[int(np.argmin(d2))]
    return int(r), int(c)


def _describe(chart: Chart, rc) -> str:
    r, c = rc
    if chart.geographic:
        return f"pixel ({r}, {c}) at lat {chart.lat[r]:.4f}, lon {chart.lon[c]:.4f}"
    return f"pixel ({r}, {c})"


def locate(chart: Chart, point, name: str) -> tuple[int, int]:
    """The pixel of a start or end point: (lat, lon) on geographic charts, (row, col) otherwise."""
    try:
        a, b = (float(v) for v in point)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a pair of numbers, got {point!r}") from None
    if not (np.isfinite(a) and np.isfinite(b)):
        raise ValueError(f"{name} must be finite, got {point!r}")
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
            lat_lo, lat_hi = sorted((chart.lat[0], chart.lat[-1]))
            raise ValueError(
                f"{name} (lat {a:g}, lon {b:g}) lies outside the chart (lat {lat_lo:g} to "
                f"{lat_hi:g}, lon {chart.lon[0]:g} to {chart.lon[-1]:g}); give a point on the "
                "chart as (lat, lon)"
            )
        r, c = min(int(round(r)), rows - 1), min(int(round(c)), cols - 1)
    else:
        if a != int(a) or b != int(b):
            raise ValueError(
                f"{name} must be a (row, col) pixel index on a planar chart, got {point!r}; to give "
                "(lat, lon) points, pass lat= and lon= (or a DataArray with lat/lon coordinates)"
            )
        r, c = int(a), int(b)
        if not (0 <= r < rows and 0 <= c < cols):
            raise ValueError(
                f"{name} (row {r}, col {c}) lies outside the chart of {rows} rows x {cols} columns; "
                f"give a (row, col) pixel index with 0 <= row < {rows} and 0 <= col < {cols}"
            )
    if not chart.passable((r, c)):
        near = _nearest_passable(chart, (r, c))
        hint = (
            f"the nearest passable pixel is {_describe(chart, near)}"
            if near
            else "no pixel of the chart is passable"
        )
        raise ValueError(f"{name} is on an impassable pixel (land, NaN or infinite cost): {_describe(chart, (r, c))}; {hint}")
    return r, c


# Route costs are sums of (cost x step length) in double precision: every step cost must be a
# normal number (subnormal steps lose the precision that exact A* relies on), and a route whose
# cost overflows to inf would read as "no route".
MAX_TOTAL, MIN_STEP = 1e300, 1e-290


def _step_range(chart: Chart, neighbourhood: int) -> tuple[float, float]:
    """Bounds on a step's length: (shortest, longest); lat/lon: 1 mm and half the Earth."""
    if chart.geographic:
        return 1e-6, np.pi * 6371.0088
    g = chart.grid
    return min(g.dx, g.dy), (neighbourhood - 1) / 2 * float(np.hypot(g.dx, g.dy))


def _check_tiny(chart: Chart, neighbourhood: int) -> None:
    u = chart.values
    shortest, _ = _step_range(chart, neighbourhood)
    limit = MIN_STEP / shortest
    lowest = chart.lowest if chart.lowest == chart.lowest else np.fmin.reduce(u, axis=None)
    if not lowest < limit:  # the usual case: known from validation, or one fast pass
        return
    tiny = (u > 0) & (u < min(limit, float(np.finfo(u.dtype).max)))
    if tiny.any():
        raise ValueError(
            f"positive costs as small as {float(u[tiny].min()):g} with steps of {shortest:g} are "
            f"too small for double precision (step costs below {MIN_STEP:g}); rescale the costs "
            "(or dx, dy), or use 0 for free pixels"
        )


def _check_overflow(chart: Chart, neighbourhood: int) -> None:
    """Called when a search left pixels at inf cost: was it overflow rather than no route?"""
    u = chart.values
    _, longest = _step_range(chart, neighbourhood)
    limit = MAX_TOTAL / (longest * u.size)
    big = (u > min(limit, float(np.finfo(u.dtype).max))) & (u < np.inf)
    if big.any():
        raise ValueError(
            f"costs up to {float(u[big].max()):g} with steps up to {longest:g} long can overflow "
            f"a route's cost (double precision) on a chart of {u.size} pixels; rescale the costs "
            f"(or dx, dy) so that largest cost x step length x pixel count stays below {MAX_TOTAL:g}"
        )


class PreparedChart:
    """A chart validated and prepared once for many routes, under any cost model.

    The land clearance and step lengths are built at construction; every query borrows a
    search workspace that is kept for the next one, so repeated queries allocate nothing
    large, and queries from several threads run at once (the GIL is released). The cost and
    land arrays are read in place: do not modify them while the PreparedChart is in use.
    `edge_cost` is the default model of route() and cost_field()."""

    def __init__(self, cost, *, lat=None, lon=None, dx=1.0, dy=1.0, land=None, neighbourhood=5,
                 directions="full", edge_cost="max", landmarks=0, keep_away=(), zones=()):
        _check_options(neighbourhood, directions)
        model = EdgeCost(edge_cost)
        if keep_away or zones:  # rasterised once, with the chart (seaway.constraints)
            from .constraints import constrain
            cost = constrain(cost, keep_away=keep_away, zones=zones, lat=lat, lon=lon, dx=dx,
                             dy=dy, land=land)
        chart = as_chart(cost, lat=lat, lon=lon, dx=dx, dy=dy, land=land)
        self._setup(chart, neighbourhood, directions, model, "segment")
        self._dims = getattr(cost, "dims", None)
        if landmarks:
            self.prepare_landmarks(landmarks)

    @classmethod
    def _from_chart(cls, chart: Chart, neighbourhood, directions, model: CostModel, land_rule):
        """A prepared chart with engine options the public API does not offer (seaway.compat)."""
        self = cls.__new__(cls)
        self._setup(chart, neighbourhood, directions, model, land_rule)
        self._dims = None
        return self

    def _setup(self, chart, neighbourhood, directions, model, land_rule):
        _check_tiny(chart, neighbourhood)
        self.chart, self.model = chart, model
        self.neighbourhood, self.directions = neighbourhood, directions
        self._router = _core.make_router(chart.values, chart.land, chart.grid, neighbourhood,
                                         directions, land_rule)
        self._landmarks, self.landmark_stats = {}, {}

    def prepare_landmarks(self, count=8, *, model=None) -> dict:
        """Tabulate the least costs from `count` landmark pixels (float32, 4 bytes per pixel
        each) for `model` (default the chart's edge_cost), so that method="landmarks" (and
        "auto") answers later queries by A* with the landmark bound. Returns the stats:
        count, seconds, bytes, bytes_per_pixel, pixels."""
        model = self.model if model is None else as_model(model)
        seed = _nearest_passable(self.chart, tuple(n // 2 for n in self.chart.shape))
        if seed is None:
            raise ValueError("no pixel of the chart is passable: landmarks need water")
        lm, seconds = interruptible(lambda cancel: _exact.build_landmarks(self, count, model, seed,
                                                                          cancel))
        self._landmarks[model.name] = lm
        px = [divmod(int(p), self.chart.shape[1]) for p in lm.pixels]
        self.landmark_stats[model.name] = stats = dict(
            count=len(px), seconds=seconds, bytes=lm.bytes, bytes_per_pixel=lm.bytes / self.chart.values.size,
            pixels=px)
        return stats

    @property
    def edge_cost(self) -> str:
        """The name of the default model."""
        return self.model.name

    def _flat(self, rc) -> int:
        return rc[0] * self.chart.shape[1] + rc[1]

    def _search(self, s, e, weight, model: CostModel, method="astar"):
        """(cost, flat path, stats, cost to each path pixel, per-step values) between two
        located pixels; cost is inf if unreachable."""
        engine = model.engine(self)
        return interruptible(lambda cancel: _exact.search(self, engine, self._flat(s), self._flat(e),
                                                          method, weight, model, cancel))

    def route(self, start, end, *, model=None, method="auto", weight=None, via=(),
              turn_penalty=None) -> Route:
        """The least-cost route from `start` to `end` under `model` (a seaway.models.CostModel
        or an edge-cost name; default the chart's edge_cost), through the `via` points in order
        and with an optional turn penalty (seaway._via). See seaway.route."""
        w = _heuristic_weight(method, weight)
        model = self.model if model is None else as_model(model)
        method = _exact.resolve(self, model, method, weight)
        w = _heuristic_weight(method, weight)  # the resolved method's: auto -> astar is A*
        if (via is not None and len(via)) or turn_penalty is not None:
            from ._via import route_constrained
            return route_constrained(self, start, end, model, method, w, via, turn_penalty)
        chart = self.chart
        s, e = locate(chart, start, "start"), locate(chart, end, "end")
        model.check_ends(self, s, e)
        total, path, stats, cumulative, per_step = self._search(s, e, w, model, method)
        if not np.isfinite(total):
            if isinstance(model, EdgeCost):
                _check_overflow(chart, self.neighbourhood)
            where = f"from start {_describe(chart, s)} to end {_describe(chart, e)}"
            raise NoRouteError(model.no_route(where, self))
        pixels = np.column_stack(np.divmod(path, chart.shape[1])).astype(np.int64)
        route = Route(chart=chart, cost=float(total), pixels=pixels, method=method,
                      neighbourhood=self.neighbourhood, model=model, stats=dict(stats),
                      step_costs=np.diff(cumulative))
        return model.finish(route, per_step)

    def cost_field(self, start, *, model=None):
        """The accumulated least cost from `start` to every pixel (inf where unreachable) under
        `model` (default the chart's edge_cost); a DataArray chart gives a DataArray, in the
        dimension order it came in."""
        model = self.model if model is None else as_model(model)
        engine = model.engine(self)
        chart = self.chart
        s = locate(chart, start, "start")
        model.check_ends(self, s, None)
        field, _ = interruptible(lambda cancel: self._router.field(engine, self._flat(s), cancel))
        if isinstance(model, EdgeCost) and not np.isfinite(field).all():
            _check_overflow(chart, self.neighbourhood)
        if chart.template is None:
            return field
        out = chart.template.copy(data=field)
        if self._dims is not None and out.dims != tuple(self._dims):
            out = out.transpose(*self._dims)  # the chart was turned to (lat, lon): give it back
        out.name = "accumulated_cost"
        out.attrs = {"long_name": "least accumulated cost from the start", "start": str(tuple(start)),
                     "units": model.unit(chart.geographic)}
        return out


def prepare(cost, *, lat=None, lon=None, dx=1.0, dy=1.0, land=None, neighbourhood=5,
            directions="full", edge_cost="max", landmarks=0, keep_away=(), zones=()) -> PreparedChart:
    """Validate and prepare a chart once for many routes; arguments as in route().
    landmarks=N (optional) also tabulates N landmarks for edge_cost (4 N bytes per pixel), so
    that later exact queries run A* with the landmark bound (PreparedChart.prepare_landmarks)."""
    return PreparedChart(cost, lat=lat, lon=lon, dx=dx, dy=dy, land=land,
                         neighbourhood=neighbourhood, directions=directions, edge_cost=edge_cost,
                         landmarks=landmarks, keep_away=keep_away, zones=zones)


def route(cost, start, end, *, lat=None, lon=None, dx=1.0, dy=1.0, land=None, neighbourhood=5,
          directions="full", edge_cost="max", method="auto", weight=None, via=(),
          turn_penalty=None, keep_away=(), zones=()) -> Route:
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
    edge_cost: one of seaway.models.EDGE_COSTS: "max" (paper 000), "mean" (paper 003) or
        "integral" (exact line integral).
    method: "auto" (default: the fastest exact method for the query), "dijkstra", "astar",
        "bidirectional" or "landmarks" (exact; see seaway._exact); "astar" with weight=w > 1
        is weighted A* (cost <= w x optimum).
    via: points the route must pass, in order; each leg between consecutive points is optimal.
    turn_penalty: cost (in the route's units) per degree of course change, or a table
        {angle_deg: cost} linear between its points; searched exactly over (pixel, last step)
        by Dijkstra (method "dijkstra") or A* (any other exact method).
    keep_away: seaway.constraints.KeepAway buffers from land or severe ice (hard and soft).
    zones: seaway.constraints.Zone exclusion or penalty areas (polygons).

    For many routes on one chart, prepare it once with seaway.prepare().
    """
    _heuristic_weight(method, weight)  # reject a bad method before the chart is prepared
    return prepare(cost, lat=lat, lon=lon, dx=dx, dy=dy, land=land, neighbourhood=neighbourhood,
                   directions=directions, edge_cost=edge_cost, keep_away=keep_away,
                   zones=zones).route(start, end, method=method, weight=weight, via=via,
                                      turn_penalty=turn_penalty)


def cost_field(cost, start, *, lat=None, lon=None, dx=1.0, dy=1.0, land=None, neighbourhood=5,
               directions="full", edge_cost="max", keep_away=(), zones=()):
    """The accumulated least cost from `start` to every pixel (inf where unreachable).

    Takes the same arguments as route() (no via points or turn penalty: a field has no single
    path). A DataArray in gives a DataArray out, on the same coordinates."""
    return prepare(cost, lat=lat, lon=lon, dx=dx, dy=dy, land=land, neighbourhood=neighbourhood,
                   directions=directions, edge_cost=edge_cost, keep_away=keep_away,
                   zones=zones).cost_field(start)
