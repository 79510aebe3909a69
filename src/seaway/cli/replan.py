"""`seaway replan ROUTE.geojson --forecast NEWER.nc --at ISO-TIME`: re-planning during the
voyage (Grinyak et al. 2018), a shell over seaway.voyage.replan.replan_voyage: where the ship is
at that time on a route `seaway route --forecast` wrote, and the quickest route from there to the
same end through the newer forecast, leaving then."""

from __future__ import annotations

from ..errors import SeawayError
from ..output.files import check_outputs
from ..voyage import open_forecast
from ..voyage.replan import replan_voyage
from .common import CLI_METHODS, EPILOG, Progress, neighbourhood, point, tell
from .forecast import report, vessel_of
from .forecastargs import add_forecast_options, add_voyage_options, iso_time


def run_replan(args) -> int:
    if not args.forecast:
        raise SeawayError("replan needs --forecast FILE (the newer forecast)")
    if args.depart is not None or args.escort or args.objective == "impact":
        raise SeawayError(
            "replan leaves at --at through the forecast: give no --depart, --escort or --objective impact"
        )
    say = Progress("replan", args.quiet)
    planned = check_outputs(args.out, args.plot)
    forecast = open_forecast(
        args.forecast, variables=dict(args.forecast_variable or []), crs=args.forecast_crs
    )
    given = args.speed is not None or args.vessel_file is not None or args.displacement is not None
    vessel, _ = vessel_of(args) if given else (None, None)
    r, _, notes = replan_voyage(
        args.route,
        forecast,
        args.at,
        end=args.end,
        vessel=vessel,
        ice_class=args.vessel,
        persist=args.persist,
        objective=args.objective or "time",
        arrive_by=args.arrive_by,
        neighbourhood=args.neighbourhood,
        method=args.method,
        name=args.name,
        progress=None if args.quiet else say,
    )
    for note in r.notes:
        if note not in forecast.notes:
            tell(note, "replan")
    return report(args, r, planned, say)


def add_replan_command(commands) -> None:
    rp = commands.add_parser(
        "replan",
        help="re-plan a voyage from where the ship is, through a newer forecast",
        description="Where is the ship at --at on ROUTE (a GeoJSON that seaway route --forecast "
        "wrote, with its vertex times), and which is the quickest route from there to "
        "the same end through the newer --forecast, leaving then (Grinyak et al. 2018).",
        epilog=f"{EPILOG} Example: seaway replan voyage.geojson --forecast gale-0106.nc --at "
        "2026-10-01T18:00 --out voyage-2.rtz",
    )
    rp.add_argument("route", metavar="ROUTE", help="the voyage's GeoJSON (seaway route --forecast ... --out)")
    rp.add_argument(
        "--at", type=iso_time, metavar="ISO-TIME", help="re-plan from the ship's position at this time (UTC)"
    )
    rp.add_argument("--to", dest="end", type=point, metavar="LAT,LON", help="a new end (default the route's)")
    rp.add_argument("--speed", type=float, metavar="KN", help="calm-water speed (default the route's)")
    rp.add_argument(
        "--vessel", metavar="CLASS", help="ice class through ice (default the route's, else Arc7)"
    )
    rp.add_argument(
        "--neighbourhood",
        type=neighbourhood,
        default=5,
        metavar="K",
        help="k of the k x k stencil (default 5)",
    )
    rp.add_argument("--method", default="astar", choices=CLI_METHODS, help="search algorithm (default astar)")
    rp.add_argument("--name", default="seaway route, re-planned", help="route name in the outputs")
    rp.add_argument(
        "--out",
        action="append",
        metavar="FILE",
        help="write the new route (.geojson, .gpx, .rtz, .csv, .html)",
    )
    rp.add_argument("--plot", metavar="PNG", help="draw the new route to a PNG (needs seaway[plot])")
    rp.add_argument("-q", "--quiet", action="store_true", help="no progress messages on stderr")
    add_voyage_options(rp)
    add_forecast_options(rp)
    rp.set_defaults(
        chart=None, start=None, land_variable=None, grid=None, assume_stage=None, fast_ice="nearby"
    )
