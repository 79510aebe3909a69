"""A route as GPX 1.1 and RTZ 1.0 (IEC 61174 route exchange, the format ECDIS equipment imports):
the waypoints (ends and course changes) with longitudes in [-180, 180); RTZ joins them by great
circle legs ("Orthodrome"), as the route was costed, with the planned speed and, on a clock, the
calculated schedule (seaway.export writes the files)."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from ..errors import SeawayError
from ..result.schedule import dated_schedule, iso, schedule
from ..result.waypoints import Waypoints, waypoint_list
from .header import describe

GPX_NS = "http://www.topografix.com/GPX/1/1"
RTZ_NS = "http://www.cirm.org/RTZ/1/0"


def gpx(route, speed_kn=None) -> str:
    """GPX 1.1 <rte> with one <rtept> per waypoint."""
    _need_latlon(route, "GPX")
    ET.register_namespace("", GPX_NS)
    root = ET.Element(f"{{{GPX_NS}}}gpx", {"version": "1.1", "creator": "seaway"})
    rte = ET.SubElement(root, f"{{{GPX_NS}}}rte")
    ET.SubElement(rte, f"{{{GPX_NS}}}name").text = route.name
    ET.SubElement(rte, f"{{{GPX_NS}}}desc").text = describe(route, speed_kn)
    wl = waypoint_list(route)  # the waypoints every format gives
    for k, (lat, lon, eta) in enumerate(zip(wl.lat, wl.lon, wl.eta), start=1):
        pt = ET.SubElement(rte, f"{{{GPX_NS}}}rtept", {"lat": f"{lat:.7f}", "lon": f"{lon:.7f}"})
        if wl.dated:  # GPX 1.1 orders time before name
            ET.SubElement(pt, f"{{{GPX_NS}}}time").text = iso(eta)
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
    wl = waypoint_list(route)  # the waypoints every format gives
    for k, (lat, lon) in enumerate(zip(wl.lat, wl.lon), start=1):
        wp = ET.SubElement(wps, f"{{{RTZ_NS}}}waypoint", {"id": str(k), "name": f"WP{k:03d}"})
        ET.SubElement(wp, f"{{{RTZ_NS}}}position", {"lat": f"{lat:.7f}", "lon": f"{lon:.7f}"})
        if k > 1:
            attrs = {"geometryType": "Orthodrome"}
            leg_speed = legs[k - 2].speed_kn if legs is not None else speed  # in ice, on a clock: the leg's
            if leg_speed:
                attrs["speedMax"] = f"{float(leg_speed):.2f}"
            ET.SubElement(wp, f"{{{RTZ_NS}}}leg", attrs)
    if timed is not None:
        _rtz_schedule(root, wl, legs)
    return _xml(root)


def _rtz_schedule(root, wl: Waypoints, legs) -> None:
    """RTZ's calculated schedule: for each waypoint its ETA and ETD (after any wait there) and
    the speed made good on the leg that ends at it (the first: the departure only)."""
    scheds = ET.SubElement(root, f"{{{RTZ_NS}}}schedules")
    one = ET.SubElement(scheds, f"{{{RTZ_NS}}}schedule", {"id": "1", "name": "seaway"})
    calc = ET.SubElement(one, f"{{{RTZ_NS}}}calculated")
    for k, (eta, etd) in enumerate(zip(wl.eta, wl.etd), start=1):
        attrs = {"waypointId": str(k)}
        if k > 1:
            attrs["eta"] = iso(eta)
        if k < len(wl):
            attrs["etd"] = iso(etd)
        if k > 1 and legs[k - 2].speed_kn is not None:
            attrs["speed"] = f"{legs[k - 2].speed_kn:.2f}"
        ET.SubElement(calc, f"{{{RTZ_NS}}}scheduleElement", attrs)


def _need_latlon(route, what):
    if not route.geographic:
        raise SeawayError(
            f"{what} needs latitudes and longitudes; this route is on a planar chart "
            "(give the chart lat/lon coordinates, or export GeoJSON or CSV)"
        )


def _xml(root) -> str:
    ET.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"
