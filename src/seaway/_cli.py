"""The `seaway route` and `seaway bench` commands (the parser is in seaway.__main__)."""

from __future__ import annotations

import argparse
import contextlib
import statistics
import sys
import time

import numpy as np

from ._cli_constraints import add_constraint_options, constraint_options
from ._engine import route
from .models import EDGE_COSTS

EPILOG = ("exit status: 0 done; 1 no route, or a chart or output file that cannot be used; "
          "2 a bad command line. Progress goes to stderr, results to stdout.")


def point(text: str) -> tuple[float, float]:
    """argparse type for LAT,LON."""
    try:
        a, b = (float(v) for v in text.replace(" ", "").split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected LAT,LON in decimal degrees (e.g. 70.3,58.5; write --from=-33.9,18.4 for a "
            f"negative first number), got {text!r}") from None
    if not (np.isfinite(a) and np.isfinite(b)):
        raise argparse.ArgumentTypeError(f"LAT,LON must be finite numbers, got {text!r}")
    return a, b


def grid(text: str) -> tuple:
    """argparse type for SOUTH,NORTH,WEST,EAST,RES (degrees)."""
    try:
        south, north, west, east, res = (float(v) for v in text.replace(" ", "").split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected SOUTH,NORTH,WEST,EAST,RES in degrees (e.g. 58,64,-55,-37,0.02), got {text!r}") from None
    if not (south < north and west < east and res > 0):
        raise argparse.ArgumentTypeError(f"need SOUTH < NORTH, WEST < EAST and RES > 0, got {text!r}")
    return south, north, west, east, res


def size(text: str) -> tuple[int, int]:
    try:
        r, c = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected ROWSxCOLS, e.g. 950x1150, got {text!r}") from None
    if r < 20 or c < 20:
        raise argparse.ArgumentTypeError(f"the chart must be at least 20x20, got {text!r}")
    return r, c


class Progress:
    """Stage messages with their time on stderr (silent with --quiet)."""

    def __init__(self, command: str, quiet: bool):
        self.command, self.quiet, self.t0 = command, quiet, time.perf_counter()

    def __call__(self, message: str) -> None:
        if not self.quiet:
            print(f"seaway {self.command}: [{time.perf_counter() - self.t0:6.1f} s] {message}",
                  file=sys.stderr, flush=True)


def searching(say, pixels: int):
    """Within the block, a running search reports the pixels it has settled once a second."""
    from ._interrupt import SettledProgress, reporting
    return contextlib.nullcontext() if say.quiet else reporting(SettledProgress(say, pixels))


def _tell(message: str) -> None:
    """What changed the voyage (a snapped end): on stderr even with --quiet."""
    print(f"seaway route: {message}", file=sys.stderr, flush=True)


def run_route(args) -> int:
    from . import export
    from ._depth_cli import for_route, why_no_route
    from ._ends import check_ends
    from .chartfile import open_chart
    from .errors import NoRouteError

    say = Progress("route", args.quiet)
    say(f"reading {args.chart}")
    data = open_chart(args.chart, variable=args.variable, vessel=args.vessel,
                      land_variable=args.land_variable, grid=args.grid,
                      ends=(args.start, args.end))
    for note in data.notes:
        say(note)
    cost = data.cost
    start, end = args.start, args.end
    if not ("lat" in cost.coords or "latitude" in cost.coords):
        say("the chart has projected y/x coordinates: --from and --to are ROW,COL pixel indices")
    chart_cost = cost
    cost, depth, shallow = for_route(args.depth, cost, draft=args.draft, ukc=args.ukc,
                                     variable=args.depth_variable, positive=args.depth_positive,
                                     say=say, crs=getattr(data.layers, "attrs", {}).get("crs"))
    start, end = check_ends(cost, data.land, data.layers, (start, end), vessel=args.vessel,
                            snap=args.snap, say=_tell, neighbourhood=args.neighbourhood,
                            reasons=shallow, chart_cost=chart_cost)
    rows, cols = cost.shape
    say(f"routing on {rows} x {cols} pixels ({data.description}; {args.method}, "
        f"{args.neighbourhood}x{args.neighbourhood} stencil, edge cost {args.edge_cost})")
    constraints = constraint_options(args)  # seaway._cli_constraints
    for name, value in constraints.items():
        if value not in (None, []):
            say(f"constraint {name}: {value if name != 'zones' else [z.name for z in value]}")
    try:
        # With a turn penalty the search settles (pixel, incoming step) states: scale the total.
        states = args.neighbourhood ** 2 - 1 if constraints["turn_penalty"] is not None else 1
        with searching(say, rows * cols * states):
            r = route(cost, start, end, land=data.land, neighbourhood=args.neighbourhood,
                      edge_cost=args.edge_cost, method=args.method, **constraints)
    except NoRouteError as exc:
        if shallow is None:
            raise
        why = why_no_route(chart_cost, data.land, depth, start, end, args.draft, args.ukc)
        raise NoRouteError(f"{exc}; {why}") from None
    say(f"found: cost {r.cost:.6g}, {len(r.pixels)} pixels, {r.stats['settled']} settled")
    if constraints["via"] or constraints["turn_penalty"] is not None:
        say("not smoothed: smoothing would cut the via-points or ignore the turn penalty")
    elif not args.no_smooth:
        say(f"smoothing {r.course_changes} course changes")
        r = r.smoothed()
        say(f"smoothed: cost {r.stats['cost_before']:.6g} -> {r.cost:.6g}, course changes "
            f"{r.stats['course_changes_before']} -> {r.stats['course_changes_after']}")
    r.name = args.name
    r.speed_kn = args.speed
    if data.environment:
        r = r.with_environment(data.environment)
    if depth is not None:  # --depth, over a chart's own depth variable
        r = r.with_environment({"depth": depth})
    print(r)
    for path in args.out or []:
        fmt = export.write(r, path)
        say(f"wrote {path} ({fmt})")
    if args.plot:
        from .plot import plot_route
        plot_route(r, args.plot, title=f"{args.name}: {data.description}")
        say(f"wrote {args.plot} (PNG)")
    return 0


def run_bench(args) -> int:
    from .charts import synthetic_endpoints, synthetic_sea

    say = Progress("bench", args.quiet)
    shape = tuple(args.size)
    say(f"building the synthetic chart seaway.charts.synthetic_sea({shape})")
    t = time.perf_counter()
    cost = synthetic_sea(shape)
    built = time.perf_counter() - t
    start, end = synthetic_endpoints(shape)
    print(f"seaway bench: synthetic_sea {shape[0]} x {shape[1]} pixels (30 % land, costs 1-30), "
          f"built in {built:.2f} s; {start} -> {end}, edge cost mean")
    print(f"{'method':10s} {'k':>3s} {'median s':>9s} {'min s':>8s} {'settled':>11s} "
          f"{'B/pixel':>8s} {'cost':>12s}")
    for k in args.neighbourhood:
        for method in args.method:
            times = []
            for i in range(args.repeat):
                say(f"{method} k={k}: run {i + 1} of {args.repeat}")
                t = time.perf_counter()
                r = route(cost, start, end, neighbourhood=k, method=method, edge_cost="mean")
                times.append(time.perf_counter() - t)
            print(f"{method:10s} {k:3d} {statistics.median(times):9.3f} {min(times):8.3f} "
                  f"{r.stats['settled']:11,d} {r.stats['state_bytes'] / cost.size:8.1f} "
                  f"{r.cost:12.2f}", flush=True)
    return 0


def add_commands(commands, neighbourhood_type) -> None:
    rp = commands.add_parser(
        "route", help="route a ship across a chart file and print, write and plot the route",
        description="Find the least-cost route across CHART from --from to --to, smooth it, print "
                    "its legs (course, distance, time, cost, ice along each leg) and optionally "
                    "write it (GeoJSON, GPX, RTZ, CSV) and plot it (PNG).", epilog=EPILOG)
    rp.add_argument("chart", metavar="CHART",
                    help="chart file: NetCDF (.nc), GeoTIFF (.tif, needs rasterio), SIGRID-3 "
                         "(.shp/.gpkg, needs seaway.ice.sigrid), or 'kara' for the built-in "
                         "synthetic Kara Sea chart")
    rp.add_argument("--from", dest="start", type=point, required=True, metavar="LAT,LON",
                    help="start in decimal degrees (ROW,COL on charts with projected y/x)")
    rp.add_argument("--to", dest="end", type=point, required=True, metavar="LAT,LON",
                    help="end in decimal degrees (ROW,COL on charts with projected y/x)")
    rp.add_argument("--vessel", metavar="CLASS",
                    help="ice class (e.g. Arc7, Arc5): turns the chart's stage of development "
                         "into paper 000's impact (default Arc7 on stage charts)")
    rp.add_argument("--variable", metavar="NAME",
                    help="chart variable holding the cost per unit length (NaN/inf impassable); "
                         "GeoTIFF: the band number (default 1)")
    rp.add_argument("--land-variable", metavar="NAME",
                    help="chart variable holding the land mask (default: 'land' if present)")
    rp.add_argument("--grid", type=grid, metavar="S,N,W,E,RES",
                    help="lat/lon grid (degrees) to rasterise a SIGRID-3 chart onto (default: the "
                         "box around the great circle between the ends, widened by a quarter of "
                         "its length (at least 300 km), at 0.05 deg of latitude and the same km "
                         "east-west, clipped to the chart; see seaway.ice.routegrid)")
    rp.add_argument("--depth", metavar="FILE",
                    help="bathymetry raster (NetCDF or GeoTIFF on lat/lon; ETOPO/GEBCO elevation "
                         "or depth positive down, told by the CF attributes): resampled onto the "
                         "chart (the shallowest depth in each pixel); the route's least depth is "
                         "reported")
    rp.add_argument("--draft", type=float, metavar="M",
                    help="the ship's draft in metres: pixels shallower than draft + UKC are "
                         "impassable (needs --depth)")
    rp.add_argument("--ukc", type=float, metavar="M",
                    help="under-keel clearance in metres (default 10 %% of the draft)")
    rp.add_argument("--depth-variable", metavar="NAME",
                    help="the bathymetry file's variable (default: found by CF standard name)")
    rp.add_argument("--depth-positive", choices=("up", "down"),
                    help="override the bathymetry's sign: up = elevation (ETOPO/GEBCO), down = "
                         "depth (default: from its CF attributes, else guessed and said so)")
    rp.add_argument("--neighbourhood", type=neighbourhood_type, default=5, metavar="K",
                    help="k of the k x k stencil: odd, 3 to 15 (default 5, as in paper 000)")
    rp.add_argument("--edge-cost", default="max", choices=tuple(EDGE_COSTS),
                    help="step cost: max (paper 000), mean (paper 003) or integral (exact line "
                         "integral); default max")
    rp.add_argument("--method", default="auto", choices=("auto", "bidirectional", "astar", "dijkstra"),
                    help="search algorithm (all exact; default auto: the fastest for the query)")
    rp.add_argument("--no-smooth", action="store_true",
                    help="keep the raw pixel route (default: any-angle smoothing, never costlier)")
    rp.add_argument("--snap", action="store_true",
                    help="move a start or end on land, in ice the class may not enter or in too "
                         "shallow water to the nearest pixel the ship can reach from the other end "
                         "(default: stop with an error naming why, that point and its distance)")
    add_constraint_options(rp, point)
    rp.add_argument("--speed", type=float, metavar="KN",
                    help="speed in knots: adds each leg's time and the voyage time")
    rp.add_argument("--name", default="seaway route", help="route name in the outputs")
    rp.add_argument("--out", action="append", metavar="FILE",
                    help="write the route; the extension picks the format: .geojson/.json, .gpx, "
                         ".rtz (IEC 61174, for ECDIS), .csv, .html (interactive map, offline; "
                         "needs seaway[plot]); may be repeated")
    rp.add_argument("--plot", metavar="PNG",
                    help="draw the chart, land and route to a PNG (needs seaway[plot])")
    rp.add_argument("-q", "--quiet", action="store_true", help="no progress messages on stderr")

    bp = commands.add_parser(
        "bench", help="time the engine on the synthetic benchmark chart",
        description="Time seaway.route on seaway.charts.synthetic_sea (30 %% land, costs 1-30), "
                    "south-west to north-east, and print the median time, pixels settled and "
                    "search memory per pixel.", epilog=EPILOG)
    bp.add_argument("--size", type=size, default=(1900, 2300), metavar="ROWSxCOLS",
                    help="chart size (default 1900x2300, paper 000's Kara Sea chart)")
    bp.add_argument("--neighbourhood", type=neighbourhood_type, nargs="+", default=[5],
                    metavar="K", help="stencil sizes to time (default 5)")
    bp.add_argument("--method", nargs="+", default=["auto", "dijkstra"],
                    choices=("auto", "bidirectional", "astar", "dijkstra"),
                    help="methods to time (default auto and dijkstra)")
    bp.add_argument("--repeat", type=int, default=3, metavar="N",
                    help="runs per case; the median is reported (default 3)")
    bp.add_argument("-q", "--quiet", action="store_true", help="no progress messages on stderr")


