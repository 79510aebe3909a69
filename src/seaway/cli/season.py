"""The `seaway season` command: the quickest route through a season of dated ice charts
(seaway.icenav.season, seaway.models.IceSeasonTime)."""

from __future__ import annotations

import argparse

import numpy as np

from ..errors import ChartError
from ..output import export
from ..voyage import open_season
from .common import (
    EPILOG,
    Progress,
    add_ends,
    add_snap_options,
    depart_window,
    fast_ice,
    grid,
    neighbourhood,
    tell,
    vessel_from,
)


def dated_chart(text: str) -> tuple[str, str]:
    """argparse type for DATE=FILE."""
    date, sep, path = text.partition("=")
    if not sep or not date or not path:
        raise argparse.ArgumentTypeError(f"expected DATE=FILE (e.g. 2026-07-01=aari_0701.shp), got {text!r}")
    try:
        np.datetime64(date, "s")
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"{date!r} is not a date (e.g. 2026-07-01 or 2026-07-01T12)"
        ) from None
    return date, path


def speed_table(text: str) -> dict:
    """argparse type for STAGE:KN,... (WMO stage codes, knots)."""
    try:
        pairs = [item.split(":") for item in text.replace(" ", "").split(",")]
        return {int(s): float(v) for s, v in pairs}
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected STAGE:KNOTS,... (e.g. 55:14,87:7,91:3,93:0), got {text!r}"
        ) from None


def _charts(args):
    """One NetCDF file, or the DATE=FILE charts as (date, path) pairs."""
    if len(args.charts) == 1 and "=" not in args.charts[0]:
        return args.charts[0]
    charts = []
    for text in args.charts:
        try:
            charts.append(dated_chart(text))
        except argparse.ArgumentTypeError as exc:
            raise ChartError(f"{exc}; or give one NetCDF file with a time dimension") from None
    return charts


def run_season(args) -> int:
    say = Progress("season", args.quiet)
    say(f"reading {len(args.charts)} chart file(s)")
    season = open_season(_charts(args), ends=(args.start, args.end), grid=args.grid)
    for note in season.notes:
        tell(note, "season")
    t = season.grid.times
    say(f"{t.size} charts from {t[0]} to {t[-1]} on {season.grid.shape[0]} x {season.grid.shape[1]} pixels")
    options = dict(
        vessel=vessel_from(args) if args.vessel_file else (args.vessel or "Arc7"),
        speed_kn=args.speed,
        speed_table=args.speed_table,
        fast_ice=args.fast_ice,
        concentration_limit=not args.no_concentration_limit,
        snap_km=args.snap_km if args.snap else None,
        neighbourhood=args.neighbourhood,
        method=args.method,
        smooth=not args.no_smooth,
        name=args.name,
        progress=None if args.quiet else say,
    )
    if args.depart_window is not None:
        first, last, step = args.depart_window
        choice = season.best_departure(
            args.start, args.end, (first, last), step_h=step, arrive_by=args.arrive_by, **options
        )
        print(f"departures tried ({choice.rule}):\n{choice.table()}")
        r = choice.route
    else:
        r = season.route(args.start, args.end, depart=args.depart, **options)
    voyage = r.stats.voyage
    for said in voyage.assumptions if voyage is not None else ():  # the fast-ice rule: even with --quiet
        tell(f"assumed: {said}", "season")
    for note in r.notes:  # moved ends
        if note not in season.notes:
            tell(note, "season")
    st, done = r.stats.voyage, r.stats.smoothing
    if done is not None:
        say(f"smoothed through the charts: {done.cost_before:.2f} -> {r.cost:.2f} h, never later")
    print(r)
    print(
        f"departure {st.departure}, arrival {str(st.arrival)[:16]}: {r.cost:.2f} h "
        f"({r.cost / 24:.2f} days), {st.hours_under_way:.2f} h under way, "
        f"{st.hours_waiting:.2f} h waiting; charts used: " + ", ".join(str(d)[:16] for d in st.charts_used)
    )
    for _, (a, b), since, hours in st.waits:
        print(f"  wait {hours:.2f} h at {a:.4f}, {b:.4f} from {str(since)[:16]}")
    for path in args.out or []:
        say(f"wrote {path} ({export.write(r, path)})")
    return 0


def add_season_command(commands) -> None:
    sp = commands.add_parser(
        "season",
        help="the quickest route through a season of dated ice charts",
        description="Find the earliest-arriving route through a time series of ice charts: each "
        "step crosses the chart valid when the ship is there, at the class's speed "
        "(Andreeva 2021's V = F x V0, or --speed-table); the ship may wait for the ice "
        "to clear (the route lists its waits). An end is moved (--snap) only when no chart "
        "of the season lets the class use it (land, or ice closed in every chart): one closed "
        "at departure but open later stays, and the ship waits. No route: the message names "
        "the ice that closes the way in the season's most open chart and the weakest class "
        "that gets through the season. Fast ice (SIGRID-3 FA 08) takes its stage from each "
        "chart, or where a chart gives none (AARI's winter charts: FA 08, SA 99) the --fast-ice "
        "rule's, chart by chart, said once on stderr and in every output.",
        epilog=EPILOG,
    )
    sp.add_argument(
        "charts",
        nargs="+",
        metavar="DATE=CHART",
        help="SIGRID-3 charts with the date each is valid from (2026-07-01=a.shp "
        "2026-07-02=b.shp ...), or one NetCDF file with a time dimension of CT "
        "(or sea_ice_area_fraction) and SA or thickness",
    )
    add_ends(sp)
    sp.add_argument("--vessel", metavar="CLASS", help="ice class (default Arc7, or the vessel file's)")
    sp.add_argument(
        "--vessel-file",
        metavar="FILE",
        help="vessel file (TOML or JSON) or a shipped example (arc7-lng-carrier, pc6-general-cargo, ...): "
        "its class, service speed and ice curve (the speed in the ice: the ship's curve, else Andreeva 2021)",
    )
    sp.add_argument(
        "--speed",
        type=float,
        metavar="KN",
        help="open-water speed in knots (default 12, or the vessel file's)",
    )
    sp.add_argument("--depart", metavar="DATE", help="departure (default the first chart's date)")
    sp.add_argument(
        "--depart-window",
        type=depart_window,
        metavar="FIRST,LAST[,HOURS]",
        help="find the best departure between FIRST and LAST (tried every HOURS, default 24): the one "
        "that arrives first (the latest of those that do), or with --arrive-by the one arriving in "
        "time with the least fuel; the departures tried are printed",
    )
    sp.add_argument(
        "--arrive-by", metavar="DATE", help="with --depart-window: arrive by then, with the least fuel"
    )
    sp.add_argument(
        "--speed-table",
        type=speed_table,
        metavar="STAGE:KN,...",
        help="speeds per WMO stage instead of Andreeva 2021 (55 is open water)",
    )
    sp.add_argument(
        "--fast-ice",
        type=fast_ice,
        default="nearby",
        metavar="RULE",
        help="stage of fast ice (SIGRID-3 FA 08) a chart gives no stage for, chart by chart: "
        "nearby (default: the thickest first-year stage that chart shows on the grid, else "
        "thick first-year 93), closed (impassable), or a WMO stage code, e.g. 91; the "
        "assumption is printed with the charts and pixels it applies to (seaway.ice.seasonfast). "
        "Fast ice is 10/10: the concentration limit keeps classes below Arc9 out of it (see "
        "--no-concentration-limit)",
    )
    sp.add_argument(
        "--no-concentration-limit",
        action="store_true",
        help="let the class enter ice above its independent-navigation concentration",
    )
    sp.add_argument(
        "--grid",
        type=grid,
        metavar="S,N,W,E,RES",
        help="lat/lon grid (degrees) to rasterise SIGRID-3 charts onto (default: as seaway "
        "route chooses it, the box around the great circle between the ends)",
    )
    add_snap_options(sp, "on land or in ice the class may not enter in any chart of the season")
    sp.add_argument(
        "--neighbourhood",
        type=neighbourhood,
        default=5,
        metavar="K",
        help="k of the k x k stencil: odd, 3 to 15 (default 5)",
    )
    sp.add_argument(
        "--method",
        default="astar",
        choices=("astar", "dijkstra"),
        help="search algorithm (both exact; default astar)",
    )
    sp.add_argument(
        "--no-smooth",
        action="store_true",
        help="keep the engine's steps (default: straight legs sailed through the charts, never "
        "later, never through closed ice, the waits kept)",
    )
    sp.add_argument("--name", default="seaway season route", help="route name in the outputs")
    sp.add_argument(
        "--out",
        action="append",
        metavar="FILE",
        help="write the route (.geojson, .gpx, .rtz, .csv); may be repeated",
    )
    sp.add_argument("-q", "--quiet", action="store_true", help="no progress messages on stderr")
