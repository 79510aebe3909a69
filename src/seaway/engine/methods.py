"""Which exact search answers a query, and running it; the engine's option checks.

Methods (all exact except weighted A*):
* "dijkstra": one search from the start.
* "astar": A* with the straight-line bound (distance x the chart's smallest cost); with
  weight=w > 1, weighted A* (cost <= w x optimum).
* "bidirectional": Dijkstra from the start and from the end at once on two threads, stopped
  by the exact rule top_f + top_b >= best meeting (cpp/seaway/bidirectional.hpp); on charts
  whose costs span at most a factor ASTAR_CONTRAST, bidirectional A* (average potential). Static
  raster models only (max, mean, integral, entered pixel): the backward search charges each
  step the forward step's cost, which needs costs that do not depend on the arrival time.
* "landmarks": bidirectional A* on two threads with the average potential of the landmark
  (ALT) bounds (one-thread A* with the landmark bound if BIDIRECTIONAL_LANDMARKS is False),
  after PreparedChart.prepare_landmarks() (or prepare(..., landmarks=N)) for this model; max,
  mean and integral only: the bound |D_L(t) - D_L(v)| needs a step to cost the same both ways, which these rules do (max and
  mean of the two ends x the step's length; the integral over the same segment).
* "auto" (the default): "astar" if a weight is given; on a chart with landmarks for the query's
  model, "landmarks" (for every voyage: see for_voyage); else, for
  a static raster model, "astar" on a chart where at least half the water costs the least
  (mostly_least_cost: the straight-line bound is then the true cost over most of the water, and
  one thread settles little more than the two sides of a bidirectional search do together;
  "bidirectional" for a voyage longer than LONG_VOYAGE_PIXELS: for_voyage) and "bidirectional"
  elsewhere (with the A* potential on a low-contrast chart); else "astar" (time-dependent
  models). It estimates no times: every two-thread search first searches alone from the start
  (cpp/seaway/bidirectional_side.hpp), so a short voyage costs what a one-way search does, and
  the landmark potential takes the max with the straight-line bound, so its bounds are at least
  as tight as bidirectional A*'s.
  (A fitted estimate of each method's time chose slower methods on charts it was not fitted
  on: benchmarks/README.md.)"""

from __future__ import annotations

import math
import time
from typing import TYPE_CHECKING, cast

import numpy as np

from .. import native as _core
from ..base.validate import number
from ..errors import SeawayError, SeawayTypeError
from ..models.base import EDGE_COSTS, EdgeCost
from .result import Search

if TYPE_CHECKING:
    from ..models.base import CostModel
    from .prepared import PreparedChart

EDGE_COST_NAMES = tuple(EDGE_COSTS)
METHODS = ("auto", "dijkstra", "astar", "bidirectional", "landmarks")
DIRECTIONS = ("full", "unique")
#: "bidirectional" adds the A* potential (the average of the distance bounds to the end and from
#: the start, x the chart's smallest cost) when the chart's passable costs span at most this
#: factor: on the summer chart (costs 1-2) it settles 45 % fewer pixels than without; on the
#: winter chart (1-30) the bound is too weak to pay for itself (benchmarks/README.md).
ASTAR_CONTRAST = 2.0
#: "landmarks" runs on two threads (bidirectional A*); False: A* on one thread (both exact).
BIDIRECTIONAL_LANDMARKS = True
#: auto takes one-way A* on a chart without landmarks when at least this share of the passable
#: pixels cost the chart's least cost (to 1 %): open water around patches of ice (the CIS and
#: AARI-shaped SIGRID-3 charts: 77 % and 100 %; the synthetic and game charts 0-27 %, the real
#: Kara chart 9 %: benchmarks/README.md).
LEAST_COST_SHARE = 0.5
#: On a chart where most water costs the least and without landmarks, auto takes bidirectional
#: search instead of one-way A* for a voyage whose ends lie more than LONG_VOYAGE_PIXELS apart
#: (straight line, in pixel steps): over a long way land makes the straight-line bound weak,
#: and the two threads pay (fresh AARI-shaped corner voyage: A* 1.43 x
#: bidirectional, DMI 2014's two voyages round Cape Farewell 1.55 x and 1.21 x; between 550 and
#: 820 pixels apart either wins by up to 1.26 x, below A* by up to 2 x: benchmarks/README.md).
LONG_VOYAGE_PIXELS = 900.0
#: The share is read from 4096 pixels at a fixed multiplicative-hash stride over the flat raster
#: (the same pixels, and answer, on every run) while the chart is prepared, in C++
#: (cpp/seaway/passability.hpp, least_cost_share): nothing is left for auto's decision to read.


def check_options(neighbourhood: int, directions: str) -> None:
    """Refuse a stencil size or direction set the engine does not take, naming the fix."""
    if isinstance(neighbourhood, bool) or not isinstance(neighbourhood, (int, np.integer)):
        raise SeawayTypeError(f"neighbourhood must be an odd integer from 3 to 15, got {neighbourhood!r}")
    if neighbourhood < 3 or neighbourhood > 15 or neighbourhood % 2 == 0:
        raise SeawayError(
            f"neighbourhood must be odd and between 3 and 15 (the k of the k x k stencil), got "
            f"{neighbourhood}; e.g. neighbourhood=5"
        )
    if directions not in DIRECTIONS:
        raise SeawayError(f"directions must be one of {DIRECTIONS}, got {directions!r}")


def heuristic_weight(method: str, weight: float | None) -> float:
    """The A* weight of `method` (0 for the methods without one); validates both."""
    if method not in METHODS:
        raise SeawayError(f"method must be one of {METHODS}, got {method!r}")
    if method == "auto" and weight is not None:
        method = "astar"  # a weight asks for (weighted) A*
    if method != "astar":
        if weight not in (None, 1, 1.0):
            raise SeawayError("weight inflates the A* heuristic; use it with method='astar'")
        return 0.0
    return (
        1.0
        if weight is None
        else number(
            weight, "weight", minimum=1, what="a finite number >= 1 (cost <= weight x optimum)", example=1.5
        )
    )


def resolve(prepared: PreparedChart, model: CostModel, method: str, weight: float | None = None) -> str:
    """The method that answers the query; refuses a method the model does not allow."""
    if method == "auto" and weight is not None:
        return "astar"
    if method == "auto":
        if model.static and prepared.landmarks_for(model) is not None:
            return "landmarks"
        if not model.static or mostly_least_cost(prepared, model):
            return "astar"
        return "bidirectional"
    if method == "bidirectional" and not model.static:
        raise SeawayError(
            f"method='bidirectional' needs a static raster model (edge_cost in {EDGE_COST_NAMES}); "
            f"the {model.name!r} model's step costs depend on the time of arrival, so the backward "
            "search cannot price them: use method='astar' or 'dijkstra'"
        )
    if method == "landmarks":
        if not (model.static and model.symmetric):
            raise SeawayError(
                f"method='landmarks' needs a symmetric static model (edge_cost in "
                f"{EDGE_COST_NAMES}), not {model.name!r}: use method='bidirectional' or 'astar'"
            )
        if prepared.landmarks_for(model) is None:
            raise SeawayError(
                f"the chart has no landmarks for the {model.name!r} model: call "
                f"prepared.prepare_landmarks(model={model.name!r}) first (or "
                "seaway.prepare(..., landmarks=True)), or use method='auto'"
            )
    return method


def search(
    prepared: PreparedChart,
    engine: _core.Model,
    s: int,
    e: int,
    method: str,
    weight: float,
    model: CostModel,
    cancel: _core.CancelToken | None,
) -> Search:
    """The search between flat pixels s and e by `method` (a public method)."""
    router = prepared.router
    # resolve() let "bidirectional" through for static models only, "landmarks" for symmetric
    # static ones with their tables (the capabilities, which the types cannot see)
    if method == "bidirectional":
        return Search.from_core(
            router.route_bidirectional(
                cast("_core.StaticModel", engine), s, e, low_contrast(prepared), cancel
            )
        )
    if method == "landmarks":
        landmarks = prepared.landmarks_for(model)
        assert landmarks is not None
        return Search.from_core(
            router.route_landmarks(
                cast("_core.RasterRule", engine), landmarks, s, e, BIDIRECTIONAL_LANDMARKS, cancel
            )
        )
    return Search.from_core(router.route(engine, s, e, weight, cancel))


def mostly_least_cost(prepared: PreparedChart, model: CostModel) -> bool:
    """At least LEAST_COST_SHARE of the chart's passable pixels cost its least cost (to 1 %),
    from the sample the preparation read; an edge-cost model only ("length" prices every step
    by its length: always)."""
    if not isinstance(model, EdgeCost):
        return False
    return model.name == "length" or prepared.router.least_cost_share >= LEAST_COST_SHARE


def for_voyage(
    prepared: PreparedChart,
    model: CostModel,
    requested: str,
    weight: float | None,
    method: str,
    s: tuple[int, int],
    e: tuple[int, int],
) -> str:
    """auto's method for the located ends s, e: "bidirectional" instead of one-way A* for a long
    voyage on a chart without landmarks where most water costs the least (LONG_VOYAGE_PIXELS);
    else `method` as resolved. A chart with landmarks keeps them for every voyage: one-way A*
    for short voyages in open water (a rule of 2026-12-06) lost to them on 12 of 15 such voyages
    of the SIGRID-3 charts once their fixed costs fell (benchmarks/README.md, "Pooled buckets
    and shared chord tables")."""
    if (
        requested != "auto"
        or weight is not None
        or not model.static
        or method != "astar"  # no landmarks: resolve() took A* for this chart
        or not mostly_least_cost(prepared, model)
    ):
        return method
    grid, across = prepared.chart.grid, abs(s[1] - e[1])
    apart = math.hypot(s[0] - e[0], min(across, grid.cols - across) if grid.wrap else across)  # the seam
    return "bidirectional" if apart > LONG_VOYAGE_PIXELS else method


def low_contrast(prepared: PreparedChart) -> bool:
    """The chart's passable costs span at most ASTAR_CONTRAST."""
    lo, hi, _ = prepared.router.cost_range  # found while the chart was prepared
    span = hi / lo if lo > 0 else np.inf
    return span <= ASTAR_CONTRAST


#: prepare_landmarks() without a count keeps 16 landmarks on charts of at most this many pixels
#: (64 B per pixel, 128 MiB of tables), else 8. The first 8 of 16 are the 8 (farthest-first
#: from the same seed), so 16 never bound worse; per voyage they cost a little more per settled
#: pixel. 16 / 8, two-sided landmark search, geometric mean per voyage over 30-40 random pairs:
#: 0.84-0.98 on six kinds of chart of 10^5-10^6 pixels; on the benchmark's voyages 0.57-1.11 by
#: kind (geometric mean 0.94). On 4.4 M-pixel charts no gain for twice the build (10 -> 18 s):
#: benchmarks/README.md, section "16 landmarks on charts of up to 2^21 pixels".
MANY_LANDMARKS_PIXELS = 1 << 21


def default_landmark_count(pixels: int) -> int:
    """How many landmarks prepare_landmarks() keeps on a chart of `pixels` pixels by default."""
    return 16 if pixels <= MANY_LANDMARKS_PIXELS else 8


def build_landmarks(
    prepared: PreparedChart,
    count: int,
    model: CostModel,
    seed_rc: tuple[int, int],
    cancel: _core.CancelToken | None,
) -> tuple[_core.Landmarks, float]:
    """The landmark tables of `model` on `prepared`, and the seconds it took."""
    if isinstance(count, bool) or not isinstance(count, (int, np.integer)):
        raise SeawayTypeError(f"landmarks must be an integer from 1 to 64, got {count!r}")
    if not 1 <= count <= 64:
        raise SeawayError(f"landmarks must be from 1 to 64 (4 bytes per pixel each), got {count}")
    if not (model.static and model.symmetric):
        raise SeawayError(
            f"landmarks need a symmetric static model (edge_cost in {EDGE_COST_NAMES}), not {model.name!r}"
        )
    t0 = time.perf_counter()
    seed = seed_rc[0] * prepared.chart.shape[1] + seed_rc[1]
    engine = cast("_core.RasterRule", model.engine(prepared))  # symmetric and static: checked above
    # A chart with landmarks is for many queries: every later landmark query under this model
    # leaves out the doubled steps two unit steps replace at no more cost
    # (cpp/seaway/collinear.hpp; the other searches read no table). Each model keeps its own
    # table; its engine model is kept
    # with the chart (the functor's type and its raster's address key the table) until a new
    # one replaces it, whose table goes first (the two share a key: the same rule, the same raster).
    old = prepared.pruned_for.pop(model.name, None)
    if old is not None:
        prepared.router.forget_pruned(old)
    if prepared.router.prune_collinear(engine):
        prepared.pruned_for[model.name] = engine
    lm = prepared.router.build_landmarks(engine, int(count), int(seed), cancel)
    return lm, time.perf_counter() - t0
