"""Query-time constraints: via-points (an ordered list of waypoints, each leg optimal) and the
turn penalty (the expanded-state search of cpp/seaway/turns.hpp). Used by PreparedChart.route."""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING, cast

import numpy as np
import numpy.typing as npt

from .. import native as _core
from ..base.interrupt import interruptible
from ..chart.locate import locate
from ..errors import SeawayError, SeawayTypeError
from ..models.base import TurnPenalised
from ..models.results import StepValues
from ..result.route import Route
from ..result.stats import Constraints, RouteStats, SearchStats
from .methods import EDGE_COST_NAMES
from .result import Search, no_route

if TYPE_CHECKING:
    from ..models.base import CostModel
    from .prepared import PreparedChart

    #: A start, end or via point: (lat, lon) on geographic charts, (row, col) on planar ones.
    Point = Iterable[float]
    #: Via points: a list of points or an (n, 2) array of them.
    Via = Sequence[Point] | npt.NDArray[np.number]
    #: A cost per degree of course change, or a table {angle_deg: cost} / [(angle_deg, cost)].
    TurnPenalty = float | dict[float, float] | Iterable[tuple[float, float]]
    #: (angles in degrees, costs) of a turn penalty.
    Turns = tuple[list[float], list[float]]


def turn_table(turn_penalty: TurnPenalty | None) -> Turns | None:
    """(angles in degrees, costs) of a turn penalty given as a cost per degree of course change
    (a number) or a table {angle_deg: cost} / [(angle_deg, cost), ...], linear between its
    points and flat beyond them; None for no penalty."""
    if turn_penalty is None:
        return None
    if isinstance(turn_penalty, bool):
        raise SeawayTypeError(
            "turn_penalty must be a cost per degree or a table {angle_deg: cost}, got a bool"
        )
    if isinstance(turn_penalty, (int, float, np.integer, np.floating)):
        p = float(turn_penalty)
        if not (math.isfinite(p) and p >= 0):
            raise SeawayError(f"turn_penalty per degree must be finite and >= 0, got {turn_penalty!r}")
        return [0.0, 180.0], [0.0, 180.0 * p]
    items = turn_penalty.items() if isinstance(turn_penalty, dict) else turn_penalty
    try:
        pairs = sorted((float(a), float(c)) for a, c in items)
    except (TypeError, ValueError):
        raise SeawayTypeError(
            "turn_penalty must be a cost per degree or a table {angle_deg: cost} "
            f"(e.g. {{0: 0, 45: 2, 90: 10, 180: 40}}), got {turn_penalty!r}"
        ) from None
    if not pairs:
        raise SeawayError("turn_penalty table is empty; give e.g. {0: 0, 90: 10, 180: 40}")
    angles, costs = [a for a, _ in pairs], [c for _, c in pairs]
    if len(set(angles)) != len(angles):
        raise SeawayError(f"turn_penalty table repeats an angle: {angles}")
    if angles[0] < 0 or angles[-1] > 180:
        raise SeawayError(f"turn_penalty angles must lie in 0..180 degrees, got {angles}")
    if not all(math.isfinite(c) and c >= 0 for c in costs):
        raise SeawayError(f"turn_penalty costs must be finite and >= 0, got {costs}")
    if angles[0] > 0:
        angles, costs = [0.0] + angles, [costs[0]] + costs
    if angles[-1] < 180:
        angles, costs = angles + [180.0], costs + [costs[-1]]
    return angles, costs


def incoming_offset(prepared: PreparedChart, pixels: npt.NDArray[np.int64]) -> int:
    """The stencil index of a path's last step (for the next leg's first turn), or -1."""
    if len(pixels) < 2:
        return -1
    di, dj = (int(v) for v in pixels[-1] - pixels[-2])
    cols = prepared.chart.shape[1]
    if prepared.chart.grid.wrap:
        dj = (dj + cols // 2) % cols - cols // 2
    return _core.offset_index(prepared.router, di, dj)


def via_list(via: Via | None) -> list[Point]:
    """The via points as a list of points (a single point is refused: it is ambiguous)."""
    if via is None:
        return []
    if isinstance(via, np.ndarray):
        via = via.tolist()
    if not isinstance(via, (list, tuple)):
        raise SeawayTypeError(
            f"via must be a list of points ((lat, lon) or (row, col)), got {type(via).__name__}"
        )
    if len(via) == 2 and all(isinstance(v, (int, float, np.integer, np.floating)) for v in via):
        raise SeawayTypeError(
            f"via must be a list of points, got one point {tuple(via)}; write via=[{tuple(via)}]"
        )
    return list(via)


def _check_turn_model(model: CostModel) -> None:
    if not model.turn_penalty:
        raise SeawayError(
            f"turn_penalty works with the static edge costs {EDGE_COST_NAMES}, not the {model.name!r} "
            "model (a time, fuel or danger cost would need its own penalty units and, for time, a "
            "clock that the penalty would shift); route without turn_penalty, or on a static cost"
        )


def search_leg(
    prepared: PreparedChart,
    s: tuple[int, int],
    e: tuple[int, int],
    weight: float,
    model: CostModel,
    turns: Turns | None,
    incoming: int,
    method: str = "astar",
) -> Search:
    """The search of one leg between located pixels; `method` as resolved by
    seaway.engine.methods. The turn search is Dijkstra for "dijkstra" and A* (weighted if asked)
    for every other method: it has no bidirectional or landmark form."""
    if turns is None:
        return prepared.search(s, e, weight, model, method)
    weight = 0.0 if method == "dijkstra" else (weight if method == "astar" else 1.0)
    engine = cast("_core.RasterRule", model.engine(prepared))  # a turn_penalty model (checked)
    angles, costs = turns
    return Search.from_core(
        interruptible(
            lambda cancel: _core.route_turns(
                prepared.router,
                engine,
                prepared.flat(s),
                prepared.flat(e),
                weight,
                angles,
                costs,
                incoming,
                cancel,
            )
        )
    )


def route_constrained(
    prepared: PreparedChart,
    start: Point,
    end: Point,
    model: CostModel,
    method: str,
    weight: float,
    via: Via | None,
    turn_penalty: TurnPenalty | None,
) -> Route:
    """PreparedChart.route with via points and/or a turn penalty: one search per leg, each
    optimal between consecutive points; with a turn penalty, a leg starts with the previous
    leg's last step, so the course change at a via point is charged. A time model's next leg
    departs when the previous one arrives (model.later)."""
    turns = turn_table(turn_penalty)
    if turns is not None:
        _check_turn_model(model)
    chart = prepared.chart
    points = [start, *via_list(via), end]
    names = ["start"] + [f"via point {i + 1}" for i in range(len(points) - 2)] + ["end"]
    located = [locate(chart, p, n) for p, n in zip(points, names)]
    if len(located) > 2 and model.time_dependent and not model.chainable:
        raise SeawayError(
            f"via points on a {model.name!r} route need each leg to depart when the "
            "last one arrives, which this model cannot do yet; route the legs one by "
            "one with their departures"
        )
    pixels, steps, per_step = np.zeros((0, 2), np.int64), [], StepValues()
    figures = SearchStats()
    leg_model, elapsed = model, 0.0
    for i, (s, e) in enumerate(zip(located[:-1], located[1:])):
        incoming = -1 if turns is None else incoming_offset(prepared, pixels)
        if i and model.chainable:
            leg_model = model.later(elapsed)
        leg_model.check_ends(prepared, s, e)
        found = search_leg(prepared, s, e, weight, leg_model, turns, incoming, method)
        if not found.found:
            raise no_route(prepared, model, ((names[i], s), (names[i + 1], e)))
        elapsed += found.cost
        leg = found.pixels(chart.shape[1])
        pixels = leg if i == 0 else np.concatenate([pixels, leg[1:]])
        steps.append(np.diff(found.cumulative))
        per_step = per_step.then(found.per_step)
        figures = found.stats if i == 0 else figures.plus(found.stats)
    asked = Constraints(
        via_pixels=tuple((int(p[0]), int(p[1])) for p in located[1:-1]),
        turn_penalty=None if turns is None else dict(zip(*turns)),
    )
    stats = RouteStats(search=figures, constraints=asked)
    step_costs = np.concatenate(steps)
    route = Route(
        chart=chart,
        cost=float(step_costs.sum()),
        pixels=pixels,
        method=method,
        neighbourhood=prepared.neighbourhood,
        model=model if turns is None else TurnPenalised(model.name),
        stats=stats,
        step_costs=step_costs,
    )
    return model.finish(route, per_step)
