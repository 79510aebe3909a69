"""Acceptance on the synthetic AARI-style February chart of the whole Northern Sea Route
(tests/support/aari_winter.py, docs/user/validation.md): the chart reads as it was written, the
Arc7 LNG carrier of the shipped vessel file crosses it from Sabetta to the Bering Strait and in
the Kara Sea on its own, every leg timed and scheduled, the command line gives the same route
and an RTZ with the schedule, and PC6 and Arc4 ships are refused with the ice that stops them.

Expected values come from the chart as written (polygons tested with shapely, not seaway's
reader) and from the vessel file's ice curve by hand: 19.5 kn in open water, 2 kn at 2.1 m,
linear between; at 10/10 the equivalent thickness is the stage's: young ice 0.20 m ->
17.83 kn, thick first-year ice 1.60 m (the middle of 1.2-2.0 m, WMO-No. 259) -> 6.17 kn."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET

import numpy as np
import pyproj
import pytest
import shapely

import seaway
from seaway.cli import main
from seaway.vessel import load
from support import aari_winter

SABETTA, BERING = (71.27, 72.07), (66.1, -169.5)
KARA_GATE, VILKITSKY = (70.4, 58.6), (77.7, 104.0)
DEPART = "2021-02-07T00:00"
GEOD = pyproj.Geod(ellps="WGS84")
#: Published Sabetta (or the Ob Bay sea canal) -> Cape Dezhnev / Bering Strait tracks of the
#: Arc7 LNG carriers (docs/user/validation.md): 2,360 nm (Jul 2018, Marine Log) to 2,563 nm
#: (May 2020, Sovcomflot/TradeWinds).
PUBLISHED_NM = (2360.0, 2563.0)
LAND = set(aari_winter.LAND)
CLOSED = {"old ice", "northern East Siberian Sea"}  # old ice governs: no Arc7 may enter
#: Land is rasterised by pixel centres (5.6 km north-south on the default grid): a leg may clip
#: a cape of the coarse coastline by less than half a pixel where no pixel centre is land.
HALF_PIXEL_KM = 2.8


def curve_kn(h_m):
    """The Arc7 LNG carrier's ice curve (its vessel file), by hand."""
    return 19.5 - (19.5 - 2.0) / 2.1 * h_m


@pytest.fixture(scope="module")
def chart(tmp_path_factory):
    path = tmp_path_factory.mktemp("aari") / "aari_winter_20210207.shp"
    aari_winter.write(path)
    return str(path)


@pytest.fixture(scope="module")
def plane():
    geoms, _, names = aari_winter.build()
    return geoms, names


@pytest.fixture(scope="module")
def arc7_route(chart):
    opened = seaway.open_chart(chart, land="chart", vessel=load("arc7-lng-carrier"), ends=(SABETTA, BERING))
    return opened, opened.route(SABETTA, BERING, depart=DEPART)


def met(route, plane, per_leg=80):
    """(the chart features, by name, under the legs as drawn: straight in lat/lon; the deepest
    any of them goes into land, km)."""
    geoms, names = plane
    land = shapely.union_all([g for g, n in zip(geoms, names) if n in LAND])
    out, deepest = [], 0.0
    w = np.asarray(route.coords, float)
    for (la0, lo0), (la1, lo1) in zip(w[:-1], w[1:]):
        for t in np.linspace(0, 1, per_leg):
            la, lo = la0 + (la1 - la0) * t, lo0 + (lo1 - lo0) * t
            name = aari_winter.feature_at(la, lo, geoms, names)
            if name in LAND:
                deepest = max(deepest, land.boundary.distance(aari_winter.point(la, lo)) / 1e3)
            else:
                out.append(name)
    return out, deepest


def check_timed(route, lowest_kn, highest_kn):
    """Every leg timed and scheduled: a finite time and speed within the curve's range for the
    ice the chart holds, its time its length over its speed, each ETA the previous plus its
    hours, and the legs' hours the voyage's."""
    legs = route.legs()
    start, hours = np.datetime64(DEPART, "s"), 0.0
    for leg in legs:
        assert np.isfinite(leg.time_h) and leg.time_h > 0 and leg.escorted_km == 0.0
        assert lowest_kn - 1e-6 <= leg.speed_kn <= highest_kn + 1e-6, leg
        assert leg.time_h == pytest.approx(leg.distance_nm / leg.speed_kn, rel=1e-9)
        for when, h in ((leg.depart, hours), (leg.arrive, hours + leg.time_h)):
            assert abs((when - start) / np.timedelta64(1, "s") - h * 3600.0) <= 1.0  # ETAs to the second
        hours += leg.time_h
    total = route.summary()["time_h"]
    assert sum(leg.time_h for leg in legs) == pytest.approx(total, rel=1e-9)
    return total


def test_the_chart_reads_as_it_was_written(chart, plane):
    """At 600 points of the chart's box, the stage (SA) and form (FA) seaway's reader puts on the
    pixel are those of the polygon that covers the point in the plane it was made in."""
    geoms, names = plane
    _, attrs, _ = aari_winter.build()
    opened = seaway.open_chart(chart, land="chart", vessel="Arc7", ends=(SABETTA, BERING))
    rng = np.random.default_rng(7)
    lat, lon = rng.uniform(66.5, 83.5, 600), rng.uniform(52.0, 198.0, 600)
    agree = n = 0
    for la, lo in zip(lat, lon):
        name = aari_winter.feature_at(la, lo, geoms, names)
        if not name or name in LAND:
            continue
        a = attrs[[i for i, g in enumerate(geoms) if g.covers(aari_winter.point(la, lo))][0]]
        px = opened.layers.sel(lat=la, lon=lo, method="nearest")
        n += 1
        agree += float(px.SA) == float(a["SA"]) and (float(px.FA) == 8.0) == (a["FA"] == "08")
    assert n > 300 and agree / n >= 0.97  # pixels of 5.6 km straddle the polygons' edges


def test_arc7_lng_carrier_sabetta_to_the_bering_strait(arc7_route, plane):
    _, r = arc7_route
    total = check_timed(r, curve_kn(1.60), curve_kn(0.20))
    assert not any("under icebreaker escort" in n for n in r.notes)
    seen, into_land = met(r, plane)
    assert not set(seen) & CLOSED and into_land <= HALF_PIXEL_KM, "the route crosses land or old ice"
    assert len(set(seen) - {"fast ice", "flaw polynya"}) >= 4  # it crosses several regions
    # Through the Vilkitsky Strait: the only water at 104.3 E lies between Cape Chelyuskin
    # (77.7 N) and Severnaya Zemlya (78.15 N) on the chart.
    w = np.asarray(r.coords)
    i = int(np.argmax(w[:, 1] > 104.3))
    t = (104.3 - w[i - 1, 1]) / (w[i, 1] - w[i - 1, 1])
    assert 77.7 < w[i - 1, 0] + t * (w[i, 0] - w[i - 1, 0]) < 78.15
    nm = r.summary()["length_nm"]
    direct = GEOD.inv(SABETTA[1], SABETTA[0], BERING[1], BERING[0])[2] / 1852.0
    assert nm > direct and 0.9 * PUBLISHED_NM[0] <= nm <= 1.1 * PUBLISHED_NM[1]
    # The hours lie between the whole length in thick first-year ice and in young ice.
    assert nm / curve_kn(0.20) < total < nm / curve_kn(1.60)


def test_the_command_line_gives_the_same_route_and_the_rtz_its_schedule(chart, arc7_route, tmp_path):
    opened, r = arc7_route
    rtz, gj = tmp_path / "r.rtz", tmp_path / "r.geojson"
    args = [
        "route",
        chart,
        "--land",
        "chart",
        "--from",
        "71.27,72.07",
        "--to",
        "66.1,-169.5",
        "--vessel-file",
    ]
    args += ["arc7-lng-carrier", "--depart", DEPART, "--snap", "--out", str(rtz), "--out", str(gj), "-q"]
    assert main(args) == 0
    snapped = opened.route(SABETTA, BERING, depart=DEPART, snap_km=20)  # --snap: at most 20 km
    api = json.loads(seaway.export.render(snapped, "geojson"))
    cli = json.loads(gj.read_text())
    assert cli["geometry"]["type"] == "MultiLineString"  # cut at the antimeridian
    for mine, theirs in zip(cli["geometry"]["coordinates"], api["geometry"]["coordinates"], strict=True):
        np.testing.assert_allclose(mine, theirs, atol=1e-9)
    for key in ("length", "time_h", "assumptions", "departure", "arrival", "waypoint_schedule"):
        assert cli["properties"][key] == api["properties"][key], key
    ns = {"r": "http://www.cirm.org/RTZ/1/0"}
    root = ET.parse(rtz).getroot()
    points = root.findall(".//r:waypoints/r:waypoint", ns)
    sched = root.findall(".//r:schedule//r:scheduleElement", ns)
    assert len(sched) == len(points) == len(r.waypoints)
    assert sched[0].get("etd") == "2021-02-07T00:00:00Z"
    etas = [np.datetime64(e.get("eta").rstrip("Z")) for e in sched[1:]]
    assert etas == sorted(etas) and etas[-1] == np.datetime64(api["properties"]["arrival"].rstrip("Z"))


@pytest.mark.parametrize("end", [SABETTA, VILKITSKY], ids=["Sabetta", "Vilkitsky Strait"])
def test_arc7_lng_carrier_in_the_kara_sea(chart, plane, end):
    opened = seaway.open_chart(chart, land="chart", vessel=load("arc7-lng-carrier"), ends=(KARA_GATE, end))
    r = opened.route(KARA_GATE, end, depart=DEPART)
    total = check_timed(r, curve_kn(1.60), curve_kn(0.20))
    seen, into_land = met(r, plane)
    assert not set(seen) & CLOSED and into_land <= HALF_PIXEL_KM
    nm = r.summary()["length_nm"]
    assert nm > GEOD.inv(KARA_GATE[1], KARA_GATE[0], end[1], end[0])[2] / 1852.0
    assert nm / curve_kn(0.20) < total < nm / curve_kn(1.60)
    if end == SABETTA:  # the Gulf of Ob opens to the north: round Yamal's tip (73.5 N)
        assert np.asarray(r.coords)[:, 0].max() > 73.0


@pytest.mark.parametrize("ship", ["pc6-general-cargo", "Arc4"])
def test_pc6_and_arc4_are_refused_with_the_ice_that_stops_them(chart, plane, ship):
    """Grinyak et al.'s (2022) tables let an Arc4 (and a PC6, taken as an Arc4) into ice no
    thicker than its 0.8 m: not medium first-year ice (to 1.2 m) nor thick (to 2.0 m)."""
    vessel = load(ship) if ship.endswith("cargo") else ship
    opened = seaway.open_chart(chart, land="chart", vessel=vessel, ends=(KARA_GATE, SABETTA))
    assert aari_winter.feature_at(*KARA_GATE, *plane) == "SW Kara Sea"  # SA 91 as written
    with pytest.raises(
        ValueError,
        match=r"start 70.4,58.6 is on an impassable pixel \(ice an? \w+ ship "
        r"may not enter: medium first-year ice \(WMO stage 91, 10/10\)",
    ):
        opened.route(KARA_GATE, SABETTA, depart=DEPART)
    # From the thin first-year ice of the Barents Sea to the flaw polynya east of the Vilkitsky
    # Strait, with and without escort (an escort opens no ice the class may not enter): the
    # thick first-year ice of the NE Kara Sea closes the way.
    a, b = (70.5, 54.0), (77.925, 104.658)
    assert [aari_winter.feature_at(*p, *plane) for p in (a, b)] == ["Barents Sea", "flaw polynya"]
    opened = seaway.open_chart(chart, land="chart", vessel=vessel, ends=(a, b))
    for escort in (False, True):
        with pytest.raises(seaway.NoRouteError) as err:
            opened.route(a, b, escort=escort)
        e = err.value
        # on its own an Arc7 ship has no speed in 1.6 m (Andreeva 2021: it passes 1.4 m): Arc8;
        # escorted, Arc7 gets through
        weakest = "Arc7" if escort else "Arc8"
        assert e.cause == "ice" and e.weakest_class == weakest
        kinds = dict(e.closing_ice)
        assert kinds[f"thick first-year ice (SA 93) at 10/10 ({weakest} and stronger may enter)"] > 125.0
        assert GEOD.inv(e.reachable[1], e.reachable[0], b[1], b[0])[2] / 1e3 == pytest.approx(
            e.reachable_km, rel=0.01
        )
