"""Fuel-optimal speeds (Sotnikova 2009): an engine setting per step from a discrete set in
[vmin, vmax], fuel burnt at a rate q(v) per hour that depends on the setting.

Each step takes the setting that minimises fuel + lambda x time, lambda being what an hour of
passage is worth in tonnes of fuel; lambda = 0 is the least fuel whatever the time, a large
lambda the quickest passage. Sweeping lambda gives the time-fuel trade-off (Sotnikova 2009: 5 % less
fuel for 3.4 % more time) and the least fuel under an arrival deadline (the smallest lambda
that meets it). Routes are found on the forecast frame valid at `at_hours` after its first time:
with fuel + lambda x time as the label, the time a step starts is not known during the search.
Points found this way are those of the lower convex hull of the time-fuel front."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..engine.methods import heuristic_weight
from ..errors import NoRouteError, SeawayError
from ..models import Fuel
from ..result.route import Route
from ..vessel import Vessel
from .grid import ForecastGrid


@dataclass(frozen=True)
class FuelCurve:
    """Fuel rate (t/h) at each engine setting (calm-water speed, kn)."""

    speeds_kn: tuple
    rates_t_per_h: tuple

    def __post_init__(self):
        v, q = np.asarray(self.speeds_kn, float), np.asarray(self.rates_t_per_h, float)
        if v.ndim != 1 or v.size == 0 or v.shape != q.shape:
            raise SeawayError("give one fuel rate per engine setting (two 1-D sequences of one length)")
        if not (np.all(v > 0) and np.all(q >= 0) and np.all(np.isfinite(v)) and np.all(np.isfinite(q))):
            raise SeawayError("speeds must be positive and fuel rates non-negative, all finite")

    @classmethod
    def cubic(cls, ref_speed_kn, ref_rate_t_per_h, vmin_kn, vmax_kn, step_kn=1.0) -> "FuelCurve":
        """q(v) = q_ref (v / v_ref)^3 (propeller law) at settings vmin, vmin + step, ..., vmax."""
        if not 0 < vmin_kn <= vmax_kn:
            raise SeawayError(f"need 0 < vmin <= vmax, got {vmin_kn}, {vmax_kn}")
        v = np.arange(vmin_kn, vmax_kn + 1e-9, step_kn)
        return cls(tuple(v), tuple(ref_rate_t_per_h * (v / ref_speed_kn) ** 3))


def route_fuel(
    forecast,
    start,
    end,
    *,
    vessel: Vessel,
    fuel: FuelCurve,
    time_value_t_per_h=0.0,
    at_hours=0.0,
    land=None,
    neighbourhood=5,
    method="astar",
    variables=None,
) -> Route:
    """The route and settings minimising fuel + time_value x hours. Route.cost is that sum;
    stats.fuel (seaway.models.results.FuelUse) holds fuel_t, hours and speeds_kn (the setting
    of each step)."""
    heuristic_weight(method, None)
    fc = ForecastGrid(forecast, variables)
    model = Fuel(fc, vessel, fuel, time_value_t_per_h, at_hours)
    return fc.prepare(land, neighbourhood).route(start, end, model=model, method=method)


def tradeoff(
    forecast, start, end, *, vessel: Vessel, fuel: FuelCurve, time_values=None, **kwargs
) -> list[Route]:
    """Non-dominated (hours, fuel) routes over a sweep of time values (t per hour), quickest
    first. The default sweep spans 0 to 10 x the highest fuel rate."""
    if time_values is None:
        top = max(fuel.rates_t_per_h)
        time_values = np.concatenate([[0.0], np.geomspace(top / 100, 10 * top, 24)])
    routes = [
        route_fuel(forecast, start, end, vessel=vessel, fuel=fuel, time_value_t_per_h=t, **kwargs)
        for t in time_values
    ]
    routes.sort(key=lambda r: (r.stats.fuel.hours, r.stats.fuel.fuel_t))
    front = []
    for r in routes:
        if not front or r.stats.fuel.fuel_t < front[-1].stats.fuel.fuel_t - 1e-12:
            front.append(r)
    return front


def route_min_fuel(
    forecast, start, end, *, deadline_h, vessel: Vessel, fuel: FuelCurve, tolerance=1e-3, **kwargs
) -> Route:
    """The least-fuel route that arrives within `deadline_h` hours: the smallest time value
    whose route meets the deadline, found by bisection."""

    def run(t):
        return route_fuel(forecast, start, end, vessel=vessel, fuel=fuel, time_value_t_per_h=t, **kwargs)

    slowest = run(0.0)
    if slowest.stats.fuel.hours <= deadline_h:
        return slowest
    lo, hi = 0.0, max(fuel.rates_t_per_h)
    while run(hi).stats.fuel.hours > deadline_h:
        hi *= 4
        if hi > 1e9:
            raise NoRouteError(f"no route arrives within {deadline_h:g} h even at full speed")
    best = run(hi)
    while hi - lo > tolerance * hi:
        mid = 0.5 * (lo + hi)
        r = run(mid)
        if r.stats.fuel.hours <= deadline_h:
            hi, best = mid, r
        else:
            lo = mid
    return best
