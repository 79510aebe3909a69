"""The forward side of the two-sided searches first searches alone as one-way A* (the bound to
the end at the potential's scale), then re-keys its queue to the average potential and goes on
with the backward side (cpp/seaway/rekeyed.hpp): exact on charts far larger than the solo phase
(4096 pixels), where the re-keyed frontier spreads wider than the bucket queue's window."""

from __future__ import annotations

import numpy as np
import pytest

import seaway
from support.grids import RTOL, blob_sea, check_path, largest_water
from support.reference import RefGraph

SOLO = 4096  # cpp/seaway/bidirectional_side.hpp: solo_pixels


def _geo(shape, seed):
    rng = np.random.default_rng(seed)
    if seed % 3 == 0:
        return dict(dx=float(rng.uniform(0.5, 2.0)), dy=float(rng.uniform(0.5, 2.0)))
    lat = np.linspace(60.0, 60.0 + 0.1 * (shape[0] - 1), shape[0])
    lon = np.linspace(20.0, 20.0 + 0.3 * (shape[1] - 1), shape[1])
    return dict(lat=lat[::-1] if seed % 2 else lat, lon=lon)


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("contrast", ["high", "low", "extreme"])
def test_two_sided_searches_past_the_solo_phase_give_dijkstra_s_cost(seed, contrast, monkeypatch):
    """Landmarks (bidirectional ALT) and bidirectional A* (forced on every chart) against the
    brute-force reference on 18,000-pixel charts, voyages of every length; several outlast the
    solo phase."""
    monkeypatch.setattr(seaway.engine.methods, "ASTAR_CONTRAST", np.inf)
    monkeypatch.setattr(seaway.engine.methods, "BIDIRECTIONAL_LANDMARKS", True)
    u = blob_sea(seed, hi={"high": 30.0, "low": 1.5, "extreme": 1000.0}[contrast])
    geo = _geo(u.shape, seed)
    plain = seaway.prepare(u, edge_cost="mean", **geo)
    with_landmarks = seaway.prepare(u, edge_cost="mean", landmarks=4, **geo)
    water = largest_water(u)
    ref = RefGraph(u, k=5, edge_cost="mean", **geo)
    rng = np.random.default_rng(seed)
    outlasted = 0

    def voyage(s, e, expect):
        nonlocal outlasted
        ps, pe = (
            (s, e)
            if "dx" in geo
            else ((geo["lat"][s[0]], geo["lon"][s[1]]), (geo["lat"][e[0]], geo["lon"][e[1]]))
        )
        for chart, method in ((plain, "bidirectional"), (with_landmarks, "landmarks")):
            r = chart.route(ps, pe, method=method)
            assert r.cost == pytest.approx(expect, rel=RTOL), (method, s, e)
            check_path(ref, r, s, e, geo)
            outlasted += r.stats.search.settled > SOLO + 1024

    for a in rng.choice(len(water), size=5, replace=False):  # to a random pixel, and the farthest
        s = tuple(map(int, water[a]))
        costs = ref.costs(s)
        far = np.unravel_index(np.argmax(np.where(np.isfinite(costs), costs, -1)), costs.shape)
        for e in (tuple(map(int, water[rng.integers(len(water))])), tuple(map(int, far))):
            voyage(s, e, costs[e])
    assert outlasted >= 4  # the re-keyed path ran


def test_a_short_voyage_is_searched_alone_as_one_way_a_star():
    """On a uniform sea (low contrast: bidirectional search takes the A* potential) a voyage that
    ends within the solo phase settles what one-way A* settles, about a third of the pixels the
    average potential needed alone (it pulls towards the end half as hard)."""
    u = np.ones((200, 200))
    chart = seaway.prepare(u, edge_cost="mean")
    s, e = (100, 60), (100, 140)
    r = chart.route(s, e, method="bidirectional")
    a = chart.route(s, e, method="astar")
    d = chart.route(s, e, method="dijkstra")
    assert r.cost == pytest.approx(d.cost, rel=RTOL) == a.cost
    assert r.stats.search.settled <= a.stats.search.settled < SOLO
    assert r.stats.search.settled < 0.05 * d.stats.search.settled
