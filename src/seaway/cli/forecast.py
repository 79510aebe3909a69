"""`seaway route --forecast FILE ...`: weather routing on the command line (seaway.weather).

Without CHART the route runs on the forecast's own lat/lon grid, land where every field is NaN
or the package's coastline (global-land-mask) has land (a projected forecast is first resampled
onto a lat/lon grid, seaway.cli.forecastgrid); with an ice CHART (SIGRID-3, an ice
NetCDF, a concentration field, or a NetCDF season of charts with a time axis) the ice and the
weather act in one voyage (seaway.weather.route_ice_weather). Objectives: the least time
(Olovyannikov 2025; with danger zones the least time in danger when no safe route exists,
Sotnikova 2009), the least fuel (Sotnikova 2009; with --arrive-by the least fuel that arrives in
time), or the least wave danger (Grinyak et al. 2018)."""

from __future__ import annotations

import dataclasses
import os

import numpy as np

from ..base.files import open_netcdf
from ..ice.classes import get_class
from ..ice.seasongrid import SeasonGrid, as_season
from ..vessel import Vessel, load
from ..voyage import ChartOptions, open_chart
from ..voyage.forecastgrid import coastline, onto_route_grid
from ..weather import (
    ForecastGrid,
    FuelCurve,
    open_forecasts,
    route_fuel,
    route_ice_weather,
    route_min_fuel,
    route_safest,
    route_time,
)
from .common import Progress, searching, tell
from .outputs import check_outputs, write_outputs


def _vessel(args, say):
    profile = load(args.vessel_file) if args.vessel_file else None
    base = profile.vessel if profile else Vessel(speed_kn=12.0)
    changes = {
        k: v for k, v in (("speed_kn", args.speed), ("displacement_t", args.displacement)) if v is not None
    }
    vessel = dataclasses.replace(base, **changes)
    if profile:
        say(f"vessel: {profile.describe()}")
    elif not changes:
        tell(
            "vessel: 12 kn in calm water, 15000 t (the defaults; give --speed, --displacement "
            "or --vessel-file)"
        )
    return vessel, profile, args.vessel or (profile.ice_class if profile else None)


def _ice(args, ice_class, say):
    """The ice of CHART: a SeasonGrid (a NetCDF with a time axis, as it is) or one chart's
    layers (a Dataset), which _season() takes as valid from the departure."""
    path = args.chart
    if path.lower().endswith((".nc", ".nc4", ".cdf", ".netcdf")):
        ds = open_netcdf(path, "an ice chart is NetCDF, GeoTIFF or SIGRID-3")
        if "time" in ds.dims and ds.sizes["time"] > 1:
            say(f"{path}: a season of {ds.sizes['time']} ice charts")
            return SeasonGrid(as_season(ds))
    options = ChartOptions(
        land_variable=args.land_variable,
        grid=args.grid,
        assume_stage=args.assume_stage,
        fast_ice=args.fast_ice,
    )
    data = open_chart(path, vessel=ice_class, ends=(args.start, args.end), options=options)
    for note in data.notes:
        tell(note)
    ice = data.layers
    if data.projection is not None or ice is None or "CT" not in ice or not ({"SA", "thickness"} & set(ice)):
        raise ValueError(
            f"{path}: a route through ice and weather needs an ice chart on a lat/lon "
            "grid with CT and SA or a thickness (SIGRID-3, NSIDC, a season NetCDF); "
            "leave CHART out to route on the forecast's own grid"
        )
    keep = [
        k for k in ("CT", "CA", "SA", "CB", "SB", "CC", "SC", "thickness", "land", "off_chart") if k in ice
    ]
    one = ice[keep].drop_vars("time", errors="ignore")
    one.attrs["date"] = data.date or ""
    return one


def _grid_of(ice):
    """(lat, lon, dims) of the ice's grid."""
    t = ice.template if isinstance(ice, SeasonGrid) else ice["CT"]
    return (*(t[d].values for d in t.dims), t.dims)


def _season(ice, departure):
    """The ice as a season: one chart taken as valid from the departure for the whole voyage
    (said)."""
    if isinstance(ice, SeasonGrid):
        return ice
    ice = ice.copy()
    date = ice.attrs.pop("date", "")
    tell(
        f"the ice chart{' of ' + date if date else ''} is taken as valid from the "
        "departure for the whole voyage (persistence of the ice)"
    )
    return SeasonGrid(ice.expand_dims(time=[np.datetime64(departure, "ns")]))


def run_forecast_route(args) -> int:
    """`seaway route [CHART] --forecast FILE ...`."""
    say = Progress("route", args.quiet)
    planned = check_outputs(args.out, args.plot)  # before any work: nothing found is then lost
    say(f"reading the forecast: {', '.join(args.forecast)}")
    variables = dict(args.forecast_variable or [])
    ds, notes = open_forecasts(args.forecast, variables)
    for note in notes:
        say(note)
    source = ", ".join(os.path.basename(p) for p in args.forecast)
    method = {"auto": "astar", "bidirectional": None}.get(args.method, args.method)
    if method is None:
        raise ValueError(
            "a route through a forecast is on a clock: it cannot be searched from both "
            "ends; use --method astar or dijkstra"
        )
    if args.chart is not None and args.objective != "time":
        raise ValueError(
            "through ice and weather at once only the least time is modelled; "
            "use --objective time, or leave CHART out"
        )
    vessel, profile, ice_class = _vessel(args, say)
    ice = _ice(args, ice_class or "Arc7", say) if args.chart is not None else None
    ds, resampled = onto_route_grid(args, ds, source, None if ice is None else _grid_of(ice))
    for said in resampled:
        tell(said)
    fc = ForecastGrid(ds, departure=args.depart, persist=args.persist, source=source)
    for said in fc.assumptions:
        tell(said)
    departure = fc.departure
    say(f"departure {departure} (forecast {fc.describe()})")
    common = dict(neighbourhood=args.neighbourhood, method=method)
    rows, cols = fc.shape
    with searching(say, rows * cols):
        if ice is not None:
            season = _season(ice, departure)
            cls = get_class(ice_class or "Arc7")
            model = (
                "IMO POLARIS speed limits"
                if cls.system in ("IACS", "FSICR")
                else "Andreeva 2021's V = F x V0"
            )
            say(f"routing {cls.name} through the ice ({model}) and the forecast")
            r = route_ice_weather(
                season,
                ds,
                args.start,
                args.end,
                ice_class=cls.name,
                vessel=vessel,
                departure=departure,
                persist=args.persist,
                source=source,
                speed="class",
                **common,
            )
            r = dataclasses.replace(r, notes=tuple(r.notes) + (f"speed in ice: {model} ({cls.name})",))
        else:
            land = fc.dry | coastline(ds)
            say(
                f"routing on the forecast's grid ({rows} x {cols} pixels), land from its NaN fields "
                "and the coastline of global-land-mask"
            )
            r = _on_forecast(args, ds, fc, vessel, profile, land, source, common, say)
    if resampled:
        r = dataclasses.replace(r, notes=tuple(resampled) + tuple(r.notes))
    return _report(args, r, planned, say)


def _on_forecast(args, ds, fc, vessel, profile, land, source, common, say):
    at_h = 0.0 if fc.times is None else float((fc.departure - fc.times[0]) / np.timedelta64(1, "h"))
    if args.objective == "time":
        if args.arrive_by is not None:
            raise ValueError(
                "--arrive-by asks for the least fuel that arrives in time: give --objective fuel"
            )
        r = route_time(
            ds,
            args.start,
            args.end,
            vessel=vessel,
            departure=fc.departure,
            land=land,
            persist=args.persist,
            source=source,
            **common,
        )
        if r.stats.danger is not None:
            tell(
                f"no route avoids the danger zones: this one spends {r.stats.danger.hours:.1f} h "
                "in them, the least possible (Sotnikova 2009); flagged in the outputs"
            )
        return r
    if args.objective == "safety":
        length = profile.vessel.length_m if profile else None
        if length is None:
            raise ValueError("--objective safety needs the ship's length: a --vessel-file with length_m")
        return route_safest(
            ds,
            args.start,
            args.end,
            ship_length_m=length,
            speed_kn=vessel.speed_kn,
            at_hours=at_h,
            land=land,
            **common,
        )
    if not (profile and profile.fuel_speeds_kn):
        raise ValueError("--objective fuel needs a fuel curve: a --vessel-file with a [fuel] table")
    fuel = FuelCurve(profile.fuel_speeds_kn, profile.fuel_rates_t_per_h)
    say("least fuel on the forecast frame at departure (Sotnikova 2009)")
    if args.arrive_by is not None:
        deadline = float((args.arrive_by - fc.departure) / np.timedelta64(1, "h"))
        if deadline <= 0:
            raise ValueError(f"--arrive-by {args.arrive_by} is not after the departure {fc.departure}")
        return route_min_fuel(
            ds,
            args.start,
            args.end,
            deadline_h=deadline,
            vessel=vessel,
            fuel=fuel,
            at_hours=at_h,
            land=land,
            **common,
        )
    return route_fuel(ds, args.start, args.end, vessel=vessel, fuel=fuel, at_hours=at_h, land=land, **common)


def _report(args, r, planned, say) -> int:
    r.name = args.name
    why = "its model prices only the engine's steps" if not r.model.smoothable else ""
    if why:
        say(f"not smoothed: {why} (the route as found)")
    print(r)
    if r.stats.fuel is not None:
        f = r.stats.fuel
        print(
            f"fuel {f.fuel_t:.2f} t over {f.hours:.1f} h; engine settings "
            f"{f.speeds_kn.min():g}-{f.speeds_kn.max():g} kn"
        )
    v = r.stats.voyage
    for w in v.waits if v is not None else ():
        print(f"  wait {w.hours:.2f} h at {w.position[0]:.4f}, {w.position[1]:.4f} from {str(w.since)[:16]}")
    write_outputs(planned, r, title=f"{args.name}: {r.length:.0f} km, {r.cost:.5g} {r.unit}", say=say)
    return 0
