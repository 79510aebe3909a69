"""The benchmark family's planar recipes (seaway.samples.family): deterministic, the land share
and cost range they promise, and exact routes on them by every method (small shapes)."""

import numpy as np
import pytest

import seaway
from seaway.samples.family import floe_sea, game_map, maze

RTOL = 1e-9


@pytest.mark.parametrize(
    "make, shape, land, lo, hi",
    [(floe_sea, (230, 190), 0.3, 1.0, 30.0), (game_map, (128, 128), 0.35, 1.0, 20.0)],
)
def test_recipes_are_deterministic_with_their_land_share_and_costs(make, shape, land, lo, hi):
    a, b = make(shape), make(shape)
    np.testing.assert_array_equal(a, b)
    assert a.shape == shape
    assert np.isinf(a).mean() == pytest.approx(land, abs=0.002)
    water = a[np.isfinite(a)]
    assert water.min() >= lo and water.max() <= hi
    assert not np.array_equal(a, make(shape, seed=7))


def test_maze_channels_join_the_corners_and_every_method_agrees():
    m = maze((120, 120), cell=12, wall=4)
    assert np.isinf(m[:4]).all() and np.isfinite(m[4:12, 4:12]).all()  # wall, first cell
    chart = seaway.prepare(m, landmarks=2)
    s, e = (6, 6), (114, 114)
    d = chart.route(s, e, method="dijkstra")
    straight = np.hypot(108, 108)
    assert d.cost > 1.5 * straight  # the maze's one way winds
    for method in ("astar", "bidirectional", "landmarks", "auto"):
        assert chart.route(s, e, method=method).cost == pytest.approx(d.cost, rel=RTOL), method
    with pytest.raises(ValueError, match="wall"):
        maze((120, 120), cell=12, wall=11)
