"""The chord bound's trigonometry is made once per lat/lon chart and thread (ChordTables in
cpp/seaway/geometry.hpp) and kept for the next query: charts of the same shape at other
latitudes, routed in turn on one thread, must each get their own tables (an equator chart's
cos(lat) on one at 72 degrees makes the bound about 3 times too large east-west: A* then misses the
least-cost route)."""

import numpy as np
import pytest

import seaway


def _chart(lat0, seed):
    rng = np.random.default_rng(seed)
    # steps of 1/8 degree: the same dlat and dlon to the last bit at every latitude
    lat, lon = lat0 + 0.125 * np.arange(60), 30.0 + 0.125 * np.arange(120)
    cost = rng.uniform(1.0, 1.3, (lat.size, lon.size))  # near the least: the bound is tight
    cost[10:50, 60] = np.inf  # a wall: east-west voyages go round it
    return seaway.prepare(cost, lat=lat, lon=lon, edge_cost="max"), lat, lon


VOYAGES = [((20, 5), (40, 115)), ((55, 10), (5, 100)), ((30, 2), (30, 117))]


@pytest.mark.parametrize("method", ["astar", "landmarks"])
def test_charts_of_one_shape_at_other_latitudes_get_their_own_tables(method):
    charts = [_chart(lat0, seed) for lat0, seed in ((0.0, 1), (72.0, 2), (0.0, 1), (40.0, 3))]
    for chart, _, _ in charts:
        chart.prepare_landmarks(4)
    dijkstra = [
        [
            chart.route((lat[s[0]], lon[s[1]]), (lat[e[0]], lon[e[1]]), method="dijkstra").cost
            for s, e in VOYAGES
        ]
        for chart, lat, lon in charts
    ]
    for _ in range(2):  # each chart's query follows another chart's on this thread
        for (chart, lat, lon), want in zip(charts, dijkstra):
            for (s, e), cost in zip(VOYAGES, want):
                r = chart.route((lat[s[0]], lon[s[1]]), (lat[e[0]], lon[e[1]]), method=method)
                assert r.method == method
                assert r.cost == pytest.approx(cost, rel=1e-9)
    # the polar chart's voyages are far shorter in km than the equator's over the same pixels
    assert dijkstra[1][2] < 0.5 * dijkstra[0][2]
