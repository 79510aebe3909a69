"""Every export of one route gives the same waypoints (issue 27, item 6: a GeoJSON line of 33
vertices beside 30 waypoints in the CSV, GPX and RTZ): GeoJSON (split at the antimeridian and
continuous), GPX, RTZ, CSV, the HTML map's line and markers and the printed leg table carry the
same vertices, as many, at the same positions (to 1e-6 degree) and, with a departure, the same
ETAs; for a static ice chart (smoothed and not, timed by the speed in the ice), a route on a clock
through ice and weather (smoothed and not), a projected chart and a route across the antimeridian."""

from __future__ import annotations

import csv
import dataclasses
import io
import json
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import seaway
from seaway import export
from seaway.result.schedule import iso, short
from seaway.result.table import fmt_point
from seaway.result.waypoints import waypoint_list
from seaway.samples import ice_impact, kara_sea
from support import timed_cases

GPX = "{http://www.topografix.com/GPX/1/1}"
RTZ = "{http://www.cirm.org/RTZ/1/0}"
DEPART = np.datetime64("2026-03-01T06:00", "s")


def _kara():
    ds = kara_sea(shape=(190, 230))
    u = np.asarray(ice_impact(ds.stage_of_development, "Arc7"))
    r = seaway.route(u, (70.3, 58.5), (77.7, 103.99), land=ds.land, lat=ds.lat.values, lon=ds.lon.values)
    knots = np.where(np.isfinite(u), 12.0 / np.maximum(u, 1.0), 0.0)  # slower in heavier ice
    return r.with_speed(12.0), knots


def _antimeridian():
    lat, lon = np.linspace(70, 60, 41), np.linspace(170, 190, 81) % 360
    lon = np.where(lon > 180, lon - 360, lon)
    cost = np.ones((41, 81))
    cost[5:30, 30:34] = np.inf  # a wall across the antimeridian: course changes on both sides
    r = seaway.route(cost, (65, 172), (62, -172), lat=lat, lon=lon).smoothed()
    return dataclasses.replace(r.with_speed(14.0), departure=DEPART)


def _projected():
    """A route on a polar stereographic grid (EPSG:3413, 10 km pixels), its vertices given in
    lat/lon as seaway route gives them on a projected chart."""
    pyproj = pytest.importorskip("pyproj")
    cost = np.ones((30, 40))
    cost[8:25, 18] = np.inf
    r = seaway.route(cost, (2, 2), (27, 37), dx=10.0, dy=10.0)
    y, x = r.coords[:, 0], r.coords[:, 1]
    to_ll = pyproj.Transformer.from_crs("EPSG:3413", "EPSG:4326", always_xy=True)
    lon, lat = to_ll.transform(x * 1000.0 - 500000.0, -y * 1000.0 - 1500000.0)
    return dataclasses.replace(r, latlon=np.column_stack([lat, lon]), speed_kn=10.0, departure=DEPART)


def _routes():
    kara, knots = _kara()
    clock = timed_cases.ice_weather(4, shape=(12, 16), smooth=True).route
    return {
        "ice chart": kara,
        "ice chart, smoothed, departure": dataclasses.replace(kara.smoothed(), departure=DEPART),
        "ice chart, speed in the ice": dataclasses.replace(
            kara.with_ice_speed(knots, "12 kn / impact"), departure=DEPART
        ),
        "ice + weather on a clock": clock,
        "ice + weather on a clock, smoothed": clock.smoothed(),
        "across the antimeridian": _antimeridian(),
        "projected chart": _projected(),
    }


@pytest.fixture(scope="module")
def routes():
    return _routes()


def _geojson(route, antimeridian):
    """[(lat, lon)] of the GeoJSON line (the points added where it is cut at +-180 dropped) and
    its vertex times."""
    f = json.loads(json.dumps(export.geojson(route, antimeridian=antimeridian)))
    g = f["geometry"]
    parts = g["coordinates"] if g["type"] == "MultiLineString" else [g["coordinates"]]
    pts = list(parts[0])
    for part in parts[1:]:
        assert abs(pts[-1][0]) == 180.0 and part[0][0] == -pts[-1][0]  # the cut, on +-180
        pts = pts[:-1] + list(part[1:])
    return [(p[1], p[0]) for p in pts], f["properties"].get("vertex_times")


def _gpx(route):
    pts = ET.fromstring(export.gpx(route)).findall(f"{GPX}rte/{GPX}rtept")
    times = [p.find(f"{GPX}time") for p in pts]
    return [(float(p.get("lat")), float(p.get("lon"))) for p in pts], [
        t.text if t is not None else None for t in times
    ]


def _rtz(route):
    root = ET.fromstring(export.rtz(route))
    pos = [w.find(f"{RTZ}position") for w in root.findall(f"{RTZ}waypoints/{RTZ}waypoint")]
    sched = root.findall(f"{RTZ}schedules/{RTZ}schedule/{RTZ}calculated/{RTZ}scheduleElement")
    times = [e.get("eta") or e.get("etd") for e in sched]  # the first: its departure
    return [(float(p.get("lat")), float(p.get("lon"))) for p in pos], times or None


def _csv(route):
    text = "\n".join(line for line in export.csv_text(route).splitlines() if not line.startswith("#"))
    rows = list(csv.DictReader(io.StringIO(text)))
    times = [r["eta"] or r["etd"] for r in rows] if rows and "eta" in rows[0] else None
    return [(float(r["lat"]), float(r["lon"])) for r in rows], times


def _html(route):
    page = export.render(route, "html")
    line = json.loads(re.search(r"L\.polyline\(\s*(\[\[.*?\]\])", page, flags=re.S).group(1))
    marks = re.findall(r"L\.(?:circleMarker|marker)\(\s*\[([-0-9.e]+),\s*([-0-9.e]+)\]", page)
    return [tuple(p) for p in line], [(float(a), float(b)) for a, b in marks]


def _same(a, b, what, geographic=True):
    assert len(a) == len(b), f"{what}: {len(a)} vertices against {len(b)}"
    a, b = np.asarray(a, float), np.asarray(b, float)
    np.testing.assert_allclose(a[:, 0], b[:, 0], atol=1e-6, err_msg=what)
    dlon = (a[:, 1] - b[:, 1] + 180.0) % 360.0 - 180.0 if geographic else a[:, 1] - b[:, 1]
    np.testing.assert_allclose(dlon, 0.0, atol=1e-6, err_msg=what)


@pytest.mark.parametrize(
    "kind",
    [
        "ice chart",
        "ice chart, smoothed, departure",
        "ice chart, speed in the ice",
        "ice + weather on a clock",
        "ice + weather on a clock, smoothed",
        "across the antimeridian",
        "projected chart",
    ],
)
def test_every_export_gives_the_same_waypoints(routes, kind):
    r = routes[kind]
    wl = waypoint_list(r)
    want = [(float(a), b) for a, b in zip(wl.lat, wl.lon)]
    assert len(want) == len(r.waypoint_index) >= 3  # ends and course changes
    gpx, gpx_t = _gpx(r)
    found = {
        "GeoJSON": _geojson(r, "split"),
        "GeoJSON continuous": _geojson(r, "continuous"),
        "GPX": (gpx, gpx_t if gpx_t[0] is not None else None),
        "RTZ": _rtz(r),
        "CSV": _csv(r),
        "Route.to_geojson": ([(p[1], p[0]) for p in r.to_geojson()["geometry"]["coordinates"]], None),
    }
    times = [iso(t) for t in wl.eta] if wl.dated else None
    if times is not None:
        times[0] = iso(wl.etd[0])  # the departure (the first ETD, after any wait at the start)
    for what, (pts, t) in found.items():
        _same(pts, want, what)
        if what not in ("Route.to_geojson", "GeoJSON", "GeoJSON continuous"):
            assert t == times, what
    for what in ("GeoJSON", "GeoJSON continuous"):  # the times at the line's vertices: their ETAs
        t = found[what][1]
        assert t == ([iso(x) for x in wl.eta] if wl.dated else None), what
    assert [leg.end for leg in r.legs()] == [tuple(map(float, c)) for c in wl.coords[1:]]
    table = [line.split() for line in str(r).splitlines() if re.match(r"^\s*\d+\s+\d\d-", line)]
    assert len(table) == len(want) - 1  # one printed leg between consecutive waypoints
    for k, cells in enumerate(table):
        row = " ".join(cells)
        assert row.startswith(f"{k + 1} {fmt_point(wl.coords[k], True)} {fmt_point(wl.coords[k + 1], True)}")
        if wl.dated:
            assert short(wl.eta[k + 1]) in row
    if r.latlon is None:  # the HTML map (lat/lon charts): its line and a marker at each waypoint
        pytest.importorskip("folium")
        line, marks = _html(r)
        _same(line, want, "HTML line")
        _same(marks, want, "HTML markers")


def test_planar_exports_give_the_same_waypoints():
    cost = np.ones((20, 20))
    cost[3:17, 9] = np.inf
    r = seaway.route(cost, (1, 1), (18, 18), dx=5.0, dy=2.0).smoothed()
    wl = waypoint_list(r)
    assert len(wl) >= 3
    pts, _ = _geojson(r, "split")
    want = wl.coords.tolist()
    _same(pts, want, "GeoJSON", geographic=False)
    _same(_csv(r)[0], want, "CSV", geographic=False)
    assert len([line for line in str(r).splitlines() if re.match(r"^\s*\d+\s+y ", line)]) == len(wl) - 1
