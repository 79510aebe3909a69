"""Drop-in replacements for scikit-image's raster routing, on seaway's engine.

    from seaway.compat import route_through_array   # was: from skimage.graph import ...

follows scikit-image's rules so results match: negative, NaN and infinite costs are
impassable; a diagonal step may pass between two impassable pixels that meet at a corner
(only the step's two ends are checked); with geometric=True a step costs the mean of its two
pixels times its length, with geometric=False the cost of every pixel on the path, start
included, is summed."""

from __future__ import annotations

import numpy as np

from .base.interrupt import interruptible
from .chart.raster import as_chart
from .engine.prepared import PreparedChart
from .errors import NoRouteError, SeawayError
from .models import EdgeCost, EnteredPixel


def _from_negative_start(prepared, s, e, fully_connected):
    """skimage seeds the start whatever its cost, so from a negative start (geometric=True)
    only the first steps cost (u_s + u_n) / 2 x length < possibly 0; every later step is between
    passable pixels (no step enters a negative pixel). The answer is the least over the start's
    passable neighbours n of that first step plus the least cost n -> end, which the engine
    gives exactly (its mean step cost is symmetric: one cost field from the end serves all n)."""
    u, (rows, cols) = prepared.chart.values, prepared.chart.shape
    if not (u[e] >= 0 and u[e] < np.inf):  # skimage never steps onto an impassable end
        return np.inf, None
    engine = prepared.model.engine(prepared)
    field, _ = interruptible(lambda cancel: prepared.router.field(engine, e[0] * cols + e[1], cancel))
    best = (np.inf, None)
    for di, dj in ((-1, -1), (-1, 0), (-1, 1), (0, -1), (0, 1), (1, -1), (1, 0), (1, 1)):
        n = (s[0] + di, s[1] + dj)
        if (di and dj and not fully_connected) or not (0 <= n[0] < rows and 0 <= n[1] < cols):
            continue
        if not (u[n] >= 0 and u[n] < np.inf and field[n] < np.inf):
            continue
        first = (u[s] + u[n]) / 2 * float(np.hypot(di, dj))
        if first + field[n] < best[0]:
            best = (first + field[n], n)
    if best[1] is None:
        return np.inf, None
    rest = prepared.search(best[1], e, 0.0, prepared.model).path
    return best[0], np.concatenate([[s[0] * cols + s[1]], rest])


def route_through_array(costs, start, end, fully_connected=True, geometric=True):
    """Like skimage.graph.route_through_array for 2-D arrays: returns (path, cost) with path a
    list of (row, col) tuples from start to end."""
    arr = np.asarray(costs)
    if arr.ndim != 2:
        raise SeawayError(
            f"seaway.compat handles 2-D cost arrays, got {arr.ndim}-D; use skimage.graph for other dimensions"
        )
    chart = as_chart(arr.astype(np.float64, copy=False), allow_negative=True)
    rows, cols = chart.shape
    pts = []
    for name, p in (("start", start), ("end", end)):
        r, c = (int(v) for v in p)
        if r < 0:
            r += rows
        if c < 0:
            c += cols
        if not (0 <= r < rows and 0 <= c < cols):
            raise SeawayError(f"{name} {tuple(p)} lies outside the array of shape {arr.shape}")
        pts.append((r, c))
    (s, e) = pts
    if not geometric and not chart.values[s] < np.inf:  # +inf or NaN start: skimage finds no path
        raise NoRouteError("no minimum-cost path was found to the specified end point")
    model = EdgeCost("mean") if geometric else EnteredPixel()
    prepared = PreparedChart.from_chart(chart, 3, "full" if fully_connected else "axis", model, "ends")
    if geometric and chart.values[s] < 0 and s != e:
        total, path = _from_negative_start(prepared, s, e, fully_connected)
    else:
        found = prepared.search(s, e, 0.0, model)
        total, path = found.cost, found.path
    if not total < np.inf:  # (a -inf start gives -inf, as in skimage)
        raise NoRouteError("no minimum-cost path was found to the specified end point")
    if not geometric:
        total += chart.values[s]
    return [tuple(int(v) for v in divmod(int(i), cols)) for i in path], np.float64(total)
