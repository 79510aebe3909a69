"""The cost models over a weather forecast (seaway.models re-exports them): travel time, fuel
and wave danger (Olovyannikov 2025, Grinyak et al. 2018 and Sotnikova 2009)."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable, Mapping, Sequence
from typing import Protocol, cast

import numpy as np
import numpy.typing as npt

from .. import native as _core
from ..base.validate import number
from ..chart.roles import STANDARD_NAMES
from ..constraints import Zone, timed_zone_engine
from ..constraints.timed import TimedGrid
from ..errors import ChartError, ForecastError
from ..vessel import Vessel
from .base import CostModel, Prepared, RouteT
from .results import FuelUse, StepValues, Voyage


class WeatherGrid(TimedGrid, Protocol):
    """What the weather models read of a forecast (seaway.weather.ForecastGrid, a layer above):
    float32 (frames, rows, cols) fields by role, the grid's shape, the engine's forecast."""

    @property
    def arrays(self) -> Mapping[str, npt.NDArray[np.float32]]: ...
    @property
    def shape(self) -> tuple[int, ...]: ...
    def engine(self) -> _core.Forecast: ...
    def best_extra_kn(self, vessel: Vessel, slowest_kn: float | None = None) -> float: ...
    def describe(self) -> str: ...
    def assumed(self, arrival: np.datetime64 | None) -> list[str]: ...
    def frame_at(self, hours: float, roles: Sequence[str]) -> WeatherGrid: ...
    def later(self, hours: float) -> WeatherGrid: ...


class FuelRates(Protocol):
    """A fuel curve (seaway.weather.FuelCurve, a layer above): fuel rate (t/h) at each engine
    setting (calm-water speed, kn)."""

    @property
    def speeds_kn(self) -> Sequence[float]: ...
    @property
    def rates_t_per_h(self) -> Sequence[float]: ...


class _OnForecast(CostModel):
    """A model whose fields come from a forecast (seaway.weather.ForecastGrid) on the chart's grid."""

    forecast: WeatherGrid

    def _check_chart(self, prepared: Prepared) -> None:
        if not prepared.chart.geographic:
            raise ChartError(f"the {self.name!r} model needs a lat/lon chart")
        if prepared.chart.shape != self.forecast.shape:
            raise ForecastError(
                f"the forecast has {self.forecast.shape} pixels but the chart "
                f"{prepared.chart.shape}: route on the forecast's grid "
                "(seaway.weather.ForecastGrid.prepare)"
            )


class TravelTime(_OnForecast):
    """Hours through a forecast of currents, wind and waves (Olovyannikov 2025 and Sotnikova 2009); `forecast` is a
    seaway.weather.ForecastGrid (its departure fixes the time axis)."""

    name = "time"
    time_dependent = chainable = smoothable = True

    def __init__(
        self, forecast: WeatherGrid, vessel: Vessel | None = None, zones: Zone | Iterable[Zone] = ()
    ) -> None:
        vessel = Vessel() if vessel is None else vessel
        vessel.check(waves="wave_height" in forecast.arrays)
        if "wave_height" in forecast.arrays:
            vessel.check_waves(float(forecast.arrays["wave_height"].max()))
        self.forecast, self.vessel = forecast, vessel
        self.best_speed_kn = vessel.speed_kn + forecast.best_extra_kn(vessel)
        self._engine: _core.TravelTimeModel | _core.ZonedTravelTimeModel
        self._engine = _core.TravelTimeModel(forecast.engine(), vessel.to_core(), self.best_speed_kn)
        self.zones: tuple[Zone, ...] = (cast(Zone, zones),) if hasattr(zones, "geometry") else tuple(zones)
        if self.zones:  # exclusions, open or closed in time windows (seaway.constraints)
            self._engine = timed_zone_engine(forecast, self._engine, self.zones)

    def later(self, hours: float) -> TravelTime:
        """The model for a ship leaving `hours` after this model's departure (the next leg of a
        route through via points)."""
        return TravelTime(self.forecast.later(hours), self.vessel, self.zones)

    def unit(self, geographic: bool) -> str:
        return "h"

    def engine(self, prepared: Prepared) -> _core.TravelTimeModel | _core.ZonedTravelTimeModel:
        self._check_chart(prepared)
        return self._engine

    def finish(self, route: RouteT, per_step: StepValues) -> RouteT:
        """The route's Voyage (departure and arrival when the forecast has a time axis; waits
        for zones to open, per step: none without zones, unreported by the least-danger
        fallback, which gives no per-step values) and the vessel's speed."""
        wait_h = per_step.wait_h
        if wait_h is None and not self.zones:
            wait_h = np.zeros(len(route.costs()))
        fc = self.forecast
        voyage = Voyage.along(
            route.cost,
            route.costs(),
            wait_h,
            fc.departure,
            pixels=route.pixels,
            coords=route.coords,
            forecast=fc.describe(),
        )
        voyage = dataclasses.replace(voyage, assumptions=tuple(fc.assumed(voyage.arrival)))
        stats = dataclasses.replace(route.stats, voyage=voyage)
        return dataclasses.replace(route, stats=stats, speed_kn=self.vessel.speed_kn)  # type: ignore[type-var]

    def no_route(self, where: str, prepared: Prepared) -> str:
        return (
            f"no route {where} within the vessel's wind and wave limits (and danger zones) "
            "of this forecast; try a later departure, other limits or another end point"
        )


class Fuel(_OnForecast):
    """Fuel + time_value x hours with an engine setting per step (Sotnikova 2009), on the forecast
    frame valid nearest `at_hours`; `fuel` a seaway.weather.FuelCurve. Cost in tonnes."""

    name = "fuel"

    def __init__(
        self,
        forecast: WeatherGrid,
        vessel: Vessel,
        fuel: FuelRates,
        time_value_t_per_h: float = 0.0,
        at_hours: float = 0.0,
    ) -> None:
        vessel.check()
        number(time_value_t_per_h, "time_value_t_per_h", minimum=0, what="a number >= 0")
        number(at_hours, "at_hours")
        self.forecast, self.vessel, self.fuel = forecast, vessel, fuel
        self.time_value_t_per_h, self.at_hours = float(time_value_t_per_h), float(at_hours)
        frame = forecast.frame_at(
            at_hours, ("current_east", "current_north", "wave_height", "wave_from", "wind_speed")
        )
        self._engine = _core.FuelModel(
            frame.engine(),
            vessel.to_core(),
            list(fuel.speeds_kn),
            list(fuel.rates_t_per_h),
            self.time_value_t_per_h,
            frame.best_extra_kn(vessel),
        )

    def unit(self, geographic: bool) -> str:
        return "t (fuel + time value x h)"

    def engine(self, prepared: Prepared) -> _core.FuelModel:
        self._check_chart(prepared)
        return self._engine

    def finish(self, route: RouteT, per_step: StepValues) -> RouteT:
        """The route's FuelUse: fuel, hours and the engine setting of each step."""
        # the fuel search reports all three (FuelModel, cpp/models.hpp)
        assert per_step.setting is not None and per_step.fuel_t is not None
        assert per_step.hours is not None
        setting = per_step.setting.astype(np.int64)
        use = FuelUse(
            fuel_t=float(np.sum(per_step.fuel_t)),
            hours=float(np.sum(per_step.hours)),
            speeds_kn=np.asarray(self.fuel.speeds_kn, dtype=np.float64)[setting],
            time_value_t_per_h=self.time_value_t_per_h,
        )
        fc, hours = self.forecast, np.asarray(per_step.hours, dtype=np.float64)
        departure = (
            None
            if fc.departure is None
            else fc.departure + np.timedelta64(int(round(self.at_hours * 3.6e12)), "ns")
        )
        voyage = Voyage.along(
            use.hours,
            hours,
            np.zeros(hours.size),
            departure,
            pixels=route.pixels,
            coords=route.coords,
            forecast=fc.describe(),
        )
        said = (
            f"the fuel route reads the weather of one forecast frame, the one valid nearest "
            f"{self.at_hours:g} h after the forecast's first time, for the whole voyage",
        )
        voyage = dataclasses.replace(voyage, step_h=hours, assumptions=said)
        stats = dataclasses.replace(route.stats, fuel=use, voyage=voyage)
        return dataclasses.replace(route, stats=stats)  # type: ignore[type-var]

    def no_route(self, where: str, prepared: Prepared) -> str:
        return f"no route {where} at any engine setting within the vessel's limits"


class WaveDanger(_OnForecast):
    """Wave danger by heading (Grinyak et al. 2018 with MSC.1/Circ.1228): sum (u_i + u_j) / 2 x km with u in
    [1, 10], on the forecast frame valid nearest `at_hours`. Cost in danger x km."""

    name = "wave danger"

    def __init__(
        self, forecast: WeatherGrid, ship_length_m: float, speed_kn: float, at_hours: float = 0.0
    ) -> None:
        number(ship_length_m, "ship_length_m", above=0, example=150.0)
        number(speed_kn, "speed_kn", above=0, example=12.0)
        number(at_hours, "at_hours")
        roles = ("wave_height", "wave_from", "wave_period")
        missing = sorted(set(roles) - set(forecast.arrays))
        if missing:
            raise ForecastError(
                f"wave danger needs {missing}: fields with standard names "
                + ", ".join(STANDARD_NAMES[m][0] for m in missing)
            )
        self.forecast, self.speed_kn = forecast, float(speed_kn)
        frame = forecast.frame_at(at_hours, roles)
        self._engine = _core.WaveDangerModel(frame.engine(), float(ship_length_m), self.speed_kn)

    def unit(self, geographic: bool) -> str:
        return "danger x km"

    def engine(self, prepared: Prepared) -> _core.WaveDangerModel:
        self._check_chart(prepared)
        return self._engine

    def finish(self, route: RouteT, per_step: StepValues) -> RouteT:
        return dataclasses.replace(route, speed_kn=self.speed_kn)  # type: ignore[type-var]

    def no_route(self, where: str, prepared: Prepared) -> str:
        return f"no route at sea {where}"
