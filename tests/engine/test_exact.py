"""The faster exact methods (bidirectional Dijkstra on two threads, A* with landmarks, "auto")
against the brute-force reference (tests/reference.py) on random charts of every stencil,
edge cost and grid kind (planar, lat/lon ascending and descending, 360-degree wrap), with
land, NaN, inf and zero-cost pixels."""

from __future__ import annotations

import threading

import numpy as np
import pytest

import seaway
from seaway import _core
from seaway.engine import methods as engine_methods
from support.grids import CASES, RTOL, check_path, make_chart, point
from support.reference import RefGraph

METHODS = ("bidirectional", "landmarks", "auto")


def _ends(ref, start, expect, rng):
    fin = np.isfinite(expect)
    reach = np.argwhere(fin)
    ends = [
        tuple(int(v) for v in reach[i])
        for i in rng.choice(len(reach), size=min(5, len(reach)), replace=False)
    ]
    ends.append(tuple(int(v) for v in reach[np.argmax(expect[fin])]))  # the farthest pixel
    return ends, [tuple(int(v) for v in e) for e in np.argwhere(~fin & ref.ok)[:2]]


@pytest.mark.parametrize("potential", [False, True], ids=["dijkstra", "astar"])
@pytest.mark.parametrize("edge_cost,k,directions,grid", CASES)
def test_exact_methods_match_reference(edge_cost, k, directions, grid, potential, monkeypatch):
    """Both forms of the bidirectional search: plain, and with the A* potential (used on
    low-contrast charts; forced here on every chart); and both forms of the landmark search:
    A* on one thread (with the plain bidirectional runs) and bidirectional A* with the average
    landmark potential on two (with the A* runs)."""
    monkeypatch.setattr(seaway.engine.methods, "ASTAR_CONTRAST", np.inf if potential else 0.0)
    monkeypatch.setattr(seaway.engine.methods, "BIDIRECTIONAL_LANDMARKS", potential)
    seed = CASES.index((edge_cost, k, directions, grid))
    u, land, geo = make_chart(3000 + seed, grid, zeros=seed % 3 == 0)
    opts = dict(land=land, neighbourhood=k, directions=directions, edge_cost=edge_cost, **geo)
    ref = RefGraph(u, land=land, k=k, directions=directions, edge_cost=edge_cost, **geo)
    rng = np.random.default_rng(seed)
    water = np.argwhere(ref.ok)
    prepared = seaway.prepare(u, landmarks=int(rng.integers(1, 5)), **opts)
    plain = seaway.prepare(u, **opts)
    for _ in range(2):
        start = tuple(int(v) for v in water[rng.integers(len(water))])
        expect = ref.costs(start)
        ends, cut = _ends(ref, start, expect, rng)
        for end in ends:
            for chart, methods in ((prepared, METHODS), (plain, ("bidirectional", "auto"))):
                for method in methods:
                    r = chart.route(point(geo, start), point(geo, end), method=method)
                    assert r.cost == pytest.approx(expect[end], rel=RTOL, abs=1e-12), (method, start, end)
                    check_path(ref, r, start, end, geo)
                    assert r.stats.search.settled >= (0 if start == end else 1)
        for end in cut:
            for method in METHODS:
                with pytest.raises(seaway.NoRouteError):
                    prepared.route(point(geo, start), point(geo, end), method=method)


def test_auto_picks_landmarks_then_bidirectional():
    """auto: bidirectional on any chart without landmarks (a short voyage is searched by the
    forward side alone: one thread, a one-way search's pixels), landmarks once the chart has
    them for the query's model; all give Dijkstra's cost."""
    u, land, geo = make_chart(11, "planar", zeros=False)
    opts = dict(land=land, edge_cost="mean", **geo)
    chart = seaway.prepare(u, **opts)
    ref = RefGraph(u, land=land, k=5, edge_cost="mean", **geo)
    ok = np.argwhere(np.isfinite(ref.costs(tuple(np.argwhere(ref.ok)[0]))))
    s, e = (tuple(int(v) for v in ok[0]), tuple(int(v) for v in ok[-1]))
    r = chart.route(s, e)
    assert r.method == "bidirectional"
    d = chart.route(s, e, method="dijkstra")
    assert r.cost == pytest.approx(d.cost, rel=RTOL)
    # the chart is smaller than the solo phase: the forward side settles what Dijkstra does
    assert r.stats.search.settled == d.stats.search.settled
    chart.prepare_landmarks(3)
    r = chart.route(s, e)
    assert r.method == "landmarks" and r.cost == pytest.approx(d.cost, rel=RTOL)
    assert chart.route(s, e, model="max").method == "bidirectional"  # landmarks are per model
    st = chart.landmark_stats["mean"]
    assert st["count"] == 3 and st["bytes_per_pixel"] == 12.0 and len(st["pixels"]) == 3
    light = seaway.prepare(1.0 + u / (10 * np.nanmax(u[np.isfinite(u)])), **opts)  # within 1.1x
    a = light.route(s, e)  # low contrast: the A* potential prunes, even alone
    assert a.method == "bidirectional"
    assert a.stats.search.settled < light.route(s, e, method="dijkstra").stats.search.settled


def test_landmarks_prune_and_bidirectional_splits_the_work(monkeypatch):
    """On a uniform sea both methods settle far fewer pixels than Dijkstra, same cost; the
    A* potential prunes further."""
    u = np.ones((200, 200))
    u[80:120, 98:102] = np.inf  # a wall to go round
    chart = seaway.prepare(u, edge_cost="mean", landmarks=4)
    d = chart.route((100, 40), (100, 160), method="dijkstra")
    for method, share in (("bidirectional", 0.5), ("landmarks", 0.5)):  # uniform: low contrast
        r = chart.route((100, 40), (100, 160), method=method)
        assert r.cost == pytest.approx(d.cost, rel=RTOL)
        assert r.stats.search.settled < share * d.stats.search.settled, method
    monkeypatch.setattr(seaway.engine.methods, "ASTAR_CONTRAST", 0.0)
    plain = seaway.prepare(u, edge_cost="mean").route((100, 40), (100, 160), method="bidirectional")
    assert plain.cost == pytest.approx(d.cost, rel=RTOL)
    assert r.stats.search.settled < plain.stats.search.settled < 0.85 * d.stats.search.settled


def test_entered_pixel_model_bidirectional():
    """The backward search charges the forward step's cost: right for asymmetric models too."""
    from seaway.models import EnteredPixel

    rng = np.random.default_rng(3)
    u = rng.uniform(0.5, 9.0, (30, 40))
    u[rng.random(u.shape) < 0.1] = np.inf
    u[0, 0] = u[29, 39] = 1.0
    chart = seaway.prepare(u)
    d = chart.route((0, 0), (29, 39), model=EnteredPixel(), method="dijkstra")
    b = chart.route((0, 0), (29, 39), model=EnteredPixel(), method="bidirectional")
    assert b.cost == pytest.approx(d.cost, rel=RTOL)
    assert b.cost == pytest.approx(float(np.sum(u[tuple(b.pixels[1:].T)])), rel=RTOL)
    with pytest.raises(ValueError, match="symmetric"):
        chart.route((0, 0), (29, 39), model=EnteredPixel(), method="landmarks")


def test_methods_refuse_what_they_cannot_do():
    u = np.ones((10, 10))
    chart = seaway.prepare(u)
    with pytest.raises(ValueError, match=r"no landmarks.*prepare_landmarks\(model=.max.\).*landmarks=True"):
        chart.route((0, 0), (9, 9), method="landmarks")
    with pytest.raises(ValueError, match="method must be one of"):
        chart.route((0, 0), (9, 9), method="fast")
    with pytest.raises(ValueError, match="weight"):
        chart.route((0, 0), (9, 9), method="bidirectional", weight=2)
    with pytest.raises(ValueError, match="1 to 64"):
        chart.prepare_landmarks(0)
    with pytest.raises(TypeError, match="integer"):
        chart.prepare_landmarks(2.5)


def test_bidirectional_refuses_time_dependent_models():
    from seaway.models import TravelTime

    class FakeTime(TravelTime):  # a time model without a forecast: resolve() looks at the type
        def __init__(self):
            self.name = "time"

    chart = seaway.prepare(np.ones((5, 5)))
    with pytest.raises(ValueError, match="time of arrival"):
        seaway.engine.methods.resolve(chart, FakeTime(), "bidirectional")
    assert seaway.engine.methods.resolve(chart, FakeTime(), "auto") == "astar"


def test_bidirectional_from_many_threads_equals_serial():
    rng = np.random.default_rng(5)
    u = rng.uniform(1.0, 5.0, (120, 150))
    u[rng.random(u.shape) < 0.15] = np.inf
    chart = seaway.prepare(u, edge_cost="max")
    water = np.argwhere(np.isfinite(u))
    pairs = [(tuple(water[i]), tuple(water[j])) for i, j in rng.integers(len(water), size=(12, 2))]
    field = {s: chart.cost_field(s) for s, _ in pairs}
    want = [field[s][e] for s, e in pairs]
    got = [None] * len(pairs)

    def work(i):
        s, e = pairs[i]
        try:
            got[i] = chart.route(s, e, method="bidirectional").cost
        except seaway.NoRouteError:
            got[i] = np.inf

    threads = [threading.Thread(target=work, args=(i,)) for i in range(len(pairs))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    np.testing.assert_allclose(got, want, rtol=RTOL)


def test_cancel_token_stops_bidirectional_and_landmark_building():
    rng = np.random.default_rng(2)
    u = rng.uniform(1.0, 30.0, (400, 400))
    chart = seaway.prepare(u)
    token = _core.CancelToken()
    token.set()
    engine = chart.model.engine(chart)
    with pytest.raises(KeyboardInterrupt, match="search cancelled"):
        chart.router.route_bidirectional(engine, 0, u.size - 1, True, token)
    with pytest.raises(KeyboardInterrupt, match="search cancelled"):
        chart.router.build_landmarks(engine, 2, 0, token)
    full = chart.cost_field((0, 0))
    assert chart.route((0, 0), (399, 399), method="bidirectional").cost == pytest.approx(
        full[399, 399], rel=RTOL
    )


def test_bidirectional_is_the_same_bit_for_bit_on_one_core_and_on_two():
    """The rounds are counts of settled pixels and the stop is decided at barriers, so the
    threads' timing cannot change the answer: pinned to one core (the two sides then take turns)
    and free on two, the route and its cost are identical, over many rounds (1024 pixels each, after the solo start)."""
    import os

    rng = np.random.default_rng(9)
    u = rng.uniform(1.0, 30.0, (300, 400))
    u[rng.random(u.shape) < 0.2] = np.inf
    u[5, 5] = u[290, 390] = 2.0
    chart = seaway.prepare(u, edge_cost="mean")
    free = chart.route((5, 5), (290, 390), method="bidirectional")
    assert free.stats.search.settled > 10 * 4096  # many rounds
    runs = [chart.route((5, 5), (290, 390), method="bidirectional") for _ in range(3)]
    if hasattr(os, "sched_setaffinity") and len(os.sched_getaffinity(0)) > 1:
        cores = os.sched_getaffinity(0)
        os.sched_setaffinity(0, {min(cores)})  # new threads inherit the calling thread's mask
        try:
            runs.append(chart.route((5, 5), (290, 390), method="bidirectional"))
        finally:
            os.sched_setaffinity(0, cores)
    for r in runs:
        assert r.cost == free.cost  # exactly: same meeting pixel, same sums
        np.testing.assert_array_equal(r.pixels, free.pixels)
        assert r.stats.search.settled == free.stats.search.settled
    assert free.cost == pytest.approx(chart.route((5, 5), (290, 390), method="dijkstra").cost, rel=RTOL)


@pytest.mark.parametrize(
    "method,two_sided", [("bidirectional", True), ("landmarks", True), ("landmarks", False)]
)
def test_labels_kept_between_queries_give_the_same_routes(method, two_sided, monkeypatch):
    """The chart keeps a query's bidirectional labels and its searches' caches of landmark bounds
    for the next one (each zeroed before a search starts): queries in any order, after a long
    one or a cancelled one, give the routes a fresh chart gives, bit for bit, by the same
    search. A bound left from a query to another end would change the search (and often break
    its bound: a wrong cost); with the caches not cleared, both landmark cases fail here."""
    monkeypatch.setattr(engine_methods, "BIDIRECTIONAL_LANDMARKS", two_sided)
    rng = np.random.default_rng(12)
    u = rng.uniform(1.0, 20.0, (250, 300))
    u[rng.random(u.shape) < 0.2] = np.inf
    water = [tuple(int(v) for v in p) for p in np.argwhere(np.isfinite(u))]
    pairs = [(water[i], water[j]) for i, j in rng.integers(len(water), size=(6, 2))]
    kept = seaway.prepare(u, edge_cost="max", landmarks=4)
    token = _core.CancelToken()
    token.set()  # stops after 4096 pixels, leaving its labels half written
    # the middle to the farthest pixel it reaches: past the forward side's solo phase
    mid = water[len(water) // 2]
    field = kept.cost_field(mid)
    far = [mid[0] * u.shape[1] + mid[1], int(np.argmax(np.where(np.isfinite(field), field, -1)))]
    engine = kept.model.engine(kept)
    with pytest.raises(KeyboardInterrupt, match="search cancelled"):
        if method == "bidirectional":
            kept.router.route_bidirectional(engine, *far, False, token)
        else:
            kept.router.route_landmarks(engine, kept.landmarks_for(kept.model), *far, two_sided, token)
    charts = []  # each fresh chart kept alive: none takes another's labels (label_spares.hpp)
    for s, e in pairs + pairs[::-1]:
        fresh = seaway.prepare(u, edge_cost="max", landmarks=4)
        charts.append(fresh)
        try:
            want = fresh.route(s, e, method=method)
        except seaway.NoRouteError:
            with pytest.raises(seaway.NoRouteError):
                kept.route(s, e, method=method)
            continue
        got = kept.route(s, e, method=method)
        assert got.cost == want.cost
        assert got.stats.search.settled == want.stats.search.settled  # the same search
        np.testing.assert_array_equal(got.pixels, want.pixels)
        assert got.cost == pytest.approx(fresh.route(s, e, method="dijkstra").cost, rel=RTOL)


def test_landmarks_go_to_the_largest_water_not_the_centre_s_lake():
    """The chart's centre lies in a walled lake: the landmarks are all placed in the open sea
    around it (the largest body of water), whose voyages they then prune; a voyage in the lake
    gets no bound from them and is still exact."""
    u = np.random.default_rng(5).uniform(1.0, 10.0, (160, 160))
    u[60:100, 60:100] = np.inf  # the wall...
    u[66:94, 66:94] = 2.0  # ...around a lake at the centre
    chart = seaway.prepare(u, edge_cost="mean", landmarks=4)
    for r, c in chart.landmark_stats["mean"]["pixels"]:
        assert not (60 <= r < 100 and 60 <= c < 100), (r, c)
    s, e = (5, 5), (150, 155)
    lm, bi = (chart.route(s, e, method=m) for m in ("landmarks", "bidirectional"))
    assert lm.cost == pytest.approx(chart.cost_field(s)[e], rel=RTOL) == bi.cost
    assert lm.stats.search.settled < 0.5 * bi.stats.search.settled
    inside = chart.route((70, 70), (90, 88), method="landmarks")
    assert inside.cost == pytest.approx(chart.cost_field((70, 70))[90, 88], rel=RTOL)
