"""Time through a season of ice charts (seaway.models re-exports it)."""

from __future__ import annotations

import dataclasses
import warnings
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from .. import native as _core
from ..base.units import KM_PER_NM
from ..base.validate import number
from ..chart.locate import describe
from ..errors import ChartError, ForecastError, SeawayError
from ..ice.classes import get_class
from ..ice.seasonfast import describer, season_rule
from ..ice.seasongrid import SeasonGrid
from ..vessel import Vessel
from .base import CostModel, Prepared, RouteT
from .results import StepValues, Voyage

if TYPE_CHECKING:
    from ..ice import classes  # classes.IceClass: one name in the API pages (seaway.ice re-exports it)
    from ..ice.seasongrid import Departure, SeasonGrid, SeasonLike, SpeedTable
    from .forecast import WeatherGrid


class IceSeasonTime(CostModel):
    """Hours through a season of ice charts: each step crosses the chart valid when
    the ship starts it, at the class's speed there (Andreeva 2021's V = F * V0 via seaway.ice.andreeva,
    or a table per stage and concentration); time-optimal and exact (FIFO). Waiting is allowed
    everywhere (without it the graph is not FIFO and no label-setting search is exact); routes
    list their waits. `season` is a seaway.icenav.season.SeasonGrid (or what it takes); departure
    a date within the season (default its first chart); see seaway.icenav.season for the speeds.
    fast_ice: the stage of fast ice of unknown stage (FA 08, SA 99), chart by chart, as
    seaway.ice.forms says for one chart: "nearby", "closed" or a WMO stage code (None: the one
    read_season recorded, else "nearby"); `.fast_ice` is the rule and `.assumptions` what the
    charts assume, in words (seaway.ice.seasonfast), which every route carries.

    Route.stats.voyage (seaway.models.results.Voyage): hours, departure, arrival, wait_h per
    step, hours_under_way, hours_waiting, waits (pixel, (lat, lon) or (y, x), arrival there,
    hours waited), charts_used (dates), ice_class."""

    name = "ice season time"
    time_dependent = smoothable = True
    #: Warn when the voyage outlasts the last chart's usual validity (it is recorded either way).
    _warn_late = True

    def __init__(
        self,
        season: SeasonGrid | SeasonLike,
        ice_class: str | classes.IceClass = "Arc7",
        v0_kn: float = 12.0,
        *,
        departure: Departure = None,
        speed: str | SpeedTable = "andreeva",
        fast_ice: str | float | None = None,
        **speed_options: Any,
    ) -> None:
        self.v0_kn = number(v0_kn, "v0_kn", above=0, example=12.0)
        self.season = season if isinstance(season, SeasonGrid) else SeasonGrid(season)
        self.ice_class = get_class(ice_class).name
        self.fast_ice: str | float = season_rule(self.season.ds, fast_ice)
        frames, first, self.valid_from_h, self.departure = self.season.class_frames(
            ice_class, v0_kn, departure, speed, fast_ice=self.fast_ice, **speed_options
        )
        self.hours_per_km = frames.hours[first:]  # read-only: shared by every departure's model
        #: What the charts from the departure on assume (fast ice, open and bergy water), in words.
        self.assumptions = self.season.assumptions + self.season.assumed_from(first, self.fast_ice)
        self._open: npt.NDArray[np.bool_] = frames.open_from[first]  # where some chart lets the class go
        if not self._open.any():
            raise SeawayError(
                f"class {self.ice_class} may go nowhere in any chart of the season from "
                f"{self.departure} on; try a stronger class or other speeds"
            )
        self._fastest = float(frames.frame_min[first:].min())
        self._engine: _core.IceSeasonModel | _core.IceWeatherModel = _core.IceSeasonModel(
            self.hours_per_km,
            list(self.valid_from_h),
            self._fastest,
            float(frames.frame_max[first:].max()),
            frames.closed_for[first:],
        )

    @property
    def open_somewhen(self) -> npt.NDArray[np.bool_]:
        """Pixels some chart from the departure on lets the class use (read-only)."""
        return self._open

    def unit(self, geographic: bool) -> str:
        return "h"

    def engine(self, prepared: Prepared) -> _core.IceSeasonModel | _core.IceWeatherModel:
        if prepared.chart.shape != self.season.shape:
            raise ChartError(
                f"the season's charts have {self.season.shape} pixels but the chart "
                f"{prepared.chart.shape}: route on the season's grid "
                "(seaway.icenav.season.SeasonGrid.prepare)"
            )
        return self._engine

    def check_ends(self, prepared: Prepared, start: tuple[int, int], end: tuple[int, int] | None) -> None:
        for name, rc in (("start", start), ("end", end)):
            if rc is None or self._open[rc]:
                continue
            open_ = np.argwhere(self._open & ~self.season.dry)
            near = (
                f"the nearest pixel it may use is "
                f"{describe(prepared.chart, tuple(open_[np.argmin(((open_ - rc) ** 2).sum(1))]))}"
                if open_.size
                else "it may use no pixel of the chart"
            )
            ice = describer(self.season.ds.isel(time=-1), self.fast_ice)(*rc)
            raise SeawayError(
                f"{name} {describe(prepared.chart, rc)} is in ice class {self.ice_class} "
                f"may not enter in any chart from {self.departure} on (last chart: {ice}); "
                f"{near}"
            )

    def finish(self, route: RouteT, per_step: StepValues) -> RouteT:
        """The route's Voyage: every wait, the charts its steps crossed (the one valid when each
        step departs; a smoothed route's legs: every chart valid while they are under way) and
        the ice class."""
        # found routes carry their step costs; the season's search reports each step's
        # departure (IceSeasonModel, cpp/models.hpp)
        assert route.step_costs is not None and per_step.depart_h is not None
        hours, cum = route.cost, np.concatenate([[0.0], np.cumsum(route.step_costs)])
        depart = per_step.depart_h
        used = np.searchsorted(self.valid_from_h, depart, side="right") - 1
        smoothed = route.stats.smoothing is not None
        if smoothed:  # a leg sails through every chart valid while it is under way
            last = np.searchsorted(self.valid_from_h, cum[1:], side="right") - 1
            used = np.concatenate([np.arange(a, b + 1) for a, b in zip(used, last)] + [used])
        used = np.unique(used)
        times = self.season.times[self.season.times.size - self.valid_from_h.size :]
        voyage = Voyage.along(
            hours,
            route.step_costs,
            depart - cum[:-1],
            self.departure,
            pixels=route.pixels,
            coords=route.coords,
            tick="ms",
            charts_used=tuple(times[k] for k in used),
            ice_class=self.ice_class,
            assumptions=self.assumptions,
        )
        # No route.speed_kn: legs at one speed would contradict the per-step times and waits.
        if hours > self.valid_from_h[-1] + self.season.last_valid_h:
            said = (
                f"the voyage arrives at {voyage.arrival}, beyond the last chart "
                f"({times[-1]}) and its usual validity; the last chart was assumed to hold"
            )
            voyage = dataclasses.replace(voyage, assumptions=voyage.assumptions + (said,))
            if self._warn_late and not smoothed:  # said once, when the search found it
                warnings.warn(said, stacklevel=3)
        return dataclasses.replace(route, stats=dataclasses.replace(route.stats, voyage=voyage))  # type: ignore[type-var]

    def no_route(self, where: str, prepared: Prepared) -> str:
        return (
            f"no route for class {self.ice_class} {where} in any chart of the season from "
            f"{self.departure} on, even waiting for the ice to clear; try a stronger class, "
            "a larger neighbourhood or another end"
        )


class IceWeatherTime(IceSeasonTime):
    """Hours through ice and weather at once (cpp/seaway/ice_weather.hpp): each step crosses the
    ice chart valid when the ship starts it at the class's speed there (as IceSeasonTime), and the
    forecast at that time changes that speed as it changes a calm-water speed (TravelTime:
    Khokhlov's or STAWAVE-1's loss in waves, the wind and wave limits, currents); the class's
    limits still close the ice it may not enter. Exact (FIFO) when the weather is; the ship may
    wait for a later chart. `season` a seaway.icenav.season.SeasonGrid (or what it takes);
    `forecast` a seaway.weather.ForecastGrid on the season's grid, whose departure is the
    voyage's; `vessel` a seaway.vessel.Vessel, its speed_kn the open-water speed V0.

    Route.stats.voyage as IceSeasonTime's, with the forecast and what it assumes."""

    name = "ice and weather time"
    _warn_late = False  # the assumption is in Route.assumptions, which the CLI prints

    def __init__(
        self,
        season: SeasonGrid | SeasonLike,
        forecast: WeatherGrid,
        ice_class: str | classes.IceClass = "Arc7",
        vessel: Vessel | None = None,
        *,
        speed: str | SpeedTable = "andreeva",
        **speed_options: Any,
    ) -> None:
        vessel = Vessel() if vessel is None else vessel
        vessel.check(waves="wave_height" in forecast.arrays)
        super().__init__(
            season, ice_class, vessel.speed_kn, departure=forecast.departure, speed=speed, **speed_options
        )
        if forecast.shape != self.season.shape:
            raise ForecastError(
                f"the forecast has {forecast.shape} pixels but the season's charts "
                f"{self.season.shape}: put it on their grid first "
                "(seaway.weather.projected.on_grid)"
            )
        self.forecast, self.vessel = forecast, vessel
        fastest_kn = 1.0 / (KM_PER_NM * self._fastest)
        best = fastest_kn + forecast.best_extra_kn(vessel, slowest_kn=0.0)
        assert isinstance(self._engine, _core.IceSeasonModel)  # set so by IceSeasonTime
        self._engine = _core.IceWeatherModel(
            self._engine, forecast.engine(), vessel.to_core(), 1.0 / (KM_PER_NM * best)
        )

    def finish(self, route: RouteT, per_step: StepValues) -> RouteT:
        """IceSeasonTime's Voyage with the forecast and what it assumes."""
        route = super().finish(route, per_step)
        v = route.stats.voyage
        said = tuple(self.forecast.assumed(v.arrival)) + v.assumptions
        voyage = dataclasses.replace(v, forecast=self.forecast.describe(), assumptions=said)
        return dataclasses.replace(route, stats=dataclasses.replace(route.stats, voyage=voyage))  # type: ignore[type-var]

    def no_route(self, where: str, prepared: Prepared) -> str:
        return (
            f"no route for class {self.ice_class} {where} through the ice charts and the "
            f"forecast from {self.departure} on (the class's ice limits, the vessel's wind and "
            "wave limits), even waiting for the ice to clear; try a stronger class, another "
            "departure or another end"
        )
