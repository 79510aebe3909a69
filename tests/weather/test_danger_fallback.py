"""Paper 004's fallback: when no route avoids the danger zones, the route with the least hours
in danger, then the least hours, flagged, with the stretches in danger listed. Checked against
a brute-force lexicographic Dijkstra (static forecast) and by re-walking the route in time."""

from __future__ import annotations

import heapq

import numpy as np
import pytest

import seaway
from seaway import _core
from seaway.weather import Vessel, route_time
from support.forecasts import forecast

SHIP = Vessel(speed_kn=12.0, speed_loss="none", danger_wind_ms=11.0)


def lexicographic_reference(lat, lon, wind, start, end, speed_kn, danger_ms):
    """(hours in danger, hours) by Dijkstra over 8-neighbour steps of a static wind field; a
    step is in danger when the wind at either end exceeds danger_ms."""
    rows, cols = wind.shape
    best = {start: (0.0, 0.0)}
    heap, done = [(0.0, 0.0, start)], set()
    while heap:
        d, t, v = heapq.heappop(heap)
        if v in done:
            continue
        done.add(v)
        if v == end:
            return d, t
        for di in (-1, 0, 1):
            for dj in (-1, 0, 1):
                w = (v[0] + di, v[1] + dj)
                if (di, dj) == (0, 0) or not (0 <= w[0] < rows and 0 <= w[1] < cols) or w in done:
                    continue
                h = _core.haversine_km(lat[v[0]], lon[v[1]], lat[w[0]], lon[w[1]]) / 1.852 / speed_kn
                nd = d + (h if max(wind[v], wind[w]) > danger_ms else 0.0)
                if (nd, t + h) < best.get(w, (np.inf, np.inf)):
                    best[w] = (nd, t + h)
                    heapq.heappush(heap, (nd, t + h, w))
    return np.inf, np.inf


@pytest.mark.parametrize("seed", range(4))
def test_least_danger_matches_lexicographic_brute_force(seed):
    rng = np.random.default_rng(seed)
    shape = (7, 9)
    wind = rng.uniform(0, 10, shape)
    wind[:, 4] = 20.0  # a storm wall from edge to edge: no safe route
    wind[rng.integers(0, 7), 3] = 15.0
    fc = forecast(shape=shape, step=0.2, wind=wind.astype(np.float32), ce=0.0, cn=0.0)
    lat, lon = fc.lat.values, fc.lon.values
    w32 = fc.wind.values[0]
    start, end = (int(rng.integers(0, 7)), 0), (int(rng.integers(0, 7)), 8)
    want_d, want_t = lexicographic_reference(lat, lon, w32, start, end, 12.0, 11.0)
    for method in ("dijkstra", "astar"):
        r = route_time(
            fc, (lat[start[0]], lon[0]), (lat[end[0]], lon[8]), vessel=SHIP, neighbourhood=3, method=method
        )
        assert r.stats.through_danger is True
        assert r.stats.danger.hours == pytest.approx(want_d, rel=1e-9)
        assert r.cost == pytest.approx(want_t, rel=1e-9)
        assert sum(leg.hours for leg in r.stats.danger.legs) == pytest.approx(want_d, rel=1e-9)
    with pytest.raises(seaway.NoRouteError):
        route_time(
            fc,
            (lat[start[0]], lon[0]),
            (lat[end[0]], lon[8]),
            vessel=SHIP,
            neighbourhood=3,
            if_no_safe_route="raise",
        )


def test_storm_wall_crossed_where_it_is_narrowest_in_time():
    """A wall of 20 m/s wind across the chart: the crossing takes the four steps into, across
    and out of the wall (columns 14-16) on the northernmost row, where east steps are shortest;
    the danger stretch says where and how long."""
    wind = np.zeros((21, 31))
    wind[:, 15] = 20.0
    fc = forecast(wind=wind, ce=0.0, cn=0.0)
    r = route_time(fc, (61.0, 0.2), (61.0, 2.8), vessel=SHIP, neighbourhood=3)
    lat_top = 62.0
    step = _core.haversine_km(lat_top, 0.0, lat_top, 0.1) / 1.852 / 12.0
    assert r.stats.danger.hours == pytest.approx(2 * step, rel=1e-9)  # 14->15, 15->16
    (leg,) = r.stats.danger.legs
    assert leg.start == pytest.approx((lat_top, 1.4)) and leg.end == pytest.approx((lat_top, 1.6))
    assert leg.hours == pytest.approx(2 * step, rel=1e-9)
    assert leg.start_h == pytest.approx(float(np.sum(r.step_costs[: leg.steps[0]])), rel=1e-12)
    assert "through danger" in r.name
    assert r.stats.voyage.hours == r.cost and r.stats.voyage.wait_h.tolist() == [0.0] * len(r.step_costs)


def test_danger_fallback_through_timed_zones_does_not_claim_its_waits():
    """With zones closed in time windows the least-danger search may wait for them but reports
    no per-step values: the voyage says its waits are unknown (None), not zero."""
    shapely = pytest.importorskip("shapely")
    wind = np.zeros((21, 31))
    wind[:, 15] = 20.0
    fc = forecast(wind=wind, ce=0.0, cn=0.0)
    zone = seaway.constraints.Zone(shapely.geometry.box(0.45, 59.0, 0.55, 60.45), active=(0.0, 1.0))
    r = route_time(fc, (61.0, 0.2), (61.0, 2.8), vessel=SHIP, neighbourhood=3, zones=[zone])
    plain = route_time(fc, (61.0, 0.2), (61.0, 2.8), vessel=SHIP, neighbourhood=3)
    assert r.stats.through_danger and r.cost == pytest.approx(plain.cost, rel=1e-12)
    assert r.stats.danger.hours == pytest.approx(plain.stats.danger.hours, rel=1e-12)
    voyage = r.stats.voyage
    assert voyage.hours == r.cost and voyage.wait_h is None and voyage.waits == ()
    assert voyage.hours_waiting is None and voyage.hours_under_way is None


def test_moving_storm_danger_hours_re_walked():
    """A storm over the whole chart for the first 6 h, fading linearly to calm at 12 h: the
    route's reported danger steps are exactly the steps that start inside a zone when re-walked
    in time, and a safe route is returned unflagged when the ship leaves after the storm."""
    wind = np.zeros((4, 21, 31))
    wind[:2] = 20.0  # 0 h and 6 h; 12 h calm: above 11 m/s until 6 + 6 x 9/20 = 8.7 h
    fc = forecast(frames=4, wind=wind, ce=0.0, cn=0.0)
    r = route_time(fc, (61.0, 0.2), (61.0, 2.8), vessel=SHIP, neighbourhood=5)
    elapsed = np.concatenate([[0.0], np.cumsum(r.step_costs)])
    strong = np.interp(elapsed[:-1], [0, 6, 12, 18], [20, 20, 0, 0]) > 11.0
    np.testing.assert_array_equal(r.stats.danger.step_h > 0, strong)
    assert r.stats.danger.hours == pytest.approx(float(np.sum(r.step_costs[strong])), rel=1e-12)
    calm = route_time(fc, (61.0, 0.2), (61.0, 2.8), vessel=SHIP, neighbourhood=5, departure="2026-01-01T12")
    assert not calm.stats.through_danger and calm.stats.danger is None


def test_hard_limits_are_never_crossed():
    wind = np.zeros((21, 31))
    wind[:, 15] = 30.0  # above max_wind_ms = 25: impassable, not danger
    fc = forecast(wind=wind, ce=0.0, cn=0.0)
    with pytest.raises(seaway.NoRouteError):
        route_time(fc, (61.0, 0.2), (61.0, 2.8), vessel=SHIP, neighbourhood=3)
    with pytest.raises(ValueError, match="if_no_safe_route"):
        route_time(fc, (61.0, 0.2), (61.0, 2.8), vessel=SHIP, if_no_safe_route="maybe")


def test_wave_danger_zone_fallback():
    """Danger by significant wave height (danger_wave_m = 3): a 4 m sea across the chart (below
    the 5 m hard limit) is crossed by the least-danger route on its narrowest row; with waves
    of 2 m nowhere is in danger and the plain time route comes back unflagged."""
    hs = np.full((21, 31), 1.0)
    hs[:, 15] = 4.0
    ship = Vessel(speed_kn=12.0, speed_loss="none", danger_wave_m=3.0)
    fc = forecast(hs=hs, ce=0.0, cn=0.0)
    r = route_time(fc, (61.0, 0.2), (61.0, 2.8), vessel=ship, neighbourhood=3)
    step = _core.haversine_km(62.0, 0.0, 62.0, 0.1) / 1.852 / 12.0
    assert r.stats.through_danger is True
    assert r.stats.danger.hours == pytest.approx(2 * step, rel=1e-9)
    (leg,) = r.stats.danger.legs
    assert leg.start == pytest.approx((62.0, 1.4)) and leg.end == pytest.approx((62.0, 1.6))
    calm = route_time(
        forecast(hs=np.full((21, 31), 2.0), ce=0.0, cn=0.0),
        (61.0, 0.2),
        (61.0, 2.8),
        vessel=ship,
        neighbourhood=3,
    )
    assert not calm.stats.through_danger and calm.stats.danger is None
