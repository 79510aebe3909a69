"""What a search gives back, typed, and the one function that turns it into a Route (or into
NoRouteError, naming the ends and, for static costs, whether the cost overflowed instead)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from ..chart.locate import check_overflow, describe
from ..errors import NoRouteError
from ..models.results import StepValues
from ..result.route import Route
from ..result.stats import RouteStats, SearchStats

if TYPE_CHECKING:
    from .. import native as _core
    from ..models.base import CostModel
    from .prepared import PreparedChart

    #: A located end of a search: its name ("start", "via point 1", ...) and pixel.
    End = tuple[str, tuple[int, int]]


@dataclass(frozen=True)
class Search:
    """One search between two pixels: cost (inf when unreachable), the flat pixel path, the
    figures, the cost to each path pixel and the model's values per step."""

    cost: float
    path: npt.NDArray[np.int64]
    stats: SearchStats
    cumulative: npt.NDArray[np.float64]
    per_step: StepValues = field(default_factory=StepValues)

    @classmethod
    def from_core(cls, result: _core.QueryResult) -> Search:
        """From the C++ search's answer (_core.QueryResult, cpp/results.hpp)."""
        return cls(
            float(result.cost),
            np.asarray(result.path),
            SearchStats.from_core(result.stats),
            np.asarray(result.cumulative, float),
            StepValues.from_core(result.steps),
        )

    @property
    def found(self) -> bool:
        return bool(np.isfinite(self.cost))

    def pixels(self, cols: int) -> npt.NDArray[np.int64]:
        """(n, 2) (row, col) of the path on a chart of `cols` columns."""
        out = np.empty((len(self.path), 2), np.int64)
        np.divmod(self.path, cols, out=(out[:, 0], out[:, 1]))
        return out


def no_route(prepared: PreparedChart, model: CostModel, ends: tuple[End, End]) -> NoRouteError:
    """The error for a search that found nothing between `ends` ((name, pixel) pairs); raises
    ValueError instead when a static cost overflowed (a route exists but its cost is inf)."""
    if model.static:
        check_overflow(prepared.chart, prepared.neighbourhood)
    (a, s), (b, e) = ends
    where = f"from {a} {describe(prepared.chart, s)} to {b} {describe(prepared.chart, e)}"
    return NoRouteError(model.no_route(where, prepared))


def to_route(prepared: PreparedChart, found: Search, model: CostModel, method: str) -> Route:
    """The Route of a found search, before the model adds its own results (model.finish)."""
    chart = prepared.chart
    return Route(
        chart=chart,
        cost=float(found.cost),
        pixels=found.pixels(chart.shape[1]),
        method=method,
        neighbourhood=prepared.neighbourhood,
        model=model,
        stats=RouteStats(search=found.stats),
        step_costs=found.cumulative[1:] - found.cumulative[:-1],  # np.diff's values, less overhead
    )
