"""Each cost model declares what it can do once in C++ (its functor's Capabilities, which decide
which searches the bindings offer it) and once in Python (the seaway.models class's flags, which
the engine reads): the two must agree, and each search must exist for exactly the models whose
capabilities it needs."""

import numpy as np
import pytest

import seaway
from seaway import _core
from seaway.models import (
    EDGE_COSTS,
    EdgeCost,
    EnteredPixel,
    Fuel,
    IceSeasonTime,
    IceWeatherTime,
    TravelTime,
    WaveDanger,
)
from support.reference import reference_costs

FLAGS = ("static", "symmetric", "turn_penalty", "time_dependent", "smoothable")
# Python class -> the engine classes its engine() returns.
PAIRS = [
    (EdgeCost, [EDGE_COSTS[name] for name in EDGE_COSTS]),
    (EnteredPixel, [_core.EnteredPixelCost]),
    (TravelTime, [_core.TravelTimeModel, _core.ZonedTravelTimeModel]),
    (Fuel, [_core.FuelModel]),
    (WaveDanger, [_core.WaveDangerModel]),
    (IceSeasonTime, [_core.IceSeasonModel]),
    (IceWeatherTime, [_core.IceWeatherModel]),
]


@pytest.mark.parametrize("model, engines", PAIRS, ids=[p[0].__name__ for p in PAIRS])
def test_python_flags_are_the_cpp_capabilities(model, engines):
    for engine in engines:
        assert engine.capabilities == {f: getattr(model, f) for f in FLAGS}, engine.__name__


def _overloads(fn) -> str:
    return fn.__doc__ or ""


@pytest.mark.parametrize(
    "search, needs",
    [
        (_core.PreparedChart.route_bidirectional, ("static",)),
        (_core.PreparedChart.build_landmarks, ("static", "symmetric")),
        (_core.route_turns, ("turn_penalty",)),
        (_core.LegPricer.__init__, ("smoothable", "static")),
        (_core.TimedLegs.__init__, ("smoothable", "time_dependent")),
    ],
)
def test_each_search_is_bound_for_exactly_the_models_that_can_take_it(search, needs):
    doc = _overloads(search)
    models = [c for c in vars(_core).values() if isinstance(c, type) and hasattr(c, "capabilities")]
    assert len(models) == 11
    for cls in models:
        able = all(cls.capabilities[n] for n in needs)
        assert (f"seaway._core.{cls.__name__}" in doc) == able, (cls.__name__, needs)


def test_the_length_model_takes_every_search_and_smoothing():
    """The worked example of docs/dev/cost-models.md: a step costs its length. Its caps alone
    give it the bidirectional, landmark and turn searches and smoothing; on a chart of unit costs
    every method finds the same length as the mean edge cost (whose cost is then the length)."""
    cost = np.ones((60, 80))
    cost[10:50, 38:42] = np.inf  # a wall with a gap at the top and bottom
    cost[25:35, 10:30] = 7.0  # dear water the length model ignores
    chart = seaway.prepare(cost, neighbourhood=5, edge_cost="length", landmarks=2)
    got = {
        m: chart.route((30, 2), (30, 77), method=m).cost
        for m in ("dijkstra", "astar", "bidirectional", "landmarks", "auto")
    }
    brute = reference_costs(cost, (30, 2), k=5, edge_cost="length")[30, 77]  # Dijkstra over all edges
    assert got == pytest.approx(dict.fromkeys(got, brute), rel=1e-12)
    # The taut string around the nearer (bottom) end of the wall, whose pixels' squares end at
    # row 49.5 and columns 37.5 / 41.5: the 5x5 stencil's route is within 1.5 % of it.
    taut = 2 * np.hypot(49.5 - 30, 37.5 - 2) + 4
    assert taut < brute < 1.015 * taut
    r = chart.route((30, 2), (30, 77))
    assert r.smoothed().cost <= r.cost and r.smoothed().cost == pytest.approx(r.smoothed().length, rel=1e-12)
    turned = chart.route((30, 2), (30, 77), turn_penalty={0: 0.0, 180: 10.0})
    assert turned.cost >= r.cost
