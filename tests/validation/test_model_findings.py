"""What a navigator would find wrong in seaway's answers on the winter NSR (docs/user/validation.md,
"What a navigator would find wrong"): each test states the right behaviour and fails today, so
it is marked xfail(strict=True) until seaway.voyage or the outputs change (then the mark goes)."""

from __future__ import annotations

import numpy as np
import pyproj
import pytest

import seaway
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


@pytest.mark.xfail(
    strict=True,
    reason="legs are checked and timed straight in lat/lon but exported as orthodromes (RTZ "
    "geometryType 'Orthodrome'): on a 786 nm leg at 70 N the great circle runs 136 km away",
)
def test_each_legs_great_circle_is_the_line_that_was_checked(chart):
    """The great circle the RTZ tells an ECDIS to sail stays within a pixel (6 km) of the line
    the route was checked and timed along."""
    opened = seaway.open_chart(chart, land="chart", vessel=load("arc7-lng-carrier"), ends=(SABETTA, BERING))
    w = np.asarray(opened.route(SABETTA, BERING).coords, float)
    worst = 0.0
    for (la0, lo0), (la1, lo1) in zip(w[:-1], w[1:]):
        pts = np.asarray(GEOD.npts(lo0, la0, lo1, la1, 50))
        t = np.linspace(0, 1, 52)[1:-1]
        straight_lon, straight_lat = lo0 + (lo1 - lo0) * t, la0 + (la1 - la0) * t
        worst = max(worst, GEOD.inv(pts[:, 0], pts[:, 1], straight_lon, straight_lat)[2].max() / 1e3)
    assert worst <= 6.0, f"{worst:.0f} km"


@pytest.mark.needs_data(*NSIDC)
def test_a_route_is_never_shorter_than_the_great_circle_between_its_ends():
    path = str(SHARED_DATA.joinpath(*NSIDC))
    a, b = SABETTA, (66.07, -169.65)
    chart = seaway.open_chart(path, vessel=load("arc7-lng-carrier"), ends=(a, b), assume_stage=91)
    r = chart.route(a, b, objective="time", snap_km=30)
    w = np.asarray(r.latlon, float)
    direct = GEOD.inv(w[0, 1], w[0, 0], w[-1, 1], w[-1, 0])[2] / 1e3
    assert r.length >= direct
