"""The options of `seaway route --forecast FILE ...` (weather routing, seaway.cli.forecast runs
it): the forecast files and their variables, the departure, the objective, the vessel file;
and the check that refuses them without --forecast."""

from __future__ import annotations

import argparse

import numpy as np

from ..weather.forecast import ROLES, check_roles

OBJECTIVES = ("time", "fuel", "safety")
EXAMPLE = (
    "example: seaway route --forecast waves.nc --forecast currents.nc --depart "
    "2026-10-01T06:00 --from 70.3,58.5 --to 76.5,95.0 --vessel-file pc6-general-cargo "
    "--out voyage.rtz"
)
#: Options that mean something only with --forecast.
_ONLY_WITH = (
    "forecast_variable",
    "forecast_crs",
    "depart",
    "persist",
    "arrive_by",
    "displacement",
    "vessel_file",
)


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
        "--depart",
        type=iso_time,
        metavar="ISO-TIME",
        help="departure in UTC (default: the forecast's first time)",
    )
    g.add_argument(
        "--persist",
        action="store_true",
        help="route a departure outside the forecast's times by holding its nearest "
        "frame (persistence), said on stderr; default: refused",
    )
    g.add_argument(
        "--objective",
        choices=OBJECTIVES,
        default="time",
        help="time (default), fuel (needs the vessel file's fuel curve) or safety "
        "(least wave danger by heading; needs wave height, direction, period)",
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
    g.add_argument(
        "--vessel-file",
        metavar="FILE",
        help="vessel profile (TOML or JSON, seaway.vessel.load) or a shipped example: "
        "arc7-lng-carrier, pc6-general-cargo, sotnikova-container-ship; --speed, "
        "--displacement and --vessel override its values",
    )


def check_forecast_options(args) -> None:
    """Refuse the weather-routing options without --forecast, naming the fix."""
    given = [f"--{name.replace('_', '-')}" for name in _ONLY_WITH if getattr(args, name, None)]
    if args.objective != "time":
        given.append("--objective")
    if given and not args.forecast:
        raise ValueError(f"{', '.join(given)} need --forecast FILE (a forecast to route through)")
