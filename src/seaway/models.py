"""Cost models: what a route minimises. Each is one Python class over one C++ functor.

A model knows its name and unit, builds its engine object for a prepared chart (the typed
classes of seaway._core, cpp/models.hpp), adds what the search reports per step to the Route,
and says whether arbitrary straight legs can be priced (smoothing, leg tables of smoothed
routes). PreparedChart.route(start, end, model=...) is the one query; seaway.route,
route_time, route_fuel and route_safest build a model and call it.

Adding a model: a functor in cpp/seaway/ (operator() and bounds()), a struct in cpp/models.hpp
with its entry in `Models`, its class in cpp/register_models.cpp, and a CostModel subclass here
(README: "Adding a cost model")."""

from __future__ import annotations

import numpy as np

from . import _core
from ._validate import number
from .vessel import Vessel

#: The static edge costs over a raster of cost per unit length: name -> engine class. The
#: public list: the API, the CLI choices and the error texts come from it.
EDGE_COSTS = {
    "max": _core.MaxCost,  # paper 000: max(u_i, u_j) x length
    "mean": _core.MeanCost,  # paper 003: (u_i + u_j) / 2 x length
    "integral": _core.IntegralCost,  # the exact line integral along the step
}
_PAIR_COSTS = {"max": _core.max_pair_costs, "mean": _core.mean_pair_costs}


class CostModel:
    """Base class. Subclasses set `name` and `smoothable` and implement `engine()`."""

    name = "?"
    #: Arbitrary straight legs can be priced (seaway.smooth), not only the engine's steps.
    smoothable = False

    def unit(self, geographic: bool) -> str:
        """The unit of a route's cost under this model."""
        raise NotImplementedError

    def engine(self, prepared):
        """The seaway._core model object for `prepared` (a PreparedChart); validates the pair."""
        raise NotImplementedError

    def check_ends(self, prepared, start, end):
        """Refuse a start or end pixel (row, col; end None for a cost field) this model can
        never use, naming why and the fix; the chart has checked land already."""

    def finish(self, route, per_step: dict):
        """The Route with what this model adds (stats from the per-step values, speed)."""
        return route

    def no_route(self, where: str, prepared) -> str:
        """The NoRouteError message; `where` names the start and end pixels."""
        return f"no route {where} under the {self.name} model"

    def segments(self, chart, neighbourhood: int):
        """Pricing and land test of arbitrary legs on `chart` (seaway._segments)."""
        raise ValueError(
            f"the {self.name!r} model prices only the engine's steps, not arbitrary straight legs "
            f"(its cost is in {self.unit(chart.geographic)}), so its routes cannot be smoothed or "
            f"re-priced along new legs; smooth a route found with edge_cost in {tuple(EDGE_COSTS)}, "
            "or use the route as found")

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.name!r})"


class EdgeCost(CostModel):
    """A static cost per unit length read from the chart's raster, priced per step by `rule`."""

    smoothable = True

    def __init__(self, rule: str = "max"):
        if rule not in EDGE_COSTS:
            raise ValueError(f"edge_cost must be one of {tuple(EDGE_COSTS)}, got {rule!r}")
        self.name = rule

    def unit(self, geographic):
        return "cost x km" if geographic else "cost x grid unit"

    def engine(self, prepared):
        return EDGE_COSTS[self.name](prepared.chart.values)

    def no_route(self, where, prepared):
        k = prepared.neighbourhood
        return (f"no route {where}: no chain of passable steps joins them with neighbourhood={k} "
                "(separate water bodies, or a passage narrower than the land rule allows); try a "
                "larger neighbourhood, check the land mask, or choose another end point")

    def segments(self, chart, neighbourhood):
        from ._segments import Segments
        return Segments(chart, self.name, neighbourhood)

    def pair_costs(self, a, b, length) -> np.ndarray:
        """Cost of steps of `length` between pixels of costs a and b, from the engine's rule
        ("integral" between two pixel centres: the mean rule, its value on axis steps)."""
        return _PAIR_COSTS.get(self.name, _core.mean_pair_costs)(a, b, length)

    def __eq__(self, other):
        return isinstance(other, EdgeCost) and other.name == self.name

    def __hash__(self):
        return hash(("EdgeCost", self.name))


class EnteredPixel(EdgeCost):
    """scikit-image's non-geometric MCP: each step costs the pixel entered (seaway.compat)."""

    smoothable = False

    def __init__(self):
        self.name = "entered"

    def engine(self, prepared):
        return _core.EnteredPixelCost(prepared.chart.values)

    def segments(self, chart, neighbourhood):
        return CostModel.segments(self, chart, neighbourhood)


def as_model(model) -> CostModel:
    """A CostModel from a model or an edge-cost name."""
    if isinstance(model, CostModel):
        return model
    if isinstance(model, str):
        return EdgeCost(model)
    raise TypeError(f"model must be a seaway.models.CostModel or one of {tuple(EDGE_COSTS)}, "
                    f"got {model!r}")


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

    def __init__(self, forecast, vessel: Vessel | None = None):
        vessel = Vessel() if vessel is None else vessel
        vessel.check()
        if "wave_height" in forecast.arrays:
            vessel.check_waves(float(forecast.arrays["wave_height"].max()))
        self.forecast, self.vessel = forecast, vessel
        best = vessel.speed_kn + forecast.best_extra_kn(vessel)
        self._engine = _core.TravelTimeModel(forecast.engine(), vessel.to_core(), best)

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
