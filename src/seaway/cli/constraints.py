"""The constraint options of `seaway route`: via-points, turn penalty, keep-away
buffers and zones, turned into seaway.route() keywords."""

from __future__ import annotations

import argparse

import numpy as np

from ..constraints import KeepAway, Zone


def _numbers(text: str, n: int, what: str) -> tuple[float, ...]:
    try:
        vals = tuple(float(v) for v in text.replace(" ", "").split(","))
    except ValueError:
        vals = ()
    if len(vals) != n or not all(np.isfinite(v) and v >= 0 for v in vals):
        raise argparse.ArgumentTypeError(f"expected {what} (non-negative numbers), got {text!r}")
    return vals


def soft_buffer(text: str) -> tuple[float, float]:
    """argparse type for KM,PENALTY."""
    return _numbers(text, 2, "KM,PENALTY, e.g. 30,2")


def ice_buffer(text: str) -> tuple[float, float]:
    """argparse type for COST,KM."""
    return _numbers(text, 2, "COST,KM, e.g. 20,10 (keep 10 km from pixels costing 20 or more)")


def penalty_zone(text: str) -> tuple[str, float]:
    """argparse type for FILE,FACTOR."""
    path, _, factor = text.rpartition(",")
    try:
        f = float(factor)
    except ValueError:
        f = float("nan")
    if not path or not f >= 1:
        raise argparse.ArgumentTypeError(f"expected FILE,FACTOR with FACTOR >= 1, got {text!r}")
    return path, f


def constraint_options(args) -> dict:
    """route() keywords for the constraint options of `seaway route`."""

    keep = []
    if args.land_buffer or args.land_soft:
        soft_km, penalty = args.land_soft or (0.0, 1.0)
        keep.append(KeepAway(km=args.land_buffer or 0.0, soft_km=soft_km, penalty=penalty))
    for cost, km in args.ice_buffer or []:
        keep.append(KeepAway(km=km, ice=cost))
    zones = [Zone(f, name=f) for f in args.zone or []]
    zones += [Zone(f, penalty=x, name=f) for f, x in args.penalty_zone or []]
    return dict(via=args.via or [], turn_penalty=args.turn_penalty, keep_away=keep, zones=zones)


def add_constraint_options(rp, point) -> None:
    """Add the constraint options to the `seaway route` parser (`point`: the LAT,LON type)."""
    rp.add_argument(
        "--via",
        type=point,
        action="append",
        metavar="LAT,LON",
        help="a waypoint the route must pass (repeatable, in order); each leg is optimal",
    )
    rp.add_argument(
        "--turn-penalty",
        type=float,
        metavar="COST",
        help="cost per degree of course change (route cost units); exact search over "
        "(pixel, last step), 9 bytes x stencil offsets per pixel",
    )
    rp.add_argument(
        "--land-buffer",
        type=float,
        metavar="KM",
        help="keep at least KM from land (great-circle km on lat/lon charts)",
    )
    rp.add_argument(
        "--land-soft",
        type=soft_buffer,
        metavar="KM,PENALTY",
        help="within KM of land multiply the cost by up to 1 + PENALTY (at the hard "
        "limit), falling linearly to 1 at KM",
    )
    rp.add_argument(
        "--ice-buffer",
        type=ice_buffer,
        action="append",
        metavar="COST,KM",
        help="keep KM from pixels whose cost is COST or more (severe ice); repeatable",
    )
    rp.add_argument(
        "--zone",
        action="append",
        metavar="FILE",
        help="exclusion area: GeoJSON, shapefile or GeoPackage polygons in the chart's lon/lat (repeatable)",
    )
    rp.add_argument(
        "--penalty-zone",
        type=penalty_zone,
        action="append",
        metavar="FILE,FACTOR",
        help="penalty area: cost x FACTOR (>= 1) inside the polygons (repeatable)",
    )
