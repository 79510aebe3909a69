"""auto's choice on a chart without landmarks: one-way A* where most of the water costs the
least (open water around patches of ice: the straight-line bound is the true cost over most of
it), bidirectional search elsewhere; every choice gives Dijkstra's cost."""

import numpy as np
import pytest

import seaway
from seaway.engine.methods import LEAST_COST_SHARE, mostly_least_cost
from seaway.models import EdgeCost


def _sea(costly_share, seed=3):
    """A 300 x 300 sea of cost 1 with square floes of cost 6 over `costly_share` of it and an
    island of land."""
    rng = np.random.default_rng(seed)
    u = np.ones((300, 300))
    while np.mean(u > 1) < costly_share:
        r, c = rng.integers(0, 290, 2)
        u[r : r + 10, c : c + 10] = 6.0
    u[120:180, 140:160] = np.inf
    return u


@pytest.mark.parametrize(("costly", "method"), [(0.2, "astar"), (0.4, "astar"), (0.7, "bidirectional")])
def test_auto_takes_astar_where_most_water_costs_the_least(costly, method):
    u = _sea(costly)
    chart = seaway.prepare(u, edge_cost="max")
    share = np.mean(u[np.isfinite(u)] == 1.0)
    assert (share >= LEAST_COST_SHARE) == (method == "astar")
    s, e = (10, 10), (290, 290)
    r = chart.route(s, e)
    d = chart.route(s, e, method="dijkstra")
    assert r.method == method
    assert r.cost == pytest.approx(d.cost, rel=1e-9)
    if method == "astar":  # the bound prunes: far fewer pixels than Dijkstra
        assert r.stats.search.settled < 0.7 * d.stats.search.settled
    assert seaway.route(u, s, e).method == method  # a fresh chart decides alike


def test_the_share_is_read_once_per_chart_from_a_fixed_sample():
    u = _sea(0.2)
    chart = seaway.prepare(u)
    assert mostly_least_cost(chart, EdgeCost("max")) and chart._least_cost_share > 0.7
    again = seaway.prepare(u)
    assert mostly_least_cost(again, EdgeCost("max")) and again._least_cost_share == chart._least_cost_share
    # land given apart from the costs is not water; "length" prices steps by length alone
    land = np.zeros(u.shape, bool)
    land[:, :200] = True  # the land covers most of the cost-1 sea: two thirds of the rest are floes
    v = u.copy()
    v[:, 200:] = np.where(np.arange(100) % 3 != 0, 6.0, 1.0)
    assert not mostly_least_cost(seaway.prepare(v, land=land), EdgeCost("max"))
    assert mostly_least_cost(seaway.prepare(v, land=land), EdgeCost("length"))
