"""Write a route as GeoJSON, GPX 1.1, CSV or RTZ (IEC 61174 route exchange, the format ECDIS
equipment imports). Every file is written atomically: to a temporary file beside the target,
then renamed over it, so a reader never sees a half-written file.

Every format carries the same waypoints (the ends and course changes, with their ETAs on a route
with a departure), from one list: seaway.result.waypoints.waypoint_list. GPX, RTZ and CSV give
longitudes in [-180, 180); ECDIS joins RTZ waypoints by great-circle legs ("Orthodrome"), as the
route was costed. GeoJSON's line runs through the same waypoints; a geographic route that crosses
the antimeridian is split into a MultiLineString at +-180 (RFC 7946, section 3.1.9: the two
points added on +-180 are cuts, not waypoints), or, with antimeridian="continuous", kept as one
LineString whose longitudes run past 180 (what Route.to_geojson() gives)."""

from __future__ import annotations

import csv
import io
import json
import os

import numpy as np

from ..base.files import replace_atomically, write_all, write_atomically  # noqa: F401 - part of this API
from ..errors import SeawayError
from ..result.environment import CATEGORICAL, STAGES, Category, extreme_name
from ..result.schedule import iso
from ..result.waypoints import waypoint_list
from .header import describe, header_lines, wrap180
from .routexml import GPX_NS, RTZ_NS, gpx, rtz
from .webmap import html_text

# The API (the page of seaway.export): the writers, from whichever module of seaway.output holds
# them (routexml: GPX and RTZ; header: the lines that head every file).
__all__ = [
    "csv_text",
    "describe",
    "format_of",
    "geojson",
    "gpx",
    "header_lines",
    "render",
    "rtz",
    "write",
    "POINTS",
    "FORMATS",
    "CSV_FIELDS",
    "GPX_NS",
    "RTZ_NS",
]

#: Summary entries that are points, given in GeoJSON properties as [lat, lon] ([y, x] or
#: [row, col] on planar charts): the ends used, the ends requested, the shallowest point.
POINTS = ("start", "end", "requested_start", "requested_end", "least_depth_at")
FORMATS = {
    ".geojson": "geojson",
    ".json": "geojson",
    ".gpx": "gpx",
    ".csv": "csv",
    ".rtz": "rtz",
    ".html": "html",
    ".htm": "html",
}


def _split_antimeridian(lat, lon):
    """Parts of a polyline with continuous longitudes, cut where it crosses +-180 (the crossing
    latitude interpolated linearly in lon/lat), each part in [-180, 180]."""
    parts, part = [], [[wrap180(lon[0]), lat[0]]]
    for k in range(1, len(lon)):
        a, b = lon[k - 1], lon[k]
        turn_a, turn_b = np.floor((a + 180) / 360), np.floor((b + 180) / 360)
        if turn_a != turn_b:
            edge = 360 * max(turn_a, turn_b) - 180  # the meridian +-180 crossed, continuous
            t = (edge - a) / (b - a)
            cross_lat = float(lat[k - 1] + t * (lat[k] - lat[k - 1]))
            side = 180.0 if b > a else -180.0
            part.append([side, cross_lat])
            parts.append(part)
            part = [[-side, cross_lat]]
        part.append([wrap180(b), lat[k]])
    parts.append(part)
    return [p for p in parts if len(p) >= 2]


def geojson(route, antimeridian: str = "split", speed_kn=None) -> dict:
    """A GeoJSON Feature of the route with its summary as properties."""
    if antimeridian not in ("split", "continuous"):
        raise SeawayError(f"antimeridian must be 'split' or 'continuous', got {antimeridian!r}")
    feature = route.to_geojson()
    props = feature["properties"]
    for k, v in route.summary(speed_kn).items():
        if isinstance(v, str) or (isinstance(v, (int, float)) and np.isfinite(v)):
            props[k] = v
        elif k in POINTS and v is not None:  # [lat, lon] (planar charts: [y, x] / [row, col])
            props[k] = [float(x) for x in v]
        elif k == "assumptions":  # what the chart's ice assumes (seaway.ice.forms)
            props[k] = list(v)
    props["name"] = route.name
    props.update(_voyage_properties(route))
    wl = waypoint_list(route)
    if route.geographic and antimeridian == "split" and len(wl) > 1:
        lat, lon = wl.lat.tolist(), wl.continuous_lon.tolist()
        parts = _split_antimeridian(lat, lon)
        if len(parts) > 1:
            feature["geometry"] = {"type": "MultiLineString", "coordinates": parts}
        else:
            feature["geometry"]["coordinates"] = [[wrap180(x), y] for y, x in zip(lat, lon)]
    return feature


CSV_FIELDS = [
    "waypoint",
    "lat",
    "lon",
    "leg",
    "course_deg",
    "distance_km",
    "distance_nm",
    "speed_kn",
    "time_h",
    "cost",
    "cumulative_km",
    "cumulative_cost",
]


def csv_text(route, speed_kn=None) -> str:
    """One row per waypoint; leg columns describe the leg that ends at the waypoint (empty on the
    first row). Planar routes give y/x in the lat/lon columns and chart units for km."""
    legs = route.legs(speed_kn)
    env = list(route.environment)
    out = io.StringIO()
    out.writelines(f"# {line}\n" for line in header_lines(route, speed_kn))
    w = csv.writer(out, lineterminator="\n")
    wl = waypoint_list(route)  # the waypoints every format gives
    dated = wl.dated
    lat = wl.lat
    lon = wl.lon if route.geographic else wl.coords[:, 1]
    w.writerow(CSV_FIELDS + (["eta", "etd"] if dated else []) + [h for n in env for h in _env_header(n)])
    w.writerow(
        [1, f"{lat[0]:.7f}", f"{lon[0]:.7f}"]
        + [""] * (len(CSV_FIELDS) - 3)
        + (["", iso(wl.etd[0])] if dated else [])
        + [""] * (2 * len(env))
    )
    km = cost = 0.0
    for leg in legs:
        km, cost = km + leg.distance, cost + leg.cost
        k = leg.number  # the waypoint the leg ends at, 0-based
        row = [
            leg.number + 1,
            f"{lat[k]:.7f}",
            f"{lon[k]:.7f}",
            leg.number,
            f"{leg.course:.2f}",
            f"{leg.distance:.4f}",
            _opt(leg.distance_nm, 4),
            _opt(leg.speed_kn, 2),
            _opt(leg.time_h, 3),
            f"{leg.cost:.6g}",
            f"{km:.4f}",
            f"{cost:.6g}",
        ]
        if dated:  # the waypoint's ETA, and its ETD (after any wait; none at the end)
            last = leg.number == len(legs)
            row += [iso(wl.eta[k]), "" if last else iso(wl.etd[k])]
        row += [c for n in env for c in _env_cells(leg.environment[n])]
        w.writerow(row)
    return out.getvalue()


def _env_header(name):
    if name in CATEGORICAL:  # stage / form codes: one category per leg, code and name
        return [f"{name}_{'governing' if name in STAGES else 'most_frequent'}", f"{name}_name"]
    return [f"{name}_mean", f"{name}_{extreme_name(name)}"]


def _env_cells(value):
    if isinstance(value, Category):
        return ["" if not np.isfinite(value.code) else str(int(value.code)), value.name]
    return ["" if not np.isfinite(v) else f"{v:.4g}" for v in value]


def render(route, fmt: str, speed_kn=None, **map_options) -> str:
    """The text of `route` in format `fmt` (one of FORMATS' values); map_options go to the HTML
    map (seaway.output.webmap.explore)."""
    makers = {
        "geojson": lambda: json.dumps(geojson(route, speed_kn=speed_kn), indent=1),
        "gpx": lambda: gpx(route, speed_kn),
        "rtz": lambda: rtz(route, speed_kn),
        "csv": lambda: csv_text(route, speed_kn),
        "html": lambda: html_text(route, speed_kn=speed_kn, **map_options),
    }
    if fmt not in makers:
        raise SeawayError(f"fmt must be one of {sorted(makers)}, got {fmt!r}")
    return makers[fmt]()


def format_of(path) -> str:
    """The format an output path's extension names; ValueError naming the extensions otherwise."""
    fmt = FORMATS.get(os.path.splitext(os.fspath(path))[1].lower())
    if fmt is None:
        raise SeawayError(
            f"cannot tell the format of {os.fspath(path)!r}: use one of the extensions "
            f"{', '.join(sorted(FORMATS))}"
        )
    return fmt


def write(route, path, fmt=None, speed_kn=None) -> str:
    """Write `route` to `path` in the format given or named by its extension, atomically;
    returns the format. Several files all or nothing: seaway.base.files.write_all over render()."""
    fmt = fmt or format_of(path)
    write_all([(path, render(route, fmt, speed_kn))])
    return fmt


def _opt(v, digits):
    return "" if v is None else f"{v:.{digits}f}"


def _voyage_properties(route) -> dict:
    """GeoJSON properties of a route with a departure: the ice class it was routed for (routes
    through ice), the time at every vertex of its line (the waypoints' ETAs, ISO 8601, in the
    order of the line) and each waypoint's ETA and ETD; empty for other routes."""
    wl = waypoint_list(route)
    if not wl.dated:
        return {}
    voyage = route.stats.voyage
    cls = {} if voyage is None or not getattr(voyage, "ice_class", None) else {"ice_class": voyage.ice_class}
    return cls | {
        "vertex_times": [iso(t) for t in wl.eta],
        "waypoint_schedule": [
            {"waypoint": k, "eta": iso(a), "etd": iso(d)}
            for k, (a, d) in enumerate(zip(wl.eta, wl.etd), start=1)
        ],
    }
