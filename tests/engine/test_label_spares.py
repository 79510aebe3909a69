"""A chart's bidirectional labels serve the next chart of its size after it is gone
(cpp/seaway/label_spares.hpp): no new pages to fault in, and the answers on the new chart are
its own (the labels are cleared, whatever chart wrote them)."""

import gc

import numpy as np
import pytest

import seaway
from seaway import _core


def _costs(seed, shape=(301, 257)):
    rng = np.random.default_rng(seed)
    u = rng.uniform(1.0, 9.0, shape)
    u[rng.random(shape) < 0.1] = np.inf
    u[0, 0] = u[-1, -1] = 1.0
    return u


def test_a_gone_charts_labels_serve_the_next_chart_of_its_size():
    end = (300, 256)
    first = seaway.prepare(_costs(1))
    r1 = first.route((0, 0), end, method="bidirectional")
    del first
    gc.collect()
    sizes, kept = _core.label_spares()
    assert sizes.count(301 * 257) == 2 and kept > 0  # both sides' labels, with their pages
    u2 = _costs(2)
    second = seaway.prepare(u2)
    r2 = second.route((0, 0), end, method="bidirectional")
    assert _core.label_spares()[0].count(301 * 257) == 0  # taken by the new chart
    # its own answer, not the first chart's: the labels were cleared (the two searches add the
    # same steps in another order: equal to rounding)
    assert r2.cost == pytest.approx(second.route((0, 0), end, method="dijkstra").cost, rel=1e-12)
    assert abs(r2.cost - r1.cost) > 1.0
    other = seaway.prepare(_costs(4, (300, 257)))  # another size: labels of its own
    got = other.route((0, 0), (299, 256), method="bidirectional").cost
    assert got == pytest.approx(other.route((0, 0), (299, 256), method="dijkstra").cost, rel=1e-12)
    del second
    gc.collect()
    assert _core.label_spares()[0].count(301 * 257) == 2


def test_the_spares_stay_under_their_bound():
    for seed in range(4):
        chart = seaway.prepare(_costs(seed, (400 + seed, 300)))
        chart.route((0, 0), (399, 299), method="bidirectional")
        del chart
    gc.collect()
    sizes, kept = _core.label_spares()
    assert 0 < kept <= 64 << 20 and len(sizes) >= 2
