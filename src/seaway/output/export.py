"""Write a route as GeoJSON, GPX 1.1, CSV or RTZ (IEC 61174 route exchange, the format ECDIS
equipment imports). Every file is written atomically: to a temporary file beside the target,
then renamed over it, so a reader never sees a half-written file.

GPX and RTZ carry the waypoints (ends and course changes) with longitudes in [-180, 180);
ECDIS joins RTZ waypoints by great-circle legs ("Orthodrome"), as the route was costed.
GeoJSON carries every vertex; a geographic route that crosses the antimeridian is split into a
MultiLineString at +-180 (RFC 7946, section 3.1.9), or, with antimeridian="continuous", kept
as one LineString whose longitudes run past 180 (what Route.to_geojson() gives)."""

from __future__ import annotations

import csv
import io
import json
import os
import xml.etree.ElementTree as ET

import numpy as np

from ..base import sphere as geo
from ..base.files import replace_atomically, write_all, write_atomically  # noqa: F401 - part of this API
from ..result.environment import CATEGORICAL, STAGES, Category, extreme_name
from ..result.schedule import Schedule, dated_schedule, iso, schedule
from .webmap import html_text

#: Summary entries that are points, given in GeoJSON properties as [lat, lon] ([y, x] or
#: [row, col] on planar charts): the ends used, the ends requested, the shallowest point.
POINTS = ("start", "end", "requested_start", "requested_end", "least_depth_at")
GPX_NS = "http://www.topografix.com/GPX/1/1"
RTZ_NS = "http://www.cirm.org/RTZ/1/0"
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
    parts, part = [], [[_wrap180(lon[0]), lat[0]]]
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
        part.append([_wrap180(b), lat[k]])
    parts.append(part)
    return [p for p in parts if len(p) >= 2]


def _wrap180(v):
    w = float(geo.wrap_lon(v))
    return 180.0 if w == -180.0 and v > 0 else w


def geojson(route, antimeridian: str = "split", speed_kn=None) -> dict:
    """A GeoJSON Feature of the route with its summary as properties."""
    if antimeridian not in ("split", "continuous"):
        raise ValueError(f"antimeridian must be 'split' or 'continuous', got {antimeridian!r}")
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
    if route.geographic and antimeridian == "split":
        c = route.coords
        lon = geo.unwrap_lon(c[:, 1])
        parts = _split_antimeridian(c[:, 0].tolist(), lon.tolist())
        if len(parts) > 1:
            feature["geometry"] = {"type": "MultiLineString", "coordinates": parts}
        else:
            feature["geometry"]["coordinates"] = [[_wrap180(x), y] for y, x in zip(c[:, 0], lon)]
    return feature


def gpx(route, speed_kn=None) -> str:
    """GPX 1.1 <rte> with one <rtept> per waypoint."""
    _need_latlon(route, "GPX")
    ET.register_namespace("", GPX_NS)
    root = ET.Element(f"{{{GPX_NS}}}gpx", {"version": "1.1", "creator": "seaway"})
    rte = ET.SubElement(root, f"{{{GPX_NS}}}rte")
    ET.SubElement(rte, f"{{{GPX_NS}}}name").text = route.name
    ET.SubElement(rte, f"{{{GPX_NS}}}desc").text = describe(route, speed_kn)
    timed = schedule(route)
    for k, ((lat, lon), i) in enumerate(zip(route.waypoints, route.waypoint_index), start=1):
        pt = ET.SubElement(rte, f"{{{GPX_NS}}}rtept", {"lat": f"{lat:.7f}", "lon": f"{_wrap180(lon):.7f}"})
        if timed is not None and timed.departure is not None:  # GPX 1.1 orders time before name
            ET.SubElement(pt, f"{{{GPX_NS}}}time").text = iso(timed.eta(int(i)))
        ET.SubElement(pt, f"{{{GPX_NS}}}name").text = f"WP{k:03d}"
    return _xml(root)


def rtz(route, speed_kn=None) -> str:
    """RTZ 1.0 (IEC 61174:2015 annex S): routeInfo, then one waypoint per course change, each with
    its position and the leg that ends at it (great circle; planned speed when known)."""
    _need_latlon(route, "RTZ")
    ET.register_namespace("", RTZ_NS)
    speed = route.speed_kn if speed_kn is None else speed_kn
    root = ET.Element(f"{{{RTZ_NS}}}route", {"version": "1.0"})
    attrs = {"routeName": route.name, "routeAuthor": "seaway", "routeStatus": "computed, not validated"}
    timed = dated_schedule(route)
    if timed is not None:  # the voyage's departure and arrival, and what the route was found through
        attrs.update(validityPeriodStart=iso(timed.eta(0)), validityPeriodStop=iso(timed.eta(-1)))
        attrs["optimizationMethod"] = f"least {route.unit} ({route.edge_cost})" + (
            f"; forecast {timed.forecast}" if timed.forecast else ""
        )
    info = ET.SubElement(root, f"{{{RTZ_NS}}}routeInfo", attrs)
    ext = ET.SubElement(
        ET.SubElement(info, f"{{{RTZ_NS}}}extensions"),
        f"{{{RTZ_NS}}}extension",
        {"manufacturer": "seaway", "name": "description", "version": "1.0"},
    )
    ext.text = describe(route, speed_kn)
    wps = ET.SubElement(root, f"{{{RTZ_NS}}}waypoints")
    default = ET.SubElement(wps, f"{{{RTZ_NS}}}defaultWaypoint", {"radius": "0.1"})
    ET.SubElement(default, f"{{{RTZ_NS}}}leg", {"geometryType": "Orthodrome"})
    legs = route.legs(speed_kn) if route.ice_speed is not None or schedule(route) is not None else None
    for k, (lat, lon) in enumerate(route.waypoints, start=1):
        wp = ET.SubElement(wps, f"{{{RTZ_NS}}}waypoint", {"id": str(k), "name": f"WP{k:03d}"})
        ET.SubElement(wp, f"{{{RTZ_NS}}}position", {"lat": f"{lat:.7f}", "lon": f"{_wrap180(lon):.7f}"})
        if k > 1:
            attrs = {"geometryType": "Orthodrome"}
            leg_speed = legs[k - 2].speed_kn if legs is not None else speed  # in ice, on a clock: the leg's
            if leg_speed:
                attrs["speedMax"] = f"{float(leg_speed):.2f}"
            ET.SubElement(wp, f"{{{RTZ_NS}}}leg", attrs)
    if timed is not None:
        _rtz_schedule(root, route, legs, timed)
    return _xml(root)


def _rtz_schedule(root, route, legs, timed: Schedule) -> None:
    """RTZ's calculated schedule: for each waypoint its ETA and ETD (after any wait there) and
    the speed made good on the leg that ends at it (the first: the departure only)."""
    scheds = ET.SubElement(root, f"{{{RTZ_NS}}}schedules")
    one = ET.SubElement(scheds, f"{{{RTZ_NS}}}schedule", {"id": "1", "name": "seaway"})
    calc = ET.SubElement(one, f"{{{RTZ_NS}}}calculated")
    for k, i in enumerate(route.waypoint_index, start=1):
        attrs = {"waypointId": str(k)}
        if k > 1:
            attrs["eta"] = iso(timed.eta(int(i)))
        if k < len(route.waypoint_index):
            attrs["etd"] = iso(timed.etd(int(i)))
        if k > 1 and legs[k - 2].speed_kn is not None:
            attrs["speed"] = f"{legs[k - 2].speed_kn:.2f}"
        ET.SubElement(calc, f"{{{RTZ_NS}}}scheduleElement", attrs)


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
    timed = dated_schedule(route)
    dated = timed is not None
    w.writerow(CSV_FIELDS + (["eta", "etd"] if dated else []) + [h for n in env for h in _env_header(n)])
    first = route.waypoints[0]
    w.writerow(
        [1, f"{first[0]:.7f}", f"{first[1]:.7f}"]
        + [""] * (len(CSV_FIELDS) - 3)
        + (["", iso(timed.etd(0))] if timed is not None else [])
        + [""] * (2 * len(env))
    )
    wi = route.waypoint_index
    km = cost = 0.0
    for leg in legs:
        km, cost = km + leg.distance, cost + leg.cost
        row = [
            leg.number + 1,
            f"{leg.end[0]:.7f}",
            f"{leg.end[1]:.7f}",
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
        if timed is not None:  # the waypoint's ETA, and its ETD (after any wait; none at the end)
            last = leg.number == len(legs)
            row += [iso(leg.arrive), "" if last else iso(timed.etd(int(wi[leg.number])))]
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
        raise ValueError(f"fmt must be one of {sorted(makers)}, got {fmt!r}")
    return makers[fmt]()


def format_of(path) -> str:
    """The format an output path's extension names; ValueError naming the extensions otherwise."""
    fmt = FORMATS.get(os.path.splitext(os.fspath(path))[1].lower())
    if fmt is None:
        raise ValueError(
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


def _need_latlon(route, what):
    if not route.geographic:
        raise ValueError(
            f"{what} needs latitudes and longitudes; this route is on a planar chart "
            "(give the chart lat/lon coordinates, or export GeoJSON or CSV)"
        )


def header_lines(route, speed_kn=None) -> list:
    """The lines that head a route's file (CSV comments, GPX and RTZ descriptions): its length,
    cost and time; the ends used and those requested; what it assumes."""
    s = route.summary(speed_kn)
    geo_ = route.geographic
    size = f"{s['length_nm']:.1f} nm" if geo_ else f"{s['length']:.4g} {s['length_units']}"
    head = f"{route.name}: {size}, cost {route.cost:.6g} {route.unit}, {s['legs']} legs"
    if "speed_model" in s:
        head += f", {s['time_h']:.1f} h" if np.isfinite(s["time_h"]) else ", no time"
        lines = [head, f"speed in ice: {s['speed_model']}"]
        if s.get("stopped_km"):
            lines.append(f"no speed on {s['stopped_km']:.1f} km (an icebreaker's escort)")
    elif "departure" in s or route.stats.voyage is not None:  # a route on a clock: its real time
        head += f", {s['time_h']:.1f} h"
        lines = [head]
        if "departure" in s:
            lines.append(f"departure {s['departure']}, arrival {s['arrival']}")
        if "forecast" in s:
            lines.append(f"forecast {s['forecast']}")
        if "hours_in_danger" in s:
            lines.append(f"through danger zones {s['hours_in_danger']:.1f} h (no route avoids them)")
    else:
        if "time_h" in s:
            head += f", {s['time_h']:.1f} h at {s['speed_kn']:g} kn"
        lines = [head]
    for end in ("start", "end"):
        line = f"{end} {_point(s[end])}"
        if f"requested_{end}" in s:
            line += f" (requested {_point(s[f'requested_{end}'], None)})"
        lines.append(line)
    return lines + [f"assumed: {a}" for a in s.get("assumptions", ())]


def _voyage_properties(route) -> dict:
    """GeoJSON properties of a route on a clock: the time at every vertex (ISO 8601, in the
    order of route.coords) and each waypoint's ETA and ETD; empty for other routes."""
    timed = schedule(route)
    if timed is None or timed.departure is None:
        return {}
    return {
        "vertex_times": [iso(timed.eta(i)) for i in range(len(route.coords))],
        "waypoint_schedule": [
            {"waypoint": k, "eta": iso(timed.eta(int(i))), "etd": iso(timed.etd(int(i)))}
            for k, i in enumerate(route.waypoint_index, start=1)
        ],
    }


def describe(route, speed_kn=None) -> str:
    """One paragraph for a GPX or RTZ description: header_lines joined."""
    return "; ".join(header_lines(route, speed_kn))


def _point(p, digits=5) -> str:
    return ",".join(f"{v:g}" if digits is None else f"{v:.{digits}f}" for v in p)


def _xml(root) -> str:
    ET.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"
