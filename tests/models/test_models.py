"""Cost models as objects (seaway.models): one query path, routes carrying their model and unit,
smoothing and leg tables right for every model or refused, unknown names refused."""

import numpy as np
import pytest

import seaway
from seaway import _core
from seaway.models import EDGE_COSTS, EdgeCost, TravelTime
from seaway.weather import ForecastGrid, Vessel, route_time
from support.forecasts import forecast

CALM = Vessel(speed_kn=12.0, speed_loss="none")


def test_one_chart_answers_every_edge_cost_as_separate_charts_do():
    rng = np.random.default_rng(3)
    cost = rng.uniform(1, 5, (30, 40))
    chart = seaway.prepare(cost, neighbourhood=5)
    for name in EDGE_COSTS:
        r = chart.route((2, 3), (27, 35), model=name)
        alone = seaway.route(cost, (2, 3), (27, 35), edge_cost=name)
        assert r.cost == alone.cost and r.edge_cost == name
        np.testing.assert_array_equal(r.pixels, alone.pixels)
        field = chart.cost_field((2, 3), model=EdgeCost(name))
        assert field[27, 35] == pytest.approx(alone.cost, rel=1e-12)


def test_unknown_model_names_raise_with_the_list():
    cost = np.ones((5, 5))
    for call in (
        lambda: seaway.route(cost, (0, 0), (4, 4), edge_cost="maximum"),
        lambda: seaway.prepare(cost).route((0, 0), (4, 4), model="time"),
        lambda: seaway.prepare(cost, edge_cost="entered"),
    ):
        with pytest.raises(
            ValueError, match=r"edge_cost must be one of \('max', 'mean', 'integral', 'length'\)"
        ):
            call()
    with pytest.raises(TypeError, match="CostModel"):
        seaway.prepare(cost).route((0, 0), (4, 4), model=3)


def test_engine_model_on_another_grid_is_refused():
    chart = seaway.prepare(np.ones((6, 6)))
    with pytest.raises(ValueError, match="6 x 7 pixels but the chart 6 x 6"):
        chart.router.route(_core.MeanCost(np.ones((6, 7))), 0, 35, 0.0)


def test_pair_costs_are_the_engines_step_costs():
    # one step of length 2 between pixels of cost 1 and 4: max 8, mean 5
    r = {
        name: seaway.route(np.array([[1.0, 4.0]]), (0, 0), (0, 1), dx=2.0, edge_cost=name).cost
        for name in ("max", "mean")
    }
    assert r == {"max": 8.0, "mean": 5.0}
    for name in ("max", "mean"):
        got = EdgeCost(name).pair_costs(np.array([1.0]), np.array([4.0]), np.array([2.0]))
        assert got[0] == r[name]


def test_routes_carry_model_and_unit():
    planar = seaway.route(np.ones((5, 5)), (0, 0), (4, 4), edge_cost="mean")
    assert planar.model == EdgeCost("mean") and planar.unit == "cost x grid unit"
    geo = seaway.route(
        np.ones((5, 5)), (60.0, 0.0), (60.4, 0.4), lat=60 + 0.1 * np.arange(5), lon=0.1 * np.arange(5)
    )
    assert geo.unit == "cost x km" and "cost x km" in str(geo)
    assert geo.to_geojson()["properties"]["cost_unit"] == "cost x km"


def test_time_route_is_in_hours_and_smooths_in_hours():
    # Regression: a time route's smoothed() priced its legs as "mean" km and compared them with
    # hours, reporting a "smoothed" route that was not. Now it sails its legs on the clock.
    r = route_time(forecast(), (60.2, 0.3), (61.7, 2.6), vessel=CALM, neighbourhood=5, smooth=False)
    assert r.edge_cost == "time" and r.unit == "h" and isinstance(r.model, TravelTime)
    assert r.stats.voyage.hours == r.cost
    # the leg table is in hours: the legs' costs sum to the passage time, each = distance / speed
    legs = r.legs()
    assert sum(leg.cost for leg in legs) == pytest.approx(r.cost, rel=1e-12)
    for leg in legs:
        assert leg.cost == pytest.approx(leg.distance / 1.852 / 12.0, rel=1e-9)
    # In calm water the smoothed route is one great circle at 12 kn, in hours.
    s = r.smoothed()
    gc_h = _core.haversine_km(60.2, 0.3, 61.7, 2.6) / 1.852 / 12.0
    assert len(s.pixels) == 2 and s.cost == pytest.approx(gc_h, rel=1e-9) and s.cost < r.cost
    assert s.stats.voyage.hours == s.cost and s.unit == "h" and s.method == "astar+smoothed"
    assert seaway.smooth(r).cost == s.cost
    with pytest.raises(ValueError, match="prices legs on the clock"):
        r.segments()


def test_weather_model_on_the_forecast_chart_equals_route_time():
    ds = forecast(frames=3, hs=2.0, wdir=0.0)
    fc = ForecastGrid(ds)
    chart = fc.prepare(neighbourhood=5)
    vessel = Vessel(speed_kn=12.0)
    via_chart = chart.route((60.2, 0.3), (61.7, 2.6), model=TravelTime(fc, vessel))
    direct = route_time(ds, (60.2, 0.3), (61.7, 2.6), vessel=vessel, neighbourhood=5, smooth=False)
    assert via_chart.cost == direct.cost
    smoothed = route_time(ds, (60.2, 0.3), (61.7, 2.6), vessel=vessel, neighbourhood=5)
    assert smoothed.cost == via_chart.smoothed().cost < direct.cost
    # the same chart routes by distance under its static model
    dist = chart.route((60.2, 0.3), (61.7, 2.6), model="max", method="dijkstra")
    assert dist.cost == pytest.approx(dist.length, rel=1e-12)
    # a model on another grid is refused with the fix
    other = ForecastGrid(forecast(shape=(11, 31)))
    with pytest.raises(ValueError, match="route on the forecast's grid"):
        chart.route((60.2, 0.3), (61.0, 2.6), model=TravelTime(other, vessel))
