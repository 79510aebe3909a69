"""Route.stats, typed: the search's own figures and what each part of the package that shaped the
route adds (the model's voyage or fuel, the least-danger fallback, via points and turn
penalties, smoothing, the corridor). A part that did not shape the route leaves its field None.

Every object here is frozen: the part that adds a result replaces Route.stats with
dataclasses.replace(route.stats, part=...)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from ..models.results import FuelUse, Voyage, Wait

__all__ = [
    "Constraints",
    "CorridorStencil",
    "Danger",
    "DangerLeg",
    "FuelUse",
    "RouteStats",
    "SearchStats",
    "Smoothing",
    "Voyage",
    "Wait",
]


@dataclass(frozen=True)
class SearchStats:
    """The search's own figures (cpp/seaway/search.hpp SearchStats); for a route of several
    legs (via points), the legs' figures combined by plus()."""

    #: Pixels (or (pixel, last step) states of a turn-penalty search) taken off the queue; both
    #: sides summed for the bidirectional search.
    settled: int = 0
    #: The largest frontier (entries in the queue).
    heap_peak: int = 0
    #: The search's own memory at its peak, bytes.
    state_bytes: int = 0
    #: The smallest passable cost per unit length (the factor of A*'s bound).
    min_cost: float = float("inf")

    @classmethod
    def from_core(cls, s: Any) -> SearchStats:
        """From the C++ search's figures (_core.SearchStats)."""
        return cls(
            settled=int(s.settled),
            heap_peak=int(s.heap_peak),
            state_bytes=int(s.state_bytes),
            min_cost=float(s.min_cost),
        )

    def plus(self, other: SearchStats) -> SearchStats:
        """Two legs' figures: settled adds up, the peaks take the larger."""
        return SearchStats(
            self.settled + other.settled,
            max(self.heap_peak, other.heap_peak),
            max(self.state_bytes, other.state_bytes),
            min(self.min_cost, other.min_cost),
        )


@dataclass(frozen=True)
class DangerLeg:
    """A stretch of consecutive steps in danger."""

    #: Where it starts and ends, (lat, lon) in degrees.
    start: tuple[float, float]
    end: tuple[float, float]
    #: When the ship enters it, hours after departure.
    start_h: float
    #: How long the ship is in danger along it, hours.
    hours: float
    #: The route's vertices (i, j) it runs between (steps i to j - 1).
    steps: tuple[int, int]


@dataclass(frozen=True, eq=False)
class Danger:
    """The least-time-in-danger fallback (Sotnikova 2009): no route avoided the danger zones
    (wind above Vessel.danger_wind_ms, waves above Vessel.danger_wave_m), so the route spends
    the least hours in them, then the least hours in all."""

    #: Hours in danger over the route.
    hours: float
    #: Hours in danger of each step.
    step_h: npt.NDArray[np.float64]
    #: The stretches in danger (where, when and how long).
    legs: tuple[DangerLeg, ...]


@dataclass(frozen=True)
class Smoothing:
    """What any-angle smoothing (seaway.smoothing.smooth) did."""

    #: The cost of the route before smoothing (the smoothed one never costs more).
    cost_before: float
    #: Course changes before and after.
    course_changes_before: int
    course_changes_after: int
    #: Refinement sweeps run.
    sweeps: int
    #: Legs of the smoothed route.
    shortcut_legs: int
    #: A route on a clock: waits the smoothed route adds, where arriving early would make the
    #: next leg late (the ship then leaves when the route did; seaway.smoothtime).
    waits_added: int = 0


@dataclass(frozen=True)
class Constraints:
    """The query-time constraints the route was found under (seaway.engine.constrained)."""

    #: (row, col) of the via points, in order (empty when there are none).
    via_pixels: tuple[tuple[int, int], ...] = ()
    #: The turn penalty as a table {course change in degrees -> cost in the route's unit},
    #: linear between its points (None without a penalty).
    turn_penalty: dict[float, float] | None = None


@dataclass(frozen=True)
class CorridorStencil:
    """A corridor route found by the C++ engine on the corridor's (row, layer) grid as a planar
    chart (seaway.corridor, steps="stencil"), then re-costed along great circles."""

    #: The cost the engine found on the planar grid.
    planar_cost: float
    #: The largest relative error of the planar step lengths against the great-circle ones.
    planar_length_error: float


@dataclass(frozen=True, eq=False)
class RouteStats:
    """Everything a route reports beyond its path and cost; a part that does not apply is None."""

    #: The search's figures (None for a route no search found, such as a corridor's layer-by-layer
    #: route).
    search: SearchStats | None = None
    #: The route on a clock (the time models TravelTime and IceSeasonTime).
    voyage: Voyage | None = None
    #: Fuel and engine settings (the Fuel model).
    fuel: FuelUse | None = None
    #: The least-danger fallback, set only when the route crosses danger zones.
    danger: Danger | None = None
    #: Smoothing (seaway.smoothing.smooth).
    smoothing: Smoothing | None = None
    #: Via points and turn penalty.
    constraints: Constraints | None = None
    #: The engine's planar search of a corridor route.
    corridor: CorridorStencil | None = None

    @property
    def through_danger(self) -> bool:
        """True when no route avoided the danger zones and this one crosses them (danger)."""
        return self.danger is not None
