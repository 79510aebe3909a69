"""The cost model behind method="auto" on charts with landmarks (seaway.engine.costmodel): its
pixel counts against the pixels each search really settles, and auto's answers (whichever
search it picks) against Dijkstra's."""

from __future__ import annotations

import numpy as np
import pytest

import seaway
from seaway.engine import costmodel, methods
from seaway.samples import synthetic_sea


@pytest.fixture(scope="module")
def sea():
    cost = synthetic_sea((400, 500))
    chart = seaway.prepare(cost, landmarks=6)
    field = chart.cost_field((380, 20))
    water = np.argwhere(np.isfinite(field))
    rng = np.random.default_rng(4)
    pairs = [((380, 20), tuple(int(v) for v in water[np.argmax(field[np.isfinite(field)])]))]
    pairs += [
        (tuple(int(v) for v in water[a]), tuple(int(v) for v in water[b]))
        for a, b in rng.choice(len(water), size=(10, 2), replace=False)
    ]
    return chart, pairs


def _counts(chart, s, e):
    lm = chart.landmarks_for(chart.model)
    return costmodel.settled(
        chart, chart.model, chart.landmark_sample(chart.model), lm.table, s, e, methods.low_contrast(chart)
    )


def test_counts_track_the_pixels_settled(sea):
    """Dijkstra's and A*'s counts within a factor of 2 of the pixels they settle on most
    voyages (the median ratio within 1.5); the landmark search's count within a factor of 4."""
    chart, pairs = sea
    ratios = {"dijkstra": [], "astar": [], "landmarks one thread": []}
    for s, e in pairs:
        est = _counts(chart, s, e)
        for m in ratios:
            weight = 1.0 if m == "astar" else 0.0
            settled = chart.search(s, e, weight, chart.model, m).stats.settled
            ratios[m].append(est[m] / max(settled, 1))
    for m in ("dijkstra", "astar"):
        q = np.abs(np.log(ratios[m]))
        assert np.median(q) < np.log(1.5) and np.mean(q < np.log(2)) >= 0.8, (m, ratios[m])
    assert np.median(np.abs(np.log(ratios["landmarks one thread"]))) < np.log(4), ratios


def test_auto_is_exact_whichever_search_it_picks(sea):
    chart, pairs = sea
    picked = set()
    for s, e in pairs:
        est = costmodel.estimate(
            chart,
            chart.model,
            chart.landmark_sample(chart.model),
            chart.landmarks_for(chart.model).table,
            s,
            e,
            methods.low_contrast(chart),
        )
        picked.add(min(est, key=lambda m: est[m]))
        r = chart.route(s, e)
        assert r.method == methods.PUBLIC.get(min(est, key=lambda m: est[m]), min(est, key=lambda m: est[m]))
        assert r.cost == pytest.approx(chart.route(s, e, method="dijkstra").cost, rel=1e-9)
        assert chart.route(s, e).pixels.tolist() == r.pixels.tolist()  # the same choice every time
    assert len(picked) >= 2, picked  # short and long voyages are answered by different searches
