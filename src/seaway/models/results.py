"""What a cost model adds to its route (CostModel.finish), typed: a voyage on a clock (the time
models) and the fuel burnt (the fuel model). Route.stats (seaway.result.stats.RouteStats)
holds them as `voyage` and `fuel`; they live here, beside the models, because the models layer
sits below the route's."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal, NamedTuple

import numpy as np
import numpy.typing as npt

if TYPE_CHECKING:
    from .. import native as _core

#: Waits shorter than this (hours) are rounding, not waits.
WAIT_EPS_H = 1e-9


class Wait(NamedTuple):
    """One stop of a voyage: the ship waits at a vertex of the route before its next step."""

    #: (row, col) of the pixel where the ship waits.
    pixel: tuple[int, int]
    #: (lat, lon) in degrees on geographic charts, (y, x) in chart units on planar ones.
    position: tuple[float, float]
    #: When the ship arrives there and starts waiting (None when the voyage has no departure).
    since: np.datetime64 | None
    #: How long it waits, hours.
    hours: float


@dataclass(frozen=True, eq=False)
class Voyage:
    """A route on a clock (TravelTime through a forecast, IceSeasonTime through a season of
    ice charts): when it leaves and arrives, and where it waits."""

    #: Passage time, hours, waits included (the route's cost under a time model).
    hours: float
    #: The departure (None when the forecast has no time axis).
    departure: np.datetime64 | None
    #: The arrival, departure + hours to the second (forecasts) or millisecond (ice seasons).
    arrival: np.datetime64 | None
    #: Hours waited before each step (one value per step; zeros when the ship never waits).
    #: None when the search did not report its waits (the least-danger fallback through zones
    #: closed in time windows).
    wait_h: npt.NDArray[np.float64] | None
    #: Every wait longer than WAIT_EPS_H, in route order.
    waits: tuple[Wait, ...] = ()
    #: The dates of the ice charts the steps crossed (ice seasons; empty for forecasts).
    charts_used: tuple[np.datetime64, ...] = ()
    #: The ice class the route was found for (ice seasons; None for forecasts).
    ice_class: str | None = None
    #: The forecast the route was found through (its files and the times they cover; None for
    #: ice seasons alone).
    forecast: str | None = None
    #: What the voyage's times rest on beyond the data (persistence of a forecast or an ice
    #: chart past its last time), in words; Route.assumptions lists them too.
    assumptions: tuple[str, ...] = ()
    #: Hours of each step when the route's cost is not hours (the fuel model); None when the
    #: step costs are the hours.
    step_h: npt.NDArray[np.float64] | None = None

    @property
    def hours_waiting(self) -> float | None:
        """Hours spent waiting (None when the waits were not reported)."""
        return None if self.wait_h is None else float(np.sum(self.wait_h))

    @property
    def hours_under_way(self) -> float | None:
        """Hours spent moving, hours - hours_waiting (None when the waits were not reported)."""
        waiting = self.hours_waiting
        return None if waiting is None else self.hours - waiting

    @classmethod
    def along(
        cls,
        hours: float,
        step_h: npt.NDArray[np.float64],
        wait_h: npt.NDArray[np.float64] | None,
        departure: np.datetime64 | None,
        *,
        pixels: npt.NDArray[np.int64],
        coords: npt.NDArray[np.float64],
        tick: Literal["s", "ms"] = "s",
        charts_used: tuple[np.datetime64, ...] = (),
        ice_class: str | None = None,
        forecast: str | None = None,
        assumptions: tuple[str, ...] = (),
    ) -> Voyage:
        """The voyage of a route of `hours` whose steps take `step_h` hours each (waits
        included), waiting `wait_h` hours before each step; `pixels` and `coords` are the
        route's vertices; times are rounded to `tick`."""
        per_h = {"s": 3600.0, "ms": 3.6e6}[tick]

        def at(h: float) -> np.datetime64 | None:
            if departure is None:
                return None
            return departure + np.timedelta64(int(round(h * per_h)), tick)

        waited = None if wait_h is None else np.asarray(wait_h, dtype=np.float64)
        stops: tuple[Wait, ...] = ()
        if waited is not None:
            cum = np.concatenate([[0.0], np.cumsum(np.asarray(step_h, dtype=np.float64))])
            px, xy = np.asarray(pixels), np.asarray(coords, dtype=np.float64)
            stops = tuple(
                Wait(
                    (int(px[i, 0]), int(px[i, 1])),
                    (float(xy[i, 0]), float(xy[i, 1])),
                    at(float(cum[i])),
                    float(waited[i]),
                )
                for i in np.flatnonzero(waited > WAIT_EPS_H)
            )
        return cls(
            float(hours),
            departure,
            at(hours),
            waited,
            stops,
            tuple(charts_used),
            ice_class,
            forecast,
            tuple(assumptions),
        )


@dataclass(frozen=True, eq=False)
class FuelUse:
    """The fuel model's route (Sotnikova 2009): fuel burnt and the engine setting of each step."""

    #: Fuel burnt over the route, tonnes.
    fuel_t: float
    #: Passage time, hours.
    hours: float
    #: The setting of each step as a speed through the water, knots (a speed of the fuel curve).
    speeds_kn: npt.NDArray[np.float64]
    #: The time value the route was priced with, tonnes of fuel per hour (cost = fuel_t +
    #: time_value_t_per_h x hours).
    time_value_t_per_h: float


_Steps = npt.NDArray[np.float64] | None


@dataclass(frozen=True, eq=False)
class StepValues:
    """What a model's search reports per step beside the route (one value per step; None where
    the model reports nothing), from the C++ search's typed StepValues; CostModel.finish reads it."""

    #: The fuel model: the engine setting of each step (an index into the fuel curve).
    setting: _Steps = None
    #: The fuel model: hours of each step.
    hours: _Steps = None
    #: The fuel model: fuel burnt on each step, tonnes.
    fuel_t: _Steps = None
    #: A season of ice charts: the hour each step leaves its first pixel (after any wait).
    depart_h: _Steps = None
    #: Zones closed in time windows: hours waited before each step for a zone to open.
    wait_h: _Steps = None

    @classmethod
    def from_core(cls, s: _core.StepValues) -> StepValues:
        """From the C++ search's values (_core.StepValues)."""
        return cls(**{f: _floats(getattr(s, f)) for f in _FIELDS})

    def then(self, other: StepValues) -> StepValues:
        """These steps followed by `other`'s (the legs of a route through via points)."""

        def join(a: _Steps, b: _Steps) -> _Steps:
            return a if b is None else b if a is None else np.concatenate([a, b])

        return StepValues(**{f: join(getattr(self, f), getattr(other, f)) for f in _FIELDS})


_FIELDS = ("setting", "hours", "fuel_t", "depart_h", "wait_h")


def _floats(x: npt.ArrayLike | None) -> _Steps:
    return None if x is None else np.asarray(x, dtype=np.float64)
