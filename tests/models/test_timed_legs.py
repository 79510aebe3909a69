"""Legs sailed on the clock (seaway.chart.legs.TimedLegs, cpp/seaway/timed_legs.hpp): an engine
step costs what the engine charged for it, any other leg equals an independent dense sampling
of the model's fields at the time the ship is at each sample (support.reference_timed), and by
hand in a uniform current and through ice that opens at a known time."""

from __future__ import annotations

import math

import numpy as np
import pytest

from seaway import _core
from seaway.base.units import KM_PER_NM, KNOTS_PER_MS
from seaway.icenav.season import route_season
from seaway.weather import Vessel, route_time
from support import timed_cases as cases
from support.forecasts import forecast
from support.seasons import planar_season

CASES = {
    "ice planar": cases.ice_planar,
    "ice lat/lon": cases.ice_latlon,
    "weather": cases.weather,
    "ice and weather": cases.ice_weather,
}


@pytest.mark.parametrize("kind", CASES)
@pytest.mark.parametrize("seed", [1, 2])
def test_an_engine_step_costs_what_the_engine_charged(kind, seed):
    case = CASES[kind](seed)
    r, legs = case.route, case.legs
    arrive, leave = cases.schedule(r)
    v = r.vertices
    got = [legs.arrive(v[i], v[i + 1], leave[i]) for i in range(len(v) - 1)]
    np.testing.assert_allclose(got, arrive[1:], rtol=1e-12)
    assert len(v) > 3


def _random_legs(rng, shape, count):
    """Pixel-centre legs that are no stencil step of the 5 x 5 stencil, and a few off-centre."""
    out = []
    while len(out) < count:
        p, q = rng.integers(0, shape), rng.integers(0, shape)
        if np.abs(q - p).max() <= 2:
            continue
        if len(out) % 4 == 3:  # fractional ends
            p, q = p + rng.uniform(-0.4, 0.4, 2), q + rng.uniform(-0.4, 0.4, 2)
        out.append((p.astype(float), q.astype(float)))
    return out


@pytest.mark.parametrize("kind", CASES)
def test_legs_equal_the_dense_sampling_reference(kind):
    case = CASES[kind](3, closed=0.04)
    legs, shape = case.legs, case.land.shape
    rng = np.random.default_rng(4)
    span = float(case.route.cost)
    finite = closed = 0
    for p, q in _random_legs(rng, shape, 24):
        t0 = float(rng.uniform(0, span))
        got = legs.arrive(p, q, t0)
        want, grazes = case.sail(p, q, t0)
        if grazes:  # the samples step over a corner of a closed pixel the exact test sees
            assert got == math.inf or got == pytest.approx(want, rel=2e-4)
            continue
        if math.isfinite(want):
            finite += 1
            assert got == pytest.approx(want, rel=2e-4), (p, q, t0)
        else:
            closed += 1
            assert got == math.inf, (p, q, t0)
    assert finite >= 5 and closed >= 2  # both kinds of legs were met


def test_a_leg_along_a_meridian_in_a_uniform_current_by_hand():
    # 12 kn through calm water; a 1 m/s current due north: 12 + 1.944 kn along a meridian, and
    # sqrt(12^2 - 1.944^2) kn holding the track across a current due east.
    ship = Vessel(speed_kn=12.0, speed_loss="none")
    for ce, cn, knots in ((0.0, 1.0, 12.0 + KNOTS_PER_MS), (1.0, 0.0, math.sqrt(144.0 - KNOTS_PER_MS**2))):
        fc = forecast(shape=(21, 11), frames=2, ce=ce, cn=cn)
        r = route_time(fc, (60.0, 0.5), (62.0, 0.5), vessel=ship, neighbourhood=5, smooth=False)
        legs = r.model.timed_legs(r.chart, 5)
        nm = _core.haversine_km(60.0, 0.5, 62.0, 0.5) / KM_PER_NM
        for t0 in (0.0, 2.5):
            assert legs.arrive((0, 5), (20, 5), t0) - t0 == pytest.approx(nm / knots, rel=1e-12)
        # a leg of 3 pixels north from 60.5 N, started at 1 h
        nm3 = _core.haversine_km(60.5, 0.5, 60.8, 0.5) / KM_PER_NM
        assert legs.arrive((5, 5), (8, 5), 1.0) == pytest.approx(1.0 + nm3 / knots, rel=1e-12)


def test_ice_that_opens_at_a_known_time_by_hand():
    # A planar season of 10 km pixels, 1 x 12: a band of closed ice (stage 93, 0 kn) at columns
    # 5-6 on the first chart, open water (12 kn) everywhere from the second at 5 h. A leg from
    # column 0 to 11 moves from pixel 4 into pixel 5 as the engine's step from 4 to 5 does: that
    # move starts at the centre of pixel 4, 40 km on (1.80 h), and must start once the ice has
    # opened: a leg left before 3.20 h is closed, one left later sails 110 km at 12 kn.
    stage = np.full((2, 1, 12), 55)
    stage[0, 0, 5:7] = 93
    ds = planar_season(stage, hours=[0.0, 5.0])
    r = route_season(ds, (0, 0), (0, 11), speed=cases.TABLE, concentration_limit=False, smooth=False)
    legs = r.model.timed_legs(r.chart, 5)
    kmh = 1.0 / float(np.float32(1.0 / (12.0 * KM_PER_NM)))  # 12 kn as the engine reads it (float32)
    opens = 5.0 - 40.0 / kmh
    assert opens == pytest.approx(3.2001, abs=1e-4)
    for t0 in (0.0, 3.0, opens - 1e-6):
        assert legs.arrive((0, 0), (0, 11), t0) == math.inf
    for t0 in (opens + 1e-6, 3.5):
        assert legs.arrive((0, 0), (0, 11), t0) == pytest.approx(t0 + 110.0 / kmh, rel=1e-12)
    assert legs.arrive((0, 7), (0, 11), 0.0) == pytest.approx(40.0 / kmh, rel=1e-12)  # beyond it
    # The engine's route waits before the band until it opens, then goes straight on.
    assert r.cost == pytest.approx(5.0 + 70.0 / kmh, rel=1e-12)
    assert r.stats.voyage.waits[0].pixel == (0, 4)
