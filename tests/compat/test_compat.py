"""seaway.compat.route_through_array against scikit-image's route_through_array."""

import math

import numpy as np
import pytest

skgraph = pytest.importorskip("skimage.graph")

import seaway  # noqa: E402
from seaway.compat import route_through_array  # noqa: E402


def passable(u):
    return np.isfinite(u) and u >= 0


def path_cost(costs, path, fully_connected, geometric):
    """A path's cost under scikit-image's rules, checking each step is a legal move."""
    costs = np.asarray(costs, dtype=float)
    assert len(path) >= 1
    for (r0, c0), (r1, c1) in zip(path[:-1], path[1:]):
        dr, dc = abs(r1 - r0), abs(c1 - c0)
        assert (dr, dc) != (0, 0) and max(dr, dc) == 1, "not a stencil step"
        if not fully_connected:
            assert dr + dc == 1, "diagonal step on a 4-connected search"
    for r, c in path[1:]:
        assert passable(costs[r, c]), f"path enters impassable pixel {(r, c)}"
    if not geometric:
        return float(sum(costs[r, c] for r, c in path))
    total = 0.0
    for (r0, c0), (r1, c1) in zip(path[:-1], path[1:]):
        step = math.sqrt(2) if (r0 != r1 and c0 != c1) else 1.0
        total += 0.5 * (costs[r0, c0] + costs[r1, c1]) * step
    return total


def random_costs(seed, shape=(20, 30), bad=0.12):
    rng = np.random.default_rng(seed)
    a = rng.uniform(0.0, 10.0, shape)
    kind = rng.integers(0, 4, shape)
    holes = rng.random(shape) < bad
    a[holes & (kind == 0)] = -1.0
    a[holes & (kind == 1)] = np.inf
    a[holes & (kind == 2)] = np.nan
    a[holes & (kind == 3)] = -np.inf
    a[rng.random(shape) < 0.03] = 0.0  # free pixels are allowed
    return a


def both(costs, start, end, **kw):
    """(skimage result or its exception type, seaway result or its exception type).

    scikit-image only skips costs that are negative or == inf: a NaN pixel enters its heap as a
    NaN cumulative cost, which gives wrong answers or a segfault (skimage 0.26). seaway treats NaN
    as impassable, as skimage means to, so skimage is given NaN as inf."""
    costs = np.asarray(costs, dtype=float)
    out = []
    for f, a in (
        (skgraph.route_through_array, np.where(np.isnan(costs), np.inf, costs)),
        (route_through_array, costs),
    ):
        try:
            out.append(f(a, start, end, **kw))
        except ValueError as e:
            out.append(type(e))
    return out


@pytest.mark.parametrize("seed", range(8))
@pytest.mark.parametrize("fully_connected", [True, False])
@pytest.mark.parametrize("geometric", [True, False])
def test_matches_skimage_on_random_arrays(seed, fully_connected, geometric):
    a = random_costs(seed)
    rng = np.random.default_rng(100 + seed)
    ok = np.argwhere(np.isfinite(a) & (a >= 0))
    compared = 0
    for _ in range(4):
        s, e = (tuple(int(v) for v in ok[i]) for i in rng.choice(len(ok), 2, replace=False))
        sk, sw = both(a, s, e, fully_connected=fully_connected, geometric=geometric)
        if isinstance(sk, type):  # no path: seaway must agree
            assert sw is seaway.NoRouteError
            continue
        (_, sk_cost), (sw_path, sw_cost) = sk, sw
        assert isinstance(sw_cost, np.floating)
        assert all(type(p) is tuple and len(p) == 2 and all(type(v) is int for v in p) for p in sw_path)
        assert sw_path[0] == s and sw_path[-1] == e
        assert sw_cost == pytest.approx(sk_cost, rel=1e-9, abs=1e-9)
        assert path_cost(a, sw_path, fully_connected, geometric) == pytest.approx(sk_cost, rel=1e-9, abs=1e-9)
        compared += 1
    assert compared >= 2


def test_matches_skimage_with_many_obstacles():
    # 35% impassable: some pairs are disconnected, both libraries must say so
    a = random_costs(42, shape=(25, 25), bad=0.35)
    ok = [tuple(int(v) for v in p) for p in np.argwhere(np.isfinite(a) & (a >= 0))]
    found = missing = 0
    for e in ok[::7]:
        sk, sw = both(a, ok[0], e, fully_connected=False)
        if isinstance(sk, type):
            assert sw is seaway.NoRouteError
            missing += 1
        else:
            assert sw[1] == pytest.approx(sk[1], rel=1e-9)
            found += 1
    assert found > 0 and missing > 0


def test_corner_passing_diagonal_allowed_like_skimage():
    a = np.array([[1.0, np.inf], [np.inf, 1.0]])
    path, cost = route_through_array(a, (0, 0), (1, 1))
    assert path == [(0, 0), (1, 1)]
    assert cost == pytest.approx(math.sqrt(2))  # (1+1)/2 * sqrt2
    assert skgraph.route_through_array(a, (0, 0), (1, 1))[1] == pytest.approx(cost)
    # non-geometric: the two pixels' costs summed
    assert route_through_array(a, (0, 0), (1, 1), geometric=False) == ([(0, 0), (1, 1)], 2.0)
    # seaway's own route forbids that diagonal (segment rule)
    with pytest.raises(seaway.NoRouteError):
        seaway.route(a, (0, 0), (1, 1), neighbourhood=3)
    # and 4-connected there is no path at all
    with pytest.raises(ValueError, match="no minimum-cost path was found"):
        route_through_array(a, (0, 0), (1, 1), fully_connected=False)
    with pytest.raises(ValueError, match="no minimum-cost path was found"):
        skgraph.route_through_array(a, (0, 0), (1, 1), fully_connected=False)


def test_hand_values():
    a = np.array([[1.0, 2, 3, 4], [5, 6, 7, 8], [9, 10, 11, 12]])
    # 4-connected, summed: 1+2+3+4+8+12 = 30 along the top row and right column
    assert route_through_array(a, (0, 0), (2, 3), fully_connected=False, geometric=False) == (
        [(0, 0), (0, 1), (0, 2), (0, 3), (1, 3), (2, 3)],
        30.0,
    )
    # 8-connected geometric: (1+2)/2 + (2+7)/2*sqrt2 + (7+12)/2*sqrt2 = 1.5 + 14 sqrt2
    path, cost = route_through_array(a, (0, 0), (-1, -1))
    assert path == [(0, 0), (0, 1), (1, 2), (2, 3)]
    assert cost == pytest.approx(1.5 + 14 * math.sqrt(2))
    # start == end
    assert route_through_array(a, (1, 1), (1, 1)) == ([(1, 1)], 0.0)
    assert route_through_array(a, (1, 1), (1, 1), geometric=False) == ([(1, 1)], 6.0)


def test_no_path_raises_value_error():
    a = np.ones((5, 5))
    a[:, 2] = -1
    for kw in ({}, {"geometric": False}, {"fully_connected": False}):
        with pytest.raises(ValueError, match="no minimum-cost path was found"):
            skgraph.route_through_array(a, (0, 0), (4, 4), **kw)
        with pytest.raises(ValueError, match="no minimum-cost path was found"):
            route_through_array(a, (0, 0), (4, 4), **kw)
    # end on an impassable pixel
    with pytest.raises(ValueError, match="no minimum-cost path was found"):
        route_through_array(a, (0, 0), (0, 2))


@pytest.mark.parametrize("bad", [np.inf, np.nan])
@pytest.mark.parametrize("geometric", [True, False])
def test_impassable_start_raises_like_skimage(bad, geometric):
    a = np.ones((3, 3))
    a[0, 0] = bad
    with pytest.raises(ValueError):  # skimage is given NaN as inf (see both())
        skgraph.route_through_array(np.where(np.isnan(a), np.inf, a), (0, 0), (2, 2), geometric=geometric)
    with pytest.raises(ValueError, match="no minimum-cost path was found"):
        route_through_array(a, (0, 0), (2, 2), geometric=geometric)


def test_nan_is_impassable_like_inf():
    a = random_costs(5)
    b = np.where(np.isnan(a), np.inf, a)
    ok = [tuple(int(v) for v in p) for p in np.argwhere(np.isfinite(a) & (a >= 0))]
    for kw in ({}, {"geometric": False}, {"fully_connected": False}):
        pa, ca = route_through_array(a, ok[0], ok[-1], **kw)
        pb, cb = route_through_array(b, ok[0], ok[-1], **kw)
        assert ca == cb and pa == pb and np.isfinite(ca)
        assert not any(np.isnan(a[p]) for p in pa)


def test_list_and_integer_input():
    a = [[1, 3, 1], [1, 9, 1], [1, 1, 1]]
    for kw in ({}, {"geometric": False}, {"fully_connected": False}):
        sk_path, sk_cost = skgraph.route_through_array(a, (0, 0), (0, 2), **kw)
        path, cost = route_through_array(a, (0, 0), (0, 2), **kw)
        assert cost == pytest.approx(sk_cost)
        assert path_cost(
            a, path, kw.get("fully_connected", True), kw.get("geometric", True)
        ) == pytest.approx(cost)


def test_bad_arguments():
    with pytest.raises(ValueError, match="lies outside the array"):
        route_through_array(np.ones((3, 3)), (0, 0), (3, 0))
    with pytest.raises(ValueError, match="use skimage.graph for other dimensions"):
        route_through_array(np.ones((3, 3, 3)), (0, 0, 0), (1, 1, 1))


# --- a negative start pixel (issue 13) -----------------------------------------------------


def test_compat_negative_start_by_hand_and_as_skimage():
    """8 x 4 ones, start (4, 1) at -0.5, end (0, 3): the first step costs (-0.5 + 1) / 2 x its
    length; diagonal first, 0.25 sqrt 2, then sqrt 2 + 2 to the end: 2 + 1.25 sqrt 2 (a
    straight first step gives 0.25 + 2 sqrt 2 + 1, more). With (3, 2) blocked it is that."""
    skgraph = pytest.importorskip("skimage.graph")
    from seaway.compat import route_through_array

    a = np.ones((8, 4))
    a[4, 1] = -0.5
    path, cost = route_through_array(a, (4, 1), (0, 3))
    assert cost == pytest.approx(2 + 1.25 * np.sqrt(2), rel=1e-14)
    assert path == [(4, 1), (3, 2), (2, 2), (1, 2), (0, 3)]
    assert cost == pytest.approx(skgraph.route_through_array(a, (4, 1), (0, 3))[1], rel=1e-14)
    a[3, 2] = np.inf
    path, cost = route_through_array(a, (4, 1), (0, 3))
    assert cost == pytest.approx(0.25 + 2 * np.sqrt(2) + 1, rel=1e-14)
    assert cost == pytest.approx(skgraph.route_through_array(a, (4, 1), (0, 3))[1], rel=1e-14)
    assert path[:2] == [(4, 1), (3, 1)]


def test_compat_negative_start_matches_skimage():
    skgraph = pytest.importorskip("skimage.graph")
    from seaway.compat import route_through_array

    rng = np.random.default_rng(13)
    compared = 0
    for _ in range(60):
        a = rng.uniform(-1.0, 5.0, (8, 4))  # negative pixels are impassable, except the start
        s, e = (4, 1), (int(rng.integers(8)), int(rng.integers(4)))
        a[s] = -rng.uniform(0.1, 1.0)
        for fc in (True, False):
            try:
                sk_path, sk_cost = skgraph.route_through_array(a, s, e, fully_connected=fc)
            except ValueError:
                with pytest.raises(ValueError, match="no minimum-cost path"):
                    route_through_array(a, s, e, fully_connected=fc)
                continue
            path, cost = route_through_array(a, s, e, fully_connected=fc)
            assert cost == pytest.approx(sk_cost, rel=1e-12, abs=1e-12)
            assert path[0] == s and path[-1] == e
            steps = zip(path[:-1], path[1:])
            again = sum((a[p] + a[q]) / 2 * np.hypot(p[0] - q[0], p[1] - q[1]) for p, q in steps)
            assert again == pytest.approx(cost)  # the path given has the cost given
            compared += 1
    assert compared > 40
