"""Re-planning during the voyage (Grinyak et al. 2018): where the ship is at a time on a route
a forecast route wrote (its GeoJSON's vertex times), and the quickest route from there to the
same end through a newer forecast, leaving then (replan_voyage; ``seaway replan``)."""

from __future__ import annotations

import dataclasses
import json

import numpy as np

from ..errors import SeawayError
from ..vessel import Vessel
from .forecast import OpenForecast


def read_voyage(path) -> tuple[np.ndarray, np.ndarray, dict]:
    """((n, 2) lat/lon of a route's vertices, (n,) their times, its properties) from the
    GeoJSON of a route on a clock; a route split at the antimeridian is joined again."""
    try:
        with open(path, encoding="utf-8") as f:
            feature = json.load(f)
        geom, props = feature["geometry"], feature["properties"]
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise SeawayError(f"{path}: not a route GeoJSON written by seaway ({exc})") from None
    if "vertex_times" not in props:
        raise SeawayError(
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
        raise SeawayError(f"{path}: {len(times)} vertex times for {len(xy)} vertices")
    return xy, times, props


def position_at(xy, times, at) -> tuple[tuple[float, float], int]:
    """((lat, lon) of the ship at `at`, the index of the vertex it last passed), linear in time
    between the vertices of the route's line (its waypoints, with their ETAs)."""
    if not (times[0] <= at <= times[-1]):
        raise SeawayError(f"--at {at} is outside the voyage ({times[0]} to {times[-1]})")
    i = int(np.searchsorted(times, at, side="right") - 1)
    if i >= len(times) - 1:
        return (float(xy[-1, 0]), float(xy[-1, 1])), len(times) - 1
    f = float((at - times[i]) / (times[i + 1] - times[i]))
    lon = xy[i, 1] + f * ((xy[i + 1, 1] - xy[i, 1] + 180.0) % 360.0 - 180.0)
    return (float(xy[i, 0] + f * (xy[i + 1, 0] - xy[i, 0])), float((lon + 180.0) % 360.0 - 180.0)), i


def replan_voyage(path, forecast: OpenForecast, at, *, end=None, vessel=None, **route_options):
    """(the new Route, (lat, lon) of the ship at `at`, what was decided in words): the quickest
    route from where the ship is at `at` on the voyage GeoJSON `path` (a route through a forecast,
    with vertex times) to `end` (default the voyage's) through `forecast`, leaving at `at`. The
    vessel defaults to the voyage's speed (its speed_kn property), the ice class to the voyage's
    (its ice_class property, through ice); route_options go to OpenForecast.route."""
    xy, times, props = read_voyage(path)
    if at is None:
        raise SeawayError("give the time to re-plan from (--at ISO-TIME), within the voyage")
    at = np.datetime64(at, "s")
    here, i = position_at(xy, times, at)
    end = tuple(end) if end is not None else (float(xy[-1, 0]), float(xy[-1, 1]))
    notes = [
        f"at {at} the ship is at {here[0]:.4f},{here[1]:.4f} (after vertex {i + 1} of {len(xy)}); "
        f"re-planning to {end[0]:.4f},{end[1]:.4f} through {forecast.source}"
    ]
    if vessel is None and props.get("speed_kn"):
        vessel = Vessel(speed_kn=float(props["speed_kn"]))
        notes.append(f"the route's speed {vessel.speed_kn:g} kn (give --speed or --vessel-file to change it)")
    if (
        route_options.get("ice_class") is None
        and props.get("ice_class")
        and getattr(vessel, "ice_class", None) is None
    ):
        route_options["ice_class"] = props["ice_class"]  # through ice: the class the route was for
        notes.append(
            f"the route's ice class {props['ice_class']} (give --vessel CLASS or --vessel-file to change it)"
        )
    r = forecast.route(here, end, vessel=vessel, depart=at, **route_options)
    return dataclasses.replace(r, notes=tuple(notes) + tuple(r.notes)), here, notes
