"""`seaway replan ROUTE.geojson --forecast NEWER.nc --at ISO-TIME`: re-planning during the
voyage (Grinyak et al. 2018): where the ship is at that time on a route `seaway route
--forecast` wrote (its GeoJSON's vertex times), and the quickest route from there to the same
end through the newer forecast, leaving then."""

from __future__ import annotations

import json

import numpy as np

from .common import CLI_METHODS, EPILOG, neighbourhood, point, tell
from .forecast import run_forecast_route
from .forecastargs import add_forecast_options, iso_time


def read_voyage(path) -> tuple[np.ndarray, np.ndarray, dict]:
    """((n, 2) lat/lon of a route's vertices, (n,) their times, its properties) from the
    GeoJSON of a route on a clock; a route split at the antimeridian is joined again."""
    try:
        with open(path, encoding="utf-8") as f:
            feature = json.load(f)
        geom, props = feature["geometry"], feature["properties"]
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise ValueError(f"{path}: not a route GeoJSON written by seaway ({exc})") from None
    if "vertex_times" not in props:
        raise ValueError(
            f"{path}: the route has no times (vertex_times): re-planning needs a route "
            "found through a forecast (seaway route --forecast ... --out ROUTE.geojson)"
        )
    parts = geom["coordinates"] if geom["type"] == "MultiLineString" else [geom["coordinates"]]
    pts = list(parts[0])
    for part in parts[1:]:  # drop the two points inserted where the route crosses +-180
        pts = pts[:-1] + list(part[1:])
    xy = np.array([[p[1], p[0]] for p in pts], float)
    times = np.array([np.datetime64(t.rstrip("Z"), "s") for t in props["vertex_times"]])
    if len(times) != len(xy):
        raise ValueError(f"{path}: {len(times)} vertex times for {len(xy)} vertices")
    return xy, times, props


def position_at(xy, times, at) -> tuple[tuple[float, float], int]:
    """((lat, lon) of the ship at `at`, the index of the vertex it last passed), linear in time
    between the vertices (a step is a few km)."""
    if not (times[0] <= at <= times[-1]):
        raise ValueError(f"--at {at} is outside the voyage ({times[0]} to {times[-1]})")
    i = int(np.searchsorted(times, at, side="right") - 1)
    if i >= len(times) - 1:
        return (float(xy[-1, 0]), float(xy[-1, 1])), len(times) - 1
    f = float((at - times[i]) / (times[i + 1] - times[i]))
    lon = xy[i, 1] + f * ((xy[i + 1, 1] - xy[i, 1] + 180.0) % 360.0 - 180.0)
    return (float(xy[i, 0] + f * (xy[i + 1, 0] - xy[i, 0])), float((lon + 180.0) % 360.0 - 180.0)), i


def run_replan(args) -> int:
    if not args.forecast:
        raise ValueError("replan needs --forecast FILE (the newer forecast)")
    xy, times, props = read_voyage(args.route)
    if args.at is None:
        raise ValueError("give --at ISO-TIME: when to re-plan from (within the voyage)")
    here, i = position_at(xy, times, args.at)
    end = args.end or (float(xy[-1, 0]), float(xy[-1, 1]))
    tell(
        f"at {args.at} the ship is at {here[0]:.4f},{here[1]:.4f} (after vertex {i + 1} of "
        f"{len(xy)}); re-planning to {end[0]:.4f},{end[1]:.4f} through {', '.join(args.forecast)}",
        "replan",
    )
    if args.speed is None and args.vessel_file is None and props.get("speed_kn"):
        args.speed = float(props["speed_kn"])
        tell(f"the route's speed {args.speed:g} kn (give --speed or --vessel-file to change it)", "replan")
    args.start, args.end, args.depart, args.chart = here, end, args.at, None
    return run_forecast_route(args)


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
    rp.add_argument("--vessel", metavar="CLASS", help="ice class (unused on the forecast's grid)")
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
    add_forecast_options(rp)
    rp.set_defaults(
        chart=None, start=None, land_variable=None, grid=None, assume_stage=None, fast_ice="nearby"
    )
