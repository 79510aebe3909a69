"""`seaway route --forecast FILE ...`: weather routing on the command line, a shell over
seaway.open_forecast (seaway.voyage.forecast): without CHART on the forecast's own grid; with an
ice CHART (SIGRID-3, an ice NetCDF, a concentration field, or a NetCDF season of charts with a
time axis) the ice and the weather act in one voyage."""

from __future__ import annotations

from ..base.files import open_netcdf
from ..errors import ChartError, SeawayError
from ..output.files import check_outputs, write_outputs
from ..voyage import ChartOptions, open_chart, open_forecast, open_season
from .common import Progress, tell, vessel_from


def vessel_of(args):
    """(the Vessel of --vessel-file, --vessel, --speed and --displacement, or None for the
    defaults; the ice class)."""
    return vessel_from(args), args.vessel


def _ice(args, ice_class):
    """The ice of CHART: a season (a NetCDF with a time axis) or one chart."""
    path = args.chart
    if path.lower().endswith((".nc", ".nc4", ".cdf", ".netcdf")):
        ds = open_netcdf(path, "an ice chart is NetCDF, GeoTIFF or SIGRID-3", ChartError)
        if "time" in ds.dims and ds.sizes["time"] > 1:
            return open_season(path)
    options = ChartOptions(
        land_variable=args.land_variable,
        grid=args.grid,
        assume_stage=args.assume_stage,
        fast_ice=args.fast_ice,
        land=getattr(args, "land", None),
    )
    return open_chart(path, vessel=ice_class, ends=(args.start, args.end), options=options)


def run_forecast_route(args) -> int:
    """`seaway route [CHART] --forecast FILE ...`."""
    say = Progress("route", args.quiet)
    planned = check_outputs(args.out, args.plot)  # before any work: nothing found is then lost
    say(f"reading the forecast: {', '.join(args.forecast)}")
    forecast = open_forecast(
        args.forecast, variables=dict(args.forecast_variable or []), crs=args.forecast_crs
    )
    for note in forecast.notes:
        say(note)
    vessel, ice_class = vessel_of(args)
    ice = _ice(args, ice_class or "Arc7") if args.chart is not None else None
    if ice is not None and hasattr(ice, "grid") and hasattr(ice.grid, "times"):
        say(f"{args.chart}: a season of {ice.grid.times.size} ice charts")
    options = dict(
        vessel=vessel,
        ice=ice,
        ice_class=ice_class,
        objective=args.objective or "time",
        persist=args.persist,
        grid=args.grid,
        neighbourhood=args.neighbourhood,
        method=args.method,
        name=args.name,
        progress=None if args.quiet else say,
        smooth=not getattr(args, "no_smooth", False),
    )
    if getattr(args, "depart_window", None) is not None:
        first, last, step = args.depart_window
        if options["objective"] not in ("time", "fuel"):
            raise SeawayError(
                "--depart-window chooses by arrival or, with --arrive-by, fuel: give --objective time"
            )
        options.pop("objective")
        choice = forecast.best_departure(
            args.start, args.end, (first, last), step_h=step, arrive_by=args.arrive_by, **options
        )
        print(f"departures tried ({choice.rule}):\n{choice.table()}")
        r = choice.route
    else:
        r = forecast.route(args.start, args.end, depart=args.depart, arrive_by=args.arrive_by, **options)
    for note in r.notes:  # what was assumed, resampled or decided: even with --quiet
        if note not in forecast.notes:
            tell(note)
    return report(args, r, planned, say)


def report(args, r, planned, say) -> int:
    done = r.stats.smoothing
    if done is not None:
        say(
            f"smoothed on the clock (legs sailed under the route's own model, never later): "
            f"{done.cost_before:.6g} -> {r.cost:.6g} {r.unit}, course changes "
            f"{done.course_changes_before} -> {done.course_changes_after}"
        )
    elif not r.model.smoothable:
        say("not smoothed: its model prices only the engine's steps (the route as found)")
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
