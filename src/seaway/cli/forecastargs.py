"""The options of `seaway route --forecast FILE ...` (weather routing, seaway.cli.forecast runs
it): the forecast files and their variables, the departure, the objective, the vessel file;
and the check that refuses them without --forecast."""

from __future__ import annotations

import argparse

import numpy as np

from ..errors import SeawayError
from ..ice.andreeva import check_stage_thickness
from ..weather.forecast import ROLES, check_roles
from .common import depart_window

#: --objective: impact (charts' default) and time on charts and seasons; time (forecasts'
#: default), fuel and safety through a forecast.
OBJECTIVES = ("impact", "time", "fuel", "safety")
EXAMPLE = (
    "example: seaway route --forecast waves.nc --forecast currents.nc --depart "
    "2026-10-01T06:00 --from 70.3,58.5 --to 76.5,95.0 --vessel-file pc6-general-cargo "
    "--out voyage.rtz"
)
#: Options that mean something only with --forecast.
_ONLY_WITH = ("forecast_variable", "forecast_crs", "persist", "arrive_by", "displacement", "depart_window")


def role_pair(text: str) -> tuple[str, str]:
    """argparse type for ROLE=NAME (a forecast role and the file's variable)."""
    role, sep, name = text.partition("=")
    if not sep or not name:
        raise argparse.ArgumentTypeError(f"expected ROLE=NAME, e.g. wave_height=var229, got {text!r}")
    try:
        check_roles({role: name})
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc).replace("forecast role", "role")) from None
    return role, name


def iso_time(text: str) -> np.datetime64:
    """argparse type for an ISO 8601 time (UTC), e.g. 2026-10-01T06:00."""
    try:
        return np.datetime64(text.rstrip("Z"), "s")
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected an ISO 8601 time in UTC such as 2026-10-01T06:00, got {text!r}"
        ) from None


def add_forecast_options(rp) -> None:
    """The weather-routing options of `seaway route`."""
    g = rp.add_argument_group(
        "weather routing",
        "with --forecast the route is the quickest (or least fuel, or safest) "
        "through the forecast from --depart; CHART may be left out (the forecast's own grid and "
        "the package's coastline) or be an ice chart (ice and weather in one voyage)",
    )
    g.add_argument(
        "--forecast",
        action="append",
        metavar="FILE",
        help="forecast file: CF NetCDF (fields by standard name, or GRIB short names), "
        "CDO output from GRIB, or GRIB (needs seaway[grib]); repeat it for one file "
        "per variable (merged on time)",
    )
    g.add_argument(
        "--forecast-variable",
        type=role_pair,
        action="append",
        metavar="ROLE=NAME",
        help=f"the variable that plays ROLE (repeatable); roles: {', '.join(ROLES)}; "
        "e.g. wave_height=var229 wave_from=var230 wave_period=var232 for CDO's "
        "ECMWF wave fields; a role mapped onto a grid-relative field of a projected "
        "forecast (standard name x/y, or none) is rotated to east/north, which is said",
    )
    g.add_argument(
        "--forecast-crs",
        metavar="CRS",
        help="the projection of a forecast on a projected grid (EPSG code, PROJ string or "
        "WKT) when its file names no grid mapping, or to override it. A projected forecast "
        "(projection_x/y_coordinate axes, e.g. polar stereographic ROMS, NEMO, WAM) is "
        "resampled bilinearly onto a lat/lon grid (the ice CHART's, else the box around the "
        "ends at the forecast's resolution, or --grid), its grid-relative currents and winds "
        "(sea_water_x/y_velocity, barotropic_sea_water_x/y_velocity, x/y_wind) rotated to "
        "east/north, calm outside the model grid; all said and recorded",
    )
    g.add_argument(
        "--persist",
        action="store_true",
        help="route a departure outside the forecast's times by holding its nearest "
        "frame (persistence), said on stderr; default: refused",
    )
    g.add_argument(
        "--arrive-by",
        type=iso_time,
        metavar="ISO-TIME",
        help="with --objective fuel: the least fuel that arrives by then (Sotnikova 2009)",
    )
    g.add_argument(
        "--displacement",
        type=float,
        metavar="T",
        help="displacement in tonnes for Khokhlov's speed loss (default 15000, or the vessel file's)",
    )


def check_forecast_options(args) -> None:
    """Refuse the weather-routing options without --forecast, naming the fix."""
    given = [f"--{name.replace('_', '-')}" for name in _ONLY_WITH if getattr(args, name, None)]
    if args.objective in ("fuel", "safety"):
        given.append(f"--objective {args.objective}")
    if given and not args.forecast:
        raise SeawayError(f"{', '.join(given)} need --forecast FILE (a forecast to route through)")
    if args.forecast and args.objective == "impact":
        raise SeawayError(
            "--objective impact is a chart's (least ice impact): through a forecast give time, fuel or safety"
        )


def add_voyage_options(rp) -> None:
    """The options every route takes: the ship (--vessel-file), the departure, the objective, the
    escort and the thickness of a stage of development."""
    g = rp.add_argument_group(
        "the voyage",
        "the ship from its vessel file, the departure (an ETA at every waypoint), what the route "
        "minimises, an icebreaker's escort, and the thickness the ice's stages are taken at",
    )
    g.add_argument(
        "--vessel-file",
        metavar="FILE",
        help="vessel file (TOML or JSON, seaway.vessel.load) or a shipped example: "
        "arc7-lng-carrier, arc7-shuttle-tanker, pc6-general-cargo, sotnikova-container-ship; its ice "
        "class, service speed, draft, ice curve and fuel curve; --vessel, --speed, --draft and --displacement "
        "override its values",
    )
    g.add_argument(
        "--depart",
        type=iso_time,
        metavar="ISO-TIME",
        help="departure in UTC: every waypoint gets its ETA in the table and every output "
        "(default through a forecast: its first time; on a chart: no dates, hours only)",
    )
    g.add_argument(
        "--depart-window",
        type=depart_window,
        metavar="FIRST,LAST[,HOURS]",
        help="through a forecast: find the best departure between FIRST and LAST, tried every HOURS "
        "(default 24): the one that arrives first, or with --arrive-by the one arriving in time with the "
        "least fuel (needs the vessel file's fuel curve); the departures tried are printed",
    )
    g.add_argument(
        "--objective",
        choices=OBJECTIVES,
        help="what the route minimises: on a chart impact (default: Grinyak et al. 2022's ice "
        "impact) or time (the quickest route, exact); through a forecast time (default), fuel "
        "(needs the vessel file's fuel curve) or safety (least wave danger by heading)",
    )
    g.add_argument(
        "--escort",
        action="store_true",
        help="where the ship has no speed of its own in ice its class may enter, go under "
        "icebreaker escort (at --escort-speed) and mark those legs; default: avoid that ice",
    )
    g.add_argument(
        "--escort-speed",
        type=float,
        metavar="KN",
        help="the speed under icebreaker escort (default 6 kn, an assumption; said)",
    )
    g.add_argument(
        "--stage-thickness",
        type=stage_thickness,
        metavar="RULE",
        help="the thickness of ice known by its stage of development: mid (default, the middle "
        "of its WMO range), upper, lower, or STAGE=M,... (e.g. 93=1.5,91=0.9); said in the output",
    )


def stage_thickness(text: str):
    """argparse type of --stage-thickness: lower, mid, upper or STAGE=M,..."""
    if "=" not in text:
        value: object = text
    else:
        try:
            value = {
                float(k): float(v) for k, v in (item.split("=") for item in text.replace(" ", "").split(","))
            }
        except ValueError:
            raise argparse.ArgumentTypeError(
                f"expected lower, mid, upper or STAGE=M,... (e.g. 93=1.5), got {text!r}"
            ) from None
    try:
        return check_stage_thickness(value)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None
