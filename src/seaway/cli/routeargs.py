"""The options of the `seaway route` command (seaway.cli.route runs it): the chart and its
reading, the ends, depth and draft, the search, smoothing and snapping, the constraints, the
speed, the outputs, and the weather-routing options (seaway.cli.forecastargs)."""

from __future__ import annotations

from ..models import EDGE_COSTS
from .common import CLI_METHODS, EPILOG, add_ends, add_snap_options, fast_ice, grid, neighbourhood, point
from .constraints import add_constraint_options
from .forecastargs import EXAMPLE as FORECAST_EXAMPLE
from .forecastargs import add_forecast_options, add_voyage_options


def add_route_command(commands) -> None:
    rp = commands.add_parser(
        "route",
        help="route a ship across a chart file and print, write and plot the route",
        description="Find the least-cost route across CHART from --from to --to, smooth it, print "
        "its legs (course, distance, time, cost, ice along each leg) and optionally "
        "write it (GeoJSON, GPX, RTZ, CSV) and plot it (PNG). With --forecast: the "
        "quickest route through a weather forecast from --depart, with its schedule.",
        epilog=f"{EPILOG} Weather routing, {FORECAST_EXAMPLE}",
    )
    rp.add_argument(
        "chart",
        metavar="CHART",
        nargs="?",
        help="chart file: NetCDF (.nc), GeoTIFF (.tif, needs rasterio), SIGRID-3 "
        "(.shp/.gpkg, needs seaway.ice.sigrid), or 'kara' for the built-in "
        "synthetic Kara Sea chart; with --forecast it may be left out (the "
        "forecast's own grid) or be an ice chart (ice and weather in one voyage)",
    )
    add_ends(rp)
    rp.add_argument(
        "--vessel",
        metavar="CLASS",
        help="ice class (e.g. Arc7, Arc5): turns the chart's stage of development "
        "into Grinyak et al. 2022's impact (default Arc7 on stage charts)",
    )
    rp.add_argument(
        "--assume-stage",
        type=float,
        metavar="CODE",
        help="WMO stage of development assumed for the ice of a chart that gives only "
        "a concentration (CF sea_ice_area_fraction, e.g. NSIDC G02202); default "
        "93, thick first-year ice; said on stderr",
    )
    rp.add_argument(
        "--fast-ice",
        type=fast_ice,
        default="nearby",
        metavar="RULE",
        help="stage of fast ice (SIGRID-3 FA 08) the chart gives no stage for: nearby "
        "(default: the thickest first-year stage on the grid, else thick "
        "first-year 93), closed (impassable), or a WMO stage code, e.g. 91; "
        "the assumption is printed (seaway.ice.forms)",
    )
    rp.add_argument(
        "--concentration-limit",
        action="store_true",
        help="on an ice chart: also close ice whose total concentration is over the class's "
        "limit for independent navigation (Grinyak et al. 2022, Table 1), as a season does by "
        "default; said in the output",
    )
    rp.add_argument(
        "--variable",
        metavar="NAME",
        help="chart variable holding the cost per unit length (NaN/inf impassable); "
        "GeoTIFF: the band number (default 1)",
    )
    rp.add_argument(
        "--land",
        metavar="FILE",
        help="a finer coastline merged with the chart's land: a land mask on any lat/lon grid "
        "(NetCDF, GeoTIFF, 1 = land; e.g. GSHHG's) or coast polygons (shapefile, GeoPackage); a pixel "
        "with any of it is land. Default: the package's coastline (GLOBE, 30 arc-seconds) where the "
        "chart's pixels are coarser than it and at most 10 km; 'chart': the chart's own land only. "
        "Which coastline was used, and its resolution, is said and recorded",
    )
    rp.add_argument(
        "--land-variable",
        metavar="NAME",
        help="chart variable holding the land mask (default: 'land' if present)",
    )
    rp.add_argument(
        "--grid",
        type=grid,
        metavar="S,N,W,E,RES",
        help="lat/lon grid (degrees) to rasterise a SIGRID-3 chart onto (default: the "
        "box around the great circle between the ends, widened by a quarter of "
        "its length (at least 300 km), at 0.05 deg of latitude and the same km "
        "east-west, clipped to the chart; see seaway.ice.routegrid), or to resample a "
        "projected --forecast onto without CHART (default: the same box at the "
        "forecast's resolution)",
    )
    rp.add_argument(
        "--depth",
        metavar="FILE",
        help="bathymetry raster (NetCDF or GeoTIFF on lat/lon; ETOPO/GEBCO elevation "
        "or depth positive down, told by the CF attributes): resampled onto the "
        "chart (the shallowest depth in each pixel); the route's least depth is "
        "reported",
    )
    rp.add_argument(
        "--draft",
        type=float,
        metavar="M",
        help="the ship's draft in metres: pixels shallower than draft + UKC are impassable (needs --depth)",
    )
    rp.add_argument(
        "--ukc", type=float, metavar="M", help="under-keel clearance in metres (default 10 %% of the draft)"
    )
    rp.add_argument(
        "--depth-variable",
        metavar="NAME",
        help="the bathymetry file's variable (default: found by CF standard name)",
    )
    rp.add_argument(
        "--depth-positive",
        choices=("up", "down"),
        help="override the bathymetry's sign: up = elevation (ETOPO/GEBCO), down = "
        "depth (default: from its CF attributes, else guessed and said so)",
    )
    rp.add_argument(
        "--neighbourhood",
        type=neighbourhood,
        default=5,
        metavar="K",
        help="k of the k x k stencil: odd, 3 to 15 (default 5, as in Grinyak et al. 2022)",
    )
    rp.add_argument(
        "--edge-cost",
        default="max",
        choices=tuple(EDGE_COSTS),
        help="step cost: max (Grinyak et al. 2022), mean (Grinyak et al. 2018), integral (exact line "
        "integral) or length (the shortest route through passable water); default max",
    )
    rp.add_argument(
        "--method",
        default="auto",
        choices=CLI_METHODS,
        help="search algorithm (all exact; default auto: the fastest for the query)",
    )
    rp.add_argument(
        "--no-smooth",
        action="store_true",
        help="keep the raw pixel route (default: any-angle smoothing, never costlier; a route "
        "through a forecast or ice charts sails its legs on the clock, never later)",
    )
    add_snap_options(rp, "on land, in ice the class may not enter or in too shallow water")
    add_constraint_options(rp, point)
    rp.add_argument(
        "--speed",
        type=float,
        metavar="KN",
        help="speed in open water, knots: adds each leg's time and the voyage time; "
        "on an ice chart the speed in the ice comes from a model named in the "
        "output: Andreeva 2021's V = F x V0 for Register classes, the IMO POLARIS "
        "speed limits for Polar Classes and Finnish-Swedish classes "
        "(seaway.ice.speed); with --forecast the calm-water speed (default 12, or the "
        "vessel file's)",
    )
    rp.add_argument("--name", default="seaway route", help="route name in the outputs")
    rp.add_argument(
        "--out",
        action="append",
        metavar="FILE",
        help="write the route; the extension picks the format: .geojson/.json, .gpx, "
        ".rtz (IEC 61174, for ECDIS), .csv, .html (interactive map, offline; "
        "needs seaway[plot]); may be repeated. Every path is checked before the "
        "chart is read, and all files are written or none; each carries the ends "
        "asked for and used and what the route assumes",
    )
    rp.add_argument(
        "--plot",
        metavar="PNG",
        help="draw the chart, land and route to a PNG (needs seaway[plot]): ice in the "
        "WMO colour code (by stage of development on stage charts, fast ice grey), "
        "with --depth/--draft the shoals and the least depth; with --forecast the sea "
        "coloured by the wave height (else wind or current speed) at departure, the ice "
        "chart's ice in the WMO colours and the pixels no chart polygon covers hatched as off chart",
    )
    rp.add_argument("-q", "--quiet", action="store_true", help="no progress messages on stderr")
    add_voyage_options(rp)
    add_forecast_options(rp)  # seaway.cli.forecast
