"""Fuel-optimal speeds (paper 004): settings per step, the trade-off, deadlines."""

import numpy as np
import pytest

from seaway import _core
from seaway.weather import Vessel
from seaway.weather.fuel import FuelCurve, route_fuel, route_min_fuel, tradeoff
from support.forecasts import forecast

SHIP = Vessel(speed_kn=14.0, speed_loss="none")
# A 40 000 t container ship's range (paper 004: 5-24 kn); 60 t/day = 2.5 t/h at 18 kn.
CURVE = FuelCurve.cubic(ref_speed_kn=18.0, ref_rate_t_per_h=2.5, vmin_kn=8.0, vmax_kn=24.0, step_kn=2.0)
A, B = (61.0, 0.5), (61.0, 2.5)
KM = sum(_core.haversine_km(61.0, a, 61.0, a + 0.1) for a in np.arange(0.5, 2.5, 0.1))


def test_cubic_curve():
    assert CURVE.speeds_kn == (8.0, 10.0, 12.0, 14.0, 16.0, 18.0, 20.0, 22.0, 24.0)
    assert CURVE.rates_t_per_h[5] == pytest.approx(2.5)
    assert CURVE.rates_t_per_h[0] == pytest.approx(2.5 * (8 / 18) ** 3)
    with pytest.raises(ValueError, match="one fuel rate per engine setting"):
        FuelCurve((10.0, 12.0), (1.0,))


@pytest.mark.parametrize("time_value", [0.0, 1.0, 5.0, 40.0])
def test_each_step_takes_the_cheapest_setting(time_value):
    # In calm water a step of d nm at v kn costs (q(v) + lambda) d / v: the best v is the same
    # for every step, found here by hand over the settings.
    v, q = np.array(CURVE.speeds_kn), np.array(CURVE.rates_t_per_h)
    best = v[np.argmin((q + time_value) / v)]
    r = route_fuel(forecast(), A, B, vessel=SHIP, fuel=CURVE, time_value_t_per_h=time_value, neighbourhood=3)
    assert np.all(r.stats.fuel.speeds_kn == best)
    hours = KM / 1.852 / best
    assert r.stats.fuel.hours == pytest.approx(hours, rel=1e-9)
    assert r.stats.fuel.fuel_t == pytest.approx(q[v == best][0] * hours, rel=1e-9)
    assert r.cost == pytest.approx(r.stats.fuel.fuel_t + time_value * hours, rel=1e-9)


def test_tradeoff_runs_from_full_speed_to_least_fuel():
    front = tradeoff(forecast(), A, B, vessel=SHIP, fuel=CURVE, neighbourhood=3)
    hours = [r.stats.fuel.hours for r in front]
    fuel = [r.stats.fuel.fuel_t for r in front]
    assert hours == sorted(hours) and fuel == sorted(fuel, reverse=True)
    assert hours[0] == pytest.approx(KM / 1.852 / 24.0, rel=1e-9)  # quickest: full speed
    assert hours[-1] == pytest.approx(KM / 1.852 / 8.0, rel=1e-9)  # least fuel: slowest
    # Fuel per distance goes as v^2 under the cubic law: 24 kn burns 9 x the fuel of 8 kn.
    assert fuel[0] / fuel[-1] == pytest.approx(9.0, rel=1e-9)


def test_least_fuel_within_a_deadline():
    full = KM / 1.852 / 24.0
    fuels = []
    for deadline in (1.1 * full, 1.5 * full, 2.2 * full):
        r = route_min_fuel(forecast(), A, B, deadline_h=deadline, vessel=SHIP, fuel=CURVE, neighbourhood=3)
        assert r.stats.fuel.hours <= deadline
        # No setting slower than the one chosen would still arrive in time.
        slower = [v for v in CURVE.speeds_kn if v < r.stats.fuel.speeds_kn[0]]
        assert all(KM / 1.852 / v > deadline for v in slower)
        fuels.append(r.stats.fuel.fuel_t)
    assert fuels[0] > fuels[1] > fuels[2]


def test_a_head_current_makes_slow_steaming_dearer():
    # Against a current c, fuel per mile is q(v) / (v - c), least near v = 1.5 c under the cubic
    # law: 7 kn of current makes slow steaming dear.
    against = forecast(ce=-7.0 / (3600 / 1852), cn=0.0)
    r = route_fuel(against, A, B, vessel=SHIP, fuel=CURVE, neighbourhood=3)
    v, q = np.array(CURVE.speeds_kn), np.array(CURVE.rates_t_per_h)
    expected = v[np.argmin(np.where(v > 7.0, q / (v - 7.0), np.inf))]
    assert expected > 8.0 and np.all(r.stats.fuel.speeds_kn == expected)


def test_a_deadline_no_speed_meets_is_a_no_route_error():
    from seaway.errors import NoRouteError

    full = KM / 1.852 / 24.0  # the quickest passage, at full speed
    with pytest.raises(NoRouteError, match="no route arrives within"):  # was a NameError
        route_min_fuel(forecast(), A, B, deadline_h=0.9 * full, vessel=SHIP, fuel=CURVE, neighbourhood=3)
