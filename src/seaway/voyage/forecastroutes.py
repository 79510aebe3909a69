"""A route on a forecast's own grid (OpenForecast.route without ice), by objective: the least
time (Olovyannikov 2025; the least time in danger when no route avoids the danger zones,
Sotnikova 2009), the least wave danger (Grinyak et al. 2018) or the least fuel (Sotnikova 2009;
with a deadline the least fuel that arrives in time)."""

from __future__ import annotations

import numpy as np

from ..errors import ForecastError
from ..weather import FuelCurve, route_fuel, route_min_fuel, route_safest, route_time
from .forecastgrid import coastline

OBJECTIVES = ("time", "fuel", "safety")


def route_on_forecast(
    ds, fc, start, end, vessel, objective, arrive_by, persist, source, notes, say, **common
):
    """The route for `objective` on the forecast's grid; land where every field is NaN and the
    package's coastline (global-land-mask)."""
    land = fc.dry | coastline(ds)
    rows, cols = fc.shape
    say(
        f"routing on the forecast's grid ({rows} x {cols} pixels), land from its NaN fields "
        "and the coastline of global-land-mask"
    )
    at_h = 0.0 if fc.times is None else float((fc.departure - fc.times[0]) / np.timedelta64(1, "h"))
    if objective == "time":
        if arrive_by is not None:
            raise ForecastError("arrive_by asks for the least fuel that arrives in time: give objective fuel")
        r = route_time(
            ds,
            start,
            end,
            vessel=vessel,
            departure=fc.departure,
            land=land,
            persist=persist,
            source=source,
            **common,
        )
        if r.stats.danger is not None:
            notes.append(
                f"no route avoids the danger zones: this one spends {r.stats.danger.hours:.1f} h "
                "in them, the least possible (Sotnikova 2009); flagged in the outputs"
            )
        return r
    if objective == "safety":
        length = vessel.length_m
        if length is None:
            raise ForecastError("objective safety needs the ship's length: a vessel file with length_m")
        return route_safest(
            ds, start, end, ship_length_m=length, speed_kn=vessel.speed_kn, at_hours=at_h, land=land, **common
        )
    if not vessel.fuel_speeds_kn:
        raise ForecastError("objective fuel needs a fuel curve: a vessel file with a [fuel] table")
    fuel = FuelCurve(vessel.fuel_speeds_kn, vessel.fuel_rates_t_per_h)
    say("least fuel on the forecast frame at departure (Sotnikova 2009)")
    if arrive_by is not None:
        deadline = float((np.datetime64(arrive_by) - fc.departure) / np.timedelta64(1, "h"))
        if deadline <= 0:
            raise ForecastError(f"arrive_by {arrive_by} is not after the departure {fc.departure}")
        return route_min_fuel(
            ds, start, end, deadline_h=deadline, vessel=vessel, fuel=fuel, at_hours=at_h, land=land, **common
        )
    return route_fuel(ds, start, end, vessel=vessel, fuel=fuel, at_hours=at_h, land=land, **common)
