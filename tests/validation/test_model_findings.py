"""What a navigator would find wrong in seaway's answers on the winter NSR (docs/user/validation.md,
"What a navigator would find wrong"): each test states the right behaviour. A finding that
fails is marked xfail(strict=True) until seaway.voyage or the outputs change (then the mark goes);
none is marked now."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np
import pyproj
import pytest

import seaway
from seaway import export
from seaway.chart.legs import leg_path
from seaway.vessel import load
from support import aari_winter
from support.data import SHARED_DATA

SABETTA, BERING, KARA_GATE = (71.27, 72.07), (66.1, -169.5), (70.4, 58.6)
GEOD = pyproj.Geod(ellps="WGS84")
NSIDC = ("sea_ice_concentration", "seaice_conc_daily_nh_20211231_f17_v04r00.nc")


@pytest.fixture(scope="module")
def chart(tmp_path_factory):
    path = tmp_path_factory.mktemp("aari") / "aari_winter.shp"
    aari_winter.write(path)
    return str(path)


def test_an_end_in_ice_the_ship_may_not_enter_is_a_seaway_error(chart):
    opened = seaway.open_chart(chart, land="chart", vessel="Arc4", ends=(KARA_GATE, SABETTA))
    with pytest.raises(seaway.SnapError):
        opened.route(KARA_GATE, SABETTA)


def test_an_end_in_fast_ice_is_said_to_be_in_fast_ice(chart):
    """Fast ice of unknown stage (AARI's FA 08, SA 99) is named so, with the stage the fast_ice
    rule gave it, never 'unknown (WMO stage 99)'."""
    opened = seaway.open_chart(chart, land="chart", vessel="Arc4", ends=(KARA_GATE, SABETTA))
    with pytest.raises(
        ValueError,
        match=r"end 71.27,72.07 is on an impassable pixel \(ice an Arc4 ship may not enter: fast ice of "
        r"unknown stage, assumed thick first-year ice \(WMO stage 93\)",
    ):
        opened.route(KARA_GATE, SABETTA, snap_km=20)


def test_thicker_ice_never_makes_an_escorted_voyage_quicker(chart):
    """The Arc7 tanker (14 kn, 2 kn at 1.8 m) with an 8.6 kn escort: thick first-year ice at the
    upper end of its range (2.0 m) cannot give a shorter voyage than at its middle (1.6 m)."""
    opened = seaway.open_chart(
        chart, land="chart", vessel=load("arc7-shuttle-tanker"), ends=(BERING, SABETTA)
    )
    hours = {}
    for rule in ("mid", "upper"):
        r = opened.route(BERING, SABETTA, escort=True, escort_speed_kn=8.6, stage_thickness=rule)
        hours[rule] = r.summary()["time_h"]
    assert hours["upper"] >= hours["mid"]


def test_each_legs_great_circle_is_the_line_that_was_checked(chart):
    """The geodesic an ECDIS sails between consecutive RTZ waypoints (legs of geometryType
    'Orthodrome') stays within a tenth of a pixel of the path the route was checked for land and
    closed ice and timed along (seaway.chart.legs.leg_path: the great circle on lat/lon charts).
    The Sabetta -> Bering Strait route has legs up to 1,461 km; the finding first filed here
    compared the great circle with a straight lat/lon line, a line no part of seaway uses."""
    opened = seaway.open_chart(chart, land="chart", vessel=load("arc7-lng-carrier"), ends=(SABETTA, BERING))
    route = opened.route(SABETTA, BERING)
    ns = {"r": "http://www.cirm.org/RTZ/1/0"}
    root = ET.fromstring(export.rtz(route))
    rtz = np.array(
        [[float(p.get("lat")), float(p.get("lon"))] for p in root.iterfind(".//r:waypoint/r:position", ns)]
    )
    g, v, wp = route.chart.grid, route.vertices, route.waypoint_index
    ours = route.coords[wp]
    np.testing.assert_allclose(rtz[:, 0], ours[:, 0], atol=1e-6)
    np.testing.assert_allclose((rtz[:, 1] - ours[:, 1] + 180) % 360 - 180, 0, atol=1e-6)  # RTZ: [-180, 180)
    legs_km = [GEOD.inv(a[1], a[0], b[1], b[0])[2] / 1e3 for a, b in zip(rtz[:-1], rtz[1:])]
    assert max(legs_km) > 1400  # the long leg across the East Siberian Sea
    worst = 0.0
    for k, ((la0, lo0), (la1, lo1)) in enumerate(zip(rtz[:-1], rtz[1:])):
        sailed = np.asarray(GEOD.npts(lo0, la0, lo1, la1, 100))  # (lon, lat)
        rows = (sailed[:, 1] - g.lat0) / g.dlat
        cols = v[wp[k], 1] + ((sailed[:, 0] - lo0 + 180) % 360 - 180) / g.dlon
        path = leg_path(route.chart, v[wp[k]], v[wp[k + 1]], False)
        t = np.linspace(0, 1, 40)[:, None]
        checked = np.concatenate([a + t * (b - a) for a, b in zip(path[:-1], path[1:])])
        off = np.hypot(rows[:, None] - checked[None, :, 0], cols[:, None] - checked[None, :, 1]).min(axis=1)
        worst = max(worst, float(off.max()))
    assert worst <= 0.1, f"{worst:.3f} pixel"


@pytest.mark.needs_data(*NSIDC)
def test_a_route_is_never_shorter_than_the_great_circle_between_its_ends():
    path = str(SHARED_DATA.joinpath(*NSIDC))
    a, b = SABETTA, (66.07, -169.65)
    chart = seaway.open_chart(path, vessel=load("arc7-lng-carrier"), ends=(a, b), assume_stage=91)
    r = chart.route(a, b, objective="time", snap_km=30)
    w = np.asarray(r.latlon, float)
    direct = GEOD.inv(w[0, 1], w[0, 0], w[-1, 1], w[-1, 0])[2] / 1e3
    assert r.length >= direct
