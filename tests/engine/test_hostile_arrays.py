"""The hostile-input campaign of issue 27, kept in the suite (seeded, a few seconds): malformed
arrays (NaN, inf, negative, huge and tiny costs; integer, bool, complex, text and object dtypes;
0-d to 3-d and empty shapes; flipped, transposed, strided, broadcast, misaligned, read-only and
Fortran views; bad land masks, points and coordinates) into seaway.route, cost_field, prepare and
route_many. Each call answers (a route of finite cost inside the chart, a field of the chart's
shape) or raises a ValueError/TypeError with a one-line message raised by seaway's own code
(support.hostile.Judge); never a crash or another library's traceback. SEAWAY_HOSTILE_ROUNDS=N
runs N seeded rounds (default 1)."""

import math

import numpy as np
import pytest

import seaway
from seaway.fleet import route_many
from support.hostile import ROUNDS, Judge

VALUES = [np.nan, np.inf, -np.inf, -1.0, -0.0, 0.0, 5e-324, 1e-300, 1e-9, 1.0, 3.0, 1e300, 1.7e308]
DTYPES = ["f8", "f4", "f2", "i8", "u1", "bool", "c16", "O", "U3", "M8[s]"]
SHAPES = [(), (0,), (3,), (0, 3), (3, 0), (1, 1), (1, 3), (3, 1), (4, 5), (6, 6), (2, 3, 4)]
VIEWS = [
    "plain",
    "flip rows",
    "flip cols",
    "transpose",
    "every other",
    "broadcast",
    "misaligned",
    "read-only",
    "fortran",
]
POINTS = [
    (0, 0),
    (1, 2),
    (3, 4),
    (-1, 0),
    (0, -1),
    (99, 0),
    (np.nan, 0),
    (np.inf, 1),
    (1e300, 0),
    (0.5, 0.5),
    ("a", 1),
    (0,),
    (0, 0, 0),
    None,
    (True, False),
    np.array([1, 1]),
    "0,0",
    2**70,
]
OPTIONS = {
    "neighbourhood": [3, 5, 15, 4, 0, -1, 17, 5.0, "5", None, True],
    "directions": ["full", "unique", "axis", "", None, 3],
    "edge_cost": ["max", "mean", "integral", "length", "min", None, 1],
    "dx": [1.0, 1e-300, 1e300, 0.0, -1.0, np.nan, "1", None],
    "method": ["auto", "dijkstra", "astar", "bidirectional", "landmarks", "bfs", None],
}


def _view(a, how, rng):
    if a.ndim == 0:
        return a
    if how == "flip rows":
        return a[::-1]
    if how == "flip cols":
        return a[..., ::-1] if a.ndim else a
    if how == "transpose":
        return a.T
    if how == "every other":
        return a[::2] if a.ndim else a
    if how == "broadcast" and a.ndim == 2 and a.size:
        return np.broadcast_to(a[:1], a.shape)
    if how == "misaligned" and a.dtype.kind in "fiu" and a.size:
        buf = np.zeros(a.nbytes + 1, np.uint8)
        odd = buf[1:].view(a.dtype).reshape(a.shape)
        odd[...] = a
        return odd
    if how == "read-only":
        b = np.array(a)
        b.flags.writeable = False
        return b
    if how == "fortran":
        return np.asfortranarray(a)
    return a


def _cost(rng):
    shape = (
        SHAPES[rng.integers(len(SHAPES))]
        if rng.random() < 0.25
        else (int(rng.integers(1, 7)), int(rng.integers(1, 8)))
    )
    values = np.array([VALUES[i] for i in rng.integers(len(VALUES), size=int(np.prod(shape)))]).reshape(shape)
    if rng.random() < 0.6:  # mostly water, so that some routes are asked of the engine
        values = np.where(rng.random(shape) < 0.8, rng.uniform(0.5, 5.0, shape), values)
    dtype = DTYPES[rng.integers(len(DTYPES))] if rng.random() < 0.2 else "f8"
    with np.errstate(all="ignore"):
        try:
            a = values.astype(dtype)
        except (ValueError, TypeError, OverflowError):
            a = values
    return _view(a, VIEWS[rng.integers(len(VIEWS))], rng) if rng.random() < 0.6 else a


def _land(rng, cost):
    shape = np.shape(cost)
    kind = rng.integers(8)
    if kind <= 2 or len(shape) != 2:
        return None
    if kind == 1:
        return np.zeros((shape[0] + 1, *shape[1:]), bool)
    if kind == 2:
        return rng.choice([0.0, 1.0, np.nan, 2.0], size=shape)
    if kind == 3:
        return np.array([["x"] * shape[1]] * shape[0])
    return _view(rng.random(shape) < 0.2, VIEWS[rng.integers(len(VIEWS))], rng)


def _kwargs(rng, cost):
    kw = {name: opts[rng.integers(len(opts))] for name, opts in OPTIONS.items() if rng.random() < 0.1}
    kw.setdefault("neighbourhood", 3)
    if rng.random() < 0.2 and np.ndim(cost) == 2:
        rows, cols = np.shape(cost)
        step = [0.5, -0.5, 0.0, np.nan][rng.integers(4)]
        kw["lat"] = 70.0 + step * np.arange(rows)
        kw["lon"] = [10.0 + 0.5 * np.arange(cols), np.zeros(cols), 170.0 + 5 * np.arange(cols)][
            rng.integers(3)
        ]
        if rng.random() < 0.2:
            kw["lat"] = kw["lat"][:-1]
    land = _land(rng, cost)
    if land is not None:
        kw["land"] = land
    return kw


def _point(rng, cost, kw):
    """Mostly a pixel of the chart (as (lat, lon) when it has coordinates), else a bad point."""
    if rng.random() < 0.35 or np.ndim(cost) != 2 or 0 in np.shape(cost):
        return POINTS[rng.integers(len(POINTS))]
    r, c = int(rng.integers(np.shape(cost)[0])), int(rng.integers(np.shape(cost)[1]))
    if "lat" in kw and len(kw["lat"]) > r:
        return (float(kw["lat"][r]), float(kw["lon"][c]))
    return (r, c)


def _check_route(judge, label, r, cost):
    if r is None:
        return
    if not (math.isfinite(r.cost) and r.cost >= 0):
        judge.fault(label, f"a route of cost {r.cost}")
    rows, cols = np.shape(cost)
    p = np.asarray(r.pixels)
    if p.size and not (
        (p[:, 0] >= 0).all() and (p[:, 0] < rows).all() and (p[:, 1] >= 0).all() and (p[:, 1] < cols).all()
    ):
        judge.fault(label, "a route leaves the chart")


@pytest.mark.parametrize("seed", range(ROUNDS))
def test_malformed_arrays_get_clean_errors_or_right_answers(seed):
    rng = np.random.default_rng(2700 + seed)
    judge = Judge()
    for case in range(160):
        cost = _cost(rng)
        kw = _kwargs(rng, cost)
        a, b = _point(rng, cost, kw), _point(rng, cost, kw)
        label = f"seed {seed} case {case}: cost {getattr(cost, 'dtype', '?')}{np.shape(cost)} {kw.keys()} {a!r} -> {b!r}"
        route_kw = {k: v for k, v in kw.items()}
        _check_route(
            judge,
            "route " + label,
            judge("route " + label, lambda: seaway.route(cost, a, b, **route_kw)),
            cost,
        )
        field_kw = {k: v for k, v in kw.items() if k != "method"}
        field = judge("cost_field " + label, lambda: seaway.cost_field(cost, a, **field_kw))
        if field is not None and np.shape(field) != np.shape(cost):
            judge.fault("cost_field " + label, f"a field of shape {np.shape(field)}")
        chart = judge("prepare " + label, lambda: seaway.prepare(cost, **field_kw))
        if chart is not None:
            _check_route(
                judge, "prepared " + label, judge("prepared " + label, lambda: chart.route(a, b)), cost
            )
    judge.verdict(at_least=100)
    assert judge.answered >= 20  # and the campaign reached the engine


@pytest.mark.parametrize("seed", range(ROUNDS))
def test_route_many_reports_every_bad_route_in_one_line_and_never_an_unexpected_error(seed):
    pytest.importorskip("pandas")
    rng = np.random.default_rng(2800 + seed)
    judge = Judge()
    for case in range(12):
        cost = _cost(rng)
        voyages = [(_point(rng, cost, {}), _point(rng, cost, {})) for _ in range(4)]
        voyages += [((0, 0),), "x", ((0, 0), (1, 1), [(0, 1)], 5)]  # malformed voyages
        label = f"seed {seed} case {case}: cost {getattr(cost, 'dtype', '?')}{np.shape(cost)}"
        table = judge(label, lambda: route_many(cost, voyages, threads=2, neighbourhood=3))
        if table is None:
            continue
        if len(table) != len(voyages):
            judge.fault(label, f"{len(table)} rows for {len(voyages)} voyages")
        for row in table.itertuples():
            if row.status == "error" or (row.status != "ok" and ("\n" in row.error or not row.error)):
                judge.fault(label, f"voyage {row.voyage}: {row.status}: {row.error!r}")
    for bad in ({"threads": 0}, {"threads": 1.5}, {"neighbourhood": 4}, {"vessels": 3}):
        judge(f"route_many {bad}", lambda: route_many(np.ones((3, 3)), [((0, 0), (2, 2))], **bad))
    judge.verdict(at_least=2)
