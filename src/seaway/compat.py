"""Drop-in replacements for scikit-image's raster routing, on seaway's engine.

    from seaway.compat import route_through_array   # was: from skimage.graph import ...

follows scikit-image's rules so results match: negative, NaN and infinite costs are
impassable; a diagonal step may pass between two impassable pixels that meet at a corner
(only the step's two ends are checked); with geometric=True a step costs the mean of its two
pixels times its length, with geometric=False the cost of every pixel on the path, start
included, is summed."""

from __future__ import annotations

import numpy as np

from ._chart import as_chart
from ._engine import PreparedChart
from .errors import NoRouteError
from .models import EdgeCost, EnteredPixel


def route_through_array(costs, start, end, fully_connected=True, geometric=True):
    """Like skimage.graph.route_through_array for 2-D arrays: returns (path, cost) with path a
    list of (row, col) tuples from start to end."""
    arr = np.asarray(costs)
    if arr.ndim != 2:
        raise ValueError(
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
            raise ValueError(f"{name} {tuple(p)} lies outside the array of shape {arr.shape}")
        pts.append((r, c))
    (s, e) = pts
    if geometric and chart.values[s] < 0:
        # skimage starts such a route with a negative step cost; seaway's search needs costs
        # >= 0 (it answered |cost|), so it refuses rather than return a wrong cost.
        raise ValueError(f"start {tuple(start)} has a negative cost ({chart.values[s]:g}); with "
                         "geometric=True a route from it would start with a negative step cost, "
                         "which seaway does not handle: start from a pixel with cost >= 0")
    if not geometric and not chart.values[s] < np.inf:  # +inf or NaN start: skimage finds no path
        raise NoRouteError("no minimum-cost path was found to the specified end point")
    model = EdgeCost("mean") if geometric else EnteredPixel()
    prepared = PreparedChart._from_chart(chart, 3, "full" if fully_connected else "axis", model,
                                         "ends")
    total, path, *_ = prepared._search(s, e, 0.0, model)
    if not np.isfinite(total):
        raise NoRouteError("no minimum-cost path was found to the specified end point")
    if not geometric:
        total += chart.values[s]
    return [tuple(int(v) for v in divmod(int(i), cols)) for i in path], np.float64(total)
