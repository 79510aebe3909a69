"""Readable routes (legs, summary, str) and the exports (GeoJSON, GPX, RTZ, CSV), read back."""

import csv
import json
import os
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import seaway
from seaway import export
from support.netcdf import small_dataset as _dataset

GPX = "{http://www.topografix.com/GPX/1/1}"
RTZ = "{http://www.cirm.org/RTZ/1/0}"


@pytest.fixture
def equator():
    """Uniform chart on the equator, 0.1-degree pixels, from 0 E to 2 E then north to 1 N."""
    lat, lon = np.linspace(1.0, -1.0, 21), np.linspace(0.0, 2.0, 21)
    cost = np.full((21, 21), 2.0)
    cost[:10, :20] = np.inf  # land north-west: go east along the equator, then north
    return seaway.route(cost, (0.0, 0.0), (1.0, 2.0), lat=lat, lon=lon, neighbourhood=3)


def test_legs_course_distance_time_cost(equator):
    r = equator
    r = r.with_speed(10.0)
    legs = r.legs()
    assert len(legs) == 2 and r.course_changes == 1
    east, north = legs
    assert east.course == pytest.approx(90.0) and north.course == pytest.approx(0.0)
    deg_km = np.pi * 6371.0088 / 180
    assert east.distance == pytest.approx(2 * deg_km, rel=1e-9)
    assert east.distance_nm == pytest.approx(2 * deg_km / 1.852, rel=1e-9)
    assert east.time_h == pytest.approx(east.distance_nm / 10.0)
    assert east.cost == pytest.approx(2.0 * east.distance, rel=1e-9)  # u = 2 on both pixels
    assert east.cost + north.cost == pytest.approx(r.cost, rel=1e-12)
    s = r.summary()
    assert s["length_nm"] == pytest.approx(3 * deg_km / 1.852) and s["time_h"] == pytest.approx(
        3 * deg_km / 1.852 / 10
    )


def test_str_prints_a_table(equator):
    equator = equator.with_speed(12)
    text = str(equator)
    lines = text.splitlines()
    assert lines[0].startswith("seaway route: 00-00.00N 000-00.00E -> 01-00.00N 002-00.00E")
    assert "2 legs, 1 course changes" in lines[0]
    assert "at 12 kn" in lines[1]
    assert lines[2].split()[:4] == ["leg", "from", "to", "course"]
    assert lines[3].split()[0] == "1" and "090.0  120.1  222.4  12   10.0" in lines[3]  # nm, km, kn, h
    assert "000.0" in lines[4] and "60.0" in lines[4]


def test_environment_along_legs(equator):
    ice = np.zeros((21, 21))
    ice[:11, 20] = 7.0  # ice only on the northbound column (rows 10 to 0)
    r = equator.with_environment({"ice": ice})
    east, north = r.legs()
    assert east.environment["ice"][1] == 7.0  # its last pixel is the corner
    assert north.environment["ice"] == (7.0, 7.0)
    assert r.summary()["max_ice"] == 7.0


def _antimeridian_route():
    lat, lon = np.linspace(10.0, 0.0, 11), np.arange(175.0, 186.0) - 360 * (np.arange(175.0, 186.0) > 180)
    return seaway.route(np.ones((11, 11)), (5.0, 176.0), (5.0, -176.0), lat=lat, lon=lon)


def test_geojson_split_at_the_antimeridian(tmp_path):
    r = _antimeridian_route()
    out = tmp_path / "r.geojson"
    assert export.write(r, out) == "geojson"
    f = json.loads(out.read_text())
    g = f["geometry"]
    assert g["type"] == "MultiLineString" and len(g["coordinates"]) == 2
    west, east = g["coordinates"]
    assert west[0] == [176.0, 5.0] and west[-1] == [180.0, 5.0]
    assert east[0] == [-180.0, 5.0] and east[-1] == [-176.0, 5.0]
    assert all(-180 <= p[0] <= 180 for part in g["coordinates"] for p in part)
    assert f["properties"]["length"] == pytest.approx(r.length)
    cont = export.geojson(r, antimeridian="continuous")["geometry"]["coordinates"]
    assert cont[-1] == [184.0, 5.0]


def test_gpx_and_rtz_read_back(tmp_path):
    r = _antimeridian_route()
    r = r.with_speed(14)
    export.write(r, tmp_path / "r.gpx")
    root = ET.parse(tmp_path / "r.gpx").getroot()
    assert root.tag == f"{GPX}gpx" and root.get("version") == "1.1"
    pts = root.findall(f"{GPX}rte/{GPX}rtept")
    assert [(float(p.get("lat")), float(p.get("lon"))) for p in pts] == [(5.0, 176.0), (5.0, -176.0)]
    export.write(r, tmp_path / "r.rtz")
    root = ET.parse(tmp_path / "r.rtz").getroot()
    assert root.tag == f"{RTZ}route" and root.get("version") == "1.0"
    assert root.find(f"{RTZ}routeInfo").get("routeName") == "seaway route"
    wps = root.findall(f"{RTZ}waypoints/{RTZ}waypoint")
    assert [w.get("id") for w in wps] == ["1", "2"]
    pos = [w.find(f"{RTZ}position") for w in wps]
    assert [(float(p.get("lat")), float(p.get("lon"))) for p in pos] == [(5.0, 176.0), (5.0, -176.0)]
    leg = wps[1].find(f"{RTZ}leg")
    assert leg.get("geometryType") == "Orthodrome" and float(leg.get("speedMax")) == 14.0


def test_csv_read_back(tmp_path, equator):
    equator = equator.with_speed(10)
    export.write(equator, tmp_path / "r.csv")
    with open(tmp_path / "r.csv", newline="") as f:
        lines = f.readlines()
    head = [x for x in lines if x.startswith("#")]  # the route's figures, then the column names
    assert head[0].startswith("# seaway route: ") and head[1].startswith("# start 0.00000,")
    rows = list(csv.DictReader(x for x in lines if not x.startswith("#")))
    assert [int(x["waypoint"]) for x in rows] == [1, 2, 3]
    assert float(rows[1]["lon"]) == pytest.approx(2.0) and float(rows[1]["course_deg"]) == 90.0
    assert float(rows[2]["cumulative_km"]) == pytest.approx(equator.length, rel=1e-6)
    assert float(rows[2]["cumulative_cost"]) == pytest.approx(equator.cost, rel=1e-5)
    assert float(rows[1]["time_h"]) == pytest.approx(float(rows[1]["distance_nm"]) / 10, rel=1e-3)


def test_planar_route_refuses_gpx_but_writes_csv(tmp_path):
    r = seaway.route(np.ones((5, 5)), (0, 0), (4, 4))
    with pytest.raises(ValueError, match="planar chart"):
        export.write(r, tmp_path / "r.gpx")
    with pytest.raises(ValueError, match="cannot tell the format"):
        export.write(r, tmp_path / "r.txt")
    export.write(r, tmp_path / "r.csv")
    assert (tmp_path / "r.csv").read_text().splitlines()[-1].startswith("2,4.0000000,4.0000000,1,")
    assert not (tmp_path / "r.gpx").exists()


def test_write_is_atomic(tmp_path, monkeypatch):
    target = tmp_path / "r.geojson"
    target.write_text("old")

    def fail(*_):
        raise OSError("disk full")

    monkeypatch.setattr(os, "replace", fail)
    with pytest.raises(OSError, match="disk full"):
        export.write_atomically(target, "new")
    assert target.read_text() == "old" and os.listdir(tmp_path) == ["r.geojson"]


# --- atomic exports ------------------------------------------------------------------------


def _route():
    return seaway.route(_dataset().cost, (71.0, 61.0), (73.0, 69.0), neighbourhood=5)


@pytest.mark.parametrize("exc", [RuntimeError("disk full"), KeyboardInterrupt()])
def test_an_export_failing_mid_write_leaves_no_file(tmp_path, monkeypatch, exc):
    target = tmp_path / "route.gpx"
    target.write_text("the previous version")
    real_fdopen = os.fdopen

    class Broken:
        def __init__(self, f):
            self.f = f

        def __enter__(self):
            return self

        def __exit__(self, *a):
            self.f.close()

        def write(self, text):
            self.f.write(text[: len(text) // 2])  # half the file reaches the disk...
            self.f.flush()
            raise exc  # ...then the write fails

    monkeypatch.setattr(export.os, "fdopen", lambda *a, **k: Broken(real_fdopen(*a, **k)))
    with pytest.raises(type(exc)):
        export.write(_route(), target)
    assert target.read_text() == "the previous version"  # untouched
    assert sorted(p.name for p in tmp_path.iterdir()) == ["route.gpx"]  # no temporary file
