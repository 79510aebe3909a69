"""Zones closed in a time window on time routes (TravelTime, cpp/seaway/timed_zones.hpp): the
route waits or detours only while a zone is closed. Expected hours come from static searches
on the calm forecast's grid (calm water: hours = km / (1.852 x speed)), an independent path."""

from __future__ import annotations

import functools

import numpy as np
import pytest

import seaway
from seaway.constraints import KeepAway, Zone
from seaway.models import TravelTime
from seaway.vessel import Vessel
from seaway.weather import ForecastGrid, route_time
from support.forecasts import forecast

shapely = pytest.importorskip("shapely")
from shapely.geometry import box  # noqa: E402

#: The engine's steps: these tests hold them to brute force and to values by hand.
route_time = functools.partial(route_time, smooth=False)

SHIP = Vessel(speed_kn=12.0, speed_loss="none")
KMH = 1.852 * 12.0  # km per hour at 12 kn in calm water
FC = forecast(frames=9, ce=0.0, cn=0.0)  # 21 x 31, 0.1 deg from (60, 0), 6-hourly to 48 h
LAT, LON = FC.lat.values, FC.lon.values
A, B = (61.0, 0.2), (61.0, 2.8)
WALL = box(1.45, 59.0, 1.55, 63.0)  # column 15 (lon 1.5), every row
BLOCK = box(1.25, 60.65, 1.75, 61.35)  # rows 7-13, columns 13-17


def km_route(start, end, land=None):
    """The static shortest route in km on the forecast's grid (k = 3)."""
    return seaway.route(
        np.ones((21, 31)), start, end, lat=LAT, lon=LON, land=land, neighbourhood=3, edge_cost="max"
    )


def test_closed_wall_makes_the_ship_wait_until_it_opens():
    """A wall across the whole chart, closed for the first 10 h: the ship reaches the wall well
    before, waits, and crosses at 10 h. Cost = 10 h + the shortest remaining time from the
    pixel before the wall (any row) to the end."""
    r = route_time(
        FC, A, B, vessel=SHIP, neighbourhood=3, zones=[Zone(WALL, active=(0.0, 10.0), name="wall")]
    )
    rest = min(km_route((LAT[row], LON[14]), B).cost for row in range(21)) / KMH
    assert r.cost == pytest.approx(10.0 + rest, rel=1e-9)
    wait = r.stats.voyage.wait_h
    (i,) = np.nonzero(wait > 0)[0]  # one wait, on the step into the wall's column
    assert r.pixels[i, 1] == 14 and r.pixels[i + 1, 1] == 15
    elapsed = np.concatenate([[0.0], np.cumsum(r.step_costs)])
    assert elapsed[i] + wait[i] == pytest.approx(10.0, rel=1e-12)  # it leaves when the wall opens
    # The voyage lists that wait: where, from when (the forecast's first time + the hours to
    # the wall), how long; the hours split into waiting and under way.
    voyage = r.stats.voyage
    (stop,) = voyage.waits
    assert stop.pixel == tuple(r.pixels[i]) and stop.position == tuple(r.coords[i])
    assert stop.hours == wait[i]
    assert stop.since == FC.time.values[0] + np.timedelta64(int(round(elapsed[i] * 3600)), "s")
    assert voyage.hours_waiting == pytest.approx(wait[i], rel=1e-12)
    assert voyage.hours_under_way == pytest.approx(r.cost - wait[i], rel=1e-12)
    plain = route_time(FC, A, B, vessel=SHIP, neighbourhood=3)
    assert plain.cost == pytest.approx(km_route(A, B).cost / KMH, rel=1e-9)
    # Without zones nothing is waited for: zeros per step, no waits, every hour under way.
    assert plain.stats.voyage.wait_h.tolist() == [0.0] * (len(plain.pixels) - 1)
    assert plain.stats.voyage.waits == () and plain.stats.voyage.hours_under_way == plain.cost
    assert r.cost > plain.cost + 3


@pytest.mark.parametrize("window", [(-10.0, 1.0), (20.0, 30.0), ("2026-01-01T20", "2026-01-02T06")])
def test_zone_closed_only_when_the_ship_is_elsewhere_changes_nothing(window):
    """Closed before the ship gets there (open again at 1 h; it reaches the wall after ~3.4 h)
    or only after it has passed (from 20 h; it arrives after ~6.3 h): the plain route."""
    plain = route_time(FC, A, B, vessel=SHIP, neighbourhood=3)
    r = route_time(FC, A, B, vessel=SHIP, neighbourhood=3, zones=[Zone(WALL, active=window)])
    assert r.cost == pytest.approx(plain.cost, rel=1e-12)
    assert r.pixels.tolist() == plain.pixels.tolist()
    assert not r.stats.voyage.wait_h.any()


def test_closed_block_is_detoured_while_closed():
    """A block over the straight line, closed all voyage: the detour of the static route with
    the block as land, in hours. Closed for the first 2 h only: the plain route."""
    chart = seaway.chart.raster.as_chart(np.ones((21, 31)), lat=LAT, lon=LON)
    block = seaway.constraints.rasterise_zone(Zone(BLOCK), chart)
    assert block.sum() == 7 * 5
    detour = km_route(A, B, land=block).cost / KMH
    r = route_time(FC, A, B, vessel=SHIP, neighbourhood=3, zones=[Zone(BLOCK, active=(0, 48))])
    assert r.cost == pytest.approx(detour, rel=1e-9)
    assert not block[tuple(r.pixels.T)].any() and not r.stats.voyage.wait_h.any()
    always = route_time(FC, A, B, vessel=SHIP, neighbourhood=3, zones=[Zone(BLOCK)])
    assert always.cost == pytest.approx(detour, rel=1e-9)
    early = route_time(FC, A, B, vessel=SHIP, neighbourhood=3, zones=[Zone(BLOCK, active=(0, 2))])
    assert early.cost == pytest.approx(km_route(A, B).cost / KMH, rel=1e-9)
    assert block[tuple(early.pixels.T)].any()  # through the block, which opened at 2 h


def test_long_steps_do_not_jump_a_thin_closed_zone():
    """With a 7 x 7 stencil a step spans three columns: a one-column wall closed all voyage must
    still stop every route (no step jumps over it)."""
    with pytest.raises(seaway.NoRouteError):
        route_time(FC, A, B, vessel=SHIP, neighbourhood=7, zones=[Zone(WALL)])


def test_via_point_legs_depart_on_arrival():
    """Through a via point the second leg departs when the first arrives: a wall closed from
    3 h to 12 h beyond the via point is met by the second leg (which starts after ~1.9 h and
    reaches the wall after ~3.4 h) and waited for. Had the second leg left at 0 h it would
    have passed the wall at ~1.5 h, before it closed."""
    via = (61.0, 1.0)
    zone = Zone(WALL, active=(3.0, 12.0))
    r = route_time(FC, A, B, vessel=SHIP, neighbourhood=3, via=[via], zones=[zone])
    first = km_route(A, via).cost / KMH
    rest = min(km_route((LAT[row], LON[14]), B).cost for row in range(21)) / KMH
    assert r.cost == pytest.approx(12.0 + rest, rel=1e-9)
    assert list(r.stats.constraints.via_pixels) == [(10, 10)]
    assert r.pixels[8].tolist() == [10, 10]  # eight steps east to the via point
    assert np.cumsum(r.step_costs)[7] == pytest.approx(first, rel=1e-9)
    fc = ForecastGrid(FC)
    # The model of the second leg is the first's, shifted by the first leg's hours.
    later = TravelTime(fc, SHIP, zones=[zone]).later(first)
    assert later.forecast.first_h == pytest.approx(-first)


def test_hard_keep_away_on_a_time_route():
    """A hard 15 km buffer around an island on a time route: the route keeps it; a soft penalty
    is refused (a time route has no static cost to scale)."""
    land = np.zeros((21, 31), bool)
    land[9:12, 14:17] = True
    kept = route_time(FC, A, B, vessel=SHIP, neighbourhood=3, land=land, keep_away=[KeepAway(km=15)])
    from support.distance import brute_distance

    d = brute_distance(land, LAT, LON)
    assert d[tuple(kept.pixels.T)].min() > 15
    want = km_route(A, B, land=d <= 15).cost / KMH
    assert kept.cost == pytest.approx(want, rel=1e-9)
    with pytest.raises(ValueError, match="hard keep-away"):
        route_time(FC, A, B, vessel=SHIP, land=land, keep_away=[KeepAway(km=5, soft_km=20)])


def test_time_zone_errors():
    with pytest.raises(ValueError, match="penalty zone"):
        route_time(FC, A, B, vessel=SHIP, zones=[Zone(BLOCK, penalty=3)])
    with pytest.raises(ValueError, match="close before"):
        route_time(FC, A, B, vessel=SHIP, zones=[Zone(BLOCK, active=(5, 2))])
    with pytest.raises(ValueError, match="exclusion zones .* only"):
        Zone(BLOCK, penalty=2, active=(0, 1))
    with pytest.raises(ValueError, match="time window, which only a time route"):
        seaway.route(np.ones((21, 31)), A, B, lat=LAT, lon=LON, zones=[Zone(BLOCK, active=(0, 1))])
    with pytest.raises(ValueError, match="at most 8 zones"):
        route_time(FC, A, B, vessel=SHIP, zones=[Zone(BLOCK)] * 9)
    with pytest.raises(ValueError, match="turn_penalty works with the static edge costs"):
        ForecastGrid(FC).prepare().route(A, B, model=TravelTime(ForecastGrid(FC), SHIP), turn_penalty=0.1)


def test_via_on_a_season_route_is_refused_with_the_fix():
    """A season model cannot yet start a leg at the previous leg's arrival: via points are
    refused (rather than every leg leaving at the departure)."""
    from seaway.ice.seasongrid import SeasonGrid
    from seaway.models import IceSeasonTime
    from support.seasons import DAY0, retreating_edge

    grid = SeasonGrid(retreating_edge(days=2))
    model = IceSeasonTime(grid, "Arc4", 14, departure=DAY0)
    with pytest.raises(ValueError, match="via points on a .* route need each leg to depart"):
        seaway.prepare(grid).route((71.0, 64.0), (76.0, 78.0), model=model, via=[(72.0, 70.0)])
