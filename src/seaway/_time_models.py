"""The time-dependent cost models (seaway.models re-exports them): travel time, fuel and wave
danger through a forecast (papers 001, 003, 004), and time through a season of ice charts."""

from __future__ import annotations

import numpy as np

from . import _core
from ._validate import number
from .models import CostModel
from .vessel import Vessel


class _OnForecast(CostModel):
    """A model whose fields come from a forecast (seaway.weather.ForecastGrid) on the chart's grid."""

    def _check_chart(self, prepared):
        if not prepared.chart.geographic:
            raise ValueError(f"the {self.name!r} model needs a lat/lon chart")
        if prepared.chart.shape != self.forecast.shape:
            raise ValueError(f"the forecast has {self.forecast.shape} pixels but the chart "
                             f"{prepared.chart.shape}: route on the forecast's grid "
                             "(seaway.weather.ForecastGrid.prepare)")


class TravelTime(_OnForecast):
    """Hours through a forecast of currents, wind and waves (papers 001, 004); `forecast` is a
    seaway.weather.ForecastGrid (its departure fixes the time axis)."""

    name = "time"

    def __init__(self, forecast, vessel: Vessel | None = None, zones=()):
        vessel = Vessel() if vessel is None else vessel
        vessel.check()
        if "wave_height" in forecast.arrays:
            vessel.check_waves(float(forecast.arrays["wave_height"].max()))
        self.forecast, self.vessel = forecast, vessel
        self.best_speed_kn = vessel.speed_kn + forecast.best_extra_kn(vessel)
        self._engine = _core.TravelTimeModel(forecast.engine(), vessel.to_core(), self.best_speed_kn)
        self.zones = (zones,) if hasattr(zones, "geometry") else tuple(zones)
        if self.zones:  # exclusions, open or closed in time windows (seaway.constraints)
            from .constraints import timed_zone_engine
            self._engine = timed_zone_engine(forecast, self._engine, self.zones)

    def later(self, hours: float) -> TravelTime:
        """The model for a ship leaving `hours` after this model's departure (the next leg of a
        route through via points)."""
        return TravelTime(self.forecast.later(hours), self.vessel, self.zones)

    def unit(self, geographic):
        return "h"

    def engine(self, prepared):
        self._check_chart(prepared)
        return self._engine

    def finish(self, route, per_step):
        hours = route.cost
        route.stats["hours"] = hours
        if self.forecast.departure is not None:
            dep = self.forecast.departure
            route.stats["departure"] = dep
            route.stats["arrival"] = dep + np.timedelta64(int(round(hours * 3600)), "s")
        route.speed_kn = self.vessel.speed_kn
        if "wait_h" in per_step:  # hours waited for zones to open, per step
            route.stats["wait_h"] = per_step["wait_h"]
        return route

    def no_route(self, where, prepared):
        return (f"no route {where} within the vessel's wind and wave limits (and danger zones) "
                "of this forecast; try a later departure, other limits or another end point")


class Fuel(_OnForecast):
    """Fuel + time_value x hours with an engine setting per step (paper 004), on the forecast
    frame valid nearest `at_hours`; `fuel` a seaway.fuel.FuelCurve. Cost in tonnes."""

    name = "fuel"

    def __init__(self, forecast, vessel: Vessel, fuel, time_value_t_per_h=0.0, at_hours=0.0):
        vessel.check()
        number(time_value_t_per_h, "time_value_t_per_h", minimum=0, what="a number >= 0")
        number(at_hours, "at_hours")
        self.forecast, self.vessel, self.fuel = forecast, vessel, fuel
        self.time_value_t_per_h = float(time_value_t_per_h)
        frame = forecast.frame_at(at_hours, ("current_east", "current_north", "wave_height",
                                             "wave_from", "wind_speed"))
        self._engine = _core.FuelModel(frame.engine(), vessel.to_core(), list(fuel.speeds_kn),
                                       list(fuel.rates_t_per_h), self.time_value_t_per_h,
                                       frame.best_extra_kn(vessel))

    def unit(self, geographic):
        return "t (fuel + time value x h)"

    def engine(self, prepared):
        self._check_chart(prepared)
        return self._engine

    def finish(self, route, per_step):
        setting = per_step["setting"].astype(np.int64)
        route.stats.update(fuel_t=float(np.sum(per_step["fuel_t"])),
                           hours=float(np.sum(per_step["hours"])),
                           speeds_kn=np.asarray(self.fuel.speeds_kn)[setting],
                           time_value_t_per_h=self.time_value_t_per_h)
        return route

    def no_route(self, where, prepared):
        return f"no route {where} at any engine setting within the vessel's limits"


class WaveDanger(_OnForecast):
    """Wave danger by heading (paper 003 with MSC.1/Circ.1228): sum (u_i + u_j) / 2 x km with u in
    [1, 10], on the forecast frame valid nearest `at_hours`. Cost in danger x km."""

    name = "wave danger"

    def __init__(self, forecast, ship_length_m, speed_kn, at_hours=0.0):
        number(ship_length_m, "ship_length_m", above=0, example=150.0)
        number(speed_kn, "speed_kn", above=0, example=12.0)
        number(at_hours, "at_hours")
        roles = ("wave_height", "wave_from", "wave_period")
        missing = sorted(set(roles) - set(forecast.arrays))
        if missing:
            from .forecast import STANDARD_NAMES
            raise ValueError(f"wave danger needs {missing}: fields with standard names "
                             + ", ".join(STANDARD_NAMES[m][0] for m in missing))
        self.forecast, self.speed_kn = forecast, float(speed_kn)
        frame = forecast.frame_at(at_hours, roles)
        self._engine = _core.WaveDangerModel(frame.engine(), float(ship_length_m), self.speed_kn)

    def unit(self, geographic):
        return "danger x km"

    def engine(self, prepared):
        self._check_chart(prepared)
        return self._engine

    def finish(self, route, per_step):
        route.speed_kn = self.speed_kn
        return route

    def no_route(self, where, prepared):
        return f"no route at sea {where}"



class IceSeasonTime(CostModel):
    """Hours through a season of ice charts (issue 10): each step crosses the chart valid when
    the ship starts it, at the class's speed there (paper 002's V = F * V0 via seaway.ice.andreeva,
    or a table per stage and concentration); time-optimal and exact (FIFO). Waiting is allowed
    everywhere (without it the graph is not FIFO and no label-setting search is exact); routes
    list their waits. `season` is a seaway.ice.season.SeasonGrid (or what it takes); departure
    a date within the season (default its first chart); see seaway.ice.season for the speeds.

    Route stats: hours, departure, arrival, hours_under_way, hours_waiting, waits (pixel,
    (lat, lon) or (y, x), arrival there, hours waited), charts_used (dates), ice_class."""

    name = "ice season time"

    def __init__(self, season, ice_class="Arc7", v0_kn=12.0, *, departure=None, speed="andreeva",
                 **speed_options):
        from .ice.classes import get_class
        from .ice.season import SeasonGrid

        self.v0_kn = number(v0_kn, "v0_kn", above=0, example=12.0)
        self.season = season if isinstance(season, SeasonGrid) else SeasonGrid(season)
        self.ice_class = get_class(ice_class).name
        self.hours_per_km, self.valid_from_h, self.departure = self.season.hours_per_km(
            ice_class, v0_kn, departure, speed, **speed_options)
        self._open = np.isfinite(self.hours_per_km).any(axis=0)
        if not self._open.any():
            raise ValueError(f"class {self.ice_class} may go nowhere in any chart of the season from "
                             f"{self.departure} on; try a stronger class or other speeds")
        fastest = float(np.min(self.hours_per_km, where=self._open[None], initial=np.inf))
        self._engine = _core.IceSeasonModel(self.hours_per_km, list(self.valid_from_h), fastest)

    def unit(self, geographic):
        return "h"

    def engine(self, prepared):
        if prepared.chart.shape != self.season.shape:
            raise ValueError(f"the season's charts have {self.season.shape} pixels but the chart "
                             f"{prepared.chart.shape}: route on the season's grid "
                             "(seaway.ice.season.SeasonGrid.prepare)")
        return self._engine

    def check_ends(self, prepared, start, end):
        from ._engine import _describe

        for name, rc in (("start", start), ("end", end)):
            if rc is None or self._open[rc]:
                continue
            open_ = np.argwhere(self._open & ~self.season.dry)
            near = (f"the nearest pixel it may use is "
                    f"{_describe(prepared.chart, tuple(open_[np.argmin(((open_ - rc) ** 2).sum(1))]))}"
                    if open_.size else "it may use no pixel of the chart")
            last = self.season.ds.isel(time=-1)
            ice = ", ".join(f"{k} {float(last[k].values[rc]):g}" for k in ("CT", "SA", "thickness")
                            if k in last)
            raise ValueError(f"{name} {_describe(prepared.chart, rc)} is in ice class {self.ice_class} "
                             f"may not enter in any chart from {self.departure} on (last chart: {ice}); "
                             f"{near}")

    def finish(self, route, per_step):
        import warnings

        hours, cum = route.cost, np.concatenate([[0.0], np.cumsum(route.step_costs)])
        depart = per_step["depart_h"]
        wait = depart - cum[:-1]
        at = lambda h: self.departure + np.timedelta64(int(round(h * 3.6e6)), "ms")  # noqa: E731
        coords = route.coords
        waits = [(tuple(int(x) for x in route.pixels[i]), tuple(float(x) for x in coords[i]),
                  at(cum[i]), float(wait[i])) for i in np.flatnonzero(wait > 1e-9)]
        used = np.unique(np.searchsorted(self.valid_from_h, depart, side="right") - 1)
        times = self.season.times[self.season.times.size - self.valid_from_h.size:]
        route.stats.update(hours=hours, departure=self.departure, arrival=at(hours),
                           hours_waiting=float(wait.sum()), hours_under_way=float(hours - wait.sum()),
                           waits=waits, charts_used=[times[k] for k in used], ice_class=self.ice_class)
        # No route.speed_kn: legs at one speed would contradict the per-step times and waits.
        if hours > self.valid_from_h[-1] + self.season.last_valid_h:
            warnings.warn(f"the voyage arrives at {route.stats['arrival']}, beyond the last chart "
                          f"({times[-1]}) and its usual validity; the last chart was assumed to hold",
                          stacklevel=3)
        return route

    def no_route(self, where, prepared):
        return (f"no route for class {self.ice_class} {where} in any chart of the season from "
                f"{self.departure} on, even waiting for the ice to clear; try a stronger class, "
                "a larger neighbourhood or another end")
