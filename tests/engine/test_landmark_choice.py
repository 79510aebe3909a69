"""prepare_landmarks keeps 16 landmarks on charts of up to 2^21 pixels, else 8
(seaway.engine.methods.MANY_LANDMARKS_PIXELS): the 16 are the 8 and 8 more, farthest-first from
the same seed, so their bound is never weaker; exact against the brute-force reference."""

from __future__ import annotations

import numpy as np
import pytest

import seaway
from seaway.engine import methods
from seaway.samples import synthetic_sea
from support.grids import RTOL, blob_geo, blob_sea, check_path, largest_water, point, reference_voyages
from support.reference import RefGraph


@pytest.mark.parametrize("seed", range(3))
@pytest.mark.parametrize("two_sided", [True, False])
def test_the_default_16_landmarks_give_dijkstra_s_cost(seed, two_sided, monkeypatch):
    """Both landmark searches on a chart prepared with the default count (16 here) give the
    brute-force reference's cost and a path it prices the same, on planar and lat/lon charts,
    for voyages to random pixels and to the farthest one."""
    monkeypatch.setattr(methods, "BIDIRECTIONAL_LANDMARKS", two_sided)
    u = blob_sea(seed, shape=(110, 140))
    geo = blob_geo(seed, u.shape)
    chart = seaway.prepare(u, edge_cost="mean", **geo)
    assert chart.prepare_landmarks()["count"] == 16
    ref = RefGraph(u, k=5, edge_cost="mean", **geo)
    for s, e, least in reference_voyages(ref, largest_water(u), np.random.default_rng(seed), starts=4):
        r = chart.route(point(geo, s), point(geo, e), method="landmarks")
        assert r.cost == pytest.approx(least, rel=RTOL), (s, e)
        check_path(ref, r, s, e, geo)


def test_16_landmarks_settle_fewer_pixels_than_8():
    """The 10^5-pixel benchmark chart ('A small'), one-way landmark A* (one thread: its counts do
    not depend on timing), 40 random voyages: the 16 landmarks begin with the 8, and settle a
    sixth fewer pixels in all (103,517 against 123,527; the same costs); no voyage settles more
    than a few pixels more (none did; ties could break otherwise)."""
    u = synthetic_sea((300, 333))
    eight, sixteen = seaway.prepare(u), seaway.prepare(u)
    few = eight.prepare_landmarks(8)
    many = sixteen.prepare_landmarks()
    assert many["bytes_per_pixel"] == 64.0 and many["pixels"][:8] == few["pixels"]
    water = largest_water(u)
    rng = np.random.default_rng(4)
    counts = []
    for _ in range(40):
        s, e = (tuple(map(int, water[i])) for i in rng.choice(len(water), size=2))
        found = [
            chart.router.route_landmarks(
                chart.model.engine(chart),
                chart.landmarks_for(chart.model),
                chart.flat(s),
                chart.flat(e),
                False,
            )
            for chart in (eight, sixteen)
        ]
        assert found[0].cost == pytest.approx(found[1].cost, rel=RTOL)
        counts.append([f.stats.settled for f in found])
    c = np.array(counts)
    assert c[:, 1].sum() < 0.85 * c[:, 0].sum(), counts
    assert np.all(c[:, 1] <= c[:, 0] + 16), counts


def test_prepare_landmarks_keeps_16_on_charts_of_up_to_2_to_the_21_pixels():
    """The default count: 16 (64 B per pixel) up to 2^21 pixels, 8 above; a count given is kept;
    seaway.prepare(landmarks=True) takes the default."""
    assert methods.default_landmark_count(2**21) == 16
    assert methods.default_landmark_count(2**21 + 1) == 8
    chart = seaway.prepare(np.ones((40, 50)))
    assert chart.prepare_landmarks()["count"] == 16
    assert chart.prepare_landmarks(5)["count"] == 5
    assert seaway.prepare(np.ones((40, 50)), landmarks=True).landmark_stats["max"]["count"] == 16
    assert seaway.prepare(np.ones((40, 50)), landmarks=3).landmark_stats["max"]["count"] == 3
    assert not seaway.prepare(np.ones((40, 50)), landmarks=False).landmark_stats
