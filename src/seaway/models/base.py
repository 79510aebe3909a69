"""Cost models: what a route minimises. Each is one Python class over one C++ functor.

A model knows its name and unit, builds its engine object for a prepared chart (the typed
classes of seaway._core, cpp/models.hpp), adds what the search reports per step to the Route,
and says whether arbitrary straight legs can be priced (smoothing, leg tables of smoothed
routes). PreparedChart.route(start, end, model=...) is the one query; seaway.route,
route_time, route_fuel and route_safest build a model and call it.

Adding a model: a functor in cpp/seaway/ (operator() and bounds()), a struct in cpp/models.hpp
with its entry in `Models`, its class in cpp/register_models.cpp, and a CostModel subclass here
(docs: "Adding a cost model")."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Protocol, TypeVar

import numpy as np
import numpy.typing as npt

from .. import native as _core
from ..chart.legs import Segments, TimedLegs
from ..errors import SeawayError, SeawayTypeError
from .results import StepValues

if TYPE_CHECKING:
    from ..chart.raster import Chart

#: The static edge costs over a raster of cost per unit length: name -> engine class. The
#: public list: the API, the CLI choices and the error texts come from it.
EDGE_COSTS: dict[str, type[_core.RasterRule]] = {
    "max": _core.MaxCost,  # Grinyak et al. 2022: max(u_i, u_j) x length
    "mean": _core.MeanCost,  # Grinyak et al. 2018: (u_i + u_j) / 2 x length
    "integral": _core.IntegralCost,  # the exact line integral along the step
    "length": _core.LengthCost,  # the step's length: the shortest route through passable pixels
}
_PAIR_COSTS = {"max": _core.max_pair_costs, "mean": _core.mean_pair_costs, "length": _core.length_pair_costs}


class Prepared(Protocol):
    """What a model reads of a prepared chart (seaway.engine.PreparedChart, a layer above)."""

    @property
    def chart(self) -> Chart: ...
    @property
    def neighbourhood(self) -> int: ...


class FoundRoute(Protocol):
    """What a model reads and sets of a route as the search found it (seaway.result.route.Route,
    a layer above), when it finishes it."""

    @property
    def cost(self) -> float: ...
    @property
    def pixels(self) -> npt.NDArray[np.int64]: ...
    @property
    def coords(self) -> npt.NDArray[np.float64]: ...
    @property
    def step_costs(self) -> npt.NDArray[np.float64] | None: ...
    def costs(self) -> npt.NDArray[np.float64]: ...

    @property
    def speed_kn(self) -> float | None: ...
    #: seaway.result.stats.RouteStats (a layer above): a model gives back a copy of the route
    #: (dataclasses.replace: a Route is immutable) with its `voyage` or `fuel` replaced.
    @property
    def stats(self) -> Any: ...


#: The route a model finishes: a Route, given back as a copy with the model's results added.
RouteT = TypeVar("RouteT", bound=FoundRoute)


class CostModel:
    """Base class. Subclasses set `name` and their capabilities and implement `engine()`.

    The capabilities are declared here, once; the engine reads them instead of guessing from
    the class or the name: the method choice (bidirectional and landmark searches), turn
    penalties, via points and smoothing."""

    name = "?"
    #: Step costs do not depend on the time of arrival: the backward half of the bidirectional
    #: search can price them, and a cost that overflowed is told from no route.
    static = False
    #: A step costs the same both ways: the landmark bound holds.
    symmetric = False
    #: Takes a turn penalty: route cost per unit length, in the penalty's units.
    turn_penalty = False
    #: The cost is hours along a clock that starts at a departure.
    time_dependent = False
    #: later(hours) gives the model of a ship leaving that much later (the next via leg).
    chainable = False
    #: Arbitrary straight legs can be priced (seaway.smooth), not only the engine's steps.
    smoothable = False

    def later(self, hours: float) -> CostModel:
        """The model for a ship leaving `hours` after this model's departure (chainable only)."""
        raise NotImplementedError(f"the {self.name!r} model cannot depart later")

    def unit(self, geographic: bool) -> str:
        """The unit of a route's cost under this model."""
        raise NotImplementedError

    def engine(self, prepared: Prepared) -> _core.Model:
        """The seaway._core model object for `prepared` (a PreparedChart); validates the pair."""
        raise NotImplementedError

    def check_ends(self, prepared: Prepared, start: tuple[int, int], end: tuple[int, int] | None) -> None:
        """Refuse a start or end pixel (row, col; end None for a cost field) this model can
        never use, naming why and the fix; the chart has checked land already."""

    def finish(self, route: RouteT, per_step: StepValues) -> RouteT:
        """The Route with what this model adds: its typed result built from the per-step values
        (seaway.models.results: a Voyage or FuelUse, put in route.stats with
        dataclasses.replace) and its speed."""
        return route

    def no_route(self, where: str, prepared: Prepared) -> str:
        """The NoRouteError message; `where` names the start and end pixels."""
        return f"no route {where} under the {self.name} model"

    def timed_legs(self, chart: Chart, neighbourhood: int) -> TimedLegs:
        """Arbitrary legs sailed on the clock on `chart` (seaway.chart.legs.TimedLegs): the
        time models that are smoothable."""
        if not (self.time_dependent and self.smoothable):
            raise SeawayError(f"the {self.name!r} model does not sail legs on a clock")
        engine = self.engine(_OnChart(chart, neighbourhood))
        assert isinstance(engine, _TIME_MODELS)  # every smoothable time model's engine
        return TimedLegs(chart, engine, neighbourhood)

    def segments(self, chart: Chart, neighbourhood: int) -> Segments:
        """Pricing and land test of arbitrary legs on `chart` (seaway.chart.legs)."""
        if self.time_dependent and self.smoothable:
            raise SeawayError(
                f"the {self.name!r} model prices legs on the clock (timed_legs), not as a cost "
                "of their own: a leg's hours depend on when it is sailed"
            )
        raise SeawayError(
            f"the {self.name!r} model prices only the engine's steps, not arbitrary straight legs "
            f"(its cost is in {self.unit(chart.geographic)}), so its routes cannot be smoothed or "
            f"re-priced along new legs; smooth a route found with edge_cost in {tuple(EDGE_COSTS)}, "
            "or use the route as found"
        )

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.name!r})"


_TIME_MODELS = (
    _core.TravelTimeModel,
    _core.ZonedTravelTimeModel,
    _core.IceSeasonModel,
    _core.IceWeatherModel,
)


class _OnChart:
    """A chart with its stencil, as a model's engine() reads a prepared one (Prepared)."""

    def __init__(self, chart: Chart, neighbourhood: int) -> None:
        self.chart, self.neighbourhood = chart, neighbourhood


class EdgeCost(CostModel):
    """A static cost per unit length read from the chart's raster, priced per step by `rule`.
    `unit`: the unit of a route's cost on a geographic chart when the raster's cost per km has
    one (e.g. "h" for hours per km: the quickest route); default "cost x km"."""

    static = symmetric = turn_penalty = smoothable = True

    def __init__(self, rule: str = "max", unit: str | None = None) -> None:
        if rule not in EDGE_COSTS:
            raise SeawayError(f"edge_cost must be one of {tuple(EDGE_COSTS)}, got {rule!r}")
        self.name, self._unit = rule, unit

    def unit(self, geographic: bool) -> str:
        length = "km" if geographic else "grid unit"
        if self._unit is not None and geographic:
            return self._unit
        return length if self.name == "length" else f"cost x {length}"  # length: r alone

    def engine(self, prepared: Prepared) -> _core.StaticModel:
        return EDGE_COSTS[self.name](prepared.chart.values)

    def no_route(self, where: str, prepared: Prepared) -> str:
        k = prepared.neighbourhood
        chart = prepared.chart
        closed = (
            ~np.isfinite(chart.values)
            if chart.land is None
            else (~np.isfinite(chart.values) & (chart.land == 0))
        )
        if chart.land is not None and not closed.any():  # only the land can part them
            return (
                f"no route {where}: no chain of passable steps joins them with neighbourhood="
                f"{k} (separate water bodies, or a passage narrower than the land rule allows); "
                "try a larger neighbourhood, check the land mask, or choose another end point"
            )
        return (
            f"no route {where}: no chain of passable steps joins them with neighbourhood={k}: "
            "impassable pixels keep them apart (land, or a cost of inf or NaN, such as ice the "
            "vessel may not enter), or a passage is narrower than the land rule allows; "
            "seaway.engine.reach.explain_no_route (seaway.icenav.noroute for ice charts) says "
            "which, and how far the ship gets"
        )

    def segments(self, chart: Chart, neighbourhood: int) -> Segments:
        return Segments(chart, EDGE_COSTS[self.name](chart.values), neighbourhood)

    def pair_costs(
        self, a: npt.ArrayLike, b: npt.ArrayLike, length: npt.ArrayLike
    ) -> npt.NDArray[np.float64]:
        """Cost of steps of `length` between pixels of costs a and b, from the engine's rule
        ("integral" between two pixel centres: the mean rule, its value on axis steps)."""
        return _PAIR_COSTS.get(self.name, _core.mean_pair_costs)(a, b, length)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, EdgeCost) and other.name == self.name

    def __hash__(self) -> int:
        return hash(("EdgeCost", self.name))


class EnteredPixel(EdgeCost):
    """scikit-image's non-geometric MCP: each step costs the pixel entered (seaway.compat)."""

    symmetric = turn_penalty = smoothable = False

    def __init__(self) -> None:
        self.name = "entered"

    def engine(self, prepared: Prepared) -> _core.EnteredPixelCost:
        return _core.EnteredPixelCost(prepared.chart.values)

    def segments(self, chart: Chart, neighbourhood: int) -> Segments:
        return CostModel.segments(self, chart, neighbourhood)


class TurnPenalised(EdgeCost):
    """The model of a turn-penalty route: a static edge cost whose route cost also holds the
    turn penalties, so arbitrary legs cannot be priced (no smoothing, which would drop them)."""

    smoothable = False
    turn_penalty = False  # it holds its penalties already

    def segments(self, chart: Chart, neighbourhood: int) -> Segments:
        raise SeawayError(
            "a turn-penalty route's cost includes its turn penalties, which smoothing cannot "
            "price along new legs; use the route as found, or smooth a route found without "
            "turn_penalty"
        )


def as_model(model: CostModel | str) -> CostModel:
    """A CostModel from a model or an edge-cost name."""
    if isinstance(model, CostModel):
        return model
    if isinstance(model, str):
        return EdgeCost(model)
    raise SeawayTypeError(
        f"model must be a seaway.models.CostModel or one of {tuple(EDGE_COSTS)}, got {model!r}"
    )
